// Adaptive Hertz drop (2D, N-CS++): a viscoelastic half-cylinder drops onto
// an elastic block while the mesh adapts every 2 steps (Kelly indicator of
// the velocity and the contact zone, up to level 4 over one global
// refinement). ParaView (tests/check_levels.py) finds the contact zone at
// the maximum level and the far field coarse; the run records its energy
// jumps, and E_total + dissipation minus them never increases; the transfers
// leave no penetration.

#include "tests.h"

int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);
  using namespace testing;

  // (the input as one string for every rank: each rank writing hertz.prm
  // and reading it back let one rank read the file while the other
  // truncated it, run the default scene, and wait for the other forever)
  std::ostringstream prm;
  prm << "set Dimension = 2\nset Output directory = results-hertz\n"
      << scene_prm("hertz",
                   "    set Load = 0.005\n    set Drop velocity = 0.1\n"
                   "    set Initial gap = 0.01\n"
                   "    set Contact zone refinements = 0\n")
      << "subsection Mesh\n  set Initial global refinements = 1\nend\n"
      << "subsection Material\n  set Poisson's ratio = 0.3\n"
      << "  set Viscous shear modulus = 0.01\nend\n"
      << "subsection Material of body 2\n  set Poisson's ratio = 0.3\nend\n"
      << "subsection Time integration\n  set Scheme = N-CS++\n"
      << "  set Time step = 0.01\n  set End time = 0.4\nend\n"
      << "subsection Mesh refinement\n  set Refinement interval = 2\n"
      << "  set Minimum level = 1\n  set Maximum level = 4\n"
      << "  set Refine fraction = 0.02\n  set Coarsen fraction = 0.5\n"
      << "  set Criteria = kelly velocity, contact zone\n"
      << "  set Initial contact refinements = 3\nend\n"
      << "subsection Output\n  set Output interval = 0.1\nend\n";
  const Statistics s = run(prm.str());

  const auto e            = s.column("energy_total");
  const auto [begin, end] = contact_interval(s);
  log() << "contact begins at " << fmt(begin, 2)
        << " (gap/v = 0.1): " << check(std::abs(begin - 0.1) <= 0.02) << "\n";
  log() << "largest energy jump of a transfer below 1% of E0: "
        << check(largest_transfer(s) <= 0.01 * std::abs(e[0])) << "\n";
  log() << "E_total + dissipation - transfers non-increasing: "
        << check(max_energy_increase_of_steps(s) <= 1e-10 * std::abs(e[0]))
        << "\n";
  log() << "no penetration after transfers (1e-10 m): "
        << check(max_of(s.column("max_penetration")) <= 1e-10) << "\n";
  log() << run_clean(std::string(DYNCONTACT_PVPYTHON) + " " + SOURCE_DIR +
                     "/check_levels.py results-hertz 4 1");
}
