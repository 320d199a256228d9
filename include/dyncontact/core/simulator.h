#ifndef dyncontact_core_simulator_h
#define dyncontact_core_simulator_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <dyncontact/base/global_parameters.h>
#include <dyncontact/base/statistics.h>
#include <dyncontact/core/simulator_access.h>
#include <dyncontact/output/checkpoint.h>
#include <dyncontact/output/run_report.h>
#include <dyncontact/problem/discrete_problem.h>
#include <dyncontact/time_stepping/simulation_control.h>

#include <memory>
#include <string>

namespace dyncontact
{
  namespace Postprocess
  {
    template <int dim>
    class Manager;
  }
  template <int dim>
  class VtuWriter;
  class OutputDirectory;
  class Progress;

  /**
   * The run: it builds the components from the parameters, starts (or
   * resumes) the DiscreteProblem and steps it; after each step it asks the
   * components for the step's moments and acts on them:
   *
   * - SimulationControl: time, tau (its estimates and events), the trial
   *   steps, the moments of output, checkpoints and mesh adaptation, the
   *   end;
   * - DiscreteProblem: mesh, system, contact rows, integrator, state;
   * - Postprocess::Manager: the statistics (plugins);
   * - MeshAdaptor: where the mesh adapts (criteria are plugins), the
   *   adaptation and its record;
   * - VtuWriter, ReferenceStates, Checkpoints, RunReport: output.
   *
   * Components read the state through SimulatorAccess; each subsection of
   * the prm has one owner (parameter_owners()).
   */
  template <int dim>
  class Simulator
  {
  public:
    /// Reads every component's parameters from @p prm (already parsed);
    /// relative file names refer to @p input_directory. Of @p set_entries
    /// (the entries the input sets, with where: check_for_misplaced_entries())
    /// each that this run does not read gets a warning naming it and why.
    Simulator(
      ParameterHandler                                       &prm,
      const std::string                                      &input_directory,
      const MPI_Comm                                          comm,
      const std::vector<std::pair<std::string, std::string>> &set_entries = {});

    ~Simulator();

    /// Runs the whole simulation; returns the statistics (on all ranks).
    Statistics
    run();

  private:
    /// The warnings of the constructor for the entries of @p set_entries
    /// that the run does not read (by the scene, the mesh adaptation, the
    /// output and the statistics chosen).
    void
    warn_of_unread_entries(
      const std::vector<std::pair<std::string, std::string>> &set_entries)
      const;

    void
    run_time_loop();
    /// The initial state and its statistics row (a new run).
    void
    start();
    /// Starts statistics.tsv and writes the initial state's VTU: only once
    /// the first time step has succeeded, so that a run that fails before
    /// leaves an earlier run's files in the output directory untouched.
    void
    open_outputs();
    /// Everything from the last good checkpoint (a resumed run).
    void
    resume();
    /// One statistics row (and a reference state, if due).
    void
    record_statistics();
    void
    refine_mesh();
    std::string
    write_checkpoint();
    /// A step failed and cannot be retried: checkpoint the last good state
    /// and stop with a message.
    [[noreturn]] void
    stop_after_failed_step(const bool finite);

    GlobalParameters             parameters;
    const MPI_Comm               comm;
    ConditionalOStream           pcout;
    std::unique_ptr<TimerOutput> timer;

    TimeIntegrationParameters             time_integration;
    SimulationControl                     control;
    const Scheme                         *scheme = nullptr;
    std::unique_ptr<DiscreteProblem<dim>> problem;
    std::unique_ptr<Scene<dim>>           scene;

    /// What follows the present step (output, refinement, checkpoint).
    StepMoments moments;
    double      step_wall_time = 0.;
    bool        outputs_open   = false;

    std::unique_ptr<MeshAdaptor<dim>>          mesh_adaptor;
    std::unique_ptr<Postprocess::Manager<dim>> postprocessors;
    std::unique_ptr<VtuWriter<dim>>            vtu_writer;
    std::unique_ptr<ReferenceStates<dim>>      reference_states;
    Checkpoints                                checkpoints;
    std::unique_ptr<OutputDirectory>           output_directory;
    std::unique_ptr<Progress>                  progress;
    RunReport<dim>                             run_report;
    Timer                                      run_clock, loop_clock;

    friend class SimulatorAccess<dim>;
  };
} // namespace dyncontact

#endif
