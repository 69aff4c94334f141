#include <fsgmpm/particles/point_locator.h>
#include <fsgmpm/step/cell_loops.h>
#include <fsgmpm/step/stages.h>

namespace fsgmpm
{
  namespace Stages
  {
    template <int dim>
    unsigned int
    relocate(const BackgroundGrid<dim> &grid, ParticleStore<dim> &particles)
    {
      const PointLocator<dim> locator(grid);
      const unsigned int      n = particles.size();
      CellLoops::parallel_range(
        n, [&](const unsigned int b, const unsigned int e) {
          for (unsigned int p = b; p < e; ++p)
            particles.cell[p]
              = locator.locate(particles.position[p], particles.cell[p]);
        });

      unsigned int lost = 0;
      for (unsigned int p = 0; p < n; ++p)
        lost += (particles.cell[p] == BackgroundGrid<dim>::invalid);
      if (lost > 0)
        {
          std::vector<std::uint8_t> flag(n, 0);
          for (unsigned int p = 0; p < n; ++p)
            flag[p] = (particles.cell[p] == BackgroundGrid<dim>::invalid);
          particles.remove_flagged(flag);
        }
      particles.sort_by_cell(grid.n_cells());
      return lost;
    }



    template <int dim>
    double
    stable_time_step(const BackgroundGrid<dim>                    &grid,
                     const ParticleStore<dim>                     &particles,
                     const std::vector<std::unique_ptr<Material>> &materials,
                     const double                                  courant)
    {
      const auto         &cells = particles.occupied_cells;
      std::vector<double> cell_dt(cells.size());
      CellLoops::parallel_range(
        cells.size(),
        [&](const unsigned int b, const unsigned int e) {
          for (unsigned int i = b; i < e; ++i)
            {
              const unsigned int c     = cells[i];
              double             speed = 0;
              for (unsigned int p = particles.cell_start[c];
                   p < particles.cell_start[c + 1];
                   ++p)
                {
                  const double    rho = particles.mass[p] / particles.volume[p];
                  const Material &mat = *materials[particles.material_id[p]];
                  speed               = std::max(speed,
                                   mat.wave_speed(rho)
                                     + particles.velocity[p].norm()
                                     + 2. * dim * mat.viscosity()
                                         / (rho * grid.cell_min_altitude[c]));
                }
              cell_dt[i] = (speed > 0) ? grid.cell_min_altitude[c] / speed
                                       : std::numeric_limits<double>::max();
            }
        },
        16);
      double dt = std::numeric_limits<double>::max();
      for (const double d : cell_dt)
        dt = std::min(dt, d);
      return courant * dt;
    }

    template unsigned int
    relocate<2>(const BackgroundGrid<2> &, ParticleStore<2> &);
    template unsigned int
    relocate<3>(const BackgroundGrid<3> &, ParticleStore<3> &);
    template double
    stable_time_step<2>(const BackgroundGrid<2> &,
                        const ParticleStore<2> &,
                        const std::vector<std::unique_ptr<Material>> &,
                        const double);
    template double
    stable_time_step<3>(const BackgroundGrid<3> &,
                        const ParticleStore<3> &,
                        const std::vector<std::unique_ptr<Material>> &,
                        const double);
  } // namespace Stages
} // namespace fsgmpm
