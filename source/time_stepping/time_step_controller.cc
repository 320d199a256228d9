#include <deal.II/base/exceptions.h>

#include <dyncontact/base/input_checks.h>
#include <dyncontact/time_stepping/row_force.h>
#include <dyncontact/time_stepping/time_step_controller.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace dyncontact
{
  void
  TimeStepController::parse_parameters(
    const TimeIntegrationParameters &parameters,
    const bool                       static_problem,
    const double                     end)
  {
    end_time             = end;
    time_step            = parameters.time_step;
    time_step_adaptation = parameters.time_step_adaptation;
    adaptive             = parameters.adaptive && !static_problem;
    min_time_step        = parameters.minimum_time_step;
    max_time_step        = parameters.maximum_time_step;
    tolerance            = parameters.tolerance;
    event_location       = parameters.event_location == "none" ?
                             EventLocation::none :
                           parameters.event_location == "every row" ?
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
    is_static   = static_problem;
    tau         = time_step;
    tau_level   = time_step;
    tau_changed = false;
  }



  void
  TimeStepController::reset(const std::size_t n_rows)
  {
    estimator.reset();
    row_forces.clear();
    settled_rows.assign(n_rows, 1);
  }



  void
  TimeStepController::stop_at_multiples_of(const double interval)
  {
    if (interval > 0.)
      stop_intervals.emplace_back(interval, false);
  }



  void
  TimeStepController::require_multiples_of(const double       interval,
                                           const std::string &entry)
  {
    AssertThrow(!is_static,
                ExcMessage(entry + ": the static problem has one state and "
                                   "no time; reference states need a "
                                   "dynamic scheme."));
    const double k = interval / time_step;
    AssertThrow(adaptive || (std::round(k) >= 1. &&
                             std::abs(k - std::round(k)) <= 1e-9 * k),
                ExcMessage(entry + " = " + format_number(interval) +
                           " s is not a multiple of Time integration/Time "
                           "step = " +
                           format_number(time_step) +
                           " s: the steps would miss its times. Choose a "
                           "multiple, or 'Time integration/Time step "
                           "control = adaptive' (its steps end at those "
                           "times)."));
    stop_intervals.emplace_back(interval, true);
  }



  void
  TimeStepController::begin_step(const double time)
  {
    step_start          = time;
    event_located       = false;
    may_grow            = false;
    pass_optional_times = false;
  }



  double
  TimeStepController::trial_timestep()
  {
    uncut_tau         = tau;
    uncut_tau_changed = tau_changed;
    ends_at           = EndsAt::level;
    if (!adaptive)
      return tau;
    if (step_start + tau > end_time)
      {
        shorten(end_time - step_start);
        ends_at = EndsAt::required_time;
      }
    for (const auto &[interval, required] : stop_intervals)
      if (required || !pass_optional_times)
        {
          // the next multiple of the interval after the step's start (a
          // start within 1e-6 intervals of a multiple is at it); a step that
          // ends there up to round-off is not shortened, nor one that would
          // be shorter than the Minimum time step for an optional time
          // (which is then passed)
          const double stop =
            (std::floor(step_start / interval + 1e-6) + 1.) * interval;
          if (step_start + tau > stop + 1e-9 * tau &&
              (required || stop - step_start >= min_time_step))
            {
              shorten(stop - step_start);
              ends_at =
                required ? EndsAt::required_time : EndsAt::optional_time;
            }
          else if (required && step_start + tau > stop - 1e-9 * tau)
            ends_at = EndsAt::required_time;
        }
    return tau;
  }



  bool
  TimeStepController::retry_after_failure()
  {
    event_located = false;
    if (adaptive)
      return halve();
    if (!time_step_adaptation || is_static ||
        tau <= time_step / 1024. * (1. + 1e-12))
      return false;
    tau /= 2.;
    tau_level   = tau;
    tau_changed = true;
    return true;
  }



  TimeStepController::Verdict
  TimeStepController::judge(const StepOperators      &operators,
                            const ContactRowOperator &row_operator,
                            const std::vector<char>  &active_before,
                            const VectorType         &u_old,
                            const VectorType         &udot_old,
                            const VectorType         &u,
                            const VectorType         &udot,
                            StepReport               &trial,
                            const MPI_Comm            comm)
  {
    if (!adaptive)
      return Verdict::accept;
    // a contact row that comes into contact or is released inside the step:
    // end the step at the predicted moment (once per step)
    if (!event_located && event_location != EventLocation::none)
      {
        const double fraction =
          StepSizeControl::event_fraction(operators,
                                          row_operator,
                                          active_before,
                                          settled_rows,
                                          row_forces,
                                          u_old,
                                          udot_old,
                                          u,
                                          trial,
                                          event_location ==
                                            EventLocation::every_row,
                                          comm);
        // an event in (t_n + tau, t_n + 2 tau), which N-CS++'s projection
        // looks at: after an optional time, that time is passed (the step
        // takes its tau again); a step that ends at a required time or at
        // End time keeps it (the event is located in the step after it);
        // a level step is cut to two steps of half the time to the event,
        // so that the first one's look ahead ends at the event
        const bool   beyond = (fraction >= 1. && fraction < 2.);
        const double theta  = !beyond                  ? fraction :
                              ends_at == EndsAt::level ? fraction / 2. :
                                                         1.;
        if (beyond && ends_at == EndsAt::optional_time)
          {
            pass_optional_times = true;
            ++passed_output_times;
            tau         = uncut_tau;
            tau_changed = uncut_tau_changed;
            return Verdict::retry;
          }
        // not below the Minimum time step
        if (theta < 1. - 1e-2 && theta * tau >= min_time_step)
          {
            shorten(theta * tau);
            event_located = true;
            ++estimator.located_events;
            return Verdict::retry;
          }
      }
    const double eta = estimator.estimate(operators, udot_old, udot, tau);
    // a step above the tolerance (but one that ends at a located event) is
    // repeated with the largest level below its tau: tau/2 for a level
    // step; a step cut to end at a given time is shorter than its level
    if (eta > tolerance && !event_located)
      {
        double level = tau_level / 2.;
        while (level >= tau * (1. - 1e-12))
          level /= 2.;
        if (level >= min_time_step * (1. - 1e-12))
          {
            tau_level   = level;
            tau         = level;
            tau_changed = true;
            ++estimator.repeated_steps;
            return Verdict::retry;
          }
      }
    trial.error_estimate = eta;
    may_grow = estimator.accept(udot_old, udot, tau, eta, tolerance) &&
               !step_is_shortened();
    row_forces.resize(trial.active.size());
    settled_rows.resize(trial.active.size());
    for (unsigned int p = 0; p < row_forces.size(); ++p)
      {
        row_forces[p]   = row_force(trial, p);
        settled_rows[p] = (trial.active[p] == active_before[p]);
      }
    return Verdict::accept;
  }



  TimeStepController::AcceptedStep
  TimeStepController::accept()
  {
    AcceptedStep step;
    step.tau         = tau;
    step.tau_changed = tau_changed;
    tau_changed      = false;
    if (tau != tau_level)
      {
        // after a shortened step: back to the level
        tau         = tau_level;
        tau_changed = true;
      }
    if (may_grow)
      grow();
    may_grow = false;
    return step;
  }



  bool
  TimeStepController::halve()
  {
    if (tau_level / 2. < min_time_step * (1. - 1e-12))
      return false;
    tau_level /= 2.;
    tau         = tau_level;
    tau_changed = true;
    return true;
  }



  bool
  TimeStepController::grow()
  {
    if (2. * tau_level > max_time_step * (1. + 1e-12))
      return false;
    tau_level *= 2.;
    tau         = tau_level;
    tau_changed = true;
    return true;
  }



  void
  TimeStepController::shorten(const double new_tau)
  {
    Assert(new_tau > 0. && new_tau <= tau_level, ExcInternalError());
    tau         = new_tau;
    tau_changed = true;
  }



  std::vector<VectorType>
  TimeStepController::save(std::map<std::string, std::string> &state,
                           const ContactRows                  &rows,
                           VectorType                         &flags,
                           const VectorType                   &like) const
  {
    auto exact = [](const double x) {
      std::ostringstream s;
      s << std::setprecision(17) << x;
      return s.str();
    };
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
    std::vector<VectorType> vectors(2, like);
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
  TimeStepController::n_checkpoint_vectors(
    const std::map<std::string, std::string> &state) const
  {
    return adaptive ? 1 + state.count("row_forces") : 0;
  }



  void
  TimeStepController::load(const std::map<std::string, std::string> &state,
                           const ContactRows                        &rows,
                           const VectorType                         &flags,
                           const std::vector<VectorType>            &vectors)
  {
    // no tau above the largest this run could take (Time step and
    // Maximum time step are the checkpoint's)
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
