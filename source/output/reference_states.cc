#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <dyncontact/base/checksum.h>
#include <dyncontact/base/collective_errors.h>
#include <dyncontact/base/triangulation.h>
#include <dyncontact/discretization/semi_discrete_system.h>
#include <dyncontact/output/reference_states.h>
#include <dyncontact/output/state_comparison.h>
#include <dyncontact/scenes/interface.h>
#include <dyncontact/time_stepping/simulation_control.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>

namespace dyncontact
{
  namespace
  {
    std::string
    state_file(const std::string &directory, const unsigned int index)
    {
      return directory + "/state_" + Utilities::int_to_string(index, 5);
    }

    /// The coarse mesh in a word: its number of cells and the sum of its
    /// vertices' coordinates (states of one coarse mesh agree in both).
    template <int dim>
    std::string
    coarse_signature(const Triangulation<dim> &triangulation)
    {
      double sum = 0.;
      for (const auto &cell : triangulation.cell_iterators_on_level(0))
        for (const auto v : cell->vertex_indices())
          for (unsigned int d = 0; d < dim; ++d)
            sum += cell->vertex(v)[d];
      std::ostringstream out;
      out << triangulation.n_cells(0) << "/" << std::setprecision(8) << sum;
      return out.str();
    }


    /// The checksums of a mesh's files (p4est's file and its .info, or the
    /// serial triangulation's one file).
    std::string
    mesh_files_checksum(const std::string &file)
    {
      return checksum_of_file(file) + "/" + checksum_of_file(file + ".info");
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
                      "Write the mesh, u and udot every 'Interval' to "
                      "'Directory' (removing the states an earlier run left "
                      "there), as the reference for other runs on this mesh "
                      "or a coarser one of the same coarse mesh.");
    prm.declare_entry("Compare with states",
                      "false",
                      Patterns::Bool(),
                      "Read the states of a reference run (on this run's "
                      "mesh or a refinement of it, any degree, any number of "
                      "MPI ranks, the same Mesh/Triangulation) from "
                      "'Directory' every 'Interval' and report the error in "
                      "the physical energy norm against them (column "
                      "error_reference).");
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
  ReferenceStates<dim>::constrain(SimulationControl &control) const
  {
    if (!write_states && !compare_states)
      return;
    AssertThrow(control.is_static_problem() ||
                  interval <= control.get_end_time() * (1. + 1e-12),
                ExcMessage("Reference solution/Interval (now " +
                           std::to_string(interval) +
                           " s) is longer than Time integration/End time (" +
                           std::to_string(control.get_end_time()) +
                           " s): no state but the initial one would be "
                           "written or compared."));
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
    const std::string              file   = state_file(directory, index);
    const bool  root   = Utilities::MPI::this_mpi_process(comm) == 0;
    const bool  serial = as_distributed(this->get_triangulation()) == nullptr;
    std::string error;
    // the first state: the folder made, and the states of an earlier
    // reference run in it removed (a comparison would take them for this
    // run's)
    if (!mesh_changed && root)
      {
        std::error_code failure;
        std::filesystem::create_directories(directory, failure);
        if (!std::filesystem::is_directory(directory))
          error = "Reference solution/Directory = '" + directory +
                  "' is no folder that can be made or written.";
        else
          for (const auto &entry :
               std::filesystem::directory_iterator(directory, failure))
            {
              // (of this time and later: a resumed run keeps its states
              // before the checkpoint)
              const std::string name = entry.path().filename().string();
              for (const std::string prefix : {"state_", "mesh_"})
                if (name.rfind(prefix, 0) == 0 &&
                    std::atoi(name.substr(prefix.size(), 5).c_str()) >= index)
                  std::filesystem::remove(entry.path(), failure);
            }
      }
    stop_with_any_message(error, comm);
    // the mesh once, and again after each change of it
    if (!mesh_changed)
      {
        mesh_changed = std::make_shared<bool>(true);
        this->get_triangulation().signals.any_change.connect(
          [flag = mesh_changed]() { *flag = true; });
      }
    if (*mesh_changed)
      {
        mesh_name = "mesh_" + Utilities::int_to_string(index, 5);
        write_state_file(directory + "/" + mesh_name,
                         system.get_dof_handler(),
                         {});
        *mesh_changed = false;
        if (root)
          mesh_checksum = mesh_files_checksum(directory + "/" + mesh_name);
      }
    const std::string values =
      file + ".values." +
      std::to_string(Utilities::MPI::this_mpi_process(comm));
    StateComparison<dim>::write_values(values,
                                       system.get_dof_handler(),
                                       system.ghosted(this->get_solution()),
                                       system.ghosted(this->get_velocity()));
    const std::vector<std::string> checksums =
      Utilities::MPI::gather(comm, checksum_of_file(values));
    if (root)
      {
        std::ofstream info(file + ".header");
        info << "dyncontact state 4\ndimension " << dim << "\ndegree "
             << system.get_fe().degree << "\ncoarse "
             << coarse_signature(this->get_triangulation())
             << "\ntriangulation " << (serial ? "serial" : "distributed")
             << "\nmesh " << mesh_name << "\nmesh_checksum " << mesh_checksum
             << "\nranks " << Utilities::MPI::n_mpi_processes(comm) << "\ntime "
             << std::setprecision(17) << time << '\n';
        for (unsigned int r = 0; r < checksums.size(); ++r)
          info << "values_checksum." << r << ' ' << checksums[r] << '\n';
        info.close();
        if (!info.good())
          error = "Cannot write the reference state '" + file +
                  ".header' (Reference solution/Directory = '" + directory +
                  "').";
      }
    stop_with_any_message(error, comm);
  }



