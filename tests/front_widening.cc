// Refinement that follows a wave front (Mesh refinement/Front widening): the
// bar impact (N-CS++, 16 coarse cells along, up to level 2, tau = h/(2c) of
// the finest cells) adapted every 8 steps by the velocity jump indicator and
// the contact zone. With Front widening = 1 the refined zone is widened by
// the distance c tau n the front travels until the next adaptation (times
// the levels a cell still has to climb), and ParaView (tests/check_front.py)
// finds the cells that hold the front at the maximum level at every output
// time, each written just before an adaptation, when the front has run a
// whole interval since the last one (from the second adaptation after the
// impact on: one level per adaptation). Without widening the front runs out
// of the refined zone (the check of the test can fail). Both runs keep
// Theorem 3.2 with the transfers accounted for and change the energy by
// less than 1% of E0 per transfer; the widened run has fewer DoFs on
// average than the uniform finest mesh.

#include "tests.h"

int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);
  using namespace testing;

  const double       tau = 1. / 128.;
  const unsigned int n   = 8;
  std::string        checks;
  for (const int widening : {1, 0})
    {
      const std::string directory = "results-front-" + std::to_string(widening);
      const std::string extra =
        "set Output directory = " + directory + "\n" +
        "subsection Output\n  set Write vtu = true\n"
        "  set Output interval = " +
        fmt(n * tau, 6) +
        "\nend\n"
        "subsection Postprocess\n  subsection Error energy norm\n"
        "    set Interval = output times\n  end\nend\n"
        "subsection Mesh refinement\n  set Refinement interval = " +
        std::to_string(n) +
        "\n  set Maximum level = 2\n"
        "  set Initial contact refinements = 2\n"
        "  set Criteria = velocity jump, contact zone\n"
        "  set Front widening = " +
        std::to_string(widening) +
        "\n  subsection Contact zone\n    set Distance = 0.07\n  end\nend\n";
      const Statistics s = run(bar_prm(2, "N-CS++", 16, tau, 1.1, extra));
      log() << "Front widening = " << widening << ":\n";
      const auto e = s.column("energy_total");
      log() << "  E_total + dissipation - transfers non-increasing: "
            << check(max_energy_increase_of_steps(s) <= 1e-10 * e[0]) << "\n";
      log() << "  each transfer changes the energy by less than 1% of E0: "
            << check(largest_transfer(s) <= 0.01 * e[0]) << "\n";
      if (widening == 1)
        log() << "  fewer DoFs on average than the uniform finest mesh: "
              << check(mean_of(s.column("dofs")) < 65. * 9. * 2.) << "\n";
      checks += std::string(checks.empty() ? "" : " --next ") + SOURCE_DIR +
                "/check_front.py " + directory + " 2 0.1 1 1 0.25 " +
                (widening == 1 ? "inside" : "leaves");
    }
  // (in one pvpython: each start takes seconds)
  if (testing::this_rank() == 0)
    log() << "ParaView (check_front.py, Front widening = 1, then 0):\n"
          << run_clean(std::string(DYNCONTACT_PVPYTHON) + " " + SOURCE_DIR +
                       "/run_checks.py " + checks);
}
