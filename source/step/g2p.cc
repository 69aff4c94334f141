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
        const std::vector<Tensor<1, dim>> *xpic_correction)
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
      const bool  apic  = particles.has_affine_velocity();
      const bool  blend = !apic && pic_fraction > 0;
      const auto &field = apic ? nodes.velocity : nodes.acceleration;
      CellLoops::for_each_occupied_cell(particles, [&](const unsigned int c) {
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
            if (apic)
              particles.velocity[p] = value;
            else
              particles.velocity[p] += dt * value;
            if (blend)
              {
                Tensor<1, dim> pic;
                for (unsigned int k = 0; k < dim + 1; ++k)
                  pic += lambda[k] * v[k];
                particles.velocity[p]
                  += pic_fraction * (pic - particles.velocity[p]);
              }
          }
      });
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
           const std::vector<Tensor<1, 2>> *);
    template void
    g2p<3>(const BackgroundGrid<3> &,
           const NodalFields<3> &,
           const double,
           ParticleStore<3> &,
           const double,
           const std::vector<Tensor<1, 3>> *);
  } // namespace Stages
} // namespace fsgmpm
