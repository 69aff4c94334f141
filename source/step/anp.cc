#include <fsgmpm/step/cell_loops.h>
#include <fsgmpm/step/stages.h>

#include <optional>

namespace fsgmpm
{
  namespace Stages
  {
    template <int dim>
    void
    average_nodal_pressure(const BackgroundGrid<dim>          &grid,
                           const NodalFields<dim>             &nodes,
                           const std::vector<MaterialOptions> &options,
                           SmoothingFields<dim>               &smoothing,
                           ParticleStore<dim>                 &particles,
                           const std::function<void()>        &synchronise)
    {
      bool any = false;
      for (unsigned int m = 0; m < options.size(); ++m)
        if (options[m].anp)
          {
            smoothing.reset(m, nodes.active_nodes);
            any = true;
          }
      if (!any)
        return;

      // Eq. (29): p_i = sum_e sum_p p_p w_p / sum_e sum_p w_p over the cells
      // attached to node i, w_p the point volumes (optionally capped per
      // cell), per material, without the free-surface points.
      CellLoops::scatter_by_colour(grid, particles, [&](const unsigned int c) {
        thread_local std::vector<double> scale;
        CellLoops::weight_scales(
          grid,
          particles,
          options,
          c,
          [&](const unsigned int p) { return !particles.free_surface[p]; },
          scale);
        // Every point of the cell adds to the same dim + 1 nodes: sum over
        // each run of points of one material first, then add once per node.
        unsigned int run_material = numbers::invalid_unsigned_int;
        double       pV_sum = 0, w_sum = 0;
        const auto   flush = [&]() {
          if (w_sum > 0)
            for (const unsigned int i : grid.cell_nodes[c])
              {
                smoothing.numerator[run_material][i] += pV_sum;
                smoothing.denominator[run_material][i] += w_sum;
              }
          pV_sum = w_sum = 0;
        };
        for (unsigned int p = particles.cell_begin(c);
             p < particles.cell_end(c);
             ++p)
          {
            const unsigned int m = particles.material_id[p];
            if (!options[m].anp || particles.free_surface[p])
              continue;
            if (m != run_material)
              {
                flush();
                run_material = m;
              }
            const double w = scale[m] * particles.volume[p];
            pV_sum += -trace(particles.stress[p]) / 3. * w;
            w_sum += w;
          }
        flush();
      });
      // MPI: the nodal values on the rim of the ghost layer from their
      // owners, before the points read them back.
      if (synchronise)
        synchronise();
      // Each node's average once, not at each of its cells' reads.
      for (unsigned int m = 0; m < options.size(); ++m)
        if (options[m].anp)
          smoothing.divide(m, nodes.active_nodes);
      CellLoops::for_each_occupied_cell(particles, [&](const unsigned int c) {
        // Without interpolation p_bar is the cell's, per material: computed
        // once per run of points of the same material.
        unsigned int run_material = numbers::invalid_unsigned_int;
        double       p_bar        = 0;
        std::optional<CellGeometry<dim>> geometry;
        for (unsigned int p = particles.cell_begin(c);
             p < particles.cell_end(c);
             ++p)
          {
            const unsigned int m = particles.material_id[p];
            if (!options[m].anp || particles.free_surface[p])
              continue;
            if (options[m].anp_interpolate)
              {
                if (!geometry)
                  geometry.emplace(CellLoops::geometry(grid, particles, c));
                const auto lambda
                  = geometry->barycentric(particles.position[p]);
                p_bar = 0;
                for (unsigned int k = 0; k < dim + 1; ++k)
                  p_bar
                    += lambda[k] * smoothing.average(m, grid.cell_nodes[c][k]);
              }
            else if (m != run_material)
              {
                p_bar = 0;
                for (const unsigned int i : grid.cell_nodes[c])
                  p_bar += smoothing.average(m, i);
                p_bar /= (dim + 1);
                run_material = m;
              }
            // Eq. (28): deviatoric part kept, spherical part averaged
            // (sigma <- dev(sigma) - p_bar I, on the diagonal only); with
            // the stabilisation a share alpha of the point's own pressure
            // stays, as NMD keeps the cell's own rate (the stress power
            // then still equals the nodal forces' power).
            SymmetricTensor<2, 3> &s     = particles.stress[p];
            const double           mean  = trace(s) / 3;
            const double           alpha = options[m].smoothing_stabilisation;
            const double pressure        = (1. - alpha) * p_bar - alpha * mean;
            for (unsigned int d = 0; d < 3; ++d)
              s[d][d] = (s[d][d] - mean) - pressure;
          }
      });
    }



    template void
    average_nodal_pressure<2>(const BackgroundGrid<2> &,
                              const NodalFields<2> &,
                              const std::vector<MaterialOptions> &,
                              SmoothingFields<2> &,
                              ParticleStore<2> &,
                              const std::function<void()> &);
    template void
    average_nodal_pressure<3>(const BackgroundGrid<3> &,
                              const NodalFields<3> &,
                              const std::vector<MaterialOptions> &,
                              SmoothingFields<3> &,
                              ParticleStore<3> &,
                              const std::function<void()> &);
  } // namespace Stages
} // namespace fsgmpm
