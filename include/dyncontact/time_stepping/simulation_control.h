#ifndef dyncontact_time_stepping_simulation_control_h
#define dyncontact_time_stepping_simulation_control_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <dyncontact/time_stepping/step_size_control.h>
#include <dyncontact/time_stepping/time_integration_parameters.h>

#include <map>
#include <string>
#include <vector>

namespace dyncontact
{
  using namespace dealii;

  /**
   * What happens after an accepted step, decided once when the step is
   * accepted (SimulationControl::advance()) and read by everyone as a value
   * (so that nothing depends on the order in which the simulator and its
   * statistics ask).
   */
  struct StepMoments
  {
    /// An output time is reached (the last step is one): VTU files are
    /// written if they are enabled, sampled statistics are evaluated.
    bool output = false;
    /// A checkpoint is written after this step (the same on all ranks).
    bool checkpoint = false;
    /// The mesh is adapted after this step (never after the last one).
    bool refinement = false;
    /// No step follows.
    bool last = false;
  };

  /// A converged trial step, as the adaptive control judges it.
  struct TrialStep
  {
    const StepOperators      &operators;
    const ContactRowOperator &row_operator;
    /// the active sets at the start of the step
    const std::vector<char> &active_before;
    /// the state at the start of the step, and the trial's
    const VectorType &u_old;
    const VectorType &udot_old;
    const VectorType &u;
    const VectorType &udot;
    /// the trial's report (the control sets its error estimate)
    StepReport &report;
  };

  /**
   * What SimulationControl::advance() asks of the problem it steps
   * (DiscreteProblem): trial steps from the state the step starts from,
   * and a return to that state.
   */
  class SteppedProblem
  {
  public:
    virtual ~SteppedProblem() = default;

    /// The present state (and its active sets) is where the next step
    /// starts from.
    virtual void
    begin_step() = 0;

    /// A trial step of length @p tau from the start of the step to the
    /// time @p t_end (the loads' time), timed in @p timer; @p level_step:
    /// tau is a level of the time step control (its step matrix is kept
    /// for later steps).
    virtual const StepReport &
    try_step(const double tau,
             const double t_end,
             const bool   level_step,
             TimerOutput &timer) = 0;

    /// Whether the trial's displacement and velocity are finite.
    /// Collective.
    virtual bool
    trial_is_finite() const = 0;

    /// Back to the start of the step; the next trial starts from the
    /// active sets of the failed trial (@p from_trial) or of the start.
    virtual void
    restore(const bool from_trial) = 0;

    /// The converged trial, for the adaptive control's judgement.
    virtual TrialStep
    trial() = 0;
  };

  /**
   * The one owner of time (as lethe's SimulationControl): the end time, the
   * step number and the time t_n = t_base + k tau (so that times do not
   * accumulate round-off; t_base is the time at which tau last changed),
   * the time step tau (fixed, halved after a failure, or adaptive: its
   * levels, the contact events it locates, the times its steps end at),
   * and the moments that follow a step (StepMoments: output, checkpoint,
   * mesh adaptation, the end). advance() runs the trial steps of one step
   * (doc/algorithms.md, "Adaptive time steps"): it asks the problem for a
   * trial with the present tau and accepts it, or retries from the start
   * of the step with the tau it has set: halved after a failed solve or an
   * error estimate above the tolerance, shortened to the predicted moment
   * of a contact event. The static problem is one step, to t = 1 (no time:
   * the load factor; the unloaded initial state is at 0).
   *
   * With 'Time step control = fixed' every step takes Time step; with
   * 'Time step adaptation' a failed step is retried with tau/2 (down to
   * Time step / 1024). With 'adaptive' tau moves between the levels
   * Time step * 2^k inside [Minimum time step, Maximum time step]; a step
   * that is shortened (to an event, or to End time) is not a level, and
   * the step after it returns to the level. Times are compared with End
   * time and the output times up to round-off of 1e-9 of the present tau
   * (end_time_tolerance()).
   *
   * The integrator stores no tau: it is handed the trial's tau with each
   * step, and each StepReport carries the tau of its step.
   */
  class SimulationControl
  {
  public:
    /// The values it is handed by the owners of their subsections
    /// besides Time integration: Output/Output interval
    /// (OutputParameters), Checkpointing/Interval in steps and Interval in
    /// minutes (Checkpoints).
    struct Parameters
    {
      double       output_interval    = 0.05;
      unsigned int checkpoint_steps   = 0;
      double       checkpoint_minutes = 0.;
    };

    /// @p pcout: for the warnings of retried steps (copied).
    SimulationControl(const MPI_Comm comm, const ConditionalOStream &pcout);

