// The gmsh scene: the shipped example prm/gmsh_two_blocks.prm (two blocks
// meshed separately in Gmsh, the upper one dropping onto the clamped lower
// one) runs: contact begins when the gap closes (g/v = 0.1 s), E_total +
// dissipation never increases, nothing penetrates, the upper block bounces.
// Meshes whose physical tags do not match the prm, a missing or corrupt mesh
// file, and two bodies sharing a vertex stop the executable with a clear
// message and a non-zero exit status.

#include <filesystem>

#include "tests.h"

int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);
  using namespace testing;

  const std::string example =
    std::string(DYNCONTACT_PRM_DIR) + "/gmsh_two_blocks.prm";
  std::ifstream     in(example);
  std::stringstream prm;
  prm << in.rdbuf() << "\nset Output directory = results-gmsh\n"
      << "subsection Output\n  set Write vtu = false\nend\n";
  const Statistics s =
    dyncontact::run_simulation(prm.str(), MPI_COMM_WORLD, example);
  const auto [begin, end] = contact_interval(s);
  log() << "example: contact begins at " << fmt(begin, 3)
        << " (gap/v = 0.1): " << check(std::abs(begin - 0.1) <= 2 * 0.0025)
        << "\n";
  log() << "  E_total + dissipation non-increasing: "
        << check(max_energy_increase(s) <= 1e-10 * s.column("energy_total")[0])
        << "\n";
  log() << "  no penetration: "
        << check(max_of(s.column("max_penetration")) < 1e-12) << "\n";
  log() << "  the upper block bounces: "
        << check(s.column("momentum_y_body2").back() > 0.) << "\n";

  // bad meshes and tags, given to the executable
  const std::string mesh =
    std::string(DYNCONTACT_PRM_DIR) + "/meshes/two_blocks.msh";
  std::ofstream("corrupt.msh") << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
                                  "$Nodes\nthis is not a mesh\n";
  // two quadrilaterals sharing an edge, tags 1 and 2
  std::ofstream("shared.msh")
    << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n6\n"
    << "1 0 0 0\n2 1 0 0\n3 2 0 0\n4 0 1 0\n5 1 1 0\n6 2 1 0\n$EndNodes\n"
    << "$Elements\n2\n1 3 2 1 1 1 2 5 4\n2 3 2 2 2 2 3 6 5\n$EndElements\n";
  const std::vector<std::pair<std::string, std::string>> cases = {
    {"unknown_body_tag", "  set Body 2 tags = 3\n"},
    {"cells_without_body",
     "  set Body 2 tags =\n"
     "  set Contact tags of body 1 =\n"
     "  set Contact tags of body 2 =\n"},
    {"contact_tag_missing", "  set Contact tags of body 2 = 99\n"},
    {"dirichlet_tag_missing", "  set Dirichlet tags = 77\n"},
    {"neumann_tag_missing", "  set Neumann tags = 55\n"},
    {"missing_mesh_file", "  set Mesh file = no_such_file.msh\n"},
    {"corrupt_mesh_file", "  set Mesh file = corrupt.msh\n"},
    {"bodies_share_a_vertex",
     "  set Mesh file = shared.msh\n"
     "  set Contact tags of body 1 =\n"
     "  set Contact tags of body 2 =\n"
     "  set Dirichlet tags =\n"},
    {"bad_velocity", "  set Initial velocity of body 2 = 1\n"},
    {"twisted_cell",
     "  set Mesh file = twisted.msh\n"
     "  set Contact tags of body 1 =\n"
     "  set Contact tags of body 2 =\n"
     "  set Dirichlet tags =\n"},
  };
  // two quadrilaterals, the first with its vertices in a twisted order
  std::ofstream("twisted.msh")
    << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n8\n"
    << "1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n5 0 2 0\n6 1 2 0\n7 1 3 0\n"
    << "8 0 3 0\n$EndNodes\n$Elements\n2\n1 3 2 1 1 1 2 4 3\n"
    << "2 3 2 2 2 5 6 7 8\n$EndElements\n";
  for (const auto &[name, text] : cases)
    {
      std::ofstream(name + ".prm")
        << "set Dimension = 2\nset Output directory = results-" << name
        << "\nsubsection Scene\n  set Name = gmsh\n  subsection Gmsh\n"
        << "  set Mesh file = " << mesh << "\n"
        << "  set Body 1 tags = 1\n  set Body 2 tags = 2\n"
        << "  set Dirichlet tags = 10\n  set Contact tags of body 1 = 11\n"
        << "  set Contact tags of body 2 = 12\n"
        << text << "end\nend\n"
        << "subsection Contact\n  set Search radius = 0.2\nend\n"
        << "subsection Time integration\n"
        << "  set End time = 0.01\n  set Time step = 0.005\nend\n";
      const Outcome outcome = run_program(name + ".prm");
      std::string   message = outcome.text.substr(
        std::min(outcome.text.find("dyncontact: error:"), outcome.text.size()));
      // the mesh's absolute path differs between machines
      for (std::size_t p; (p = message.find(mesh)) != std::string::npos;)
        message.replace(p, mesh.size(), "two_blocks.msh");
      log() << name << ": exit status non-zero: " << check(outcome.status != 0)
            << ", clean message: "
            << check(!message.empty() &&
                     outcome.text.find("Stacktrace") == std::string::npos)
            << "\n"
            << message << "\n";
    }

  // a failing input leaves the previous output in its directory alone
  std::ifstream     before_in("results-gmsh/statistics.tsv");
  std::stringstream before;
  before << before_in.rdbuf();
  std::ofstream("overwrite.prm")
    << "set Dimension = 2\nset Output directory = results-gmsh\n"
    << testing::scene_prm("gmsh", "    set Mesh file = corrupt.msh\n");
  const Outcome     failed = run_program("overwrite.prm");
  std::ifstream     after_in("results-gmsh/statistics.tsv");
  std::stringstream after;
  after << after_in.rdbuf();
  log() << "a failing run leaves the previous statistics.tsv alone: "
        << check(failed.status != 0 && !before.str().empty() &&
                 before.str() == after.str())
        << "\n";
}
