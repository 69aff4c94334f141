#include <fsgmpm/run/output_schedule.h>

#include <cmath>

namespace fsgmpm
{
  OutputSchedule::OutputSchedule(const double       interval,
                                 const unsigned int every_steps)
    : interval(interval)
    , every_steps(every_steps)
    , next(interval)
  {}



  bool
  OutputSchedule::due(const double       time,
                      const unsigned int step,
                      const bool         last_step_of_run) const
  {
    if (step == last)
      return false;
    if (last_step_of_run)
      return true;
    if (interval > 0)
      return time >= next * (1 - 1e-12);
    return every_steps > 0 && step % every_steps == 0;
  }



  void
  OutputSchedule::written(const double time, const unsigned int step)
  {
    last = step;
    if (interval > 0 && next <= time * (1 + 1e-12))
      next = next_time_after(time);
  }



  double
  OutputSchedule::next_time_after(const double time) const
  {
    return interval * (std::floor(time * (1 + 1e-12) / interval) + 1);
  }
} // namespace fsgmpm