    /// Takes and checks the time integration's End time, Time step, Time
    /// step adaptation, Time step control, Event location, Minimum/Maximum
    /// time step, Time step tolerance and the intervals of @p parameters;
    /// @p is_static: one step, to t = 1, without time step control.
    /// Adaptive steps end at the output times.
    void
    parse_parameters(const TimeIntegrationParameters &time_integration,
                     const Parameters                &parameters,
                     const bool                       is_static);

    /// @name The time
    /// @{

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

    double
    get_end_time() const
    {
      return end_time;
    }

    /// Whether the run is the static problem (one step).
    bool
    is_static_problem() const
    {
      return is_static;
    }

    /// Whether another step is to be taken: not once the time is within
    /// end_time_tolerance() of the end time.
    bool
    keep_going() const;

    /// 1e-9 min(tau, End time) (s): a time within it of the end time is at
    /// it (round-off of the steps' sum; for a step longer than the whole run
    /// that of the end time, or a step of 1e9 times the run would end it
    /// before it started).
    double
    end_time_tolerance() const;

    /// The steps of length @p tau that keep_going() takes from the present
    /// time on (the last one may end after the end time).
    double
    steps_to_end(const double tau) const;

    /// The mesh adapts after every @p interval-th step (0: never):
    /// Mesh refinement/Refinement interval, handed by its owner, MeshAdaptor,
    /// after it has read it.
    void
    set_refinement_interval(const unsigned int interval)
    {
      refinement_interval = interval;
    }

    /// Whether the mesh is due to adapt after step @p n (Refinement
    /// interval), the last step included (a resumed run adapts after it).
    bool
    refinement_due(const unsigned int n) const
    {
      return refinement_interval > 0 && n % refinement_interval == 0;
    }
    /// @}

    /// @name The time step
    /// @{

    /// The tau of the next trial (after an accepted step: the level the
    /// next step starts from).
    double
    get_timestep() const
    {
      return tau;
    }

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

    /// Steps shortened to a located event, and steps repeated because
    /// their estimate exceeded the tolerance.
    unsigned int
    n_located_events() const
    {
      return estimator.located_events;
    }

    unsigned int
    n_repeated_steps() const
    {
      return estimator.repeated_steps;
    }

    /// Output times passed because a contact event followed (each costs a
    /// trial step).
    unsigned int
    n_passed_output_times() const
    {
      return passed_output_times;
    }

    /// The steps must reach every multiple of @p interval (the times of
    /// reference states, which a writing and a comparing run must both
    /// reach): the adaptive control ends a step there where it would pass
    /// one; a fixed Time step must divide it, or the run stops with a
    /// message naming @p entry (the parameter that sets the interval).
    void
    require_multiples_of(const double interval, const std::string &entry);

    /// The contact rows changed (a new mesh, or the first one): forgets
    /// the estimates and the rows' last forces and states.
    void
    reset(const std::size_t n_rows);
    /// @}

    /// What advance() did.
    struct Outcome
    {
      /// A trial failed and cannot be retried: the problem is at the
      /// start of the step, the time has not moved, get_timestep() is the
      /// failed trial's.
      bool failed = false;
      /// of a failed trial: whether its solution was finite
      bool finite = true;
      /// of an accepted step: what follows it
      StepMoments moments;
    };

    /// One step of @p problem from the present time: trial steps until
    /// one is accepted (retried after a failed solve, a located contact
    /// event, an error estimate above the tolerance), then t_{n+1} and the
    /// step's moments: the next output time moves on by one interval when
    /// one is reached, the checkpoint clock restarts. The adaptive
    /// control's judgement is timed as 'time step control'.
    Outcome
    advance(SteppedProblem &problem, TimerOutput &timer);

    /// @name The trial loop's parts, in the order advance() calls them
    /// (public for the unit tests)
    /// @{

    /// A new step (until a trial is accepted).
    void
    begin_step();

    /// The tau of the next trial of the present step: get_timestep(), but
    /// a step of the adaptive control that would pass End time, an output
    /// time or a time of require_multiples_of() ends there.
    double
    trial_timestep();

    /// Whether the present trial is shortened (to an event or a time):
    /// its step matrix is not kept as a level's.
    bool
    step_is_shortened() const
    {
      return tau != tau_level;
    }

    /// The trial failed (a solve did not converge, or the state is not
    /// finite): true, with tau halved for a retry from the start of the
    /// step, where the control allows it (adaptive, or 'Time step
    /// adaptation' down to Time step / 1024); false otherwise.
    bool
    retry_after_failure();

    /// The adaptive control's judgement of the converged @p trial: true to
    /// retry it from the start of the step with the new get_timestep(),
    /// shortened to a contact event predicted inside it (once per step) or
    /// halved where its error estimate exceeds the tolerance; false to
    /// accept it, with the trial's error estimate set. Collective. With
    /// fixed tau: false.
    bool
    retry_after_judgement(const TrialStep &trial);

