#include <dyncontact/core/simulator.h>
#include <dyncontact/core/simulator_access.h>
#include <dyncontact/mesh_refinement/mesh_adaptor.h>
#include <dyncontact/postprocess/interface.h>

namespace dyncontact
{
  template <int dim>
  void
  SimulatorAccess<dim>::initialize_simulator(const Simulator<dim> &s)
  {
    simulator = &s;
  }

  template <int dim>
  MPI_Comm
  SimulatorAccess<dim>::get_mpi_communicator() const
  {
    return simulator->comm;
  }

  template <int dim>
  const ConditionalOStream &
  SimulatorAccess<dim>::get_pcout() const
  {
    return simulator->pcout;
  }

  template <int dim>
  TimerOutput &
  SimulatorAccess<dim>::get_timer() const
  {
    return *simulator->timer;
  }

  template <int dim>
  const GlobalParameters &
  SimulatorAccess<dim>::get_parameters() const
  {
    return simulator->parameters;
  }

  template <int dim>
  const TimeIntegrationParameters &
  SimulatorAccess<dim>::get_time_integration() const
  {
    return simulator->time_integration;
  }

  template <int dim>
  const Scene<dim> &
  SimulatorAccess<dim>::get_scene() const
  {
    return *simulator->scene;
  }

  template <int dim>
  const Triangulation<dim> &
  SimulatorAccess<dim>::get_triangulation() const
  {
    return simulator->problem->get_triangulation();
  }

  template <int dim>
  const Mapping<dim> &
  SimulatorAccess<dim>::get_mapping() const
  {
    return simulator->problem->get_mapping();
  }

  template <int dim>
  const SemiDiscreteSystem<dim> &
  SimulatorAccess<dim>::get_system() const
  {
    return simulator->problem->get_system();
  }

  template <int dim>
  const ContactSetup<dim> &
  SimulatorAccess<dim>::get_contact() const
  {
    return simulator->problem->get_contact();
  }

  template <int dim>
  const Statistics &
  SimulatorAccess<dim>::get_statistics() const
  {
    return simulator->postprocessors->get_statistics();
  }

  template <int dim>
  const StepMoments &
  SimulatorAccess<dim>::get_moments() const
  {
    return simulator->moments;
  }

  template <int dim>
  const MeshTransfer &
  SimulatorAccess<dim>::get_mesh_transfer() const
  {
    return simulator->mesh_adaptor->get_record();
  }

  template <int dim>
  const TimeIntegrator &
  SimulatorAccess<dim>::get_integrator() const
  {
    return simulator->problem->get_integrator();
  }

  template <int dim>
  const SimulationControl &
  SimulatorAccess<dim>::get_control() const
  {
    return simulator->control;
  }

  template <int dim>
  const VectorType &
  SimulatorAccess<dim>::get_solution() const
  {
    return simulator->problem->get_solution();
  }

  template <int dim>
  const VectorType &
  SimulatorAccess<dim>::get_velocity() const
  {
    return simulator->problem->get_velocity();
  }

  template <int dim>
  const VectorType &
  SimulatorAccess<dim>::get_old_solution() const
  {
    return simulator->problem->get_old_solution();
  }

  template <int dim>
  const StepReport &
  SimulatorAccess<dim>::get_step_report() const
  {
    return simulator->problem->get_report();
  }

  template <int dim>
  double
  SimulatorAccess<dim>::get_step_wall_time() const
  {
    return simulator->step_wall_time;
  }

  template <int dim>
  const MeshAdaptor<dim> &
  SimulatorAccess<dim>::get_mesh_adaptor() const
  {
    return *simulator->mesh_adaptor;
  }

  template <int dim>
  const ReferenceStates<dim> &
  SimulatorAccess<dim>::get_reference_states() const
  {
    return *simulator->reference_states;
  }

  template class SimulatorAccess<2>;
  template class SimulatorAccess<3>;
} // namespace dyncontact
