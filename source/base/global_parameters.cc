#include <deal.II/base/parameter_handler.h>

#include <dyncontact/base/global_parameters.h>

namespace dyncontact
{
  using namespace dealii;

  void
  GlobalParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Dimension",
                      "2",
                      Patterns::Integer(2, 3),
                      "Space dimension of the simulation: 2 or 3.");
    prm.declare_entry("Output directory",
                      "results",
                      Patterns::Anything(),
                      "Folder for the VTU/PVTU/PVD files and statistics.tsv; "
                      "created if missing, relative to the working directory.");
    prm.declare_entry(
      "Polynomial degree",
      "1",
      Patterns::Integer(1, 4),
      "Degree p of the displacement space FE_Q(p)^dim, 1 to 4.");
    prm.enter_subsection("Mesh");
    prm.declare_entry("Initial global refinements",
                      "0",
                      Patterns::Integer(0, 12),
                      "Number of global refinements of the scene's coarse "
                      "mesh, 0 to 12.");
    prm.declare_entry(
      "Triangulation",
      "distributed",
      Patterns::Selection("distributed|serial"),
      "Which triangulation holds the mesh. 'distributed': p4est's "
      "(parallel::distributed::Triangulation), on any number of MPI ranks. "
      "'serial': deal.II's Triangulation, on one rank only; it marks and "
      "balances as p4est does (the same meshes in the tests, the results "
      "to the solver's tolerance), and refines and coarsens with the "
      "transfer in 2.6-6 times less time than p4est in 2D, 1.5-7 in 3D "
      "(doc/results.md, 'Cost of a mesh adaptation'). Its checkpoints "
      "resume with 'serial' on one rank.");
    prm.leave_subsection();
  }



  void
  GlobalParameters::parse_parameters(ParameterHandler &prm)
  {
    dimension        = prm.get_integer("Dimension");
    output_directory = prm.get("Output directory");
    degree           = prm.get_integer("Polynomial degree");
    AssertThrow(!output_directory.empty(),
                ExcMessage("Output directory must not be empty."));
    // 'results/' is 'results' (the paths in messages and in summary.txt
    // have no '//'); '/' stays
    while (output_directory.size() > 1 && output_directory.back() == '/')
      output_directory.pop_back();
    prm.enter_subsection("Mesh");
    initial_refinements  = prm.get_integer("Initial global refinements");
    serial_triangulation = prm.get("Triangulation") == "serial";
    prm.leave_subsection();
  }
} // namespace dyncontact
