#include <fsgmpm/step/cell_loops.h>
#include <fsgmpm/step/stages.h>

namespace fsgmpm
{
  namespace Stages
  {
    template <int dim>
    void
    g2p(const BackgroundGrid<dim>         &grid,
        const NodalFields<dim>            &nodes,
        const double                       dt,
        ParticleStore<dim>                &particles,
        const double                       pic_fraction,
        const std::vector<Tensor<1, dim>> *xpic_correction,
        CompensatedSum                    *removed)
    {
      // FLIP (Eq. 19): v_p += dt a(x_p), blended with a PIC fraction beta:
      // v_p = (1 - beta)(v_p + dt a(x_p)) + beta v(x_p), which leaves the
      // grid-resolved motion alone and lets the sub-cell part (FLIP's noise)
      // decay by (1 - beta) per step (Zhu and Bridson 2005). APIC (Jiang et al.
      // 2015): the point takes the grid's velocity, v_p = v(x_p), so the
      // sub-cell velocity noise that FLIP keeps on the points is dropped; its
      // affine part C_p is set after the remap (store_affine_velocity).
      // With XPIC's correction c the blend's target is S (v^L + c): the
      // grid-resolved motion is kept to 1 - (1 - a)^m instead of a
      // (xpic_correction()).
      const bool  apic          = particles.has_affine_velocity();
      const bool  blend         = !apic && pic_fraction > 0;
      const auto &field         = apic ? nodes.velocity : nodes.acceleration;
      const auto  transfer_cell = [&](const unsigned int c, double &lost) {
        Tensor<1, dim>          f[dim + 1], v[dim + 1];
        const CellGeometry<dim> geometry
          = CellLoops::geometry(grid, particles, c);
        for (unsigned int k = 0; k < dim + 1; ++k)
          {
            f[k] = field[grid.cell_nodes[c][k]];
            if (blend)
              {
                v[k] = nodes.velocity[grid.cell_nodes[c][k]];
                if (xpic_correction != nullptr)
                  v[k] += (*xpic_correction)[grid.cell_nodes[c][k]];
              }
          }
        for (unsigned int p = particles.cell_begin(c);
             p < particles.cell_end(c);
             ++p)
          {
            const auto     lambda = geometry.barycentric(particles.position[p]);
            Tensor<1, dim> value;
            for (unsigned int k = 0; k < dim + 1; ++k)
              value += lambda[k] * f[k];
            // FLIP's velocity, against which the blend's or APIC's loss
            // is booked.
            Tensor<1, dim> flip = particles.velocity[p];
            if (!apic)
              flip += dt * value;
            else if (removed != nullptr)
              for (unsigned int k = 0; k < dim + 1; ++k)
                flip += (dt * lambda[k])
                        * nodes.acceleration[grid.cell_nodes[c][k]];
            if (apic)
              particles.velocity[p] = value;
            else
              particles.velocity[p] = flip;
            if (blend)
              {
                Tensor<1, dim> pic;
                for (unsigned int k = 0; k < dim + 1; ++k)
                  pic += lambda[k] * v[k];
                particles.velocity[p]
                  += pic_fraction * (pic - particles.velocity[p]);
              }
            if (removed != nullptr)
              {
                lost += 0.5 * particles.mass[p]
                        * (flip.norm_square()
                           - particles.velocity[p].norm_square());
              }
          }
      };
      if (removed == nullptr || !(blend || apic))
        {
          CellLoops::for_each_occupied_cell(particles,
                                            [&](const unsigned int c) {
                                              double unused = 0;
                                              transfer_cell(c, unused);
                                            });
          return;
        }
      // Owned points only (MPI), in fixed chunks of 16 cells: the same sum
      // for any number of threads.
      const auto          &cells = particles.occupied_cells;
      const CompensatedSum sum   = CellLoops::chunked_reduction(
        cells.size(),
        16,
        CompensatedSum(),
        [&](const unsigned int a, CompensatedSum &s) {
          const unsigned int c    = cells[a];
          double             lost = 0;
          transfer_cell(c, lost);
          const unsigned int begin = particles.cell_begin(c);
          if (particles.ghost.empty() || begin == particles.cell_end(c)
              || particles.ghost[begin] == 0)
            s.add(lost);
        },
        [](CompensatedSum &total, const CompensatedSum &chunk) {
          total.add(chunk);
        });
      removed->add(sum);
    }



    template <int dim>
    void
    store_affine_velocity(const SmoothingFields<dim> &smoothing,
                          ParticleStore<dim>         &particles)
    {
      if (!particles.has_affine_velocity())
        return;
      CellLoops::for_each_occupied_cell(particles, [&](const unsigned int c) {
        for (unsigned int p = particles.cell_begin(c);
             p < particles.cell_end(c);
             ++p)
          particles.affine_velocity[p] = smoothing.cell_velocity_gradient(c);
      });
    }

    template void
    store_affine_velocity<2>(const SmoothingFields<2> &, ParticleStore<2> &);
    template void
    store_affine_velocity<3>(const SmoothingFields<3> &, ParticleStore<3> &);

    template void
    g2p<2>(const BackgroundGrid<2> &,
           const NodalFields<2> &,
           const double,
           ParticleStore<2> &,
           const double,
           const std::vector<Tensor<1, 2>> *,
           CompensatedSum *);
    template void
    g2p<3>(const BackgroundGrid<3> &,
           const NodalFields<3> &,
           const double,
           ParticleStore<3> &,
           const double,
           const std::vector<Tensor<1, 3>> *,
           CompensatedSum *);
  } // namespace Stages
} // namespace fsgmpm
