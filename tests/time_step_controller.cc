// Unit test of the one owner of tau, TimeStepController, and of the time
// SimulationControl counts from the accepted steps' tau: a step that would
// pass End time ends there and is not a level; the step after it returns to
// the level; a failed trial halves tau (adaptive: down to the Minimum time
// step; fixed with 'Time step adaptation': down to Time step / 1024; fixed
// without it, or the static problem: never); each accepted step reports
// whether tau changed since the one before, and t_n = t_base + k tau is
// counted from the last change, so that a run of equal steps accumulates no
// round-off; a checkpoint's tau and level come back; bad parameters are
// refused with the entry's name.

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <dyncontact/time_stepping/simulation_control.h>
#include <dyncontact/time_stepping/time_step_controller.h>

#include <cctype>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <string>

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

/// SimulationControl's parameters: End time from @p parameters.
SimulationControl::Parameters
control_parameters(const TimeIntegrationParameters &parameters)
{
  SimulationControl::Parameters p;
  p.end_time = parameters.end_time;
  return p;
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  out << std::setprecision(6);
  TimeIntegrationParameters parameters;

  {
    out << "adaptive, tau = 0.3, End time = 1, levels [0.075, 0.6]\n";
    parse(parameters,
          "set Time step = 0.3\nset End time = 1\nset Time step control = "
          "adaptive\nset Minimum time step = 0.075\nset Maximum time step = "
          "0.6");
    TimeStepController tau;
    SimulationControl  control(MPI_COMM_WORLD, tau);
    control.parse_parameters(control_parameters(parameters), false);
    tau.parse_parameters(parameters, false, control.get_end_time());
    tau.reset(0);
    // three level steps: 0.3, 0.6, 0.9
    for (unsigned int k = 0; k < 3; ++k)
      {
        tau.begin_step(control.get_time());
        const double trial = tau.trial_timestep();
        const auto   step  = tau.accept();
        control.advance(step.tau, step.tau_changed);
        if (k == 0)
          check("the first step takes Time step, unchanged",
                trial == 0.3 && step.tau == 0.3 && !step.tau_changed);
      }
    check("three steps of 0.3 end at t = 3 * 0.3 exactly",
          control.get_time() == 3 * 0.3 && control.get_step() == 3);
    // the last step ends at End time: 0.1, shortened
    tau.begin_step(control.get_time());
    const double last = tau.trial_timestep();
    check("the last trial ends at End time", std::abs(last - 0.1) < 1e-15);
    check("and is shortened (not a level)", tau.step_is_shortened());
    // it fails: tau is halved from the level, 0.15, and clipped again
    check("a failed trial is retried", tau.retry_after_failure());
    check("with the level halved (0.15), clipped to End time again",
          std::abs(tau.trial_timestep() - 0.1) < 1e-15);
    const auto step = tau.accept();
    control.advance(step.tau, step.tau_changed);
    check("the accepted step reports its tau and a change",
          std::abs(step.tau - 0.1) < 1e-15 && step.tau_changed);
    check("the next step returns to the level 0.15",
          tau.get_timestep() == 0.15 && !tau.step_is_shortened());
    check("t = End time, no further step",
          std::abs(control.get_time() - 1.) < 1e-15 && !control.keep_going());
    // halving stops at the Minimum time step: 0.15 -> 0.075 -> refused
    check("halved to the Minimum time step", tau.retry_after_failure());
    check("not below it", !tau.retry_after_failure());
    check("tau = Minimum time step", tau.get_timestep() == 0.075);

    // a checkpoint's tau and level come back
    std::map<std::string, std::string> state;
    ContactRows                        rows;
    VectorType                         flags;
    const auto         vectors = tau.save(state, rows, flags, flags);
    TimeStepController resumed;
    resumed.parse_parameters(parameters, false, 1.);
    resumed.load(state, rows, flags, vectors);
    check("a checkpoint restores tau", resumed.get_timestep() == 0.075);
    resumed.begin_step(0.5);
    resumed.trial_timestep();
    check("and counts the time anew after a resume",
          resumed.accept().tau_changed);
  }

  {
    out << "fixed tau = 1/3 with Time step adaptation, End time = 1\n";
    parse(parameters,
          "set Time step = 0.333333333333333\nset End time = 1\nset Time "
          "step adaptation = true");
    TimeStepController tau;
    SimulationControl  control(MPI_COMM_WORLD, tau);
    control.parse_parameters(control_parameters(parameters), false);
    tau.parse_parameters(parameters, false, control.get_end_time());
    unsigned int n_halvings = 0;
    bool         clipped    = false;
    while (tau.retry_after_failure())
      ++n_halvings;
    check("a failed step is halved 10 times (down to Time step / 1024)",
          n_halvings == 10);
    parse(parameters, "set Time step = 0.25\nset End time = 1");
    TimeStepController fixed;
    fixed.parse_parameters(parameters, false, 1.);
    check("without Time step adaptation a failed step is not retried",
          !fixed.retry_after_failure());
    TimeStepController static_problem;
    static_problem.parse_parameters(parameters, true, 1.);
    check("nor in the static problem",
          !static_problem.retry_after_failure() &&
            !static_problem.is_adaptive());
    // fixed steps: the time is k tau, the last step passes End time
    SimulationControl fixed_control(MPI_COMM_WORLD, fixed);
    fixed_control.parse_parameters(control_parameters(parameters), false);
    while (fixed_control.keep_going())
      {
        fixed.begin_step(fixed_control.get_time());
        clipped         = clipped || fixed.trial_timestep() != 0.25;
        const auto step = fixed.accept();
        fixed_control.advance(step.tau, step.tau_changed);
      }
    check("a fixed step is never clipped", !clipped);
    check("four steps to t = 1",
          fixed_control.get_step() == 4 && fixed_control.get_time() == 1.);
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
            TimeStepController tau;
            tau.parse_parameters(parameters, false, 1.);
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
