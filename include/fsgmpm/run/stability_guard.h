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
   *   initial energy plus the external work minus the damping work by more
   *   than Stability/Energy creation tolerance times the energy put in
   *   (slow instabilities, e.g. a no-slip geotube growing for 15 s);
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

      double       energy_creation_tolerance = 0.5; ///< 0: off
      double       growth_factor             = 10;
      unsigned int growth_window             = 100;
    };

    explicit StabilityGuard(const Settings &settings);

    /// Start the energy bookkeeping from the present state (the run's
    /// start, or after the state was changed from outside).
    void
    reset(const Monitors &monitors);

    /// Check the state after a step. Returns what went wrong, or an empty
    /// string.
    std::string
    check(const Monitors &monitors, const double displacement_ratio);

    /// The energy balance's residual for @p monitors: kinetic plus strain
    /// energy less the initial energy plus the external work minus the
    /// damping work (J, per metre of thickness in 2D). Positive: the step
    /// created energy; negative: plastic, viscous and transfer
    /// dissipation, which no monitor books, removed it.
    double
    energy_residual(const Monitors &monitors) const;

    /// The energy put in, that the residual is measured against: the
    /// initial energy plus the largest |external work| so far.
    double
    energy_scale() const
    {
      return initial_energy + external_work_scale;
    }

    /// The bookkeeping, for a checkpoint, and its restoration.
    std::vector<double>
    state() const;
    void
    set_state(const std::vector<double> &state);

  private:
    Settings settings;
    /// Kinetic plus strain energy at the start and the largest |external
    /// work| so far.
    double initial_energy = 0, external_work_scale = 0;
    /// (kinetic + strain energy, external work) of the last window of
    /// steps.
    std::deque<std::array<double, 2>> history;
  };
} // namespace fsgmpm

#endif
