#include <fsgmpm/particles/point_locator.h>
#include <fsgmpm/step/cell_loops.h>
#include <fsgmpm/step/stages.h>

#include <optional>

namespace fsgmpm
{
  namespace Stages
  {
    template <int dim>
    unsigned int
    relocate(const BackgroundGrid<dim>                    &grid,
             ParticleStore<dim>                           &particles,
             const std::vector<std::unique_ptr<Material>> *materials,
             CompensatedSum                               *outflow_energy)
    {
      const PointLocator<dim> locator(grid);
      const unsigned int      n = particles.size();
      CellLoops::parallel_range(
        n, [&](const unsigned int b, const unsigned int e) {
          // The points are still in cell order: the geometry of a cell
          // once for its points.
          unsigned int cached = BackgroundGrid<dim>::invalid;
          std::optional<CellGeometry<dim>> geometry;
          for (unsigned int p = b; p < e; ++p)
            {
              const unsigned int c = particles.cell[p];
              if (c != cached)
                {
                  geometry.emplace(CellLoops::geometry(grid, particles, c));
                  cached = c;
                }
              particles.cell[p]
                = locator.locate(particles.position[p], c, *geometry);
            }
        });

      unsigned int lost = 0;
      for (unsigned int p = 0; p < n; ++p)
        lost += (particles.cell[p] == BackgroundGrid<dim>::invalid);
      if (lost > 0)
        {
          std::vector<std::uint8_t> flag(n, 0);
          for (unsigned int p = 0; p < n; ++p)
            flag[p] = (particles.cell[p] == BackgroundGrid<dim>::invalid);
          // What leaves with them: kinetic and stored energy (gravity's
          // work on them is in the external work already).
          if (materials != nullptr && outflow_energy != nullptr)
            for (unsigned int p = 0; p < n; ++p)
              if (flag[p] != 0)
                outflow_energy->add(
                  0.5 * particles.mass[p] * particles.velocity[p].norm_square()
                  + (*materials)[particles.material_id[p]]->add_strain_energy(
                    &particles.stress[p],
                    &particles.volume[p],
                    &particles.reference_volume[p],
                    1,
                    0.));
          particles.remove_flagged(flag);
        }
      particles.sort_by_cell(grid.n_cells());
      return lost;
    }



    template unsigned int
    relocate<2>(const BackgroundGrid<2> &,
                ParticleStore<2> &,
                const std::vector<std::unique_ptr<Material>> *,
                CompensatedSum *);
    template unsigned int
    relocate<3>(const BackgroundGrid<3> &,
                ParticleStore<3> &,
                const std::vector<std::unique_ptr<Material>> *,
                CompensatedSum *);
  } // namespace Stages
} // namespace fsgmpm
