#include <fsgmpm/base/compensated_sum.h>
#include <fsgmpm/base/parallel_reductions.h>
#include <fsgmpm/run/energy_balance.h>

#include <array>
#include <cmath>
#include <limits>

namespace fsgmpm
{
  namespace EnergyBalance
  {
    template <int dim>
    std::vector<CompensatedSum>
    local_energies(const ParticleStore<dim>                     &particles,
                   const std::vector<std::unique_ptr<Material>> &materials,
                   const Membrane<dim>                          *membrane,
                   const Tensor<1, dim>                         &gravity,
                   const NodalFields<dim>                       *nodes,
                   const std::vector<std::uint8_t>              *counted_nodes)
    {
      // Each cell's points summed plainly, the cells compensated (in fixed
      // chunks, in parallel: Reductions::compensated_sums): the energies do
      // not depend on the order of the cells, on how they are split over
      // processes or on the number of threads.
      const auto &cells = particles.occupied_cells;
      const auto  cell_sums // kinetic, strain, potential
        = Reductions::compensated_sums<3>(
          cells.size(), [&](const unsigned int i, auto &sums) {
            const unsigned int c = cells[i];
            double             k = 0, s = 0, g = 0;
            const unsigned int end = particles.cell_end(c);
            for (unsigned int p = particles.cell_begin(c); p < end;)
              {
                // A run of points of one material: its strain energy in
                // one call (Material::add_strain_energy(), in point order).
                const unsigned int last = particles.material_run_end(p, end);
                s = materials[particles.material_id[p]]->add_strain_energy(
                  particles.stress.data() + p,
                  particles.volume.data() + p,
                  particles.reference_volume.data() + p,
                  last - p,
                  s);
                for (; p < last; ++p)
                  {
                    k += 0.5 * particles.mass[p]
                         * particles.velocity[p].norm_square();
                    g -= particles.mass[p] * (gravity * particles.position[p]);
                  }
              }
            sums[0].add(k);
            sums[1].add(s);
            sums[2].add(g);
          });
      std::vector<CompensatedSum> sums(cell_sums.begin(), cell_sums.end());
      if (membrane)
        {
          sums[0].add(membrane->kinetic_energy());
          sums[1].add(membrane->strain_energy());
          for (unsigned int a = 0; a < membrane->n_nodes(); ++a)
            sums[2].add(-membrane->mass[a] * (gravity * membrane->position[a]));
        }
      // Eq. (30)'s kinetic energy of the grid, compensated.
      if (nodes)
        sums.push_back(Reductions::compensated_sums<1>(
          nodes->active_nodes.size(), [&](const unsigned int a, auto &sum) {
            const unsigned int i = nodes->active_nodes[a];
            if (counted_nodes == nullptr || (*counted_nodes)[i])
              sum[0].add(0.5 * nodes->mass[i]
                         * nodes->velocity[i].norm_square());
          })[0]);
      return sums;
    }



    void
    set_energies(const ArrayView<const double> &totals, Monitors &monitors)
    {
      Assert(totals.size() == 3 || totals.size() == 4, ExcInternalError());
      monitors.kinetic_energy   = totals[0];
      monitors.strain_energy    = totals[1];
      monitors.potential_energy = totals[2];
      if (totals.size() == 4)
        monitors.grid_kinetic_energy = totals[3];
    }



    template <int dim>
    void
    compute_energies(const ParticleStore<dim>                     &particles,
                     const std::vector<std::unique_ptr<Material>> &materials,
                     const Membrane<dim>                          *membrane,
                     const Tensor<1, dim>                         &gravity,
                     Monitors                                     &monitors,
                     const MPI_Comm                                communicator)
    {
      const std::vector<double> totals = sum_over_processes(
        local_energies<dim>(particles, materials, membrane, gravity),
        communicator);
      set_energies(make_array_view(totals), monitors);
    }



    void
    add_step(const Stages::GridUpdateResult &grid_result,
             const StepLosses               &losses,
             const unsigned int              lost_particles,
             Monitors                       &monitors)
    {
      monitors.lost_particles += lost_particles;
      monitors.material_dissipation += losses.material;
      monitors.numerical_dissipation += losses.numerical;
      monitors.outflow_energy += losses.outflow;
      monitors.external_work += grid_result.external_work_increment.value();
      monitors.dissipated_energy += grid_result.damping_work_increment.value();

      // Eq. (30) from the nodal (remapped) velocities.
      const double nodal_ke      = monitors.grid_kinetic_energy;
      monitors.dr_energy_ratio   = (monitors.external_work > 0)
                                     ? nodal_ke / monitors.external_work
                                     : std::numeric_limits<double>::infinity();
      const double unbalanced_sq = grid_result.unbalanced_norm_sq.value();
      const double external_sq   = grid_result.external_norm_sq.value();
      monitors.dr_force_ratio    = (external_sq > 0)
                                     ? std::sqrt(unbalanced_sq / external_sq)
                                     : std::numeric_limits<double>::infinity();
    }



    template <int dim>
    double
    potential_energy_above(const ParticleStore<dim> &particles,
                           const Tensor<1, dim>     &gravity,
                           const Point<dim>         &datum)
    {
      double energy = 0;
      for (unsigned int p = 0; p < particles.size(); ++p)
        energy
          -= particles.mass[p] * (gravity * (particles.position[p] - datum));
      return energy;
    }

#define FSGMPM_INSTANTIATE(dim)                                           \
  template std::vector<CompensatedSum> local_energies<dim>(               \
    const ParticleStore<dim> &,                                           \
    const std::vector<std::unique_ptr<Material>> &,                       \
    const Membrane<dim> *,                                                \
    const Tensor<1, dim> &,                                               \
    const NodalFields<dim> *,                                             \
    const std::vector<std::uint8_t> *);                                   \
  template void compute_energies<dim>(                                    \
    const ParticleStore<dim> &,                                           \
    const std::vector<std::unique_ptr<Material>> &,                       \
    const Membrane<dim> *,                                                \
    const Tensor<1, dim> &,                                               \
    Monitors &,                                                           \
    const MPI_Comm);                                                      \
  template double potential_energy_above<dim>(const ParticleStore<dim> &, \
                                              const Tensor<1, dim> &,     \
                                              const Point<dim> &);
    FSGMPM_INSTANTIATE(2)
    FSGMPM_INSTANTIATE(3)
#undef FSGMPM_INSTANTIATE
  } // namespace EnergyBalance
} // namespace fsgmpm
