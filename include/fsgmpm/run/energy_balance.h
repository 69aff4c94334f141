#ifndef fsgmpm_run_energy_balance_h
#define fsgmpm_run_energy_balance_h

#include <deal.II/base/array_view.h>
#include <deal.II/base/tensor.h>

#include <fsgmpm/base/compensated_sum.h>

#include <fsgmpm/grid/nodal_fields.h>
#include <fsgmpm/materials/material.h>
#include <fsgmpm/membrane/membrane.h>
#include <fsgmpm/particles/particle_store.h>
#include <fsgmpm/run/monitors.h>
#include <fsgmpm/step/stages.h>

#include <cstdint>
#include <memory>
#include <vector>

namespace fsgmpm
{
  /**
   * The energy bookkeeping of a run (the common columns of monitors.csv,
   * the stability guard's balance and Eq. 30): what the state holds, and
   * what each step adds to the work done on it.
   */
  namespace EnergyBalance
  {

    /// Kinetic, strain and potential (-m g.x) energy of the points and the
    /// membrane's nodes into @p monitors. Summed per occupied cell in
    /// parallel, then over the cells with compensated sums and over the
    /// processes of @p communicator (each passes its own points, one of
    /// them the membrane): the result does not depend on the number of
    /// threads, and on the number of processes only in the last bit or two.
    /// The step itself calls local_energies() with the nodes and sends the
    /// sums along with the grid update's (Simulator::advance).
    template <int dim>
    void
    compute_energies(const ParticleStore<dim>                     &particles,
                     const std::vector<std::unique_ptr<Material>> &materials,
                     const Membrane<dim>                          *membrane,
                     const Tensor<1, dim>                         &gravity,
                     Monitors                                     &monitors,
                     const MPI_Comm communicator = MPI_COMM_SELF);

    /// This process's part of compute_energies(), compensated (kinetic,
    /// strain, potential, and with @p nodes (after a step) the grid's
    /// kinetic energy from the nodal velocities, with @p counted_nodes
    /// (MPI) only at the nodes marked 1 there, so that each counts once):
    /// summed over the processes (sum_over_processes(), maybe with other
    /// sums in the same collective), then stored by set_energies().
    template <int dim>
    std::vector<CompensatedSum>
    local_energies(const ParticleStore<dim>                     &particles,
                   const std::vector<std::unique_ptr<Material>> &materials,
                   const Membrane<dim>                          *membrane,
                   const Tensor<1, dim>                         &gravity,
                   const NodalFields<dim>          *nodes         = nullptr,
                   const std::vector<std::uint8_t> *counted_nodes = nullptr);

    /// The totals of local_energies() into @p monitors.
    void
    set_energies(const ArrayView<const double> &totals, Monitors &monitors);

    /// A step's booked losses (MpmStep::Result), summed over the processes.
    struct StepLosses
    {
      double material = 0, numerical = 0, outflow = 0;
    };

    /// Books a step's external and damping work, its losses and its lost
    /// points, and
    /// the dynamic-relaxation ratios of Eq. (30): E_v = grid kinetic
    /// energy (compute_energies() with the nodes, called before) / external
    /// work, E_f = |F_ext - F_int| / |F_ext| over the unconstrained nodal
    /// components (infinite until there is external work or force). With
    /// MPI, @p grid_result and @p lost_particles are already global.
    void
    add_step(const Stages::GridUpdateResult &grid_result,
             const StepLosses               &losses,
             const unsigned int              lost_particles,
             Monitors                       &monitors);

    /// Potential energy of the points above @p datum (a point of zero
    /// height, e.g. the mesh's lowest corner): the scale of the at-rest
    /// tolerance.
    template <int dim>
    double
    potential_energy_above(const ParticleStore<dim> &particles,
                           const Tensor<1, dim>     &gravity,
                           const Point<dim>         &datum);
  } // namespace EnergyBalance
} // namespace fsgmpm

#endif
