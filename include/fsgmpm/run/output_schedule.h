#ifndef fsgmpm_run_output_schedule_h
#define fsgmpm_run_output_schedule_h

namespace fsgmpm
{
  /**
   * When a run writes something that recurs (output files, checkpoints):
   * every @p interval of simulated time (at the first step at or past each
   * multiple of it), or, without an interval, every @p every_steps steps.
   * Both 0: never.
   */
  class OutputSchedule
  {
  public:
    OutputSchedule(const double interval, const unsigned int every_steps = 0);

    /// Anything scheduled at all.
    bool
    active() const
    {
      return interval > 0 || every_steps > 0;
    }

    /// Due at @p time, step @p step; or if @p last_step_of_run (a run's
    /// final state is always written). Never twice in one step.
    bool
    due(const double       time,
        const unsigned int step,
        const bool         last_step_of_run = false) const;

    /// Written at @p time, step @p step: the next is due at the first
    /// multiple of the interval after @p time.
    void
    written(const double time, const unsigned int step);

    /// The first multiple of the interval after @p time (a loop adding the
    /// interval would never end when it is below the round-off of the
    /// time).
    double
    next_time_after(const double time) const;

    double
    next_time() const
    {
      return next;
    }
    unsigned int
    last_step() const
    {
      return last;
    }
    /// Restore (a checkpoint).
    void
    set_state(const double next_time, const unsigned int last_step)
    {
      next = next_time;
      last = last_step;
    }

  private:
    double       interval;
    unsigned int every_steps;
    double       next;
    unsigned int last = 0;
  };
} // namespace fsgmpm

#endif
