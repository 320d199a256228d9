// Mesh refinement/Error tolerance on the 2D bar impact (10 cells along at
// level 0, N-CS++, tau = 0.01 s, to 2.5 s; exact solution). Checked:
// - the estimate (statistics column estimated_error, the energy norm of
//   the error relative to sqrt(E) by Zienkiewicz and Zhu's indicators) on
//   fixed meshes of 10, 20 and 40 cells (Maximum level 0, tau with h): it
//   falls by at least 1.25 per halving of h, and lies between 0.3 and 1
//   times the exact error (it sees the local error, not the dispersion
//   that the front leaves behind: measured 0.68, 0.54, 0.43 of it);
// - the marking (levels 0 to 3, every 2 steps): with delta = 0.1 the run
//   has more DoFs and an exact error (largest over time) at least 20 %
//   below that with delta = 0.4 (measured 0.23 against 0.35); no
//   adaptation's coarsening removes more than delta^2 / 4 of the energy
//   (the limit the tolerance implies); summary.txt says that the tolerance
//   was not kept exactly when cells it would refine were at Maximum level
//   (column cells_above_tolerance); with delta = 0.1, a run resumed from a
//   checkpoint at t = 1 s has the same DoFs, estimates and cells above the
//   tolerance in every row, and (on one rank) the serial triangulation
//   the same DoFs in every row and the same exact error.
// And on the Hertz drop of prm/hertz_drop_adaptive.prm (Maximum level 4,
// to 1 s), where the error is local, against the uniform level-4 mesh's
// states: halving the tolerance (0.2 to 0.1) halves the error within a
// factor 1.5 (measured 1.85), and the runs' estimate stays within 10 % of
// the tolerance (0.200 and 0.106: the global split keeps the sum of the
// estimates at about delta^2 E); split by volume, the same tolerance
// refines more and the error is smaller (measured 0.0025 against 0.0085).
// Also on 2 ranks (error_tolerance.mpirun=2).

#include <cmath>
#include <fstream>
#include <sstream>

#include "tests.h"

