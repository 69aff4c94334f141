#ifndef fsgmpm_run_stability_guard_h
#define fsgmpm_run_stability_guard_h

#include <deal.II/base/parameter_handler.h>

#include <fsgmpm/run/monitors.h>

#include <array>
#include <deque>
#include <string>
#include <vector>

namespace fsgmpm
{
  /**
   * The stability guards of the explicit step (doc/stability.md), checked
   * after every step:
   * - no non-finite energy or displacement;
   * - no point crossing more than one cell in a step (displacement ratio
   *   above 1);
   * - energy creation: kinetic plus strain energy may not exceed the
   *   initial energy plus the external work minus the booked losses
   *   (damping, plastic and viscous work, the transfers' and the
   *   free-surface reset's losses, the outflow) by more than
   *   Stability/Energy creation tolerance times the energy scale: the
   *   energy put in and the energy the scene holds (slow instabilities,
   *   e.g. a no-slip geotube growing for 15 s). A booked loss that comes out
   *   negative (energy a stage created) is not allowed to cancel creation
   *   elsewhere. The default 0.05 is about three times the largest reading
   *   of the cases that are not unstable (an impact at 20 m/s, 0.017) and
   *   nine times that of the shipped scenes (0.0057, doc/stability.md);
   * - kinetic-energy growth: not more than Stability/Kinetic energy growth
   *   factor times the energy available Growth window steps earlier plus
   *   the external work since.
   */
  class StabilityGuard
  {
  public:
    struct Settings
    {
      /// Declare the Stability subsection.
      static void
      declare_parameters(dealii::ParameterHandler &prm);
      /// Read it.
      void
      parse_parameters(dealii::ParameterHandler &prm);

      double       energy_creation_tolerance = 0.05; ///< 0: off
      double       growth_factor             = 10;
      unsigned int growth_window             = 100;
    };

    explicit StabilityGuard(const Settings &settings);

    /// Start the energy bookkeeping from the present state (the run's
    /// start, or after the state was changed from outside). @p held_energy
    /// is the energy the scene holds besides its kinetic and strain energy
    /// (the points' potential energy above the mesh's lowest corner), part
    /// of the scale the creation is measured against, so that a tank at
    /// rest, whose work is tiny, is not stopped for a rounding.
    void
    reset(const Monitors &monitors, const double held_energy = 0);

    /// Check the state after a step. Returns what went wrong, or an empty
    /// string.
    std::string
    check(const Monitors &monitors, const double displacement_ratio);

    /// The energy balance's residual for @p monitors: kinetic plus strain
    /// energy less the initial energy plus the external work minus every
    /// booked loss (J, per metre of thickness in 2D). Positive: the steps
    /// created energy; negative: losses no monitor books (walls, contact,
    /// the grid transfers) removed it.
    double
    energy_residual(const Monitors &monitors) const;

    /// What the guard reads as created: energy_residual() with each booked
    /// loss counted only where it is a loss.
    double
    energy_created(const Monitors &monitors) const;

    /// The scale that the creation is measured against: the initial energy,
    /// the largest |external work| so far and the energy held (reset()).
    double
    energy_scale() const
    {
      return initial_energy + external_work_scale + held_energy;
    }

    /// The largest energy_created() over the run so far (J; J/m in 2D)
    /// and its share of the energy scale at that step: how near the run
    /// came to the guard's limit (summary.json).
    double
    largest_created() const
    {
      return largest_created_energy;
    }
    double
    largest_created_share() const
    {
      return largest_created_ratio;
    }

    /// The bookkeeping, for a checkpoint, and its restoration.
    std::vector<double>
    state() const;
    void
    set_state(const std::vector<double> &state);
    /// The largest creation so far, for a checkpoint, and its restoration.
    std::vector<double>
    largest_state() const
    {
      return {largest_created_energy, largest_created_ratio};
    }
    void
    set_largest_state(const std::vector<double> &state);

  private:
    Settings settings;
    /// Kinetic plus strain energy at the start and the largest |external
    /// work| so far.
    double initial_energy = 0, external_work_scale = 0, held_energy = 0;
    /// The largest energy_created() so far and its largest share of the
    /// scale.
    double largest_created_energy = 0, largest_created_ratio = 0;
    /// (kinetic + strain energy, external work) of the last window of
    /// steps.
    std::deque<std::array<double, 2>> history;
  };
} // namespace fsgmpm

#endif
