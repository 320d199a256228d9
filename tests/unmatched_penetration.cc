// Slave nodes without a constraint row (the search radius is smaller than the
// initial gap) let the bodies pass through each other; the penetration check
// must still measure how deep, by the closest point on the deformed master
// surface at any distance. Each rank holds only the master faces of its own
// cells and gets from the others the faces closest to its slave nodes, so on
// two ranks the closest face of a node is often another rank's.
//
// Without rows nothing touches: the bodies fly on rigidly, and the deepest
// node lies exactly v_rel (t - t0) behind the master surface once they meet
// at t0 = gap / v_rel (two bars: v_rel = 2 m/s, gap 0.2 m; the 3D ball on
// block: v = 0.1 m/s, gap 0.01 m, at most 0.03 m deep here, less than the
// distance to the block's sides).

#include "tests.h"

int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);
  using namespace testing;

  auto check_depths = [](const std::string &name,
                         const Statistics  &s,
                         const double       v_rel,
                         const double       t0) {
    const auto t = s.column("time"), depth = s.column("max_penetration"),
               rows = s.column("active_nodes");
    double worst    = 0.;
    for (unsigned int i = 0; i < t.size(); ++i)
      worst =
        std::max(worst, std::abs(depth[i] - v_rel * std::max(t[i] - t0, 0.)));
    log() << name << ": " << t.size() - 1
          << " steps, max_penetration at t = " << fmt(t.back(), 3) << " s is "
          << fmt(depth.back(), 4) << " m (exact "
          << fmt(v_rel * (t.back() - t0), 4)
          << "), every step within 1e-9 m of v (t - t0): "
          << check(worst < 1e-9 && max_of(rows) == 0.) << "\n";
  };

  check_depths("two bars (2D)",
               run(bar_prm(2,
                           "N-CS++",
                           10,
                           0.0125,
                           0.2,
                           scene_prm("two bars") +
                             "subsection Contact\n  set Search radius = "
                             "0.01\n  set Pair without rows = warn\nend\n")),
               2.,
               0.1);

  check_depths("ball on block (3D)",
               run(
                 "set Dimension = 3\nset Output directory = results-ball\n" +
                 scene_prm("ball on block",
                           "    set Load = 0\n    set Drop velocity = 0.1\n"
                           "    set Initial gap = 0.01\n"
                           "    set Contact zone refinements = 1\n") +
                 "subsection Mesh\n  set Initial global refinements = 1\nend\n"
                 "subsection Contact\n  set Search radius = 0.001\n"
                 "  set Pair without rows = warn\nend\n"
                 "subsection Time integration\n  set Scheme = N-CS++\n"
                 "  set Time step = 0.04\n  set End time = 0.4\nend\n"
                 "subsection Output\n  set Write vtu = false\nend\n"),
               0.1,
               0.1);
}
