#include <fsgmpm/step/cell_loops.h>
#include <fsgmpm/step/stages.h>

namespace fsgmpm
{
  namespace Stages
  {
    template <int dim>
    std::pair<unsigned int, unsigned int>
    detect_free_surface(const BackgroundGrid<dim>          &grid,
                        const NodalFields<dim>             &nodes,
                        const std::vector<MaterialOptions> &options,
                        SmoothingFields<dim>               &smoothing,
                        ParticleStore<dim>                 &particles)
    {
      bool any = false;
      for (const auto &o : options)
        any = any || o.detect_free_surface;
      if (!any)
        return {0, 0};

      // phi_i = sum_p N_i(x_p) V_p / Vbar_i, Vbar_i the lumped volume of the
      // node's non-empty cells: the volume-fraction form of Eqs. (31)-(33),
      // counting the points of every material.
      auto &phi = smoothing.volume_fraction;
      auto &vol = smoothing.lumped_volume;
      if (phi.size() != grid.n_nodes())
        {
          phi.assign(grid.n_nodes(), 0.);
          vol.assign(grid.n_nodes(), 0.);
        }
      for (const unsigned int i : nodes.active_nodes)
        phi[i] = vol[i] = 0.;
      CellLoops::scatter_by_colour(grid, particles, [&](const unsigned int c) {
        double share[dim + 1] = {};
        for (unsigned int p = particles.cell_start[c];
             p < particles.cell_start[c + 1];
             ++p)
          {
            const auto lambda = grid.barycentric(c, particles.position[p]);
            for (unsigned int k = 0; k < dim + 1; ++k)
              share[k] += lambda[k] * particles.volume[p];
          }
        for (unsigned int k = 0; k < dim + 1; ++k)
          {
            const unsigned int i = grid.cell_nodes[c][k];
            phi[i] += share[k];
            vol[i] += grid.cell_volume[c] / (dim + 1);
          }
      });
      for (const unsigned int i : nodes.active_nodes)
        if (vol[i] > 0)
          phi[i] /= vol[i];

      std::vector<std::pair<unsigned int, unsigned int>> flagged(
        particles.occupied_cells.size(), {0, 0});
      CellLoops::parallel_range(
        particles.occupied_cells.size(),
        [&](const unsigned int b, const unsigned int e) {
          for (unsigned int ci = b; ci < e; ++ci)
            {
              const unsigned int c = particles.occupied_cells[ci];
              for (unsigned int p = particles.cell_start[c];
                   p < particles.cell_start[c + 1];
                   ++p)
                {
                  const MaterialOptions &o = options[particles.material_id[p]];
                  if (!o.detect_free_surface)
                    continue;
                  ++flagged[ci].second;
                  const auto lambda
                    = grid.barycentric(c, particles.position[p]);
                  double phi_p = 0;
                  for (unsigned int k = 0; k < dim + 1; ++k)
                    phi_p += lambda[k] * phi[grid.cell_nodes[c][k]];
                  const bool free = (phi_p <= o.free_surface_threshold);
                  particles.free_surface[p] = free;
                  if (free)
                    {
                      // Zero pressure, volume back to the reference state.
                      particles.stress[p] = deviator(particles.stress[p]);
                      particles.volume[p] = particles.reference_volume[p];
                      ++flagged[ci].first;
                    }
                }
            }
        },
        16);
      std::pair<unsigned int, unsigned int> n = {0, 0};
      for (const auto &f : flagged)
        {
          n.first += f.first;
          n.second += f.second;
        }
      return n;
    }



    template std::pair<unsigned int, unsigned int>
    detect_free_surface<2>(const BackgroundGrid<2> &,
                           const NodalFields<2> &,
                           const std::vector<MaterialOptions> &,
                           SmoothingFields<2> &,
                           ParticleStore<2> &);
    template std::pair<unsigned int, unsigned int>
    detect_free_surface<3>(const BackgroundGrid<3> &,
                           const NodalFields<3> &,
                           const std::vector<MaterialOptions> &,
                           SmoothingFields<3> &,
                           ParticleStore<3> &);
  } // namespace Stages
} // namespace fsgmpm
