#include <fsgmpm/step/cell_loops.h>
#include <fsgmpm/step/stages.h>

#include <atomic>

namespace fsgmpm
{
  namespace Stages
  {
    template <int dim>
    double
    update_positions(const BackgroundGrid<dim> &grid,
                     const NodalFields<dim>    &nodes,
                     const double               dt,
                     ParticleStore<dim>        &particles)
    {
      std::vector<double> cell_ratio_squared(particles.occupied_cells.size(),
                                             0.);
      const auto         &cells = particles.occupied_cells;
      CellLoops::parallel_range(
        cells.size(),
        [&](const unsigned int b, const unsigned int e) {
          for (unsigned int i = b; i < e; ++i)
            {
              const unsigned int      c = cells[i];
              const CellGeometry<dim> geometry
                = CellLoops::geometry(grid, particles, c);
              Tensor<1, dim> v[dim + 1];
              for (unsigned int k = 0; k < dim + 1; ++k)
                v[k] = nodes.velocity[grid.cell_nodes[c][k]];
              double max_disp = 0;
              for (unsigned int p = particles.cell_begin(c);
                   p < particles.cell_end(c);
                   ++p)
                {
                  const auto lambda
                    = geometry.barycentric(particles.position[p]);
                  Tensor<1, dim> dx;
                  for (unsigned int k = 0; k < dim + 1; ++k)
                    dx += lambda[k] * v[k];
                  dx *= dt;
                  particles.position[p] += dx;
                  max_disp = std::max(max_disp, dx.norm_square());
                }
              // The ratio squared, (|dx| / h)^2 = |dx|^2 / h^2: no root or
              // division per cell; one root of the largest below.
              cell_ratio_squared[i]
                = max_disp * geometry.inverse_square_min_altitude();
            }
        },
        16);
      double ratio_squared = 0;
      for (const double r : cell_ratio_squared)
        ratio_squared = std::max(ratio_squared, r);
      return std::sqrt(ratio_squared);
    }

    template double
    update_positions<2>(const BackgroundGrid<2> &,
                        const NodalFields<2> &,
                        const double,
                        ParticleStore<2> &);
    template double
    update_positions<3>(const BackgroundGrid<3> &,
                        const NodalFields<3> &,
                        const double,
                        ParticleStore<3> &);
  } // namespace Stages
} // namespace fsgmpm
