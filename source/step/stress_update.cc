#include <fsgmpm/materials/hill_rotation.h>
#include <fsgmpm/step/cell_loops.h>
#include <fsgmpm/step/stages.h>

#include <cmath>

namespace fsgmpm
{
  namespace Stages
  {
    template <int dim>
    void
    stress_update(const BackgroundGrid<dim>                    &grid,
                  const std::vector<std::unique_ptr<Material>> &materials,
                  const std::vector<MaterialOptions>           &options,
                  const double                                  dt,
                  SmoothingFields<dim>                         &smoothing,
                  ParticleStore<dim>                           &particles,
                  const StressIntegration                       integration)
    {
      const bool per_point
        = (integration == StressIntegration::nodal_projection);
      // Uses smoothing.velocity_gradient (velocity_gradients stage) and,
      // for NMD materials, the nodal rates of the nmd stage.
      CellLoops::for_each_occupied_cell(particles, [&](const unsigned int c) {
        const auto kinematics_of = [dt](const Tensor<2, dim> &L) {
          Tensor<2, 3> L3;
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int j = 0; j < dim; ++j)
              L3[i][j] = L[i][j];
          PointKinematics kin;
          kin.strain_rate = symmetrize(L3);
          kin.spin        = 0.5 * (L3 - transpose(L3));
          kin.rotation    = incremental_rotation(kin.spin, dt);
          return kin;
        };
        // With the projection every point gets its own kinematics below;
        // the cell's (and its rotation) are not needed then.
        const PointKinematics cell_kin
          = per_point ? PointKinematics()
                      : kinematics_of(smoothing.velocity_gradient[c]);

        // Before any volume changes: the share p2g used.
        const double theta
          = per_point ? CellLoops::projection_share(grid, particles, c) : 0.;
        thread_local std::vector<PointKinematics> kinematics;
        const unsigned int begin = particles.cell_start[c];
        const unsigned int end   = particles.cell_start[c + 1];
        kinematics.assign(end - begin, cell_kin);
        for (unsigned int p = begin; p < end; ++p)
          {
            PointKinematics &kin = kinematics[p - begin];
            if (per_point)
              kin = kinematics_of(point_velocity_gradient(
                grid,
                smoothing,
                c,
                theta,
                grid.barycentric(c, particles.position[p])));
            const double       rate = trace(kin.strain_rate);
            const unsigned int m    = particles.material_id[p];
            if (options[m].nmd)
              {
                // Eq. (25): the smoothed rate at the cell centre replaces the
                // volumetric part; in plane strain only xx and yy change, so
                // that the zz strain rate stays zero.
                double smoothed = 0;
                for (const unsigned int i : grid.cell_nodes[c])
                  smoothed += smoothing.average(m, i);
                smoothed /= (dim + 1);
                const double correction = (smoothed - rate) / dim;
                for (unsigned int d = 0; d < dim; ++d)
                  kin.strain_rate[d][d] += correction;
              }
            // Volume (and so density) with the same volumetric rate as the
            // pressure.
            const double J = materials[m]->admissible_volume_ratio(
              particles.volume[p] * std::exp(dt * trace(kin.strain_rate))
              / particles.reference_volume[p]);
            particles.volume[p] = J * particles.reference_volume[p];
            kin.volume_ratio    = J;
          }

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
      });
    }

    template void
    stress_update<2>(const BackgroundGrid<2> &,
                     const std::vector<std::unique_ptr<Material>> &,
                     const std::vector<MaterialOptions> &,
                     const double,
                     SmoothingFields<2> &,
                     ParticleStore<2> &,
                     StressIntegration);
    template void
    stress_update<3>(const BackgroundGrid<3> &,
                     const std::vector<std::unique_ptr<Material>> &,
                     const std::vector<MaterialOptions> &,
                     const double,
                     SmoothingFields<3> &,
                     ParticleStore<3> &,
                     StressIntegration);
  } // namespace Stages
} // namespace fsgmpm
