// Hostile input, by class of failure (a review of the trust in the results):
// include cycles, Gmsh meshes the program cannot use, damaged checkpoints,
// meshes too large for the machine, data outside physical ranges, static
// problems that nothing holds (singular: the message names the free body),
// incompatible options, a locked output directory. Every case runs the program
// with the output directory of an earlier, successful run and must
//  - exit with a non-zero status,
//  - print "dyncontact: error:" with a message that names the parameter or
//    file (a fragment of it is checked), and no backtrace,
//  - leave the earlier run's statistics.tsv as it was, and no lock file.
// The cases, the earlier run and the checkpointed runs they resume run the
// executable's code in this process (testing::run_in_process():
// run_command_line(), what main() runs once MPI has started; a start of the
// executable costs about a second, and there are 94 cases), before the
// first start of the executable (whose end removes this process's Open MPI
// session directory, which MPI-IO needs); the exit status is the one that
// main() would return. The runs after them start the executable itself.
// The messages themselves are not printed (some hold machine-dependent
// figures such as the memory available). Then a few inputs that must run:
// a byte-order mark, a stale lock of a killed run, a viscosity so large
// that the linear solver's tolerance breaks the energy balance (the monitor
// must report it) or that the step matrix cannot hold the mass (a warning
// must say so), a Time step larger than End time (a warning names where
// the last step ends), and a search radius too small for the rows to catch the
// contact (max_penetration must measure how far the bars pass into each
// other, and a warning name the radius).

#include <boost/crc.hpp>

#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <tuple>

#include "tests.h"

namespace
{
  namespace fs = std::filesystem;
  using testing::Outcome;
  using testing::read;
  using testing::run_in_process;
  using testing::run_program;

  const std::string base = "set Dimension = 2\n"
                           "set Output directory = previous\n"
                           "subsection Time integration\n"
                           "  set End time = 0.05\n"
                           "end\n"
                           "subsection Output\n"
                           "  set Write vtu = false\n"
                           "end\n";

  /// The values of one column of a statistics.tsv file (nan if none).
  std::vector<double>
  column_values(const std::string &file, const std::string &name)
  {
    const auto statistics = testing::read_statistics(file);
    if (!statistics.has_column(name) || statistics.rows.empty())
      return {std::nan("")};
    return statistics.column(name);
  }

  std::string
  bar(const std::string &entries)
  {
    return testing::scene_entries("Bar impact", entries);
  }

  /// The Gmsh scene on mesh @p mesh (the two blocks' tags).
  std::string
  gmsh(const std::string &mesh, const std::string &more = "")
  {
    return testing::scene_prm("gmsh",
                              "    set Mesh file = " + mesh +
                                "\n"
                                "    set Body 1 tags = 1\n"
                                "    set Body 2 tags = 2\n"
                                "    set Dirichlet tags = 10\n"
                                "    set Contact tags of body 1 = 11\n"
                                "    set Contact tags of body 2 = 12\n" +
                                more) +
           "subsection Contact\n  set Search radius = 0.2\nend\n";
  }

  /// The Gmsh scene on the two blocks, as Bodies with Contact pairs @p
  /// pairs (the lower block clamped) and @p more entries.
  std::string
  gmsh_pairs(const std::string &pairs, const std::string &more = "")
  {
    return testing::scene_prm("gmsh",
                              "    set Mesh file = two_blocks.msh\n"
                              "    set Bodies = 1; 2\n"
                              "    set Dirichlet tags = 10\n"
                              "    set Contact tags = 11; 12\n"
                              "    set Contact pairs = " +
                                pairs + "\n" + more) +
           "subsection Contact\n  set Search radius = 0.2\nend\n";
  }

  /// The two blocks' mesh with line @p line (1-based) replaced by @p text.
  void
  edit_mesh(const std::string &file,
            const unsigned int line,
            const std::string &text)
  {
    std::istringstream in(read("two_blocks.msh"));
    std::ofstream      out(file);
    unsigned int       n = 0;
    for (std::string l; std::getline(in, l);)
      out << (++n == line ? text : l) << "\n";
  }
} // namespace

