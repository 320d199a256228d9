#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <dyncontact/base/collective_errors.h>
#include <dyncontact/discretization/semi_discrete_system.h>
#include <dyncontact/output/reference_states.h>
#include <dyncontact/time_stepping/simulation_control.h>

#include <cmath>
#include <filesystem>
#include <fstream>

namespace dyncontact
{
  namespace
  {
    std::string
    state_file(const std::string &directory,
               const unsigned int index,
               const unsigned int rank)
    {
      return directory + "/state_" + Utilities::int_to_string(index, 5) + "." +
             std::to_string(rank) + ".bin";
    }
  } // namespace



  template <int dim>
  void
  ReferenceStates<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Reference solution");
    prm.declare_entry("Write states",
                      "false",
                      Patterns::Bool(),
                      "Write u and udot every 'Interval' to 'Directory', as "
                      "the reference for other runs on the same mesh.");
    prm.declare_entry("Compare with states",
                      "false",
                      Patterns::Bool(),
                      "Read the states of a reference run (same mesh, same "
                      "number of MPI ranks) from 'Directory' every "
                      "'Interval' and report the error in the physical "
                      "energy norm against them (column error_reference).");
    prm.declare_entry("Directory",
                      "reference",
                      Patterns::Anything(),
                      "Folder of the reference states.");
    prm.declare_entry("Interval",
                      "0.1",
                      Patterns::Double(0.),
                      "Time between two reference states, in s (> 0; a "
                      "multiple of a fixed Time step; with Time step control "
                      "= adaptive the steps end at its multiples).");
    prm.leave_subsection();
  }



  template <int dim>
  void
  ReferenceStates<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Reference solution");
    write_states   = prm.get_bool("Write states");
    compare_states = prm.get_bool("Compare with states");
    directory      = prm.get("Directory");
    interval       = prm.get_double("Interval");
    prm.leave_subsection();
    AssertThrow(!(write_states && compare_states),
                ExcMessage("Reference solution: a run either writes states "
                           "or compares with them, not both."));
    AssertThrow(interval > 0.,
                ExcMessage("Reference solution/Interval must be > 0 (s)."));
  }



  template <int dim>
  void
  ReferenceStates<dim>::constrain(SimulationControl &control,
                                  const bool         adaptive_mesh) const
  {
    if (!write_states && !compare_states)
      return;
    AssertThrow(!adaptive_mesh,
                ExcMessage(
                  "Reference solutions need the same mesh in both "
                  "runs: they cannot be combined with adaptive "
                  "meshes (Mesh refinement/Refinement interval > 0)."));
    control.require_multiples_of(interval, "Reference solution/Interval");
  }



  template <int dim>
  int
  ReferenceStates<dim>::reference_index(const double time) const
  {
    // only at (numerically) multiples of the interval
    const double       k     = time / interval;
    const unsigned int index = std::lround(k);
    return std::abs(k - index) > 1e-6 ? -1 : int(index);
  }



  template <int dim>
  void
  ReferenceStates<dim>::write(const double time) const
  {
    const int index = reference_index(time);
    if (!write_states || index < 0)
      return;
    const MPI_Comm                 comm   = this->get_mpi_communicator();
    const SemiDiscreteSystem<dim> &system = this->get_system();
    const VectorType              &u      = this->get_solution();
    const VectorType              &udot   = this->get_velocity();
    const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
    const std::string  file = state_file(directory, index, rank);
    if (rank == 0)
      std::filesystem::create_directories(directory);
    MPI_Barrier(comm);
    std::ofstream       out(file, std::ios::binary);
    const unsigned long n     = system.locally_owned_dofs().n_elements();
    const unsigned long total = system.get_dof_handler().n_dofs();
    out.write(reinterpret_cast<const char *>(&total), sizeof(total));
    out.write(reinterpret_cast<const char *>(&n), sizeof(n));
    for (const auto i : system.locally_owned_dofs())
      {
        const unsigned long index_    = i;
        const double        values[2] = {u(i), udot(i)};
        out.write(reinterpret_cast<const char *>(&index_), sizeof(index_));
        out.write(reinterpret_cast<const char *>(values), sizeof(values));
      }
    out.close();
    // (on every rank: a rank that stopped alone would leave the others
    // waiting)
    stop_with_any_message(out.good() ?
                            "" :
                            "Cannot write the reference state '" + file + "'.",
                          comm);
  }



  template <int dim>
  double
  ReferenceStates<dim>::error(const double time) const
  {
    const int index = reference_index(time);
    if (!compare_states || index < 0)
      return std::nan("");

    const MPI_Comm                 comm          = this->get_mpi_communicator();
    const SemiDiscreteSystem<dim> &system        = this->get_system();
    const auto                    &locally_owned = system.locally_owned_dofs();
    const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
    const std::string  file = state_file(directory, index, rank);
    std::ifstream      in(file, std::ios::binary);
    AssertThrow(in.good(),
                ExcMessage(
                  "Reference solution: there is no reference state '" + file +
                  "' (a reference run on the same mesh and number of "
                  "MPI ranks, with the same Interval, must write it)."));
    unsigned long total = 0, n = 0;
    in.read(reinterpret_cast<char *>(&total), sizeof(total));
    in.read(reinterpret_cast<char *>(&n), sizeof(n));
    AssertThrow(total == system.get_dof_handler().n_dofs() &&
                  n == locally_owned.n_elements(),
                ExcMessage("Reference solution: the state '" + file +
                           "' belongs to a different mesh or partition (" +
                           std::to_string(total) + " DoFs, here " +
                           std::to_string(system.get_dof_handler().n_dofs()) +
                           ")."));
    VectorType e(this->get_solution()), edot(this->get_velocity());
    for (unsigned long j = 0; j < n; ++j)
      {
        unsigned long index_;
        double        values[2];
        in.read(reinterpret_cast<char *>(&index_), sizeof(index_));
        in.read(reinterpret_cast<char *>(values), sizeof(values));
        AssertThrow(in.good() && locally_owned.is_element(index_),
                    ExcMessage("Reference solution: the state '" + file +
                               "' does not match this mesh's partition."));
        e(index_) -= values[0];
        edot(index_) -= values[1];
      }
    // (subtracted: added to locally owned entries)
    e.compress(VectorOperation::add);
    edot.compress(VectorOperation::add);
    VectorType tmp(e);
    system.matrices().mass_vmult(tmp, edot);
    double error2 = 0.5 * (tmp * edot);
    system.stiffness_vmult(tmp, e);
    error2 += 0.5 * (tmp * e);
    return std::sqrt(std::max(error2, 0.));
  }

  template class ReferenceStates<2>;
  template class ReferenceStates<3>;
} // namespace dyncontact
