#include <deal.II/base/utilities.h>

#include <dyncontact/base/input_checks.h>
#include <dyncontact/time_stepping/simulation_control.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace dyncontact
{
  SimulationControl::SimulationControl(const MPI_Comm            comm,
                                       const ConditionalOStream &pcout)
    : comm(comm)
    , pcout(pcout)
  {}



  void
  SimulationControl::parse_parameters(
    const TimeIntegrationParameters &time_integration,
    const Parameters                &parameters,
    const bool                       static_problem)
  {
    // the time
    end_time = time_integration.end_time;
    AssertThrow(std::isfinite(end_time) && end_time >= 0.,
                ExcMessage("Time integration/End time must be a finite "
                           "number >= 0 (s); got " +
                           format_number(end_time) + "."));
    // (the static problem's loads that are functions of t: at End time)
    static_load_time = end_time;
    if (static_problem)
      // no time: its one state is that of load factor 1 (the unloaded
      // initial state is at 0)
      end_time = 1.;

    output_interval = parameters.output_interval;
    AssertThrow(std::isfinite(output_interval) && output_interval >= 0.,
                ExcMessage("Output/Output interval must be a finite number "
                           ">= 0 (s); got " +
                           format_number(output_interval) + "."));
    checkpoint_steps   = parameters.checkpoint_steps;
    checkpoint_minutes = parameters.checkpoint_minutes;

    is_static   = static_problem;
    step        = 0;
    time        = 0.;
    time_base   = 0.;
    steps_since = 0;
    next_output = output_interval;

    // the time step
    time_step            = time_integration.time_step;
    time_step_adaptation = time_integration.time_step_adaptation;
    adaptive             = time_integration.adaptive && !static_problem;
    min_time_step        = time_integration.minimum_time_step;
    max_time_step        = time_integration.maximum_time_step;
    tolerance            = time_integration.tolerance;
    event_location       = time_integration.event_location == "none" ?
                             EventLocation::none :
                           time_integration.event_location == "every row" ?
                             EventLocation::every_row :
                             EventLocation::onset_and_separation;
    AssertThrow(std::isfinite(time_step) && time_step > 0.,
                ExcMessage("Time integration/Time step must be a finite "
                           "number > 0 (s); got " +
                           format_number(time_step) + "."));
    AssertThrow(end_time / time_step < 1e8,
                ExcMessage("Time integration: End time / Time step = " +
                           format_number(end_time / time_step) +
                           " steps; at most 1e8 steps are allowed."));
    if (min_time_step == 0.)
      min_time_step = time_step / 64.;
    if (max_time_step == 0.)
      max_time_step = time_step;
    // the adaptive control's parameters matter only with it
    if (adaptive)
      {
        AssertThrow(std::isfinite(min_time_step) && min_time_step > 0. &&
                      min_time_step <= time_step,
                    ExcMessage("Time integration/Minimum time step must be a "
                               "finite number in (0, Time step = " +
                               format_number(time_step) +
                               "] (s), or 0 for Time step / 64; got " +
                               format_number(min_time_step) + "."));
        AssertThrow(std::isfinite(max_time_step) && max_time_step >= time_step,
                    ExcMessage("Time integration/Maximum time step must be a "
                               "finite number >= Time step = " +
                               format_number(time_step) +
                               " (s), or 0 for Time step; got " +
                               format_number(max_time_step) + "."));
        AssertThrow(std::isfinite(tolerance) && tolerance > 0.,
                    ExcMessage("Time integration/Time step tolerance must be "
                               "a finite number > 0; got " +
                               format_number(tolerance) + "."));
        AssertThrow(end_time == 0. || min_time_step < end_time,
                    ExcMessage(
                      "Time integration/Time step = " +
                      format_number(time_step) +
                      " s with 'Time step control = adaptive': its Minimum "
                      "time step (" +
                      format_number(min_time_step) +
                      " s) is not below End time = " + format_number(end_time) +
                      " s, so no step could be cut at a contact event or "
                      "repeated after an error estimate: the run would be "
                      "one unchecked step. Choose a Time step (and Minimum "
                      "time step) below End time."));
        AssertThrow(end_time / min_time_step < 1e9,
                    ExcMessage("Time integration: End time / Minimum time "
                               "step = " +
                               format_number(end_time / min_time_step) +
                               " steps; at most 1e9 are allowed: raise "
                               "Time integration/Minimum time step."));
      }
    tau         = time_step;
    tau_level   = time_step;
    tau_changed = false;
    stop_intervals.clear();
    // adaptive steps end at the output times (fixed ones output at the
    // first step at or after each)
    stop_at_multiples_of(output_interval);
  }



  bool
  SimulationControl::keep_going() const
  {
    return is_static ? step < 1 : time < end_time - end_time_tolerance();
  }



  double
  SimulationControl::end_time_tolerance() const
  {
    return 1e-9 * std::min(tau, end_time);
  }



  double
  SimulationControl::steps_to_end(const double step_tau) const
  {
    return std::max(0.,
                    std::ceil((end_time - time - end_time_tolerance()) /
                              step_tau));
  }



  SimulationControl::Outcome
  SimulationControl::advance(SteppedProblem &problem, TimerOutput &timer)
  {
    problem.begin_step();
    begin_step();
    while (true)
      {
        // (trial_timestep() decides whether the trial is shortened)
        const double      trial_tau = trial_timestep();
        const StepReport &report    = problem.try_step(trial_tau,
                                                    end_of_trial(),
                                                    !step_is_shortened(),
                                                    timer);
        const bool        finite    = problem.trial_is_finite();
        if (!report.converged() || !finite)
          {
            // back to the last good state, warm started from the failed
            // trial's active sets: retry with a smaller step, or stop
            problem.restore(true);
            if (!retry_after_failure())
              return {true, finite, {}};
            pcout << "   warning: step " << step + 1 << " (t = " << time
                  << " s) failed; retrying with tau = " << tau << " s"
                  << std::endl;
            continue;
          }
        if (adaptive)
          {
            TimerOutput::Scope t(timer, "time step control");
            if (retry_after_judgement(problem.trial()))
              {
                // from the start of the step, with its active sets
                problem.restore(false);
                continue;
              }
          }
        return {false, true, accept()};
      }
  }



  double
  SimulationControl::end_of_trial() const
  {
    // (as accept() counts it: from t_base, or from t_n if tau changed)
    if (is_static)
      return static_load_time;
    return tau_changed ? time + tau : time_base + (steps_since + 1) * tau;
  }



  StepMoments
  SimulationControl::accept()
  {
    // the time step: the next one returns to the level after a shortened
    // step, and grows where the estimates allow it
    const double step_tau     = tau;
    const bool   step_changed = tau_changed;
    const double new_time     = end_of_trial();
    (void)new_time;
    tau_changed = false;
    if (tau != tau_level)
      {
        tau         = tau_level;
        tau_changed = true;
      }
    if (may_grow)
      grow();
    may_grow = false;

    // the time
    ++step;
    if (step_changed)
      {
        time_base   = time;
        steps_since = 0;
      }
    ++steps_since;
    time = is_static ? end_time : time_base + steps_since * step_tau;
    Assert(is_static || time == new_time, ExcInternalError());

    // the last step is an output too, but the next output time moves on
    // only when it is reached (a resumed run writes the same outputs)
    StepMoments moments;
    moments.last       = !keep_going();
    const bool reached = time >= next_output - 1e-9 * tau;
    moments.output     = reached || moments.last;
    if (reached)
      next_output += output_interval;
    moments.checkpoint = checkpoint_steps > 0 && step % checkpoint_steps == 0;
    if (checkpoint_minutes > 0.)
      moments.checkpoint =
        moments.checkpoint ||
        Utilities::MPI::broadcast(
          comm, since_checkpoint.wall_time() > 60. * checkpoint_minutes, 0);
    if (moments.checkpoint)
      since_checkpoint.restart();
    moments.refinement = refinement_due(step) && !moments.last;
    return moments;
  }



  namespace
  {
    std::string
    exact(const double x)
    {
      std::ostringstream s;
      s << std::setprecision(17) << x;
      return s.str();
    }
  } // namespace



  std::vector<VectorType>
  SimulationControl::save(std::map<std::string, std::string> &state,
                          const ContactRows                  &rows,
                          VectorType                         &flags) const
  {
    state["step"]                = std::to_string(step);
    state["time"]                = exact(time);
    state["next_output"]         = exact(next_output);
    state["tau"]                 = exact(tau);
    state["tau_level"]           = exact(tau_level);
    state["passed_output_times"] = std::to_string(passed_output_times);
    estimator.save(state);
    if (!adaptive)
      return {};
    // + 4: a row that changed its state in the last step
    for (unsigned int p = 0; p < rows.size(); ++p)
      if (p < settled_rows.size() && !settled_rows[p])
        flags(rows.rows[p].eliminated_dof()) += 4.;
    flags.compress(VectorOperation::insert);
    std::vector<VectorType> vectors(2, flags);
    // the error estimate's last acceleration (zero if it has none)
    VectorType &acceleration = vectors[0];
    acceleration             = 0.;
    if (estimator.get_acceleration().size() == acceleration.size())
      acceleration = estimator.get_acceleration();
    // the rows' forces (zero where there are none: no release is located)
    VectorType &forces = vectors[1];
    forces             = 0.;
    for (unsigned int p = 0; p < rows.size() && p < row_forces.size(); ++p)
      forces(rows.rows[p].eliminated_dof()) = row_forces[p];
    forces.compress(VectorOperation::insert);
    state["row_forces"] = "in checkpoint";
    return vectors;
  }



  unsigned int
  SimulationControl::n_checkpoint_vectors(
    const std::map<std::string, std::string> &state) const
  {
    return adaptive ? 1 + state.count("row_forces") : 0;
  }



  void
  SimulationControl::load(const std::map<std::string, std::string> &state,
                          const ContactRows                        &rows,
                          const VectorType                         &flags,
                          const std::vector<VectorType>            &vectors)
  {
    // the time
    const double huge = std::numeric_limits<double>::max();
    step = checkpoint_number(state, "step", "step number", 0., 4e9);
    time = checkpoint_number(state, "time", "time t (s)", 0., huge);
    next_output =
      checkpoint_number(state, "next_output", "next output time (s)", 0., huge);
    AssertThrow(end_time > time,
                ExcMessage(
                  "Time integration/End time = " + format_number(end_time) +
                  " s is not after the checkpoint's time t = " +
                  format_number(time) +
                  " s: a resumed run needs a later End time."));
    // t = t_base + k tau from here on
    time_base   = time;
    steps_since = 0;

    // the time step: none above the largest this run could take (Time step
    // and Maximum time step are the checkpoint's)
    const double largest  = std::max(time_step, max_time_step) * (1. + 1e-12);
    const double smallest = std::numeric_limits<double>::min();
    tau =
      checkpoint_number(state, "tau", "time step tau (s)", smallest, largest);
    tau_level           = state.count("tau_level") ?
                            checkpoint_number(state,
                                    "tau_level",
                                    "time step level (s)",
                                    smallest,
                                    largest) :
                            tau;
    passed_output_times = state.count("passed_output_times") ?
                            checkpoint_number(state,
                                              "passed_output_times",
                                              "passed output times",
                                              0.,
                                              4e9) :
                            0;
    // t = t_base + k tau is counted from the checkpoint's time
    tau_changed = true;
    reset(rows.size());
    if (!adaptive)
      return;
    AssertThrow(vectors.size() == n_checkpoint_vectors(state),
                ExcInternalError());
    estimator.load(state, vectors[0]);
    for (unsigned int p = 0; p < rows.size(); ++p)
      settled_rows[p] =
        (std::lround(flags(rows.rows[p].eliminated_dof())) & 4) == 0;
    if (vectors.size() > 1)
      {
        row_forces.resize(rows.size());
        for (unsigned int p = 0; p < rows.size(); ++p)
          row_forces[p] = vectors[1](rows.rows[p].eliminated_dof());
      }
  }
} // namespace dyncontact
