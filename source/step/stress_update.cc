#include <fsgmpm/materials/hill_rotation.h>
#include <fsgmpm/step/cell_loops.h>
#include <fsgmpm/step/stages.h>

namespace fsgmpm
{
  namespace Stages
  {
    template <int dim>
    void
    stress_update(const BackgroundGrid<dim>                    &grid,
                  const NodalFields<dim>                       &nodes,
                  const std::vector<std::unique_ptr<Material>> &materials,
                  const double                                  dt,
                  ParticleStore<dim>                           &particles)
    {
      CellLoops::for_each_occupied_cell(particles, [&](const unsigned int c) {
        // Linear simplices: grad v is constant in the cell.
        Tensor<2, dim> L;
        for (unsigned int k = 0; k < dim + 1; ++k)
          L += outer_product(nodes.velocity[grid.cell_nodes[c][k]],
                             grid.shape_gradients[c][k]);
        Tensor<2, 3> L3;
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            L3[i][j] = L[i][j];
        PointKinematics kin;
        kin.strain_rate = symmetrize(L3);
        kin.spin        = 0.5 * (L3 - transpose(L3));
        kin.rotation    = incremental_rotation(kin.spin, dt);

        Tensor<2, dim> F_increment = unit_symmetric_tensor<dim>();
        F_increment += dt * L;
        const double J_increment = determinant(F_increment);

        thread_local std::vector<PointKinematics> kinematics;
        const unsigned int begin = particles.cell_start[c];
        const unsigned int end   = particles.cell_start[c + 1];
        kinematics.assign(end - begin, kin);

        // One call per run of points of the same material.
        unsigned int run = begin;
        while (run < end)
          {
            const std::uint16_t mat  = particles.material_id[run];
            unsigned int        last = run + 1;
            while (last < end && particles.material_id[last] == mat)
              ++last;
            materials[mat]->update_stresses(kinematics.data() + (run - begin),
                                            particles.stress.data() + run,
                                            last - run,
                                            dt);
            run = last;
          }
        for (unsigned int p = begin; p < end; ++p)
          particles.volume[p] *= J_increment;
      });
    }

    template void
    stress_update<2>(const BackgroundGrid<2> &,
                     const NodalFields<2> &,
                     const std::vector<std::unique_ptr<Material>> &,
                     const double,
                     ParticleStore<2> &);
    template void
    stress_update<3>(const BackgroundGrid<3> &,
                     const NodalFields<3> &,
                     const std::vector<std::unique_ptr<Material>> &,
                     const double,
                     ParticleStore<3> &);
  } // namespace Stages
} // namespace fsgmpm