int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);
  using namespace testing;

  // a clean start (the folder may hold a previous run of this test)
  for (const std::string leftover : {"previous",
                                     "ck",
                                     "ck_pristine",
                                     "gmsh_ck",
                                     "edited.msh",
                                     "locked",
                                     "stale",
                                     "viscous",
                                     "viscous_tight",
                                     "special",
                                     "failing",
                                     "grown",
                                     "subnormal",
                                     "pieces",
                                     "unread",
                                     "static_viscous",
                                     "touch"})
    fs::remove_all(leftover);

  // the earlier run whose files must survive every failing case
  std::ofstream("previous.prm") << base;
  log() << "earlier run: exit status zero: "
        << check(run_in_process("previous.prm").status == 0) << "\n";
  const std::string previous = read("previous/statistics.tsv");

  // files for the cases
  fs::copy_file(std::string(DYNCONTACT_PRM_DIR) + "/meshes/two_blocks.msh",
                "two_blocks.msh",
                fs::copy_options::overwrite_existing);
  std::ofstream("self.prm") << "include self.prm\n";
  std::ofstream("self_capitals.prm") << "INCLUDE self_capitals.prm\n";
  std::ofstream("a.prm") << base << "include b.prm\n";
  std::ofstream("b.prm") << "include a.prm\n";
  for (unsigned int k = 0; k < 40; ++k)
    std::ofstream("deep" + std::to_string(k) + ".prm")
      << "include deep" << k + 1 << ".prm\n";
  std::ofstream("deep40.prm") << "\n";
  std::ofstream("included_value.prm")
    << "# a value out of range, in an included file\n"
    << "subsection Time integration\n  set Time step = -1\nend\n";
  std::ofstream("nested.prm") << "# includes another file\n"
                              << "include deep40.prm\n\n";
  std::ofstream("unclosed.prm")
    << "# a subsection that the file does not close\n"
    << "subsection Time integration\n  set Time step = 0.0125\n";
  std::ofstream("included_entry.prm")
    << "# an entry that does not exist, in an included file\n\n"
    << "set Tme step = 1\n";
  fs::create_directories("a_directory.prm");
  fs::create_directories("a_directory.msh");
  std::ofstream("empty.msh");
  std::ofstream("text.msh") << "this is not a mesh\n";
  edit_mesh("triangle.msh", 725, "113 2 2 1 1 1 9 149");
  edit_mesh("prism.msh", 725, "113 6 2 1 1 1 9 149 104 2 3");
  edit_mesh("nan.msh", 10, "5 nan 0.05 0");
  edit_mesh("inf.msh", 10, "5 inf 0.05 0");
  edit_mesh("words.msh", 10, "5 one 0.05 0");
  edit_mesh("missing_node.msh", 725, "113 3 2 1 1 1 9 149 99999");
  edit_mesh("binary.msh", 2, "2.2 1 8");
  edit_mesh("format3.msh", 2, "3.0 0 8");
  edit_mesh("node_count.msh", 5, "99999");
  edit_mesh("no_end_nodes.msh", 610, "$Elements");
  {
    const std::string mesh = read("two_blocks.msh");
    std::ofstream("truncated.msh")
      << mesh.substr(0, mesh.rfind('\n', mesh.size() / 2) + 1);
    std::ofstream("no_elements.msh") << mesh.substr(0, mesh.find("$Elements"));
  }
  // two unit squares, the second moved by (0.5, 0.5): they overlap; or by
  // (1, 0.5): they touch along x = 1
  for (const auto &[name, x, y] :
       std::vector<std::tuple<std::string, double, double>>{
         {"overlap.msh", 0.5, 0.5}, {"touch.msh", 1., 0.5}})
    std::ofstream(name) << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n8\n"
                        << "1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n"
                        << "5 " << x << " " << y << " 0\n6 " << x + 1 << " "
                        << y << " 0\n7 " << x + 1 << " " << y + 1 << " 0\n8 "
                        << x << " " << y + 1 << " 0\n"
                        << "$EndNodes\n$Elements\n2\n1 3 2 1 1 1 2 3 4\n"
                        << "2 3 2 2 2 5 6 7 8\n$EndElements\n";
  std::ofstream("tetrahedron.msh")
    << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n"
       "2 1 0 0\n3 0 1 0\n4 0 0 1\n$EndNodes\n$Elements\n1\n"
       "1 4 2 1 1 1 2 3 4\n$EndElements\n";
  // a lock held by a live process (this test)
  fs::create_directories("locked");
  std::ofstream("locked/.lock")
    << "host-of-this-test " << ::getpid() << "\n"; // another host: alive
  const std::string locked_statistics = "locked/statistics.tsv";
  std::ofstream(locked_statistics) << "step\ttime\n0\t0\n";

  // a checkpointed run: every case below resumes from a copy of it
  std::ofstream("checkpointed.prm")
    << base << "set Output directory = ck\n"
    << "subsection Checkpointing\n  set Interval in steps = 2\nend\n";
  log() << "checkpointed run: exit status zero: "
        << check(run_in_process("checkpointed.prm").status == 0) << "\n";
  const std::string ck_step =
    "ck/checkpoints/" + read("ck/checkpoints/last")
                          .substr(0, read("ck/checkpoints/last").find('\n'));
  const std::string resume =
    base + "set Output directory = ck\n"
           "subsection Checkpointing\n  set Resume = true\nend\n"
           "subsection Time integration\n  set End time = 0.1\nend\n";
  fs::copy("ck", "ck_pristine", fs::copy_options::recursive);

  // a checkpointed Gmsh run, for a mesh edited before the resume
  fs::copy_file("two_blocks.msh", "edited.msh");
  const std::string gmsh_ck =
    base + gmsh("edited.msh") +
    "set Output directory = gmsh_ck\n"
    "subsection Time integration\n  set End time = 0.01\n  set Time step = "
    "0.005\nend\n"
    "subsection Checkpointing\n  set Interval in steps = 1\nend\n";
  std::ofstream("gmsh_ck.prm") << gmsh_ck;
  log() << "checkpointed Gmsh run: exit status zero: "
        << check(run_in_process("gmsh_ck.prm").status == 0) << "\n";

  struct Case
  {
    std::string klass;
    std::string name;
    std::string prm;      // appended to base
    std::string expected; // a fragment of the message
    std::string damage = "";
  };
  const std::string mesh_line = "set Mesh file = ";
  std::vector<Case> cases     = {
        // crashes: include cycles
    {"include", "includes itself", "include self.prm\n", "includes itself"},
    {"include",
         "includes itself, INCLUDE in capitals",
         "INCLUDE self_capitals.prm\n",
         "includes itself"},
    {"include",
         "two files include each other",
         "include a.prm\n",
         "includes itself"},
    {"include",
         "include of a missing file",
         "include nowhere.prm\n",
         "nowhere.prm"},
    {"include",
         "include of a directory",
         "include a_directory.prm\n",
         "a_directory.prm"},
    {"include",
         "41 nested includes",
         "include deep0.prm\n",
         "more than 32 nested"},
    {"include", "include without a name", "include \n", "needs a file name"},
    // messages name the included file's own line, not the expanded text's
    {"include",
         "a bad value in an included file",
         "include included_value.prm\n",
         "Line 3 of 'included_value.prm'"},
    {"include",
         "an unknown entry in an included file",
         "include included_entry.prm\n",
         "Line 3 of 'included_entry.prm'"},
    {"include",
         "an unknown entry after an include, INCLUDE in capitals",
         "INCLUDE nested.prm\nset Tme step = 1\n",
         "Line " + std::to_string(std::count(base.begin(), base.end(), '\n') + 2) +
           " of 'case.prm'"},
    // (until 2026-11-29 reported in the including file, at its end)
    {"include",
         "an unclosed subsection in an included file",
         "include unclosed.prm\n",
         "'unclosed.prm' (included at line 9 of 'case.prm'): 'subsection "
             "Time integration' at its line 2 has no 'end'"},
    // Gmsh meshes
    {"gmsh", "triangles", gmsh("triangle.msh"), "triangles"},
    {"gmsh", "prisms", gmsh("prism.msh"), "prisms"},
    {"gmsh",
         "tetrahedra (3D)",
         "set Dimension = 3\n" + gmsh("tetrahedron.msh"),
         "tetrahedra"},
    {"gmsh", "a directory", gmsh("a_directory.msh"), "a_directory.msh"},
    {"gmsh", "an empty file", gmsh("empty.msh"), "empty.msh' is empty"},
    {"gmsh", "a missing file", gmsh("nowhere.msh"), "nowhere.msh"},
    {"gmsh", "a text file", gmsh("text.msh"), "no $MeshFormat"},
    {"gmsh", "truncated in the middle", gmsh("truncated.msh"), "truncated"},
    {"gmsh", "no $Elements", gmsh("no_elements.msh"), "no $Elements"},
    {"gmsh",
         "$EndNodes missing",
         gmsh("no_end_nodes.msh"),
         "no_end_nodes.msh', line"},
    {"gmsh", "wrong node count", gmsh("node_count.msh"), "node_count.msh'"},
    {"gmsh", "NaN coordinate", gmsh("nan.msh"), "nan.msh', line 10"},
    {"gmsh", "infinite coordinate", gmsh("inf.msh"), "inf.msh', line 10"},
    {"gmsh",
         "a word for a coordinate",
         gmsh("words.msh"),
         "words.msh', line 10"},
    {"gmsh",
         "element with a missing node",
         gmsh("missing_node.msh"),
         "node 99999"},
    {"gmsh", "binary file", gmsh("binary.msh"), "binary .msh"},
    {"gmsh", "format 3", gmsh("format3.msh"), "not supported"},
    {"gmsh",
         "a 2D mesh in 3D",
         "set Dimension = 3\n" + gmsh("two_blocks.msh"),
         "no hexahedra"},
    {"gmsh",
         "contact tag of body 2 on body 1",
         gmsh("two_blocks.msh") +
           testing::scene_entries("Gmsh",
                              "    set Contact tags of body 1 = 12\n"
                                  "    set Contact tags of body 2 = 11\n"),
         "belong to body"},
    {"gmsh",
         "tag that is a word",
         gmsh("two_blocks.msh") +
           testing::scene_entries("Gmsh", "    set Body 2 tags = one\n"),
         "Scene/Gmsh/Body 2 tags"},
    {"gmsh",
         "tag out of range",
         gmsh("two_blocks.msh") +
           testing::scene_entries("Gmsh", "    set Dirichlet tags = 70000\n"),
         "Scene/Gmsh/Dirichlet tags"},
    {"gmsh",
         "a Dirichlet component that is not x or y",
         gmsh("two_blocks.msh") +
           testing::scene_entries("Gmsh", "    set Dirichlet tags = 10: z\n"),
         "Scene/Gmsh/Dirichlet tags: '10: z' names the component 'z'; the "
             "components of a tag (after ':') are letters of 'xy'"},
    {"gmsh",
         "a Dirichlet tag with ':' and no component",
         gmsh("two_blocks.msh") +
           testing::scene_entries("Gmsh", "    set Dirichlet tags = 10:\n"),
         "Scene/Gmsh/Dirichlet tags: '10:' names no component after ':'"},
    {"gmsh",
         "an empty item in Dirichlet tags",
         gmsh("two_blocks.msh") +
           testing::scene_entries("Gmsh", "    set Dirichlet tags = 10,,11: y\n"),
         "Scene/Gmsh/Dirichlet tags has an empty item (two commas in a row, "
             "or one alone) in '10,,11: y'"},
    {"gmsh",
         "a Dirichlet component without its tag",
         gmsh("two_blocks.msh") +
           testing::scene_entries("Gmsh", "    set Dirichlet tags = : y\n"),
         "Scene/Gmsh/Dirichlet tags: ': y' has no tag before ':'"},
    {"gmsh",
         "velocity that is a word",
         gmsh("two_blocks.msh") +
           testing::scene_entries("Gmsh",
                              "    set Initial velocity of body 2 = 0, "
                                  "fast\n"),
         "Scene/Gmsh/Initial velocity of body 2"},
    {"gmsh",
         "a third velocity component in 2D",
         gmsh("two_blocks.msh") +
           testing::scene_entries("Gmsh",
                              "    set Initial velocity of body 2 = 0, "
                                  "0, 5\n"),
         "Initial velocity of body 2 has a third component in 2D"},
    {"gmsh",
         "velocity 1e300",
         gmsh("two_blocks.msh") +
           testing::scene_entries("Gmsh",
                              "    set Initial velocity of body 2 = 1e300, "
                                  "0\n"),
         "Initial velocity of body 2: each component must lie in [-1e+09"},
    // (until 2026-11-29 run, the bodies passing through each other)
    {"gmsh",
         "two bodies in no contact pair that overlap at t = 0",
         scene_prm("gmsh",
               "    set Mesh file = overlap.msh\n    set Body 1 tags = 1\n"
                   "    set Body 2 tags = 2\n"),
         "bodies 1 and 2 overlap at t = 0 (the point (1, 1) of body 1 lies "
             "inside body 2), and no contact pair holds them apart"},
    {"gmsh",
         "contact tags on clamped faces",
         gmsh("two_blocks.msh") +
           testing::scene_entries("Gmsh", "    set Dirichlet tags = 10, 11, 12\n"),
         "lie on a Dirichlet boundary: they get no contact rows"},
    // contact pairs without rows at t = 0 (until 2026-11-29 the bodies
    // passed through each other with exit status zero)
    {"contact",
         "Gmsh: the contact tag of body 1 is its clamped face",
         gmsh("two_blocks.msh") +
           testing::scene_entries("Gmsh", "    set Contact tags of body 1 = 10\n"),
         "has no constraint row at t = 0: all 41 of its slave nodes lie on "
             "a Dirichlet boundary"},
    {"contact",
         "two bars whose search radius is below their gap",
         scene_prm("two bars") +
           "subsection Contact\n  set Search radius = 0.01\nend\n",
         "lies within the search radius (0.01 m) of a master face"},
    // (until 2026-11-29 refused as bodies that overlap "0.55 m inside the
    // other body", with advice pointing the wrong way)
    {"contact",
         "Gmsh: the master's contact tag on its far face",
         testing::scene_prm("gmsh",
                        "    set Mesh file = two_blocks.msh\n"
                            "    set Bodies = 1; 2\n"
                            "    set Dirichlet tags = 10\n"
                            "    set Contact tags = 10; 12\n"
                            "    set Contact pairs = 2 : 1\n") +
           "subsection Contact\n  set Search radius = 0.2\nend\n",
         "name faces on its far side, which look away from the slave: the "
             "slave node at (0.7, 0.05) lies 0.55 m behind the nearest master "
             "face"},
    // damaged checkpoints
    {"checkpoint",
         "truncated data file",
         resume,
         "mesh_fixed.data' has",
         "truncate data"},
    {"checkpoint",
         "one byte of the data changed",
         resume,
         "mesh_fixed.data' is damaged",
         "flip data"},
    {"checkpoint",
         "mesh file deleted",
         resume,
         "'mesh' is missing",
         "delete mesh"},
    {"checkpoint",
         "state.txt deleted",
         resume,
         "state.txt is missing",
         "delete state"},
    {"checkpoint",
         "state.txt truncated",
         resume,
         "state.txt is truncated",
         "truncate state"},
    {"checkpoint",
         "state.txt edited",
         resume,
         "state.txt is damaged",
         "edit state"},
    {"checkpoint",
         "'last' names a missing folder",
         resume,
         "the folder does not exist",
         "bad last"},
    {"checkpoint",
         "'last' deleted, checkpoints kept",
         resume,
         "The newest checkpoint there that passes the checks is 'step_",
         "delete last"},
    {"checkpoint",
         "'last' is a FIFO (opening it would block)",
         resume,
         "is not a regular file",
         "fifo last"},
    {"checkpoint",
         "no checkpoint at all",
         resume,
         "no checkpoint",
         "delete all"},
    {"checkpoint",
         "Output directory with trailing slashes, no checkpoint there",
         base + "set Output directory = previous//\n"
                    "subsection Checkpointing\n  set Resume = true\nend\n",
         "'previous/checkpoints/last'"},
    {"checkpoint",
         "time edited to nan, checksums recomputed",
         resume,
         "the checkpoint's time t (s) ('time' = 'nan')",
         "edit time"},
    {"checkpoint",
         "time step edited to 1e300, checksums recomputed",
         resume,
         "the checkpoint's time step tau (s) ('tau' = '1e300')",
         "edit tau"},
    {"checkpoint",
         "statistics' columns edited (as in an earlier version's order), "
             "checksums recomputed",
         resume,
         "the statistics in the checkpoint have other columns than this run's",
         "edit columns"},
    {"checkpoint",
         "End time before the checkpoint",
         resume + "subsection Time integration\n  set End time = 0.01\nend\n",
         "Time integration/End time = 0.01 s is not after"},
    {"checkpoint",
         "a parameter changed",
         resume + "subsection Material\n  set Density = 2\nend\n",
         "Material/Density"},
    {"checkpoint",
         "Gmsh mesh edited before the resume",
         gmsh_ck + "subsection Checkpointing\n  set Resume = true\nend\n"
                       "subsection Time integration\n  set End time = 0.02\nend\n",
         "checksum of the input files",
         "edit gmsh mesh"},
    // meshes too large for the machine
    {"memory",
         "12 global refinements",
         "subsection Mesh\n  set Initial global refinements = 12\nend\n",
         "Mesh/Initial global refinements (now 12)"},
    {"memory",
         "ten million cells along the bar",
         bar("    set Cells along length = 10000000\n"),
         "Scene/Bar impact"},
    {"memory",
         "two bars, 12 refinements",
         scene_prm("two bars") +
           "subsection Mesh\n  set Initial global refinements = 12\nend\n",
         "Scene/Two bars"},
    {"memory",
         "3D bar, 9 refinements",
         "set Dimension = 3\nsubsection Mesh\n  set Initial global refinements = "
             "9\nend\n",
         "Mesh/Initial global refinements (now 9)"},
    {"memory",
         "hertz block 1000 radii wide",
         scene_prm("hertz", "    set Block width = 1000\n") +
           "subsection Mesh\n  set Initial global refinements = 8\nend\n",
         "Scene/Hertz"},
    {"memory",
         "Gmsh mesh, 12 refinements",
         gmsh("two_blocks.msh") +
           "subsection Mesh\n  set Initial global refinements = 12\nend\n",
         "Scene/Gmsh"},
    // data far outside physical ranges
    {"range",
         "Height 1e-300",
         bar("    set Height = 1e-300\n"),
         "Scene/Bar impact/Height"},
    {"range",
         "Height 1e-5 with 40 cells (degenerate cells)",
         bar("    set Height = 1e-5\n"),
         "Scene/Bar impact/Height"},
    {"range",
         "Length 1e30",
         bar("    set Length = 1e30\n"),
         "Scene/Bar impact/Length"},
    {"range",
         "Impact velocity 1e300",
         bar("    set Impact velocity = 1e300\n"),
         "Scene/Bar impact/Impact velocity"},
    {"range",
         "Impact velocity -1",
         bar("    set Impact velocity = -1\n"),
         "Scene/Bar impact/Impact velocity"},
    {"range",
         "Young's modulus 1e300",
         "subsection Material\n  set Young's modulus = 1e300\nend\n",
         "Material/Young's modulus"},
    {"range",
         "Young's modulus 1e-300",
         "subsection Material\n  set Young's modulus = 1e-300\nend\n",
         "Material/Young's modulus"},
    {"range",
         "Density 1e-300",
         "subsection Material\n  set Density = 1e-300\nend\n",
         "Material/Density"},
    {"range",
         "Density 1e300",
         "subsection Material\n  set Density = 1e300\nend\n",
         "Material/Density"},
    // a step 2e301 times the run (End time 0.05 s): until 2026-11-28 the
    // run took no step at all and ended with exit status zero
    {"range",
         "Time step 1e300",
         "subsection Time integration\n  set Time step = 1e300\nend\n",
         "Time integration/Time step"},
    {"range",
         "Viscous shear modulus 1e30",
         "subsection Material\n  set Viscous shear modulus = 1e30\nend\n",
         "Material/Viscous shear modulus"},
    {"range",
         "Viscous Lame parameter -1e30",
         "subsection Material\n  set Viscous Lame parameter = -1e30\nend\n",
         "Material/Viscous Lame parameter"},
    {"range",
         "body 2's density 1e-300",
         scene_prm("hertz") +
           "subsection Material of body 2\n  set Density = 1e-300\nend\n",
         "Material of body 2/Density"},
    {"range",
         "two bars: Height 1e-300",
         scene_prm("two bars", "    set Height = 1e-300\n"),
         "Scene/Two bars/Height"},
    {"range",
         "two bars: Initial gap 1e300",
         scene_prm("two bars", "    set Initial gap = 1e300\n"),
         "Scene/Two bars/Initial gap"},
    {"range",
         "hertz: Radius 1e-300",
         scene_prm("hertz", "    set Radius = 1e-300\n"),
         "Scene/Hertz/Radius"},
    {"range",
         "hertz: Load 1e300",
         scene_prm("hertz", "    set Load = 1e300\n"),
         "Scene/Hertz/Load"},
    {"range",
         "Rotation angle 1e300",
         bar("    set Rotation angle = 1e300\n"),
         "Scene/Bar impact/Rotation angle = '1e300' is refused; the values "
             "allowed are [Double -360...360"},
    {"range",
         "Body force 1e300",
         bar("    set Body force = 1e300\n"),
         "Scene/Bar impact/Body force = '1e300' is refused"},
    {"range",
         "Output interval nan",
         "subsection Output\n  set Output interval = nan\nend\n",
         "Output/Output interval = 'nan' is refused; the values allowed are "
             "[Double 0..."},
    // (until 2026-11-29 one step across the impact, without a word)
    {"range",
         "Time step 1e300 with adaptive tau",
         "subsection Time integration\n  set Time step = 1e300\n"
             "  set Time step control = adaptive\nend\n",
         "Minimum time step (1.5625e+298 s) is not below End time"},
    // (until 2026-11-29 blamed on Maximum active-set iterations)
    {"range",
         "blocks on the floor at 1e9 m/s (within the range)",
         scene_prm("gmsh",
               "    set Mesh file = two_blocks.msh\n"
                   "    set Bodies = 1; 2\n    set Contact tags = 10, 11; 12\n"
                   "    set Initial velocities = 0, 0; 0, -1e9\n"
                   "    set Contact pairs = 1 : obstacle, 2 : 1 : 0.2\n"
                   "    set Obstacle point = 0, -0.5\n"
                   "    set Obstacle normal = 0, 1\n") +
           "subsection Time integration\n  set Time step = 0.0025\nend\n",
         "times the size of the whole mesh (2.17 m), so that no contact can "
             "be resolved"},
    // static problems that nothing holds (singular)
    {"static",
         "hertz with Load 0 and a gap",
         scene_prm("hertz", "    set Load = 0\n    set Initial gap = 0.01\n") +
           "subsection Time integration\n  set Scheme = static\nend\n",
         "nothing holds body 1 (1 rigid motion)"},
    {"static",
         "a bar with a gap and no load",
         bar("") + "subsection Time integration\n  set Scheme = static\nend\n",
         "nothing holds body 1 (3 rigid motions)"},
    {"static",
         "a Gmsh body without Dirichlet tags",
         gmsh("two_blocks.msh") +
           "subsection Time integration\n  set Scheme = static\nend\n",
         "nothing holds body 2 (3 rigid motions)"},
    // incompatible options
    {"incompatible",
         "reference states every 0.03 s with Time step 0.0125 s",
         "subsection Reference solution\n  set Write states = true\n  set "
             "Interval = 0.03\nend\n",
         "Reference solution/Interval = 0.03 s is not a multiple of Time "
             "integration/Time step = 0.0125 s"},
    {"incompatible",
         "Initial strain with Fixed far end",
         bar("    set Initial strain = 0.01\n    set Fixed far end = true\n"),
         "cannot be combined"},
    // (until 2026-11-29 the advice named Contact/Slave side, which such a
    // scene refuses)
    {"contact",
         "a roller on the slave face of a pair of Contact pairs",
         gmsh_pairs("2 : 1", "    set Dirichlet tags = 10, 12: y\n"),
         "lie on a Dirichlet boundary: they get no contact rows, and the "
             "master body would pass through them. Make the clamped side the "
             "master (write the pair the other way round)"},
    // (until 2026-11-29 Slave side silently swapped the pair's sides)
    {"incompatible",
         "Contact/Slave side with Scene/Gmsh/Contact pairs",
         gmsh_pairs("2 : 1") + "subsection Contact\n  set Slave side = 2\nend\n",
         "Contact/Slave side = 2 would override the 'slave : master' order"},
    // messages naming the parameter
    {"message",
         "a word for an integer",
         bar("    set Cells along length = one\n"),
         "Cells along length"},
    {"message",
         "a word for the dimension",
         "set Dimension = two\n",
         "Dimension"},
    // output directory
    {"output",
         "an output directory name of 5000 characters",
         "set Output directory = " + std::string(5000, 'a') + "\n",
         "cannot be created: File name too long"},
    {"output",
         "output directory locked by a live run",
         "set Output directory = locked\n",
         "in use by another run"},
  };

  // a value of the checkpoint's state.txt replaced, with the checksum
  // recomputed: an edited, not a damaged, checkpoint
  auto edit_state = [&](const std::string &key, const std::string &value) {
    const std::string text = read(ck_step + "/state.txt");
    std::string       body = text.substr(0, text.rfind("checksum "));
    const std::size_t at   = body.find("\n" + key + " ") + 1;
    const std::size_t eol  = body.find('\n', at);
    const std::size_t length =
      std::stoul(body.substr(at + key.size() + 1, eol - at - key.size() - 1));
    body.replace(at,
                 eol + 1 + length - at,
                 key + " " + std::to_string(value.size()) + "\n" + value);
    boost::crc_32_type crc;
    crc.process_bytes(body.data(), body.size());
    std::ofstream(ck_step + "/state.txt")
      << body << "checksum " << std::hex << crc.checksum() << "\n";
  };
  const std::map<std::string, std::function<void()>> damages = {
    {"edit time", [&] { edit_state("time", "nan"); }},
    {"edit tau", [&] { edit_state("tau", "1e300"); }},
    {"edit columns",
     [&] { edit_state("statistics_columns", "step time energy_kinetic"); }},
    {"truncate data",
     [&] { fs::resize_file(ck_step + "/mesh_fixed.data", 100); }},
    {"flip data",
     [&] {
       std::fstream f(ck_step + "/mesh_fixed.data",
                      std::ios::in | std::ios::out | std::ios::binary);
       f.seekg(200);
       const char c = f.get();
       f.seekp(200);
       f.put(char(c ^ 1));
     }},
    {"delete mesh", [&] { fs::remove(ck_step + "/mesh"); }},
    {"delete state", [&] { fs::remove(ck_step + "/state.txt"); }},
    {"truncate state",
     [&] {
       fs::resize_file(ck_step + "/state.txt",
                       fs::file_size(ck_step + "/state.txt") / 2);
     }},
    {"edit state",
     [&] {
       std::string text = read(ck_step + "/state.txt");
       text[text.find("Time step") + 20] ^= 1;
       std::ofstream(ck_step + "/state.txt") << text;
     }},
    {"bad last", [&] { std::ofstream("ck/checkpoints/last") << "step_9\n"; }},
    {"delete last", [&] { fs::remove("ck/checkpoints/last"); }},
    {"fifo last",
     [&] {
       fs::remove("ck/checkpoints/last");
       mkfifo("ck/checkpoints/last", 0600);
     }},
    {"delete all", [&] { fs::remove_all("ck/checkpoints"); }},
    {"edit gmsh mesh", [&] {
       std::string mesh = read("edited.msh");
       mesh.replace(mesh.find("\n5 0.7 0.05 0"), 13, "\n5 0.7 0.0502 0");
       std::ofstream("edited.msh") << mesh;
     }}};

  std::map<std::string, std::pair<unsigned int, unsigned int>> counts;
  for (const Case &c : cases)
    {
      // a fresh checkpoint for every case that resumes
      fs::remove_all("ck");
      fs::copy("ck_pristine", "ck", fs::copy_options::recursive);
      if (!c.damage.empty())
        damages.at(c.damage)();
      const std::string directory =
        c.prm.find("Output directory = ck") != std::string::npos ? "ck" :
        c.prm.find("gmsh_ck") != std::string::npos               ? "gmsh_ck" :
        c.prm.find("= locked") != std::string::npos              ? "locked" :
                                                                   "previous";
      const std::string statistics = directory + "/statistics.tsv";
      const std::string before     = read(statistics);

      std::ofstream("case.prm") << base << c.prm;
      const Outcome outcome = run_in_process("case.prm");
      const bool    named   = error_names(outcome, c.expected);
      const bool    clean =
        without_backtrace(outcome) &&
        outcome.text.find("Segmentation") == std::string::npos &&
        outcome.text.find("TimerOutput objects finalize") == std::string::npos;
      const bool kept =
        read(statistics) == before &&
        (directory == "locked" || !fs::exists(directory + "/.lock"));
      const bool ok = outcome.status != 0 && named && clean && kept;
      ++counts[c.klass].first;
      counts[c.klass].second += ok;
      log() << c.klass << ": " << c.name
            << ": exit status non-zero: " << check(outcome.status != 0)
            << ", message names '" << c.expected << "': " << check(named)
            << ", no backtrace: " << check(clean)
            << ", earlier files kept: " << check(kept) << "\n";
      if (!ok)
        std::cout << c.name << ":\n" << outcome.text << std::endl;
    }
  log() << "\n";
  for (const auto &[klass, count] : counts)
    log() << klass << ": " << count.second << " of " << count.first
          << " cases handled\n";
  log() << "\n";

  // a damaged last checkpoint, beside it the one before and a newer folder
  // left incomplete by a crash while writing: the refusal names the one
  // before (the newest that passes the checks) and how to resume from it;
  // done as it says, the run resumes from that one
  {
    fs::remove_all("ck");
    fs::copy("ck_pristine", "ck", fs::copy_options::recursive);
    damages.at("flip data")();
    fs::create_directories("ck/checkpoints/step_0099999");
    std::ofstream("case.prm") << base << resume;
    const Outcome     refused = run_program("case.prm");
    const std::string advice  = "', is kept beside it";
    const auto        at      = refused.text.find(advice);
    const auto        begin   = refused.text.rfind('\'', at - 1) + 1;
    const std::string previous =
      at == std::string::npos ? "" : refused.text.substr(begin, at - begin);
    const bool named_previous =
      refused.status != 0 && !previous.empty() &&
      fs::is_directory("ck/checkpoints/" + previous) &&
      "ck/checkpoints/" + previous != ck_step && previous != "step_0099999" &&
      refused.text.find("echo " + previous + " > 'ck/checkpoints/last'") !=
        std::string::npos;
    std::ofstream("ck/checkpoints/last") << previous << "\n";
    const Outcome resumed = run_program("case.prm");
    log() << "damaged last checkpoint (and a newer incomplete one): the "
             "refusal names the one before it and how to resume from it: "
          << check(named_previous) << "; done so, the run resumes from it: "
          << check(resumed.status == 0 &&
                   resumed.text.find("resumed from ck/checkpoints/" +
                                     previous) != std::string::npos)
          << "\n";
  }

  // special files in place of the files a run writes (a symbolic link to
  // the user's own file, a FIFO that would block whoever opens it, a
  // directory): refused before the run starts, with a message naming the
  // file; nothing is written through the link, nothing hangs (timeout's
  // status 124 would tell), and the folder holds nothing else afterwards
  {
    struct Special
    {
      std::string name;
      std::string kind;
      std::string expected;
    };
    const std::vector<Special> specials = {
      {"statistics.tsv", "symbolic link", "' is a symbolic link"},
      {"summary.txt", "symbolic link", "' is a symbolic link"},
      {"solution.pvd", "symbolic link", "' is a symbolic link"},
      {"statistics.tsv", "FIFO", "' is a FIFO"},
      {"summary.txt", "FIFO", "' is a FIFO"},
      {"solution.pvd", "FIFO", "' is a FIFO"},
      {".lock", "FIFO", "' is a FIFO"},
      {"statistics.tsv", "directory", "' is a directory"},
      {"statistics.tsv", "hard link", "' is a file with other names"},
      {"checkpoints", "file", "/' is not a directory"}};
    const std::string users_text = "the user's own file\n";
    for (const Special &special : specials)
      {
        fs::remove_all("special");
        fs::create_directories("special");
        std::ofstream("users_file.txt") << users_text;
        const std::string path = "special/" + special.name;
        if (special.kind == "symbolic link")
          fs::create_symlink(fs::absolute("users_file.txt"), path);
        else if (special.kind == "hard link")
          fs::create_hard_link("users_file.txt", path);
        else if (special.kind == "FIFO")
          mkfifo(path.c_str(), 0600);
        else if (special.kind == "file")
          std::ofstream(path) << users_text;
        else
          fs::create_directories(path);
        std::ofstream("case.prm") << base << "set Output directory = special\n";
        const Outcome outcome = run_program("case.prm", "timeout 300 ");
        const auto    entries =
          std::distance(fs::directory_iterator("special"), {});
        log() << "output: " << special.name << " is a " << special.kind
              << ": refused before the run ("
              << check(outcome.status != 0 && outcome.status != 124 &&
                       without_backtrace(outcome) &&
                       error_names(outcome, special.name + special.expected))
              << "), the user's file unchanged and nothing else written ("
              << check(read("users_file.txt") == users_text && entries == 1)
              << ")\n";
        if (outcome.status == 0 || outcome.status == 124)
          std::cout << outcome.text << std::endl;
      }
  }

  // a run that fails midway (the active-set limit at the impact, t = 0.1
  // s) in the folder of a complete earlier run: its summary.txt says that
  // it failed, after which step and why; the earlier run's summary is gone
  {
    fs::remove_all("failing");
    const std::string run = base + "set Output directory = failing\n" +
                            "subsection Time integration\n"
                            "  set End time = 0.3\nend\n";
    std::ofstream("failing.prm") << run;
    const Outcome     complete = run_program("failing.prm");
    const std::string earlier  = read("failing/summary.txt");
    const auto earlier_steps = column_values("failing/statistics.tsv", "step");
    std::ofstream("failing.prm")
      << run << "subsection Contact solver\n"
      << "  set Maximum active-set iterations = 1\nend\n";
    const Outcome     failed  = run_program("failing.prm");
    const std::string summary = read("failing/summary.txt");
    const auto        steps   = column_values("failing/statistics.tsv", "step");
    const std::string first_line = summary.substr(0, summary.find('\n'));
    log() << "a run that fails at step " << steps.back() + 1 << " of "
          << earlier_steps.back() << ": exit status non-zero ("
          << check(complete.status == 0 && failed.status != 0 &&
                   steps.back() > 0 && steps.back() < earlier_steps.back())
          << "), summary.txt says '" << first_line << "' ("
          << check(earlier.find("FAILED") == std::string::npos &&
                   first_line == "run: FAILED after step " +
                                   std::to_string(int(steps.back())) +
                                   " (t = " +
                                   [&] {
                                     std::ostringstream t;
                                     t << 0.0125 * steps.back();
                                     return t.str();
                                   }() +
                                   " s); statistics.tsv holds the "
                                   "steps up to there" &&
                   summary.find("Maximum active-set iterations") !=
                     std::string::npos)
          << ")\n";
  }

  // mesh adaptations that would outgrow the memory: a front widening of
  // 100 with an adaptation every step grows the bar from 160 cells to
  // millions within 8 steps (5 GB). Under an address-space limit (ulimit
  // -v) of 1.5 GB (the program's own address space is about 0.9 GB) the
  // check before each refinement stops the run with a
  // message naming the limit and the parameters (not a bare bad_alloc);
  // the statistics of the steps before are intact and the summary says
  // that the run failed
  {
    fs::remove_all("grown");
    std::ofstream("grown.prm")
      << base << "set Output directory = grown\n"
      << "subsection Time integration\n  set End time = 0.15\nend\n"
      << "subsection Mesh refinement\n  set Refinement interval = 1\n"
      << "  set Front widening = 100\nend\n";
    const Outcome grown = run_program("grown.prm", "ulimit -v 1500000; ");
    const auto    steps = column_values("grown/statistics.tsv", "step");
    log() << "adaptations past an address-space limit of 1.5 GB: stopped with "
             "a message naming the limit and the parameters ("
          << check(grown.status != 0 && without_backtrace(grown) &&
                   error_names(grown, "the adapted mesh would have") &&
                   error_names(grown, "address-space limit (ulimit -v)") &&
                   error_names(grown, "Front widening (now 100)") &&
                   grown.text.find("bad_alloc") == std::string::npos)
          << "), the statistics of the steps before intact ("
          << check(steps.size() > 1 && steps.back() == steps.size() - 1 &&
                   read("grown/summary.txt").find("run: FAILED") == 0)
          << ")\n";
    if (grown.status == 0 || !error_names(grown, "the adapted mesh"))
      std::cout << grown.text << std::endl;
  }

  // inputs that must run
  // an obstacle normal of length 4.9e-324 (any length > 0 is normalised;
  // until 2026-11-29 its normal became infinite and the run failed with
  // "the gap is not finite"): the same run as with the normal 0, 1
  {
    dyncontact::Statistics statistics[2];
    bool                   ran = true;
    for (const std::string normal : {"0, 4.9e-324", "0, 1"})
      {
        fs::remove_all("subnormal");
        std::ofstream("subnormal.prm")
          << base << "set Output directory = subnormal\n"
          << gmsh_pairs("2 : 1, 1 : obstacle",
                        "    set Obstacle point = 0, -0.6\n"
                        "    set Obstacle normal = " +
                          normal + "\n");
        ran = ran && run_program("subnormal.prm").status == 0;
        statistics[normal == "0, 1"] =
          testing::read_statistics("subnormal/statistics.tsv");
      }
    log() << "an obstacle normal of length 4.9e-324 runs as the normal 0, 1: "
          << check(ran && statistics[0].rows.size() == 5 &&
                   testing::statistics_difference(statistics[0], statistics[1])
                       .first == 0.)
          << "\n";
  }

  // two bodies in no pair that touch along a side: no overlap
  {
    std::ofstream("touch.prm")
      << base << "set Output directory = touch\n"
      << scene_prm("gmsh",
                   "    set Mesh file = touch.msh\n    set Body 1 tags = 1\n"
                   "    set Body 2 tags = 2\n");
    log() << "two bodies in no pair that touch along a side run: "
          << check(run_program("touch.prm").status == 0) << "\n";
  }

  // 'Bodies = 1, 2' (a comma for ';'): one body of the two blocks, which
  // would never touch each other; a warning counts the pieces
  {
    std::ofstream("pieces.prm")
      << base << "set Output directory = pieces\n"
      << testing::scene_prm("gmsh",
                            "    set Mesh file = two_blocks.msh\n"
                            "    set Bodies = 1, 2\n"
                            "    set Dirichlet tags = 10\n");
    const Outcome pieces = run_program("pieces.prm");
    log() << "Bodies = 1, 2: a warning says that body 1 is made of 2 "
             "disconnected pieces: "
          << check(pieces.text.find("warning: body 1 of mesh file") !=
                     std::string::npos &&
                   pieces.text.find("is made of 2 disconnected pieces") !=
                     std::string::npos)
          << "\n";
  }

  // entries the input sets but the run does not read: a warning before the
  // run names each, its line and why (until 2026-11-29 the two bars ran
  // as equal bars without a word, whatever Material of body 2 said); the
  // entries it does read get none
  {
    std::ofstream("unread.prm")
      << base << "set Output directory = unread\n"
      << scene_prm("two bars", "    set Initial gap = 0.1\n")
      << testing::scene_entries("Bar impact", "    set Length = 2\n")
      << "subsection Material of body 2\n  set Young's modulus = 4\nend\n"
      << "subsection Mesh refinement\n  set Refine fraction = 0.3\n"
      << "  set Initial contact refinements = 2\nend\n"
      << "subsection Output\n  set Compression = best\nend\n"
      << "subsection Reference solution\n  set Interval = 0.2\nend\n"
      << "subsection Time integration\n  set Consistent mass fraction = "
         "0.6\nend\n"
      << "subsection Output\n  set Compression = fast\nend\n";
    const Outcome unread = run_program("unread.prm");
    // (Output/Compression is set twice: the warning names the later line,
    // whose value the run would take; until 2026-12-01 the first)
    const std::string unread_text = read("unread.prm");
    const std::size_t last_line =
      std::count(unread_text.begin(),
                 unread_text.begin() + unread_text.rfind("set Compression"),
                 '\n') +
      1;
    const auto warned = [&](const std::string &entry, const std::string &why) {
      return unread.text.find(entry +
                              " is set, but this run does not read "
                              "it: " +
                              why) != std::string::npos;
    };
    const std::string line = "warning: Line ";
    log() << "entries set but not read are named with their line and why: "
             "another scene's ("
          << check(warned("Scene/Bar impact/Length",
                          "the scene is 'two bars', which reads Scene/Two "
                          "bars only"))
          << "), Material of body 2 in the two bars ("
          << check(warned("Material of body 2/Young's modulus",
                          "the 'two bars' scene makes each of its 2 bodies "
                          "of Material"))
          << "), a mesh that does not adapt ("
          << check(warned("Mesh refinement/Refine fraction",
                          "the mesh does not adapt during the run"))
          << "), no VTU files, at the last line that sets it ("
          << check(warned("Output/Compression", "Output/Write vtu = false") &&
                   unread.text.find("Line " + std::to_string(last_line) +
                                    " of 'unread.prm': Output/Compression") !=
                     std::string::npos)
          << "), no reference states ("
          << check(warned("Reference solution/Interval",
                          "neither Write states nor Compare with states"))
          << "), a blend of masses that are lumped ("
          << check(warned("Time integration/Consistent mass fraction",
                          "only Mass matrix = blended reads it"))
          << "); the initial contact refinements that refine nothing ("
          << check(unread.text.find("Initial contact refinements = 2: no "
                                    "cell was refined") != std::string::npos)
          << "); nothing else ("
          << check(
               unread.status == 0 &&
               std::count(unread.text.begin(), unread.text.end(), '\n') > 0 &&
               [&] {
                 std::size_t n = 0;
                 for (auto at = unread.text.find(line); at != std::string::npos;
                      at      = unread.text.find(line, at + 1))
                   ++n;
                 return n == 6;
               }())
          << ")\n";
  }

  // a static problem of viscous bodies: no time, so no viscous work and no
  // energy balance (until 2026-11-29 both were computed with the unused
  // Time step: W_visc > 0 and a positive energy_balance)
  {
    std::ofstream("static_viscous.prm")
      << base << "set Output directory = static_viscous\n"
      << scene_prm("hertz")
      << "subsection Time integration\n  set Scheme = static\nend\n"
      << "subsection Material\n  set Viscous shear modulus = 10\nend\n";
    const Outcome ran = run_program("static_viscous.prm");
    const auto    w =
      column_values("static_viscous/statistics.tsv", "dissipation_viscous");
    const auto balance =
      column_values("static_viscous/statistics.tsv", "energy_balance");
    log() << "a static problem of viscous bodies: dissipation_viscous and "
             "energy_balance are 0: "
          << check(ran.status == 0 && w.size() >= 2 && w.back() == 0. &&
                   balance.back() == 0.)
          << "\n";
  }

  std::ofstream("bom.prm") << "\xEF\xBB\xBF" << base;
  log() << "a UTF-8 byte-order mark is ignored: "
        << check(run_program("bom.prm").status == 0) << "\n";

  fs::create_directories("stale");
  std::ofstream("stale/.lock") << [] {
    char name[256] = {};
    gethostname(name, sizeof(name) - 1);
    return std::string(name);
  }() << " 999999999\n";
  std::ofstream("stale.prm") << base << "set Output directory = stale\n";
  const Outcome stale = run_program("stale.prm");
  log() << "a stale lock (no such process) is replaced: "
        << check(stale.status == 0 &&
                 stale.text.find("replaced the lock file") !=
                   std::string::npos &&
                 !fs::exists("stale/.lock"))
        << "\n";

  // the bar impact to t = 1 s with a loose CG tolerance: the balance holds
  // even so (each step's residual does no work on its increment: the
  // solution is corrected along it), no warning
  const std::string impact = "subsection Time integration\n"
                             "  set End time = 1\nend\n";
  std::ofstream("loose.prm")
    << base << "set Output directory = loose\n"
    << impact
    << "subsection Contact solver\n  set Step solver tolerance = 1e-2\nend\n";
  const Outcome loose = run_program("loose.prm");
  log() << "with Step solver tolerance = 1e-2 the balance holds (no "
           "warning): "
        << check(loose.status == 0 &&
                 loose.text.find("which Theorem 3.2 excludes") ==
                   std::string::npos &&
                 loose.text.find("Theorem 3.2 held") != std::string::npos)
        << "\n";
  // a disc that moves along the block's top, whose constraint is
  // linearised at each node's reference position: the energy grows (by up
  // to 0.5% in a step), which the monitor reports with the reason
  std::ofstream("curved.prm")
    << "set Dimension = 2\nset Output directory = curved\n"
    << testing::scene_prm("gmsh",
                          "    set Mesh file = " +
                            std::string(DYNCONTACT_PRM_DIR) +
                            "/meshes/two_blocks.msh\n"
                            "    set Bodies = 1; 2\n"
                            "    set Contact tags = 11;\n"
                            "    set Contact pairs = 1 : obstacle\n"
                            "    set Dirichlet tags = 10, 13\n"
                            "    set Obstacles = sphere 0.3, 0.16 radius "
                            "0.15 moving 0.5*t, -0.03*t\n")
    << "subsection Contact\n  set Search radius = 0.5\nend\n"
    << "subsection Time integration\n  set Time step = 0.01\n"
    << "  set End time = 0.6\nend\n"
    << "subsection Output\n  set Write vtu = false\nend\n";
  const Outcome curved = run_program("curved.prm");
  log() << "energy growth at a moving curved obstacle is reported with the "
           "reason: "
        << check(curved.status == 0 &&
                 curved.text.find("which Theorem 3.2 excludes") !=
                   std::string::npos &&
                 curved.text.find("a curved rigid obstacle moves") !=
                   std::string::npos)
        << "\n";

  // at the default tolerance the step matrix itself cannot hold the mass
  // (tau/2 mu_v outweighs rho h^2 by 4e13): momentum drifts by about 1% per
  // step, which the program must say
  std::ofstream("viscous_default.prm")
    << base << "set Output directory = viscous_default\n"
    << "subsection Material\n  set Viscous shear modulus = 1e12\nend\n"
    << bar("    set Initial gap = 10\n");
  const Outcome drowned = run_program("viscous_default.prm");
  const auto    momentum =
    column_values("viscous_default/statistics.tsv", "momentum_x");
  // (by how much, and in which direction, is round-off)
  log() << "momentum drifts by more than 0.1% and a warning says that S "
        << "holds the mass only to about 1e-2: "
        << check(drowned.status == 0 &&
                 std::abs(momentum.back() / momentum.front() - 1.) > 1e-3 &&
                 drowned.text.find("outweigh the mass") != std::string::npos)
        << "\n";
  const Outcome plain = run_program("previous.prm");
  log() << "no such warning for an ordinary bar: "
        << check(plain.status == 0 &&
                 plain.text.find("outweigh the mass") == std::string::npos)
        << "\n";

  // a Time step larger than End time: one step to t = tau, which the banner
  // must say, with a warning (the ordinary bar's End time is a multiple)
  std::ofstream("overshoot.prm")
    << base << "set Output directory = overshoot\n"
    << "subsection Time integration\n  set Time step = 0.5\n"
    << "  set End time = 0.2\nend\n";
  const Outcome overshoot = run_program("overshoot.prm");
  log() << "Time step 0.5 s > End time 0.2 s: one step to t = 0.5 s, and a "
        << "warning: "
        << check(overshoot.status == 0 &&
                 overshoot.text.find("1 steps from t = 0 to 0.5 s") !=
                   std::string::npos &&
                 overshoot.text.find("the last step ends at t = 0.5 s") !=
                   std::string::npos &&
                 plain.text.find("is not reached in whole steps") ==
                   std::string::npos)
        << "\n";

  // a search radius smaller than the gap: no slave node gets a row and the
  // bars pass through each other from t = 0.1 s on. max_penetration must
  // say so: exactly 2 v (t - 0.1 s) = 0.2 m at t = 0.2 s
  std::ofstream("missed.prm")
    << base << "set Output directory = missed\n"
    << "subsection Time integration\n  set End time = 0.2\n"
    << "  set Time step = 0.0125\nend\n"
    << testing::scene_prm("two bars")
    << "subsection Contact\n  set Search radius = 0.01\n"
    << "  set Pair without rows = warn\nend\n";
  const Outcome missed = run_program("missed.prm");
  const auto    penetration =
    column_values("missed/statistics.tsv", "max_penetration");
  log() << "bars that pass through each other for lack of rows: "
           "max_penetration at t = 0.2 s is "
        << testing::fmt(penetration.back(), 4) << " m (exact 0.2), with a "
        << "warning naming the search radius: "
        << check(
             missed.status == 0 && std::abs(penetration.back() - 0.2) < 1e-9 &&
             missed.text.find("has no constraint row") != std::string::npos &&
             missed.text.find("Contact/Search radius") != std::string::npos)
        << "\n";
  std::ofstream("matched.prm")
    << base << "set Output directory = matched\n"
    << "subsection Time integration\n  set End time = 0.2\n"
    << "  set Time step = 0.0125\nend\n"
    << testing::scene_prm("two bars");
  const Outcome matched = run_program("matched.prm");
  const auto held = column_values("matched/statistics.tsv", "max_penetration");
  log() << "with the default radius the rows hold the bars apart: "
        << "max_penetration " << testing::fmt(testing::max_of(held), 1)
        << " m, no warning: "
        << check(matched.status == 0 && testing::max_of(held) < 1e-9 &&
                 matched.text.find("has no constraint row") ==
                   std::string::npos)
        << "\n";
}