    /// The trial was accepted: t_{n+1} (counted from t_n if tau changed
    /// since the step before) and the step's moments; tau returns to the
    /// level after a shortened step and doubles the level where the
    /// estimates allow it.
    StepMoments
    accept();

    /// The time at which a trial of the present tau ends, as accept() will
    /// count it; for the static problem (whose one state has the time 1,
    /// its load factor) Time integration/End time, the time of its loads.
    double
    end_of_trial() const;
    /// @}

    /**
     * The state a resumed run needs: step, time, next output, tau, its
     * level and the estimator's scalars into @p state. With the adaptive
     * control also each row's state (+4 at its eliminated DoF of @p flags,
     * which hold the integrator's active sets: a row that changed its
     * state in the last step), and the vectors returned, nodal vectors laid
     * out as @p flags that the checkpoint carries after u, udot and the
     * flags: the estimator's last acceleration (zero without history) and
     * each row's force in the last step at its eliminated DoF (so that the
     * first step after a resume locates a release as the uninterrupted run
     * does). None with fixed tau.
     */
    std::vector<VectorType>
    save(std::map<std::string, std::string> &state,
         const ContactRows                  &rows,
         VectorType                         &flags) const;

    /// How many vectors save() put into the checkpoint of @p state (older
    /// checkpoints of the adaptive control have no rows' forces).
    unsigned int
    n_checkpoint_vectors(const std::map<std::string, std::string> &state) const;

    /// The inverse of save(), on the mesh the checkpoint's vectors were
    /// transferred to: @p flags and the n_checkpoint_vectors() @p vectors.
    /// Refuses an End time that is not after the checkpoint's time.
    void
    load(const std::map<std::string, std::string> &state,
         const ContactRows                        &rows,
         const VectorType                         &flags,
         const std::vector<VectorType>            &vectors);

  private:
    /// The level tau/2 (adaptive: false at the Minimum time step).
    bool
    halve();

    /// The level 2 tau (false at the Maximum time step).
    bool
    grow();

    /// The next trial takes @p new_tau < the level; the level is kept.
    void
    shorten(const double new_tau);

    /// The steps end at every multiple of @p interval (0: none) that they
    /// would pass (the output times), except where a contact event lies
    /// within the step after that time (N-CS++'s projection would see it
    /// from there): then the step takes its level, and the time is passed.
    /// Fixed steps do not change.
    void
    stop_at_multiples_of(const double interval);

    /// Which contact events the adaptive control locates.
    enum class EventLocation
    {
      none,
      onset_and_separation,
      every_row
    };

    const MPI_Comm comm;
    /// (a copy: it holds no reference to its owner's)
    const ConditionalOStream pcout;

    // parameters of the time
    double       end_time            = 2.5;
    double       output_interval     = 0.05;
    unsigned int checkpoint_steps    = 0;
    double       checkpoint_minutes  = 0.;
    unsigned int refinement_interval = 0;
    bool         is_static           = false;

    // parameters of the time step
    double        time_step            = 0.0125;
    bool          time_step_adaptation = false;
    bool          adaptive             = false;
    double        min_time_step        = 0.;
    double        max_time_step        = 0.;
    double        tolerance            = 1e-2;
    EventLocation event_location       = EventLocation::onset_and_separation;
    /// The intervals of stop_at_multiples_of() (false) and of
    /// require_multiples_of() (true).
    std::vector<std::pair<double, bool>> stop_intervals;

    // state of the time
    unsigned int step      = 0;
    double       time      = 0.;
    double       time_base = 0.;
    /// Time integration/End time, the static problem's time of loads
    /// (its end_time is 1).
    double       static_load_time = 0.;
    unsigned int steps_since      = 0;
    double       next_output      = 0.05;
    Timer        since_checkpoint;

    // state of the time step
    double tau       = 0.0125;
    double tau_level = 0.0125;
    /// tau changed since the last accepted step
    bool tau_changed = false;
    /// What the present trial ends at: an output time, a time of
    /// require_multiples_of() or End time; nothing of these.
    enum class EndsAt
    {
      level,
      optional_time,
      required_time
    } ends_at = EndsAt::level;
    /// The trial's tau and tau_changed before it was made to end at a time
    /// (restored where an event follows an optional time).
    double uncut_tau         = 0.;
    bool   uncut_tau_changed = false;
    /// Optional times are passed in the present step.
    bool pass_optional_times = false;
    /// n_passed_output_times()
    unsigned int passed_output_times = 0;
    /// the present step has been shortened to a located event
    bool event_located = false;
    /// the estimates of the trial that was judged allow a larger tau
    bool            may_grow = false;
    StepSizeControl estimator;
    /// per row: the contact force of the last accepted step, and whether
    /// that step left the row in the state it started in
    std::vector<double> row_forces;
    std::vector<char>   settled_rows;
  };
} // namespace dyncontact

#endif
