// A traction of its own per boundary tag (Scene/Gmsh/Neumann tractions): a
// free block [0, 1] x [0, 0.5] (no support), its top (tag 11, length 1)
// pulled by (0, -2) Pa and its left side (tag 12, length 0.5) by (3, 0)
// Pa. The total force (1.5, -2) N/m changes the momentum by exactly
// t (1.5, -2) (the stiffness moves no momentum), which a traction applied
// to the wrong tag or to both would break. A tag listed twice, a tag also
// in Neumann tags, a tag not in the mesh and an item without ':' are
// refused naming the entry.

#include <cmath>

#include "tests.h"

int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);
  using namespace testing;
  write_block_msh("block.msh", {{0, 1, 0, 0.5, 8, 4, 1, 10, 11, 12}});
  const auto prm = [](const std::string &entries) {
    return "set Dimension = 2\nset Output directory = results-tractions\n" +
           scene_prm("gmsh", "    set Mesh file = block.msh\n" + entries) +
           "subsection Material\n  set Young's modulus = 100\nend\n"
           "subsection Time integration\n  set Scheme = N-CS++\n"
           "  set Time step = 0.01\n  set End time = 0.1\nend\n"
           "subsection Output\n  set Write vtu = false\nend\n";
  };
  const Statistics s = run(
    tight_steps() + prm("    set Neumann tractions = 11: 0, -2; 12: 3, 0\n"));
  const double t  = s.column("time").back();
  const double px = s.column("momentum_x").back();
  const double py = s.column("momentum_y").back();
  log() << "momentum at t = " << fmt(t) << " s: (" << fmt(px, 6) << ", "
        << fmt(py, 6) << "), exact (" << fmt(1.5 * t, 6) << ", "
        << fmt(-2. * t, 6) << "): "
        << check(std::abs(px - 1.5 * t) <= 1e-12 &&
                 std::abs(py + 2. * t) <= 1e-12)
        << "\n";

  const std::vector<std::pair<std::string, std::string>> cases = {
    {"    set Neumann tractions = 11: 0, -2; 11: 1, 0\n",
     "tag 11 has a traction already"},
    {"    set Neumann tractions = 11: 0, -2\n    set Neumann tags = 11\n",
     "tag 11 has a traction already"},
    {"    set Neumann tractions = 13: 0, -2\n",
     "Scene/Gmsh/Neumann tractions: the mesh file"},
    {"    set Neumann tractions = 11 0, -2\n", "is no 'tag: components'"}};
  for (const auto &[entries, fragment] : cases)
    log() << "refused: " << entries.substr(4, entries.find('\n') - 4) << ": "
          << check(error_of(prm(entries)).find(fragment) != std::string::npos)
          << "\n";
}
