// Unit test of the one owner of time and tau, SimulationControl: a step
// that would pass End time ends there and is not a level; the step after it
// returns to the level; a failed trial halves tau (adaptive: down to the
// Minimum time step; fixed with 'Time step adaptation': down to Time step /
// 1024; fixed without it, or the static problem: never); t_n = t_base + k
// tau is counted from the last change of tau, so that a run of equal steps
// accumulates no round-off; a checkpoint's step, time, tau and level come
// back; the trial loop advance() retries failed trials of a problem from
// the start of the step and stops where no retry is allowed; the moments
// of output, checkpoint and mesh adaptation follow their intervals; bad
// parameters are refused with the entry's name.

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <dyncontact/time_stepping/simulation_control.h>

#include <cctype>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

using namespace dealii;
using namespace dyncontact;

std::ofstream out("output");

void
check(const std::string &what, const bool ok)
{
  out << what << ": " << (ok ? "OK" : "FAILED") << "\n";
}

/// The parameters with @p time_integration as the body of subsection Time
/// integration.
void
parse(TimeIntegrationParameters &parameters,
      const std::string         &time_integration)
{
  ParameterHandler prm;
  TimeIntegrationParameters::declare_parameters(prm);
  prm.parse_input_from_string("subsection Time integration\n" +
                              time_integration + "\nend\n");
  parameters.parse_parameters(prm);
}

/// A problem whose trials fail (do not converge) @p n_failures times, or
/// are not finite, and which records what the control asked.
class MockProblem : public SteppedProblem
{
public:
  unsigned int        n_failures = 0;
  bool                finite     = true;
  unsigned int        n_begins   = 0;
  unsigned int        n_restores = 0;
  std::vector<double> trial_steps;

  void
  begin_step() override
  {
    ++n_begins;
  }

  const StepReport &
  try_step(const double tau, const double, const bool, TimerOutput &) override
  {
    trial_steps.push_back(tau);
    report     = StepReport();
    report.tau = tau;
    if (n_failures > 0)
      {
        --n_failures;
        report.displacement_solve.status =
          ActiveSetSolver::Status::linear_solver_failed;
      }
    return report;
  }

  bool
  trial_is_finite() const override
  {
    return finite;
  }

  void
  restore(const bool) override
  {
    ++n_restores;
  }

  TrialStep
  trial() override
  {
    throw std::logic_error("fixed steps are not judged");
  }

private:
  StepReport report;
};

