#include <fsgmpm/run/termination.h>

namespace fsgmpm
{
  std::string
  to_string(const Termination termination)
  {
    switch (termination)
      {
        case Termination::running:
          return "running";
        case Termination::end_time:
          return "end_time";
        case Termination::max_steps:
          return "max_steps";
        case Termination::at_rest:
          return "at_rest";
        case Termination::dr_converged:
          return "dr_converged";
        case Termination::unstable:
          return "unstable";
        case Termination::error:
          return "error";
        case Termination::interrupted:
          return "interrupted";
      }
    return "unknown";
  }
} // namespace fsgmpm
