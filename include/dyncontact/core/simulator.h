#ifndef dyncontact_core_simulator_h
#define dyncontact_core_simulator_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/fe/mapping_q1.h>

#include <dyncontact/base/global_parameters.h>
#include <dyncontact/base/statistics.h>
#include <dyncontact/contact/active_set_solver.h>
#include <dyncontact/core/simulator_access.h>
#include <dyncontact/mesh_refinement/mesh_transfer.h>
#include <dyncontact/output/checkpoint.h>
#include <dyncontact/output/run_report.h>
#include <dyncontact/time_stepping/integrators.h>
#include <dyncontact/time_stepping/simulation_control.h>
#include <dyncontact/time_stepping/time_step_controller.h>

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
   * The time loop, and nothing else: it builds the scene's mesh, asks the
   * components to set themselves up on it, and steps. What happens in a
   * step, to the statistics, the output, the mesh and the checkpoints is
   * each one component's job:
   *
   * - SimulationControl: time, tau, output and checkpoint moments, retries;
   * - SemiDiscreteSystem: DoFs, constraints, M, A, B, f, w, state transfer;
   * - ContactSetup: the constraint rows (obstacle or phi_h);
   * - TimeIntegrator: the scheme (N-CI, N-CS, N-CS++, static) and its
   *   active-set solvers;
   * - Postprocess::Manager: the statistics (plugins);
   * - MeshAdaptor: when and where the mesh adapts (criteria are plugins);
   * - VtuWriter, ReferenceStates, Checkpoints: output.
   *
   * Components read the state through SimulatorAccess; each declares its own
   * parameters (declare_all_parameters() collects them).
   */
  template <int dim>
  class Simulator
  {
  public:
    /// Reads every component's parameters from @p prm (already parsed);
    /// relative file names refer to @p input_directory.
    Simulator(ParameterHandler  &prm,
              const std::string &input_directory,
              const MPI_Comm     comm);

    ~Simulator();

    /// Runs the whole simulation; returns the statistics (on all ranks).
    Statistics
    run();

  private:
    void
    run_time_loop();
    void
    build_mesh();
    /// DoFs, matrices and contact rows on the current mesh.
    void
    setup_discretization();
    void
    make_integrator();
    /// Warns once if S = M + tau^2/4 A + tau/2 B keeps the mass only to a
    /// poor relative accuracy.
    void
    check_inertia();
    /// One step from (u, udot) = (u_old, udot_old): trial steps with the
    /// TimeStepController's tau until it accepts one (it retries after a
    /// failed solve, a located contact event, an error estimate above the
    /// tolerance); returns the accepted step's tau.
    TimeStepController::AcceptedStep
    take_step();
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

    /// tau (declared before the control, which reads it)
    TimeStepController          time_step_controller;
    SimulationControl           control;
    const Scheme               &scheme;
    ActiveSetSolver::Parameters solver_parameters;
    std::unique_ptr<Scene<dim>> scene;

    parallel::distributed::Triangulation<dim> triangulation;
    MappingQ1<dim>                            mapping;
    std::unique_ptr<SemiDiscreteSystem<dim>>  system;
    std::unique_ptr<ContactSetup<dim>>        contact;
    std::unique_ptr<TimeIntegrator>           integrator;

    VectorType u, udot, u_old, udot_old;
    StepReport report, initial_report;
    /// What follows the present step (output, refinement, checkpoint).
    StepMoments moments;
    /// What the transfers to adapted meshes did since the last row.
    MeshTransfer mesh_transfer;
    double       step_wall_time = 0.;
    bool         outputs_open   = false;
    bool         warned_inertia = false;
    /// step matrices S built by the integrators of earlier meshes
    unsigned int n_step_matrices = 0;

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