  template <int dim>
  double
  ReferenceStates<dim>::error(const double time) const
  {
    const int index = reference_index(time);
    if (!compare_states || index < 0)
      return std::nan("");

    const MPI_Comm                 comm   = this->get_mpi_communicator();
    const SemiDiscreteSystem<dim> &system = this->get_system();
    const std::string              file   = state_file(directory, index);
    // the header, read on every rank (a small text file)
    std::ifstream info(file + ".header");
    AssertThrow(info.good(),
                ExcMessage("Reference solution: there is no reference state '" +
                           file +
                           ".header' (a reference run with Write states = true "
                           "and the same Interval writes it)."));
    std::map<std::string, std::string> header;
    for (std::string line; std::getline(info, line);)
      {
        const auto space = line.find(' ');
        if (space != std::string::npos)
          header[line.substr(0, space)] = line.substr(space + 1);
      }
    const std::string coarse = coarse_signature(this->get_triangulation());
    AssertThrow(header.count("degree") && header.count("mesh") &&
                  header.count("ranks") && header.count("time") &&
                  header.count("triangulation") &&
                  header.count("mesh_checksum") && header.count("dimension") &&
                  header.count("coarse"),
                ExcMessage("Reference solution: '" + file +
                           ".header' is not the header of a reference state "
                           "of this program (written by an older version? "
                           "run the reference again)."));
    AssertThrow(
      header["dimension"] == std::to_string(dim) && header["coarse"] == coarse,
      ExcMessage("Reference solution: the state '" + file +
                 "' belongs to another coarse mesh (" + header["dimension"] +
                 "D, coarse mesh " + header["coarse"] +
                 "; this run: " + std::to_string(dim) + "D, " + coarse +
                 "): reference and run must refine the same "
                 "coarse mesh."));
    const std::string triangulation =
      as_distributed(this->get_triangulation()) == nullptr ? "serial" :
                                                             "distributed";
    AssertThrow(header["triangulation"] == triangulation,
                ExcMessage("Reference solution: the state '" + file +
                           "' was written with Mesh/Triangulation = " +
                           header["triangulation"] + ", this run has " +
                           triangulation +
                           ": reference and run must use the same."));
    AssertThrow(std::abs(std::atof(header["time"].c_str()) - time) <=
                  1e-9 * std::max(1., std::abs(time)),
                ExcMessage(
                  "Reference solution: the state '" + file +
                  "' was written at t = " + header["time"] +
                  " s, this run compares it at t = " + std::to_string(time) +
                  " s: reference and run must have the same "
                  "Interval."));
    const std::string mesh_file = directory + "/" + header["mesh"];
    if (mesh_file != checked_mesh)
      {
        AssertThrow(std::filesystem::is_regular_file(mesh_file) &&
                      mesh_files_checksum(mesh_file) == header["mesh_checksum"],
                    ExcMessage("Reference solution: the mesh file '" +
                               mesh_file + "' of the state '" + file +
                               "' is missing or damaged (its checksum differs "
                               "from the one written): run the reference "
                               "again."));
        checked_mesh = mesh_file;
      }
    std::vector<std::string> values_checksums;
    for (int r = 0; r < std::atoi(header["ranks"].c_str()); ++r)
      values_checksums.push_back(
        header["values_checksum." + std::to_string(r)]);
    if (!comparison)
      {
        auto mesh = make_triangulation<dim>(
          as_distributed(this->get_triangulation()) == nullptr, comm);
        build_mesh(this->get_scene(),
                   *mesh,
                   0,
                   system.get_fe().degree,
                   /*coarse_only=*/true);
        comparison = std::make_unique<StateComparison<dim>>(this->get_scene(),
                                                            this->get_mapping(),
                                                            std::move(mesh));
      }
    return comparison->difference(mesh_file,
                                  file + ".values",
                                  values_checksums,
                                  std::stoi(header["degree"]),
                                  system.get_dof_handler(),
                                  system.ghosted(this->get_solution()),
                                  system.ghosted(this->get_velocity()));
  }



  template <int dim>
  ReferenceStates<dim>::ReferenceStates() = default;



  template <int dim>
  ReferenceStates<dim>::~ReferenceStates() = default;



  template class ReferenceStates<2>;
  template class ReferenceStates<3>;
} // namespace dyncontact
