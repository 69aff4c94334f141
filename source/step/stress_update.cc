#include <fsgmpm/materials/hill_rotation.h>
#include <fsgmpm/step/cell_loops.h>
#include <fsgmpm/step/stages.h>

#include <cmath>
#include <cstdint>
#include <optional>

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
      // for NMD materials, the nodal rates of the nmd stage. The rotation
      // of the step (Eq. 6) only for the materials that rotate their stress
      // (Material::rotates_stress()); the others get the identity.
      static const Tensor<2, 3> identity(unit_symmetric_tensor<3>());
      // Asked once per call, not once per cell and run.
      std::vector<std::uint8_t> rotates(materials.size());
      for (unsigned int m = 0; m < materials.size(); ++m)
        rotates[m] = materials[m]->rotates_stress();
      // d = sym(L) in 3x3 (plane strain: zero third row and column),
      // written entry by entry: the tensor expressions compile to partial
      // stores reloaded as pairs, which stall.
      const auto strain_rate_of = [](const Tensor<2, dim> &L) {
        SymmetricTensor<2, 3> d;
        for (unsigned int i = 0; i < dim; ++i)
          {
            d[i][i] = L[i][i];
            for (unsigned int j = i + 1; j < dim; ++j)
              d[i][j] = (L[i][j] + L[j][i]) * 0.5;
          }
        return d;
      };
      // R of W = skew(L), exactly orthogonal (hill_rotation.h).
      const auto rotation_of = [dt](const Tensor<2, dim> &L) {
        Tensor<2, 3> spin;
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = i + 1; j < dim; ++j)
            {
              spin[i][j] = 0.5 * (L[i][j] - L[j][i]);
              spin[j][i] = -spin[i][j];
            }
        return incremental_rotation(spin, dt);
      };
      CellLoops::for_each_occupied_cell(particles, [&](const unsigned int c) {
        // Without the projection every point of the cell has the cell's
        // strain rate, and its rotation where a material needs it (computed
        // at the first such run). With it every point gets its own below.
        Tensor<2, dim>        cell_L;
        SymmetricTensor<2, 3> cell_strain_rate;
        if (!per_point)
          {
            cell_L           = smoothing.cell_velocity_gradient(c);
            cell_strain_rate = strain_rate_of(cell_L);
          }
        std::optional<Tensor<2, 3>> cell_rotation;

        // Before any volume changes: the share p2g used.
        const double theta
          = per_point ? CellLoops::projection_share(grid, particles, c) : 0.;
        std::optional<CellGeometry<dim>> geometry;
        if (per_point)
          geometry.emplace(CellLoops::geometry(grid, particles, c));
        thread_local std::vector<PointKinematics> kinematics;
        const unsigned int begin = particles.cell_begin(c);
        const unsigned int end   = particles.cell_end(c);
        // Sized, not filled: each point's entry is written below once.
        if (kinematics.size() < end - begin)
          kinematics.resize(end - begin);
        // The volumetric strain rate and its exponential are those of the
        // cell and material unless every point has its own kinematics: one
        // exp per run of points of the same material, not per point.
        unsigned int run_material  = numbers::invalid_unsigned_int;
        double       volume_factor = 1.;
        for (unsigned int p = begin; p < end; ++p)
          {
            PointKinematics   &kin = kinematics[p - begin];
            const unsigned int m   = particles.material_id[p];
            if (per_point || m != run_material)
              {
                if (per_point)
                  {
                    const Tensor<2, dim> L
                      = point_velocity_gradient(grid,
                                                smoothing,
                                                c,
                                                theta,
                                                geometry->barycentric(
                                                  particles.position[p]));
                    kin.strain_rate = strain_rate_of(L);
                    kin.rotation    = rotates[m] ? rotation_of(L) : identity;
                  }
                else
                  {
                    kin.strain_rate = cell_strain_rate;
                    if (rotates[m] && !cell_rotation)
                      cell_rotation = rotation_of(cell_L);
                    kin.rotation = rotates[m] ? *cell_rotation : identity;
                  }
                if (options[m].nmd)
                  {
                    // Eq. (25): the smoothed rate at the cell centre
                    // replaces the volumetric part; in plane strain only xx
                    // and yy change, so that the zz strain rate stays zero.
                    double smoothed = 0;
                    for (const unsigned int i : grid.cell_nodes[c])
                      smoothed += smoothing.average(m, i);
                    smoothed /= (dim + 1);
                    const double correction
                      = (smoothed - trace(kin.strain_rate)) / dim;
                    for (unsigned int d = 0; d < dim; ++d)
                      kin.strain_rate[d][d] += correction;
                  }
                volume_factor = std::exp(dt * trace(kin.strain_rate));
                run_material  = m;
              }
            else
              // The run's kinematics (with its NMD rate), as the point
              // before; its volume ratio is this point's below.
              kin = kinematics[p - begin - 1];
            // Volume (and so density) with the same volumetric rate as the
            // pressure.
            const double J = materials[m]->admissible_volume_ratio(
              particles.volume[p] * volume_factor
              / particles.reference_volume[p]);
            particles.volume[p] = J * particles.reference_volume[p];
            kin.volume_ratio    = J;
          }

        // One call per run of points of the same material.
        unsigned int run = begin;
        while (run < end)
          {
            const unsigned int last = particles.material_run_end(run, end);
            materials[particles.material_id[run]]->update_stresses(
              kinematics.data() + (run - begin),
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
