#include <fsgmpm/step/cell_loops.h>
#include <fsgmpm/step/stages.h>

namespace fsgmpm
{
  namespace Stages
  {
    template <int dim>
    void
    nmd(const BackgroundGrid<dim>          &grid,
        const NodalFields<dim>             &nodes,
        const std::vector<MaterialOptions> &options,
        SmoothingFields<dim>               &smoothing,
        const ParticleStore<dim>           &particles)
    {
      // NMD, Eq. (24): nodal volumetric strain rate, averaged over the
      // attached non-empty cells with the volumes of the material's points
      // as weights (per material), optionally capped per cell. The points
      // flagged at the free surface (by the last step's detection, which
      // gave them zero pressure) are left out as ANP leaves them out of
      // Eq. (29): with the same weights in both averages the points' stress
      // power equals the nodal forces' power. With them in, the rate of a
      // closing cavity's surface cells compressed the water below without
      // the work of a force, creating energy.
      bool any_nmd = false;
      for (unsigned int m = 0; m < options.size(); ++m)
        if (options[m].nmd)
          {
            smoothing.reset(m, nodes.active_nodes);
            any_nmd = true;
          }
      if (any_nmd)
        CellLoops::scatter_by_colour(
          grid, particles, [&](const unsigned int c) {
            const double rate = trace(smoothing.cell_velocity_gradient(c));
            thread_local std::vector<double> scale;
            CellLoops::weight_scales(
              grid,
              particles,
              options,
              c,
              [&](const unsigned int p) { return !particles.free_surface[p]; },
              scale);
            // Every point of the cell adds to the same dim + 1 nodes: sum
            // the weights over each run of points of one material first.
            unsigned int run_material = numbers::invalid_unsigned_int;
            double       w_sum        = 0;
            const auto   flush        = [&]() {
              if (w_sum > 0)
                for (const unsigned int i : grid.cell_nodes[c])
                  {
                    smoothing.numerator[run_material][i] += w_sum * rate;
                    smoothing.denominator[run_material][i] += w_sum;
                  }
              w_sum = 0;
            };
            for (unsigned int p = particles.cell_begin(c);
                 p < particles.cell_end(c);
                 ++p)
              {
                const unsigned int m = particles.material_id[p];
                if (!options[m].nmd || particles.free_surface[p])
                  continue;
                if (m != run_material)
                  {
                    flush();
                    run_material = m;
                  }
                w_sum += scale[m] * particles.volume[p];
              }
            flush();
          });
    }

    template void
    nmd<2>(const BackgroundGrid<2> &,
           const NodalFields<2> &,
           const std::vector<MaterialOptions> &,
           SmoothingFields<2> &,
           const ParticleStore<2> &);
    template void
    nmd<3>(const BackgroundGrid<3> &,
           const NodalFields<3> &,
           const std::vector<MaterialOptions> &,
           SmoothingFields<3> &,
           const ParticleStore<3> &);
  } // namespace Stages
} // namespace fsgmpm
