// Hertz contact of a Gmsh disc bound to its circle (prm/hertz_gmsh.prm on
// prm/meshes/hertz_disc.msh): the half model of a cylinder R = 1 m on a
// block, P = 0.005 N/m, static. Hertz: b = 0.1076 m, p0 = 0.02957 Pa.
//
// - Refined uniformly 2, 3, 4 times with the arc bound to the circle, the
//   peak pressure approaches Hertz's (error 14 %, 7 %, 1.4 %: each level's
//   below the last's, the last below 2 %).
// - Not bound, the facets stay flat: the disc touches the block with the
//   corner of two chords, and the peak pressure grows with each level
//   (0.88, 1.77, 3.53 p0), beyond twice Hertz's at 4 levels.
// - The example's own setting (4 global and 3 contact refinements): b_h
//   within 2 % and p0_h within 1 % of Hertz's.

#include <filesystem>

#include "tests.h"

namespace
{
  const double hertz_b  = std::sqrt(4. * 0.005 / (M_PI * 0.5 / (1. - 0.09)));
  const double hertz_p0 = 2. * 0.005 / (M_PI * hertz_b);

  /// prm/hertz_gmsh.prm with @p global and @p contact refinements, its arc
  /// bound to the circle or not.
  testing::Statistics
  run_example(const unsigned int global,
              const unsigned int contact,
              const bool         bound)
  {
    const std::string file = DYNCONTACT_PRM_DIR "/hertz_gmsh.prm";
    std::ifstream     in(file);
    std::stringstream text;
    text << in.rdbuf() << "\nset Output directory = results-hertz-gmsh\n"
         << "subsection Mesh\n  set Initial global refinements = " << global
         << "\nend\nsubsection Mesh refinement\n"
         << "  set Initial contact refinements = " << contact << "\nend\n"
         << "subsection Output\n  set Write vtu = false\nend\n";
    if (!bound)
      text << "subsection Scene\n  subsection Gmsh\n    set Manifolds =\n"
           << "  end\nend\n";
    return dyncontact::run_simulation(text.str(), MPI_COMM_WORLD, file);
  }

  double
  last(const testing::Statistics &s, const std::string &column)
  {
    return s.column(column).back();
  }
} // namespace

int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);
  using namespace testing;
  log() << "Hertz: b = " << fmt(hertz_b, 4) << " m, p0 = " << fmt(hertz_p0, 4)
        << " Pa\n";

  double previous_error = 1e10;
  bool   converging     = true;
  double previous_p0    = 0.;
  bool   growing        = true;
  double last_error = 0., last_flat = 0.;
  for (unsigned int global = 2; global <= 4; ++global)
    {
      const Statistics with    = run_example(global, 0, true);
      const Statistics flat    = run_example(global, 0, false);
      const double     p0      = last(with, "max_contact_pressure") / hertz_p0;
      const double     p0_flat = last(flat, "max_contact_pressure") / hertz_p0;
      log() << global << " global refinements, " << last(with, "dofs")
            << " DoFs: bound p0_h/p0 = " << fmt(p0, 3)
            << ", not bound p0_h/p0 = " << fmt(p0_flat, 3) << "\n";
      converging     = converging && std::abs(p0 - 1.) < previous_error;
      previous_error = std::abs(p0 - 1.);
      growing        = growing && p0_flat > previous_p0;
      previous_p0    = p0_flat;
      last_error     = std::abs(p0 - 1.);
      last_flat      = p0_flat;
    }
  log() << "bound: the peak pressure's error falls with every level, below "
           "2 % at the last: "
        << check(converging && last_error < 0.02) << "\n";
  log() << "not bound: the peak pressure grows with every level, beyond "
           "2 p0 at the last: "
        << check(growing && last_flat > 2.) << "\n";

  const Statistics example = run_example(4, 3, true);
  const double     b       = last(example, "active_measure") / hertz_b;
  const double     p0      = last(example, "max_contact_pressure") / hertz_p0;
  log() << "4 global and 3 contact refinements: b_h/b = " << fmt(b, 3)
        << ", p0_h/p0 = " << fmt(p0, 3) << ", total force "
        << fmt(last(example, "contact_force"), 4) << " N/m: "
        << check(std::abs(b - 1.) < 0.02 && std::abs(p0 - 1.) < 0.01 &&
                 std::abs(last(example, "contact_force") - 0.0025) < 1e-8)
        << "\n";
}
