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
                  const StressIntegration                       integration,
                  CompensatedSum                               *dissipation)
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
      // The kinematics of a run of points of material m from its velocity
      // gradient L (the cell's, or a point's with the projection): the
      // strain rate with Eq. (25)'s smoothed volumetric part for NMD
      // materials, the rotation where the material reads it.
      const auto run_kinematics = [&](const unsigned int           c,
                                      const unsigned int           m,
                                      const Tensor<2, dim>        &L,
                                      const SymmetricTensor<2, 3> &strain_rate,
                                      const Tensor<2, 3>          *rotation,
                                      PointKinematics             &kin) {
        kin.strain_rate = strain_rate;
        kin.rotation
          = rotates[m] ? (rotation ? *rotation : rotation_of(L)) : identity;
        if (options[m].nmd)
          {
            // Eq. (25): the smoothed rate at the cell centre replaces the
            // volumetric part; in plane strain only xx and yy change, so
            // that the zz strain rate stays zero.
            double smoothed = 0;
            for (const unsigned int i : grid.cell_nodes[c])
              smoothed += smoothing.average(m, i);
            smoothed /= (dim + 1);
            // With the stabilisation, a share alpha of the cell's own rate
            // stays (MaterialOptions::smoothing_stabilisation).
            const double alpha = options[m].smoothing_stabilisation;
            smoothed = (1. - alpha) * smoothed + alpha * trace(kin.strain_rate);
            const double correction = (smoothed - trace(kin.strain_rate)) / dim;
            for (unsigned int d = 0; d < dim; ++d)
              kin.strain_rate[d][d] += correction;
          }
      };
      // Volume (and so density) with the same volumetric rate as the
      // pressure: point p's volume ratio.
      const auto update_volume = [&](const unsigned int p,
                                     const unsigned int m,
                                     const double       volume_factor) {
        const double J = materials[m]->admissible_volume_ratio(
          particles.volume[p] * volume_factor / particles.reference_volume[p]);
        particles.volume[p] = J * particles.reference_volume[p];
        return J;
      };
      // The material dissipation is booked for the points this process
      // owns (not for ghost copies, MPI), from each run's stresses and
      // volumes before and after (Material::dissipated_energy()).
      const bool                book = (dissipation != nullptr);
      std::vector<std::uint8_t> dissipates(materials.size());
      for (unsigned int m = 0; m < materials.size(); ++m)
        dissipates[m] = materials[m]->dissipates();
      const auto is_ghost_cell
        = [&](const unsigned int begin, const unsigned int end) {
            return !particles.ghost.empty() && end > begin
                   && particles.ghost[begin] != 0;
          };
      thread_local std::vector<SymmetricTensor<2, 3>> old_stress;
      thread_local std::vector<double>                old_volume;
      const auto                                      remember
        = [&](const unsigned int begin, const unsigned int end) {
            if (old_stress.size() < end - begin)
              {
                old_stress.resize(end - begin);
                old_volume.resize(end - begin);
              }
            std::copy(particles.stress.begin() + begin,
                      particles.stress.begin() + end,
                      old_stress.begin());
            std::copy(particles.volume.begin() + begin,
                      particles.volume.begin() + end,
                      old_volume.begin());
          };
      // With it the points' plastic state, where they keep one.
      const bool keep_plasticity   = particles.has_plasticity();
      const auto dissipated_in_run = [&](const unsigned int     begin,
                                         const unsigned int     run,
                                         const unsigned int     last,
                                         const PointKinematics &kin) {
        const PointPlasticity plasticity{
          keep_plasticity ? particles.plastic_strain.data() + run : nullptr,
          keep_plasticity ? particles.yielding.data() + run : nullptr};
        return materials[particles.material_id[run]]->dissipated_energy(
          old_stress.data() + (run - begin),
          particles.stress.data() + run,
          old_volume.data() + (run - begin),
          particles.volume.data() + run,
          kin,
          last - run,
          dt,
          keep_plasticity ? &plasticity : nullptr);
      };
      const auto update_cell = [&](const unsigned int c, double &dissipated) {
        const unsigned int begin  = particles.cell_begin(c);
        const unsigned int end    = particles.cell_end(c);
        bool               booked = book && !is_ghost_cell(begin, end);
        if (booked)
          {
            // Only the cells that hold a dissipating material keep their
            // old state.
            booked = false;
            for (unsigned int p = begin; p < end && !booked; ++p)
              booked = dissipates[particles.material_id[p]] != 0;
          }
        if (booked)
          remember(begin, end);
        if (!per_point)
          {
            // Every point of the cell has the cell's strain rate, and its
            // rotation where a material needs it (computed at the first
            // such run): a run of points of one material shares its
            // kinematics and one exp, and the material gets them once
            // with the points' volume ratios (update_stresses_of_run()).
            const Tensor<2, dim>        L = smoothing.cell_velocity_gradient(c);
            const SymmetricTensor<2, 3> strain_rate = strain_rate_of(L);
            std::optional<Tensor<2, 3>> cell_rotation;
            thread_local std::vector<double> volume_ratio;
            if (volume_ratio.size() < end - begin)
              volume_ratio.resize(end - begin);
            for (unsigned int run = begin; run < end;)
              {
                const unsigned int last = particles.material_run_end(run, end);
                const unsigned int m    = particles.material_id[run];
                if (rotates[m] && !cell_rotation)
                  cell_rotation = rotation_of(L);
                PointKinematics kin;
                run_kinematics(c,
                               m,
                               L,
                               strain_rate,
                               cell_rotation ? &*cell_rotation : nullptr,
                               kin);
                const double volume_factor
                  = std::exp(dt * trace(kin.strain_rate));
                for (unsigned int p = run; p < last; ++p)
                  volume_ratio[p - begin] = update_volume(p, m, volume_factor);
                materials[m]->update_stresses_of_run(kin,
                                                     volume_ratio.data()
                                                       + (run - begin),
                                                     particles.stress.data()
                                                       + run,
                                                     last - run,
                                                     dt);
                if (booked)
                  dissipated += dissipated_in_run(begin, run, last, kin);
                run = last;
              }
            return;
          }

        // With the projection every point has its own velocity gradient,
        // the nodal average of the cells' (nodal_velocity_gradients).
        const CellGeometry<dim> geometry
          = CellLoops::geometry(grid, particles, c);
        thread_local std::vector<PointKinematics> kinematics;
        // Sized, not filled: each point's entry is written below once.
        if (kinematics.size() < end - begin)
          kinematics.resize(end - begin);
        for (unsigned int p = begin; p < end; ++p)
          {
            PointKinematics   &kin = kinematics[p - begin];
            const unsigned int m   = particles.material_id[p];
            // With the stabilisation, a share alpha of the cell's own
            // volumetric rate (p2g keeps the same share of the point's
            // mean stress in the cell).
            const Tensor<2, dim> L = stabilised_point_velocity_gradient(
              grid,
              smoothing,
              c,
              geometry.barycentric(particles.position[p]),
              options[m].smoothing_stabilisation);
            run_kinematics(c, m, L, strain_rate_of(L), nullptr, kin);
            kin.volume_ratio
              = update_volume(p, m, std::exp(dt * trace(kin.strain_rate)));
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
            if (booked)
              for (unsigned int p = run; p < last; ++p)
                dissipated
                  += dissipated_in_run(begin, p, p + 1, kinematics[p - begin]);
            run = last;
          }
      };
      const auto &cells = particles.occupied_cells;
      if (!book)
        {
          CellLoops::for_each_occupied_cell(particles, [&](const unsigned c) {
            double unused = 0;
            update_cell(c, unused);
          });
          return;
        }
      // Compensated sums in fixed chunks of 16 cells (the loop's own grain,
      // so that the threads share the work as well): the same for any
      // number of threads.
      const CompensatedSum sum = CellLoops::chunked_reduction(
        cells.size(),
        16,
        CompensatedSum(),
        [&](const unsigned int a, CompensatedSum &s) {
          double dissipated = 0;
          update_cell(cells[a], dissipated);
          s.add(dissipated);
        },
        [](CompensatedSum &total, const CompensatedSum &chunk) {
          total.add(chunk);
        });
      dissipation->add(sum);
    }

    template void
    stress_update<2>(const BackgroundGrid<2> &,
                     const std::vector<std::unique_ptr<Material>> &,
                     const std::vector<MaterialOptions> &,
                     const double,
                     SmoothingFields<2> &,
                     ParticleStore<2> &,
                     StressIntegration,
                     CompensatedSum *);
    template void
    stress_update<3>(const BackgroundGrid<3> &,
                     const std::vector<std::unique_ptr<Material>> &,
                     const std::vector<MaterialOptions> &,
                     const double,
                     SmoothingFields<3> &,
                     ParticleStore<3> &,
                     StressIntegration,
                     CompensatedSum *);
  } // namespace Stages
} // namespace fsgmpm
