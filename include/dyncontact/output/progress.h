#ifndef dyncontact_output_progress_h
#define dyncontact_output_progress_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

namespace dyncontact
{
  using namespace dealii;

  /**
   * Signs of life of a long run: a line at most every 'Output/Progress
   * interval' seconds of wall time with the step, t / T, tau, the active
   * rows, the active-set and CG iterations of the last step, the wall time
   * per step and an estimate of the time to the end. A run shorter than
   * the interval prints none. Only rank 0 prints (through pcout); nothing
   * here communicates.
   */
  class Progress
  {
  public:
    /// @p interval: Output/Progress interval, in s of wall time; 0: no
    /// progress lines.
    Progress(const double interval, const ConditionalOStream &pcout);

    /// Starts the clock (after the set-up, before the first step).
    void
    start();

    /// After a step: prints a line if the interval has passed, with the
    /// wall time left estimated from @p steps_to_end, the steps left at
    /// @p tau (SimulationControl::steps_to_end()).
    void
    step(const unsigned int step,
         const double       time,
         const double       end_time,
         const double       tau,
         const double       steps_to_end,
         const unsigned int active_rows,
         const unsigned int rows,
         const unsigned int active_set_iterations,
         const unsigned int linear_iterations);

  private:
    const double              interval;
    const ConditionalOStream &pcout;
    Timer                     clock;
    double                    last_line      = 0.;
    unsigned int              steps_at_start = 0;
    bool                      started        = false;
  };
} // namespace dyncontact

#endif
