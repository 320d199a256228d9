#ifndef dyncontact_core_simulator_access_h
#define dyncontact_core_simulator_access_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/trilinos_vector.h>

namespace dyncontact
{
  using namespace dealii;
  using VectorType = TrilinosWrappers::MPI::Vector;

  template <int dim>
  class Simulator;
  template <int dim>
  class Scene;
  template <int dim>
  class SemiDiscreteSystem;
  template <int dim>
  class ContactSetup;
  template <int dim>
  class MeshAdaptor;
  template <int dim>
  class ReferenceStates;
  class TimeIntegrator;
  class SimulationControl;
  struct Statistics;
  struct StepReport;
  struct StepMoments;
  struct MeshTransfer;
  struct GlobalParameters;
  struct TimeIntegrationParameters;

  /**
   * One read-only view of the simulation's state for every component that
   * needs it (postprocessors, refinement criteria, output), as ASPECT's
   * SimulatorAccess: a component derives from it and is given the simulator
   * once with initialize_simulator(); nothing is a friend or a member of
   * Simulator but this class.
   */
  template <int dim>
  class SimulatorAccess
  {
  public:
    virtual ~SimulatorAccess() = default;

    /// Gives this object access to @p simulator.
    virtual void
    initialize_simulator(const Simulator<dim> &simulator);

    MPI_Comm
    get_mpi_communicator() const;

    const ConditionalOStream &
    get_pcout() const;

    /// The timer, for TimerOutput::Scope sections of the component.
    TimerOutput &
    get_timer() const;

    const GlobalParameters &
    get_parameters() const;

    /// The entries of subsection 'Time integration'.
    const TimeIntegrationParameters &
    get_time_integration() const;

    const Scene<dim> &
    get_scene() const;

    /// p4est's triangulation, or deal.II's serial one
    /// (Mesh/Triangulation).
    const Triangulation<dim> &
    get_triangulation() const;

    const Mapping<dim> &
    get_mapping() const;

    /// DoFs, constraints, M, A, B, f, w of the current mesh.
    const SemiDiscreteSystem<dim> &
    get_system() const;

    /// The contact rows of the current mesh and their operator.
    const ContactSetup<dim> &
    get_contact() const;

    const TimeIntegrator &
    get_integrator() const;

    /// Step number, time, tau (its bounds, its counts of events and
    /// retries).
    const SimulationControl &
    get_control() const;

    /// The statistics table so far (every row on every rank).
    const Statistics &
    get_statistics() const;

    /// u^n and udot^n after the last step.
    const VectorType &
    get_solution() const;
    const VectorType &
    get_velocity() const;

    /// u^{n-1}: the displacement before the last step.
    const VectorType &
    get_old_solution() const;

    /// What the last step (or the initial velocity, at step 0) reported.
    const StepReport &
    get_step_report() const;

    /// What follows the last step: output, refinement, checkpoint, the end
    /// (all false before the first step).
    const StepMoments &
    get_moments() const;

    /// What the transfers to adapted meshes did since the last statistics
    /// row.
    const MeshTransfer &
    get_mesh_transfer() const;

    /// Wall time of the last step, in s (0 at step 0).
    double
    get_step_wall_time() const;

    const MeshAdaptor<dim> &
    get_mesh_adaptor() const;

    const ReferenceStates<dim> &
    get_reference_states() const;

  private:
    const Simulator<dim> *simulator = nullptr;
  };
} // namespace dyncontact

#endif
