#ifndef dyncontact_core_simulation_control_h
#define dyncontact_core_simulation_control_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <map>
#include <string>

namespace dealii
{
  class ParameterHandler;
}

namespace dyncontact
{
  using namespace dealii;

  /**
   * The one owner of time (as lethe's SimulationControl): the time step tau,
   * the end time, the step number and the time t_n = t_base + k tau (so that
   * times do not accumulate round-off), the moments of VTU output and of
   * checkpoints, and the retry policy of a failed step (tau/2, down to
   * tau/1024, when 'Time step adaptation' is on). The static problem is one
   * step to the end time.
   *
   * With 'Time step control = adaptive' tau moves between the levels
   * Time step * 2^k inside [Minimum time step, Maximum time step]: halve()
   * after a rejected step, grow() when the error estimate allows, and
   * shorten() for one step that ends at a located contact event (or at End
   * time); the step after it returns to the level. t_n then sums the steps
   * (t = t_base + k tau since the last change of tau).
   */
  class SimulationControl
  {
  public:
    /// Declares Time integration/Time step, End time, Time step
    /// adaptation, Time step control, Minimum/Maximum time step, Time step
    /// tolerance; Output/Output interval; Checkpointing/Interval in steps,
    /// Interval in minutes.
    static void
    declare_parameters(ParameterHandler &prm);

    SimulationControl(const MPI_Comm comm);

    /// Reads and checks the parameters; @p is_static: one step, to End time.
    void
    parse_parameters(ParameterHandler &prm, const bool is_static);

    unsigned int
    get_step() const
    {
      return step;
    }

    double
    get_time() const
    {
      return time;
    }

    /// The time step in use.
    double
    get_timestep() const
    {
      return tau;
    }

    double
    get_end_time() const
    {
      return end_time;
    }

    /// Whether another step is to be taken.
    bool
    keep_going() const;

    /// After a successful step: t_{n+1}.
    void
    advance();

    /// Whether an output time has been reached after this step: VTU files
    /// are written then (if they are written at all), and the sampled
    /// postprocessors (the error norm) are evaluated.
    bool
    output_due() const;

    /// Moves the next output time on by one interval.
    void
    output_written();

    /// Whether a checkpoint is due after this step (the same on all ranks).
    bool
    checkpoint_due() const;

    void
    checkpoint_written();

    /// A step failed: with 'Time step adaptation', halve tau (down to
    /// tau/1024) and return true; otherwise return false.
    bool
    reduce_timestep();

    /// Whether 'Time step control = adaptive'.
    bool
    is_adaptive() const
    {
      return adaptive;
    }

    double
    get_minimum_timestep() const
    {
      return min_time_step;
    }

    double
    get_maximum_timestep() const
    {
      return max_time_step;
    }

    /// Which contact events the adaptive control locates.
    enum class EventLocation
    {
      none,
      onset_and_separation,
      every_row
    };

    EventLocation
    get_event_location() const
    {
      return event_location;
    }

    /// The tolerance of the error estimate (adaptive control).
    double
    get_tolerance() const
    {
      return tolerance;
    }

    /// Whether the present step is shortened (event or End time).
    bool
    step_is_shortened() const
    {
      return tau != tau_level;
    }

    /// Adaptive control: the next step takes @p new_tau < the level (an
    /// event located inside the step); the level is kept.
    void
    shorten(const double new_tau);

    /// Adaptive control: a step that would pass End time ends there.
    void
    clip_to_end_time();

    /// Adaptive control: the level tau/2; false at the Minimum time step.
    bool
    halve();

    /// Adaptive control: the level 2 tau; false at the Maximum time step.
    bool
    grow();

    /// Whether the run is the static problem (one step).
    bool
    is_static_problem() const
    {
      return is_static;
    }

    /// The state a resumed run needs (step, time, tau, next output).
    void
    save(std::map<std::string, std::string> &state) const;
    void
    load(const std::map<std::string, std::string> &state);

  private:
    const MPI_Comm comm;

    // parameters
    double        time_step            = 0.0125;
    double        end_time             = 2.5;
    bool          time_step_adaptation = false;
    double        output_interval      = 0.05;
    unsigned int  checkpoint_steps     = 0;
    double        checkpoint_minutes   = 0.;
    bool          is_static            = false;
    bool          adaptive             = false;
    double        min_time_step        = 0.;
    double        max_time_step        = 0.;
    double        tolerance            = 1e-2;
    EventLocation event_location       = EventLocation::onset_and_separation;

    /// t = t_base + k tau from here on (after a change of tau)
    void
    restart_count();

    // state
    double       tau         = 0.0125;
    double       tau_level   = 0.0125;
    unsigned int step        = 0;
    double       time        = 0.;
    double       time_base   = 0.;
    unsigned int steps_since = 0;
    double       next_output = 0.05;
    Timer        since_checkpoint;
  };
} // namespace dyncontact

#endif
