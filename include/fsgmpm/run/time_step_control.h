#ifndef fsgmpm_run_time_step_control_h
#define fsgmpm_run_time_step_control_h

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace fsgmpm
{
  /**
   * The time step of each step of an explicit run: the stable step of the
   * step's stages (MpmStep::stable_time_step, already scaled by the Courant
   * number), or Simulation/Fixed time step if one is set and stable, cut so
   * that the run lands on Simulation/End time. Keeps the current step and
   * its extremes (summary.json dt_min, dt_max), and says when the run has
   * reached its end time or its largest number of steps. dt_min() is the
   * smallest step the stability limit (or the fixed step) chose: the last
   * step, shortened to land on the end time, does not count, since it
   * says nothing about the run's stability (dt() is that step).
   */
  class TimeStepControl
  {
  public:
    struct Settings
    {
      /// Declare Simulation/End time, Maximum number of steps, Courant
      /// number and Fixed time step.
      static void
      declare_parameters(dealii::ParameterHandler &prm);
      /// Read them; throws if the end time is not positive or the Courant
      /// number is outside (0, 1].
      void
      parse_parameters(dealii::ParameterHandler &prm);

      double       courant   = 0.5; ///< of MpmStep::stable_time_step
      double       fixed_dt  = 0;   ///< 0: automatic
      double       end_time  = 1;
      unsigned int max_steps = 0; ///< 0: no limit
    };

    explicit TimeStepControl(const Settings &settings);

    /**
     * Choose the step from @p dt_stable at @p time (step number @p step,
     * for the message). Returns an empty string, or, if no valid step
     * exists (a fixed step above the stability limit, a zero or non-finite
     * step), what went wrong and what to change; then dt() is unchanged.
     */
    std::string
    choose(const double dt_stable, const double time, const unsigned int step);

    /// What choose() says of Simulation/Fixed time step against
    /// @p dt_stable at step @p step: empty if it is automatic or stable.
    /// The scene asks before it writes anything.
    std::string
    check_fixed(const double dt_stable, const unsigned int step) const;

    /// Whether a run at @p time after @p step steps has reached
    /// Simulation/End time or Maximum number of steps.
    bool
    reached_end(const double time, const unsigned int step) const;

    /// Whether a run at @p time has reached Simulation/End time (so a run
    /// that reached_end() and not this stopped at its step limit).
    bool
    reached_end_time(const double time) const;

    /// The chosen step was taken, and it was the run's step number @p step
    /// (1 for the first): keeps dt_min() and dt_max().
    void
    record_step(const unsigned int step);

    double
    dt() const
    {
      return current;
    }
    /// The smallest step taken, leaving out a last step shortened to land
    /// on the end time (unless it was the only one).
    double
    dt_min() const
    {
      return smallest > 0 ? smallest : current;
    }
    double
    dt_max() const
    {
      return largest;
    }

    /// {dt, dt_min, dt_max}, for a checkpoint, and its restoration.
    std::vector<double>
    state() const;
    void
    set_state(const std::vector<double> &state);

  private:
    Settings settings;
    double   current = 0, smallest = 0, largest = 0;
    /// Whether the current step was shortened to land on the end time.
    bool shortened = false;
  };
} // namespace fsgmpm

#endif