/// No output times, checkpoints or mesh adaptation.
const SimulationControl::Parameters no_intervals = {0., 0, 0.};

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  out << std::setprecision(6);
  const ConditionalOStream pcout(out, true);
  TimerOutput timer(out, TimerOutput::never, TimerOutput::wall_times);
  TimeIntegrationParameters parameters;

  {
    out << "adaptive, tau = 0.3, End time = 1, levels [0.075, 0.6]\n";
    parse(parameters,
          "set Time step = 0.3\nset End time = 1\nset Time step control = "
          "adaptive\nset Minimum time step = 0.075\nset Maximum time step = "
          "0.6");
    SimulationControl control(MPI_COMM_WORLD, pcout);
    control.parse_parameters(parameters, no_intervals, false);
    control.reset(0);
    // three level steps: 0.3, 0.6, 0.9
    for (unsigned int k = 0; k < 3; ++k)
      {
        control.begin_step();
        const double trial = control.trial_timestep();
        control.accept();
        if (k == 0)
          check("the first step takes Time step, unchanged",
                trial == 0.3 && control.get_timestep() == 0.3 &&
                  control.get_time() == 0.3);
      }
    check("three steps of 0.3 end at t = 3 * 0.3 exactly",
          control.get_time() == 3 * 0.3 && control.get_step() == 3);
    // the last step ends at End time: 0.1, shortened
    control.begin_step();
    const double last = control.trial_timestep();
    check("the last trial ends at End time", std::abs(last - 0.1) < 1e-15);
    check("and is shortened (not a level)", control.step_is_shortened());
    // it fails: tau is halved from the level, 0.15, and clipped again
    check("a failed trial is retried", control.retry_after_failure());
    check("with the level halved (0.15), clipped to End time again",
          std::abs(control.trial_timestep() - 0.1) < 1e-15);
    const StepMoments moments = control.accept();
    check("the accepted step of 0.1 is counted from t = 0.9: t = End time, "
          "no further step, the last step is an output",
          std::abs(control.get_time() - 1.) < 1e-15 && !control.keep_going() &&
            moments.last && moments.output);
    check("the next step returns to the level 0.15",
          control.get_timestep() == 0.15 && !control.step_is_shortened());
    // halving stops at the Minimum time step: 0.15 -> 0.075 -> refused
    check("halved to the Minimum time step", control.retry_after_failure());
    check("not below it", !control.retry_after_failure());
    check("tau = Minimum time step", control.get_timestep() == 0.075);

    // a checkpoint's step, time, tau and level come back (in a run with a
    // later End time)
    std::map<std::string, std::string> state;
    ContactRows                        rows;
    VectorType                         flags;
    const auto        vectors = control.save(state, rows, flags);
    SimulationControl resumed(MPI_COMM_WORLD, pcout);
    parse(parameters,
          "set Time step = 0.3\nset End time = 2\nset Time step control = "
          "adaptive\nset Minimum time step = 0.075\nset Maximum time step = "
          "0.6");
    resumed.parse_parameters(parameters, no_intervals, false);
    resumed.load(state, rows, flags, vectors);
    check("a checkpoint restores tau, the step and the time",
          resumed.get_timestep() == 0.075 && resumed.get_step() == 4 &&
            resumed.get_time() == control.get_time());
    resumed.begin_step();
    resumed.trial_timestep();
    resumed.accept();
    check("and counts the time on from there",
          std::abs(resumed.get_time() - 1.075) < 1e-15 &&
            resumed.get_step() == 5);
    // a checkpoint at End time or later cannot be resumed
    SimulationControl ended(MPI_COMM_WORLD, pcout);
    parse(parameters, "set Time step = 0.3\nset End time = 1");
    ended.parse_parameters(parameters, no_intervals, false);
    try
      {
        ended.load(state, rows, flags, {});
        check("a checkpoint at End time is refused", false);
      }
    catch (const std::exception &e)
      {
        // (on one line: deal.II breaks long messages)
        std::string message;
        for (const char c : std::string(e.what()))
          if (!std::isspace(c))
            message += c;
          else if (!message.empty() && message.back() != ' ')
            message += ' ';
        check("a checkpoint at End time is refused, naming End time",
              message.find("End time = 1 s is not after the checkpoint's "
                           "time t = 1 s") != std::string::npos);
      }
  }

  {
    out << "fixed tau = 1/3 with Time step adaptation, End time = 1\n";
    parse(parameters,
          "set Time step = 0.333333333333333\nset End time = 1\nset Time "
          "step adaptation = true");
    SimulationControl tau(MPI_COMM_WORLD, pcout);
    tau.parse_parameters(parameters, no_intervals, false);
    unsigned int n_halvings = 0;
    bool         clipped    = false;
    while (tau.retry_after_failure())
      ++n_halvings;
    check("a failed step is halved 10 times (down to Time step / 1024)",
          n_halvings == 10);
    parse(parameters, "set Time step = 0.25\nset End time = 1");
    SimulationControl fixed(MPI_COMM_WORLD, pcout);
    fixed.parse_parameters(parameters, no_intervals, false);
    check("without Time step adaptation a failed step is not retried",
          !fixed.retry_after_failure());
    SimulationControl static_problem(MPI_COMM_WORLD, pcout);
    static_problem.parse_parameters(parameters, no_intervals, true);
    check("nor in the static problem",
          !static_problem.retry_after_failure() &&
            !static_problem.is_adaptive());
    // fixed steps: the time is k tau, the last step passes End time
    SimulationControl fixed_control(MPI_COMM_WORLD, pcout);
    fixed_control.parse_parameters(parameters, no_intervals, false);
    while (fixed_control.keep_going())
      {
        fixed_control.begin_step();
        clipped = clipped || fixed_control.trial_timestep() != 0.25;
        fixed_control.accept();
      }
    check("a fixed step is never clipped", !clipped);
    check("four steps to t = 1",
          fixed_control.get_step() == 4 && fixed_control.get_time() == 1.);
  }

  {
    out << "the trial loop: tau = 0.25, End time = 1, outputs every 0.5 s, "
           "checkpoints every 3 steps, the mesh adapts every 2 steps\n";
    parse(parameters,
          "set Time step = 0.25\nset End time = 1\nset Time step "
          "adaptation = true");
    SimulationControl control(MPI_COMM_WORLD, pcout);
    control.parse_parameters(parameters, {0.5, 3, 0.}, false);
    control.set_refinement_interval(2);
    MockProblem problem;
    problem.n_failures = 2;
    auto outcome       = control.advance(problem, timer);
    check("two failed trials are retried from the start of the step with "
          "tau/2 and tau/4, the third is accepted",
          !outcome.failed && problem.n_begins == 1 && problem.n_restores == 2 &&
            problem.trial_steps == std::vector<double>{0.25, 0.125, 0.0625} &&
            control.get_time() == 0.0625 && control.get_step() == 1);
    // the moments of the following steps of 0.0625: outputs at 0.5 and 1,
    // checkpoints after steps 3, 6, ..., the mesh after steps 2, 4, ...
    std::string moments;
    while (control.keep_going())
      {
        outcome = control.advance(problem, timer);
        if (outcome.moments.output || outcome.moments.checkpoint ||
            outcome.moments.refinement || outcome.moments.last)
          moments += " " + std::to_string(control.get_step()) + ":" +
                     (outcome.moments.output ? "o" : "") +
                     (outcome.moments.checkpoint ? "c" : "") +
                     (outcome.moments.refinement ? "r" : "") +
                     (outcome.moments.last ? "l" : "");
      }
    out << "moments (step: output, checkpoint, refinement, last):" << moments
        << "\n";
    check("16 steps to t = 1",
          control.get_step() == 16 && control.get_time() == 1.);

    parse(parameters, "set Time step = 0.25\nset End time = 1");
    SimulationControl fixed(MPI_COMM_WORLD, pcout);
    fixed.parse_parameters(parameters, no_intervals, false);
    MockProblem failing;
    failing.n_failures = 1;
    outcome            = fixed.advance(failing, timer);
    check("without Time step adaptation a failed trial stops the run at the "
          "start of the step",
          outcome.failed && outcome.finite && failing.n_restores == 1 &&
            fixed.get_step() == 0 && fixed.get_time() == 0.);
    MockProblem infinite;
    infinite.finite = false;
    outcome         = fixed.advance(infinite, timer);
    check("so does a trial that is not finite, and says so",
          outcome.failed && !outcome.finite && infinite.n_restores == 1);
  }

  {
    out << "bad parameters\n";
    for (const std::string &entry :
         {std::string("set Time step = 0"),
          std::string("set Time step = 1e-12\nset End time = 1"),
          std::string("set Time step control = adaptive\nset Minimum time "
                      "step = 1"),
          std::string("set Time step control = adaptive\nset Time step "
                      "tolerance = 0")})
      {
        parse(parameters, entry);
        std::string message;
        try
          {
            SimulationControl tau(MPI_COMM_WORLD, pcout);
            tau.parse_parameters(parameters, no_intervals, false);
          }
        catch (const std::exception &e)
          {
            message = e.what();
          }
        // the message, from the entry's name to its end, on one line
        const auto begin = message.find("Time integration");
        if (begin == std::string::npos)
          message = "(accepted)";
        else
          message = message.substr(begin, message.find("\n\n", begin) - begin);
        std::string line;
        for (const char c : message)
          if (!std::isspace(c))
            line += c;
          else if (!line.empty() && line.back() != ' ')
            line += ' ';
        out << line << "\n";
      }
  }
  return 0;
}
