#ifndef fsgmpm_run_termination_h
#define fsgmpm_run_termination_h

#include <ostream>
#include <string>

namespace fsgmpm
{
  /// Why a run stopped (summary.json "termination", exit status of fsgmpm).
  enum class Termination
  {
    /// Still running (or not started).
    running,
    /// Simulation/End time reached (exit 0).
    end_time,
    /// Simulation/Maximum number of steps reached before the end time
    /// (exit 0).
    max_steps,
    /// Termination = at_rest: the grid's kinetic energy stayed below
    /// Rest tolerance x the initial potential energy (exit 0).
    at_rest,
    /// Termination = dr_converged: both Eq. (30) ratios stayed below their
    /// tolerances over the convergence window (exit 0).
    dr_converged,
    /// A stability guard stopped the run (exit 3).
    unstable,
    /// The run cannot go on: no point left, a membrane node out of the
    /// mesh (exit 1).
    error,
    /// SIGTERM or SIGINT: the run finished its step, wrote a checkpoint
    /// (where enabled) and its summary, and stopped (exit 130 for SIGINT,
    /// 143 for SIGTERM, as a shell reports a process killed by them).
    interrupted
  };

  /// The name written to summary.json: "end_time", "unstable", ...
  std::string
  to_string(const Termination termination);

  /// A run that ended as asked (end time, step limit, at rest, converged).
  inline bool
  finished_normally(const Termination termination)
  {
    return termination == Termination::end_time
           || termination == Termination::max_steps
           || termination == Termination::at_rest
           || termination == Termination::dr_converged;
  }

  inline std::ostream &
  operator<<(std::ostream &out, const Termination termination)
  {
    return out << to_string(termination);
  }
} // namespace fsgmpm

#endif
