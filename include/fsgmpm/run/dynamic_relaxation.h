#ifndef fsgmpm_run_dynamic_relaxation_h
#define fsgmpm_run_dynamic_relaxation_h

#include <deal.II/base/parameter_handler.h>

#include <fsgmpm/run/monitors.h>
#include <fsgmpm/run/termination.h>

#include <vector>

namespace fsgmpm
{
  // Declared only: this header is read by every user of Parameters.
  template <int dim>
  class ParticleStore;
  template <int dim>
  class Membrane;

  /**
   * Dynamic relaxation's run control, for runs that seek a static state
   * (a geotube's shape): kinetic damping (all velocities zeroed at each
   * peak of the kinetic energy), the convergence criterion of Eq. (30)
   * (both ratios below their tolerances over a window of steps) and the
   * at-rest criterion (the grid's kinetic energy below a fraction of the
   * initial potential energy over the window, after the material has
   * moved). Local damping, the other half of dynamic relaxation, acts on
   * the grid update (MpmStep::Settings::local_damping).
   */
  class DynamicRelaxation
  {
  public:
    struct Settings
    {
      /// Declare the entries these settings come from: Damping/Kinetic
      /// damping, Energy tolerance, Force tolerance, Convergence window;
      /// Simulation/Termination, Rest tolerance.
      static void
      declare_parameters(dealii::ParameterHandler &prm);
      /// Read them, and Simulation/Gravity ramp time as the load time.
      void
      parse_parameters(dealii::ParameterHandler &prm);

      /// Damping/Kinetic damping.
      bool kinetic_damping = false;
      /// E_v and E_f of Eq. (30) (Damping/Energy tolerance, Force
      /// tolerance).
      double energy_tolerance = 0.05, force_tolerance = 0.05;
      /// Damping/Convergence window: consecutive steps a criterion must
      /// hold.
      unsigned int convergence_window = 1000;
      /// Simulation/Rest tolerance: at rest below this fraction of the
      /// initial potential energy.
      double rest_tolerance = 1e-6;
      /// Simulation/Gravity ramp time: convergence only counts once the
      /// full load is on.
      double load_time = 0;
      /// Simulation/Termination: stop when converged, or when at rest.
      bool stop_when_converged = false, stop_when_at_rest = false;
    };

    explicit DynamicRelaxation(const Settings &settings);

    /// Start from the present state (the run's start, or after the state
    /// was changed from outside): its kinetic energy is the last one seen;
    /// @p initial_potential_energy scales the at-rest tolerance.
    void
    reset(const Monitors &monitors, const double initial_potential_energy);

    /// Kinetic damping after a step: if the kinetic energy in @p monitors
    /// has passed a peak, zero every velocity of the points (and APIC's
    /// affine velocities) and of the membrane's nodes (they carry momentum
    /// of their own, which Eq. 20 remaps into the fill), and book the energy
    /// removed as dissipated. Does nothing unless Kinetic damping is on.
    template <int dim>
    void
    apply_kinetic_damping(Monitors           &monitors,
                          ParticleStore<dim> &particles,
                          Membrane<dim>      *membrane);

    /// Count the step at @p time towards the two criteria. Returns
    /// Termination::at_rest or dr_converged when the run should stop for
    /// one of them, else Termination::running.
    Termination
    update(const Monitors &monitors, const double time);

    /// Steps for which both Eq. (30) ratios have been below tolerance.
    unsigned int
    converged_steps() const
    {
      return n_converged;
    }

    /// {previous kinetic energy, initial potential energy, largest grid
    /// kinetic energy} and {rest steps, converged steps}, for a
    /// checkpoint, and their restoration.
    std::vector<double>
    energy_state() const;
    std::vector<unsigned int>
    counter_state() const;
    void
    set_state(const std::vector<double>       &energies,
              const std::vector<unsigned int> &counters);

  private:
    Settings     settings;
    double       previous_kinetic_energy  = 0;
    double       initial_potential_energy = 0, max_kinetic_energy = 0;
    unsigned int n_rest = 0, n_converged = 0;
  };
} // namespace fsgmpm

#endif