int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);
  using namespace testing;

  const double energy = 0.05; // J/m: the bar's kinetic energy, conserved

  // the estimate on fixed meshes
  double previous = 0.;
  for (const unsigned int cells : {10u, 20u, 40u})
    {
      std::ostringstream s;
      s << "subsection Mesh refinement\n  set Refinement interval = 2\n"
        << "  set Maximum level = 0\n  set Criteria = contact zone\n"
        << "  set Error tolerance = 0.01\nend\n";
      const Statistics stats =
        run(bar_prm(2, "N-CS++", cells, 0.1 / cells, 2.5, s.str()));
      double estimate = 0., exact = 0.;
      for (const double e : stats.column("estimated_error"))
        estimate = std::max(estimate, e);
      exact = max_of(stats.column("error_energy_norm")) / std::sqrt(energy);
      log() << cells << " cells: estimate between 0.3 and 1 times the exact "
            << "error (largest over time): "
            << check(estimate >= 0.3 * exact && estimate <= exact);
      if (previous > 0.)
        log() << "; 1.25 times below the coarser mesh's: "
              << check(estimate * 1.25 <= previous);
      log() << "\n";
      previous = estimate;
    }

  // the marking
  double loose_error = 0., loose_dofs = 0.;
  for (const double delta : {0.4, 0.1})
    {
      std::ostringstream s;
      s << "subsection Mesh refinement\n  set Refinement interval = 2\n"
        << "  set Maximum level = 3\n  set Criteria = contact zone\n"
        << "  set Error tolerance = " << delta << "\nend\n";
      const Statistics stats =
        run(bar_prm(2, "N-CS++", 10, 0.01, 2.5, s.str()));
      const double error =
        max_of(stats.column("error_energy_norm")) / std::sqrt(energy);
      double dofs = 0., removed = 0., above = 0.;
      for (const double d : stats.column("dofs"))
        dofs += d / stats.column("dofs").size();
      for (const double r : stats.column("coarsening_removed"))
        removed = std::max(removed, r);
      for (const double a : stats.column("cells_above_tolerance"))
        above = std::max(above, a);
      log() << "Error tolerance = " << delta << ":\n"
            << "   no adaptation's coarsening removes more than delta^2/4 of "
               "the energy: "
            << check(removed <= 0.25 * delta * delta * energy * (1. + 1e-6))
            << "\n";
      const std::string summary = read("output-N-CS++-10/summary.txt");
      log() << "   summary.txt gives the tolerance, and says it was not kept "
               "exactly when cells to refine were at Maximum level: "
            << check(summary.find("error tolerance: Mesh refinement/Error "
                                  "tolerance = ") != std::string::npos &&
                     (summary.find("NOT KEPT") != std::string::npos) ==
                       (above > 0.))
            << "\n";
      if (delta == 0.4)
        {
          loose_error = error;
          loose_dofs  = dofs;
          continue;
        }
      log() << "   more DoFs than with 0.4: " << check(dofs > loose_dofs)
            << "; exact error (largest over time) at least 20 % below: "
            << check(error <= 0.8 * loose_error) << "\n";

      // resumed from a checkpoint at t = 1 s: the same marking after it
      const auto split = [&](const double end, const bool resume) {
        return bar_prm(2, "N-CS++", 10, 0.01, end, s.str()) +
               "set Output directory = resumed\n" + checkpointing(100, resume);
      };
      run(split(1., false));
      const Statistics resumed = run(split(2.5, true));
      bool same = resumed.column("dofs").size() == stats.column("dofs").size();
      for (unsigned int i = 0; same && i < stats.column("dofs").size(); ++i)
        same = resumed.column("dofs")[i] == stats.column("dofs")[i] &&
               std::abs(resumed.column("estimated_error")[i] -
                        stats.column("estimated_error")[i]) <= 1e-9 &&
               resumed.column("cells_above_tolerance")[i] ==
                 stats.column("cells_above_tolerance")[i];
      log() << "   resumed from t = 1 s: the same DoFs, estimates and cells "
               "above the tolerance in every row: "
            << check(same) << "\n";

      // the serial triangulation marks the same cells (on one rank; both
      // with CG to 1e-12, so that round-off alone separates the runs)
      if (n_ranks() > 1)
        continue;
      const std::string prm =
        tight_steps() + bar_prm(2, "N-CS++", 10, 0.01, 2.5, s.str());
      const Statistics distributed = run(prm);
      const Statistics serial =
        run(prm + "subsection Mesh\n  set Triangulation = serial\nend\n");
      log() << "   the serial triangulation: the same DoFs in every row, the "
               "same exact error: "
            << check(
                 serial.column("dofs") == distributed.column("dofs") &&
                 std::abs(max_of(serial.column("error_energy_norm")) -
                          max_of(distributed.column("error_energy_norm"))) <=
                   1e-6 * std::sqrt(energy))
            << "\n";
    }

  // cells_above_tolerance counts the cells at Maximum level that the same
  // rule would refine without the level limit: a run that cannot refine
  // (Minimum level = Maximum level = 1) counts at its first adaptation
  // that counts or refines anything what a run with Maximum level 2,
  // identical until then, refines there (3 new cells for each in 2D; no
  // other criterion flags: Kelly's indicator is not used by the
  // tolerance). And that adaptation is the first whose estimate exceeds
  // delta: there 16 cells of equal estimates (two columns across the bar)
  // hold S = 1.68 delta^2 E, and deal.II's threshold is their common
  // value. Measured: 16 counted, 48 new cells. Until 2026-12-01 the count
  // took every cell of a nonzero estimate where nothing was left to
  // refine (16 there, 112 at the next adaptation), and a cell at the
  // threshold was not refined (none there, 16 at the next adaptation).
  {
    const auto count_run = [&](const unsigned int max_level) {
      std::ostringstream s;
      s << "subsection Mesh\n  set Initial global refinements = 1\nend\n"
        << "subsection Mesh refinement\n  set Refinement interval = 2\n"
        << "  set Minimum level = 1\n  set Maximum level = " << max_level
        << "\n  set Criteria = kelly velocity\n"
        << "  set Error tolerance = 0.05\nend\n";
      return run(bar_prm(2, "N-CS++", 40, 0.0125, 0.3, s.str()));
    };
    const Statistics fixed = count_run(1), free = count_run(2);
    const auto      &counted  = fixed.column("cells_above_tolerance");
    const auto      &cells    = free.column("cells");
    const auto      &estimate = free.column("estimated_error");
    bool             found = false, same = false, first = false;
    for (unsigned int i = 1; !found && i < counted.size() && i < cells.size();
         ++i)
      if (counted[i] > 0. || cells[i] != cells[i - 1] || estimate[i] > 0.05)
        {
          found = true;
          same  = counted[i] > 0. && cells[i] - cells[i - 1] == 3. * counted[i];
          first = estimate[i] > 0.05;
        }
    log() << "Bar, Error tolerance 0.05 at Maximum level 1: the cells counted "
             "at the level limit are those refined without it: "
          << check(same)
          << "; at the first adaptation whose estimate exceeds delta: "
          << check(first) << "\n";
  }

  // halving the tolerance on the Hertz drop, against the uniform mesh of
  // its Maximum level
  std::ifstream     in(std::string(DYNCONTACT_PRM_DIR) +
                   "/hertz_drop_adaptive.prm");
  std::stringstream hertz;
  hertz << in.rdbuf() << "\nsubsection Output\n  set Write vtu = false\nend\n";
  const std::string states = "subsection Reference solution\n"
                             "  set Directory = states\n"
                             "  set Interval = 0.1\n";
  run(hertz.str() +
      "set Output directory = uniform\n"
      "subsection Mesh\n  set Initial global refinements = 4\nend\n"
      "subsection Mesh refinement\n  set Refinement interval = 0\n"
      "  set Initial contact refinements = 0\nend\n" +
      states + "  set Write states = true\nend\n");
  struct Run
  {
    double error, estimate, dofs; // error relative to sqrt(E(0)), as estimate
  };
  const auto adaptive = [&](const double delta, const std::string &split) {
    std::ostringstream s;
    s << hertz.str() << "set Output directory = adaptive\n"
      << "subsection Mesh refinement\n  set Maximum level = 4\n"
      << "  set Error tolerance = " << delta << "\n"
      << "  set Error tolerance split = " << split << "\nend\n"
      << states << "  set Compare with states = true\nend\n";
    const Statistics stats = run(s.str());
    Run              result{max_of(stats.column("error_reference")) /
                 std::sqrt(stats.column("energy_total")[0]),
               0.,
               0.};
    for (const double e : stats.column("estimated_error"))
      result.estimate = std::max(result.estimate, e);
    for (const double d : stats.column("dofs"))
      result.dofs += d / stats.column("dofs").size();
    return result;
  };
  const Run loose = adaptive(0.2, "global"), tight = adaptive(0.1, "global"),
            by_volume = adaptive(0.2, "by volume");
  log() << "Hertz drop, Error tolerance 0.2 and 0.1:\n"
        << "   the error against the uniform level-4 mesh halves within a "
           "factor 1.5: "
        << check(loose.error / tight.error >= 2. / 1.5 &&
                 loose.error / tight.error <= 2. * 1.5)
        << "\n   the estimate within 10 % of the tolerance: "
        << check(std::abs(loose.estimate / 0.2 - 1.) <= 0.1 &&
                 std::abs(tight.estimate / 0.1 - 1.) <= 0.1)
        << "\n   split by volume, 0.2 gives a smaller error than globally: "
        << check(by_volume.error < loose.error) << "\n";

  // tolerances below what level 4 can reach (its estimate about 0.062):
  // the cells at Maximum level take no share of the refinement, and the
  // smallest estimates, whose sum is below a quarter of the tolerance's
  // error energy, are left alone, so that the difference from the uniform
  // level-4 mesh still follows delta and the smaller tolerance refines
  // more (measured 1.03 and 1.37 times delta, 1780 and 2273 DoFs on
  // average). Refining every cell of a nonzero estimate instead (until
  // 2026-12-01) refined where the waves had reached in round-off: 0.28
  // and 1.37 times delta, 10 061 and 5507 DoFs; both checks below fail
  // with it.
  const Run beyond     = adaptive(0.02, "global"),
            far_beyond = adaptive(0.004, "global");
  log() << "Hertz drop, Error tolerance 0.02 and 0.004 (beyond level 4):\n"
        << "   the estimate above both: "
        << check(beyond.estimate > 0.04 && far_beyond.estimate > 0.04)
        << "\n   the error against the uniform level-4 mesh within 0.5 to 2 "
           "times delta: "
        << check(beyond.error >= 0.5 * 0.02 && beyond.error <= 2. * 0.02 &&
                 far_beyond.error >= 0.5 * 0.004 &&
                 far_beyond.error <= 2. * 0.004)
        << "\n   more DoFs for the smaller tolerance: "
        << check(far_beyond.dofs > beyond.dofs) << "\n";
}
