#include <deal.II/base/exceptions.h>

#include <fsgmpm/base/format.h>
#include <fsgmpm/base/real_interval.h>
#include <fsgmpm/run/time_step_control.h>

#include <algorithm>
#include <cmath>

namespace fsgmpm
{
  void
  TimeStepControl::Settings::declare_parameters(dealii::ParameterHandler &prm)
  {
    using namespace dealii;
    prm.enter_subsection("Simulation");
    {
      prm.declare_entry("End time",
                        "0.6",
                        RealInterval::above(0),
                        "Simulated time at which the run stops (s, > 0).");
      prm.declare_entry("Maximum number of steps",
                        "0",
                        Patterns::Integer(0),
                        "Stop after this many steps (0: no limit).");
      prm.declare_entry("Courant number",
                        "0.5",
                        RealInterval(0, 1, true, false),
                        "C in dt = C min h/(c + |v|), 0 < C <= 1.");
      prm.declare_entry("Fixed time step",
                        "0",
                        Patterns::Double(0),
                        "If > 0, use this time step (s) instead of the "
                        "automatic one; the run stops as unstable if it "
                        "exceeds the stability limit by more than 1/C.");
    }
    prm.leave_subsection();
  }



  void
  TimeStepControl::Settings::parse_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Simulation");
    end_time  = prm.get_double("End time");
    courant   = prm.get_double("Courant number");
    fixed_dt  = prm.get_double("Fixed time step");
    max_steps = prm.get_integer("Maximum number of steps");
    prm.leave_subsection();
    AssertThrow(end_time > 0,
                dealii::ExcMessage("Simulation/End time must be positive."));
    AssertThrow(courant > 0 && courant <= 1,
                dealii::ExcMessage(
                  "Simulation/Courant number must lie in (0, 1]; got "
                  + std::to_string(courant) + "."));
  }



  TimeStepControl::TimeStepControl(const Settings &settings)
    : settings(settings)
  {}



  bool
  TimeStepControl::reached_end(const double time, const unsigned int step) const
  {
    // choose() lands the last step on the end time up to round-off.
    return reached_end_time(time)
           || (settings.max_steps > 0 && step >= settings.max_steps);
  }



  bool
  TimeStepControl::reached_end_time(const double time) const
  {
    return time >= settings.end_time * (1 - 1e-14);
  }



  std::string
  TimeStepControl::check_fixed(const double       dt_stable,
                               const unsigned int step) const
  {
    // dt_stable carries the Courant number; the limit itself does not.
    if (settings.fixed_dt > 0
        && settings.fixed_dt > dt_stable / settings.courant)
      return "Simulation/Fixed time step = " + format(settings.fixed_dt)
             + " s exceeds the explicit stability limit "
             + format(dt_stable / settings.courant) + " s at step "
             + std::to_string(step)
             + "; use a smaller fixed time step or 0 (automatic).";
    return "";
  }



  std::string
  TimeStepControl::choose(const double       dt_stable,
                          const double       time,
                          const unsigned int step)
  {
    const std::string fixed_problem = check_fixed(dt_stable, step);
    if (!fixed_problem.empty())
      return fixed_problem;
    double     dt  = settings.fixed_dt > 0 ? settings.fixed_dt : dt_stable;
    const bool cut = settings.end_time - time < dt;
    if (cut)
      dt = settings.end_time - time;
    if (!(dt > 0) || !std::isfinite(dt))
      return "the time step became " + format(dt) + " s at step "
             + std::to_string(step) + ".";
    current   = dt;
    shortened = cut;
    return "";
  }



  void
  TimeStepControl::record_step(const unsigned int step)
  {
    // A step shortened to land on the end time says nothing about the
    // stability limit: dt_min() leaves it out (0: no other step yet).
    if (step == 1)
      smallest = 0;
    if (!shortened)
      smallest = (smallest == 0) ? current : std::min(smallest, current);
    largest = std::max(largest, current);
  }



  std::vector<double>
  TimeStepControl::state() const
  {
    return {current, smallest, largest};
  }



  void
  TimeStepControl::set_state(const std::vector<double> &state)
  {
    AssertThrow(state.size() == 3,
                dealii::ExcMessage(
                  "A time-step state holds dt, dt_min and dt_max."));
    current  = state[0];
    smallest = state[1];
    largest  = state[2];
  }
} // namespace fsgmpm
