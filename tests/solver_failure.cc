// When the active-set iteration fails (here: at most 2 iterations, N-CI,
// a soft block dropping onto one 1e4 times stiffer, which needs 3 in step
// 38): the executable stops with exit status 1 and a message naming the
// step, the time and the complementarity residual, having written the last
// good state as a checkpoint; resumed from it with a larger iteration limit
// the run completes and ends exactly as an uninterrupted run with that
// limit. With 'Time step adaptation = true' the failed step is retried with
// tau/2 and the run gets past the time where it failed before. A CG that
// runs out of iterations takes the same path (checkpoint, message naming
// 'Maximum linear iterations'), not an exception from inside the solver.

#include <filesystem>

#include "tests.h"


int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);
  using namespace testing;

  auto prm = [](const std::string &dir,
                const int          iterations,
                const bool         adapt,
                const bool         resume) {
    std::ostringstream s;
    s << "set Dimension = 2\nset Output directory = " << dir << "\n"
      << testing::scene_prm(
           "gmsh",
           "    set Mesh file = " + std::string(DYNCONTACT_PRM_DIR) +
             "/meshes/two_blocks.msh\n"
             "    set Body 1 tags = 1\n    set Body 2 tags = 2\n"
             "    set Dirichlet tags = 10\n"
             "    set Contact tags of body 1 = 11\n"
             "    set Contact tags of body 2 = 12\n"
             "    set Initial velocity of body 2 = 0, -0.5\n")
      << "subsection Contact\n  set Search radius = 0.2\nend\n"
      << "subsection Material\n  set Young's modulus = 1e4\n"
      << "  set Poisson's ratio = 0.3\nend\n"
      << "subsection Material of body 2\n  set Poisson's ratio = 0.3\nend\n"
      << "subsection Time integration\n  set Scheme = N-CI\n"
      << "  set Time step = 0.005\n  set End time = 0.6\n"
      << "  set Time step adaptation = " << (adapt ? "true" : "false")
      << "\nend\n"
      << "subsection Contact solver\n  set Maximum active-set iterations = "
      << iterations
      << "\nend\n"
      // (the resumed run compared to 1e-10)
      << testing::tight_steps() << "subsection Checkpointing\n  set Resume = "
      << (resume ? "true" : "false") << "\nend\n"
      << "subsection Output\n  set Write vtu = false\nend\n";
    return s.str();
  };
  std::ofstream("failing.prm") << prm("results-failing", 2, false, false);
  std::ofstream("resumed.prm") << prm("results-failing", 50, false, true);
  std::ofstream("full.prm") << prm("results-full", 50, false, false);
  std::ofstream("adaptive.prm") << prm("results-adaptive", 2, true, false);

  const Outcome failed = run_program("failing.prm");
  const auto    at     = failed.text.find("dyncontact: error:");
  log() << "a failing step stops the run: exit status non-zero: "
        << check(failed.status != 0) << ", message:\n"
        << (at == std::string::npos ? failed.text : failed.text.substr(at))
        << "\n";
  log() << "the last good state is a checkpoint: "
        << check(std::filesystem::exists("results-failing/checkpoints/last"))
        << "\n";

  const Outcome resumed = run_program("resumed.prm");
  run_program("full.prm");
  const Statistics a    = read_statistics("results-full/statistics.tsv");
  const Statistics b    = read_statistics("results-failing/statistics.tsv");
  bool             same = resumed.status == 0 && a.columns == b.columns &&
              !a.rows.empty() && a.rows.size() == b.rows.size();
  const auto last = [](const Statistics &s, const std::string &name) {
    return s.column(name).back();
  };
  // time and energies to 1e-10, the energy balance (a difference of
  // energies) to 1e-10 of the total energy, the momentum to 1e-10 of its
  // magnitude (momentum_x is round-off of order 1e-11 here): the resumed
  // run solves to the same tolerance, not with the same round-off
  if (same)
    {
      for (const std::string name :
           {"time", "energy_kinetic", "energy_elastic", "energy_total"})
        same = same && std::abs(last(a, name) - last(b, name)) <=
                         1e-10 * std::abs(last(a, name)) + 1e-14;
      same = same &&
             std::abs(last(a, "energy_balance") - last(b, "energy_balance")) <=
               1e-10 * std::abs(last(a, "energy_total"));
      const double momentum =
        std::hypot(last(a, "momentum_x"), last(a, "momentum_y"));
      for (const std::string name : {"momentum_x", "momentum_y"})
        same =
          same && std::abs(last(a, name) - last(b, name)) <= 1e-10 * momentum;
    }
  log() << "resumed with 50 iterations, it completes and ends as the "
        << "uninterrupted run: " << check(same) << "\n";

  const Outcome adaptive = run_program("adaptive.prm");
  const auto    times    = last_row("results-adaptive/statistics.tsv");
  log() << "with time step adaptation the step is retried with tau/2: "
        << check(adaptive.text.find("retrying with tau = 0.0025 s") !=
                 std::string::npos)
        << ", and the run gets past t = 0.185 s: "
        << check(times.size() > 2 && times[1] > 0.25) << "\n";

  // a CG failure: the same path, with the limit named
  std::ofstream("cg.prm") << prm("results-cg", 50, false, false)
                          << "subsection Contact solver\n"
                          << "  set Maximum linear iterations = 2\nend\n";
  const Outcome cg    = run_program("cg.prm");
  const auto    cg_at = cg.text.find("dyncontact: error:");
  log() << "a CG failure stops the run: exit status non-zero: "
        << check(cg.status != 0) << ", message names the limit: "
        << check(cg_at != std::string::npos &&
                 cg.text.find("'Contact solver/Maximum linear iterations'") !=
                   std::string::npos &&
                 cg.text.find("Stacktrace") == std::string::npos)
        << ", the last good state is a checkpoint: "
        << check(std::filesystem::exists("results-cg/checkpoints/last"))
        << "\n";
}
