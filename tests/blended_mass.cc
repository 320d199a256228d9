// Time integration/Mass matrix = blended: element mass matrices (1 - beta)
// times the lumped plus beta times the consistent one. With linear
// elements and the trapezoidal rule, beta = 1/2 + (c tau/h)^2 cancels the
// leading term of the phase error (doc/algorithms.md). On the 2D bar
// impact (H = 0.1, Q1, N-CS++), against the exact solution:
// - the blend keeps the mass of each body: E(0) (the rigid motion's
//   kinetic energy) equals that of the lumped mass to round-off;
// - at tau = h/(2c) (beta = 0.75, the default) the energy-norm error at T
//   is below 0.75 of the lumped mass's on 16 and 32 cells along, and it
//   falls faster from 16 to 32 cells (a dispersion error of fourth instead
//   of second order);
// - at tau = h/(4c) (64 cells along) the formula's beta = 0.5625 has an
//   error below 0.85 of 0.75's (which is then the wrong blend) and 0.75 of
//   the lumped mass's: the formula, not just any blend, removes the
//   dispersion;
// - Theorem 3.2 (E + W never increases) for N-CS++, N-CI and N-CS (also
//   at a Step solver tolerance of 1e-3: the projection in the M-norm stops
//   at Linear solver tolerance), the normal
//   velocity of persistently active nodes is zero (eq. 19), the energy is
//   constant after the release, the contact ends within 2 tau + h/c of the
//   exact 2.1 s;
// - p = 2: the matrix-free step matrix with the p-multigrid (whose linear
//   level assembles its own blended mass) gives the assembled run's
//   statistics to 1e-8.
// Also on two MPI ranks (blended_mass.mpirun=2), with the same output.

#include "tests.h"

namespace
{
  using namespace testing;

  std::string
  blended_prm(const double beta)
  {
    return "subsection Time integration\n  set Mass matrix = blended\n"
           "  set Consistent mass fraction = " +
           fmt(beta, 6) + "\nend\n";
  }
} // namespace

int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);
  const double                c = 1.;

  // tau = h/(2c): lumped against the default blend
  std::vector<double> lumped_errors, blended_errors;
  for (const unsigned int cells : {16u, 32u})
    {
      const double     tau    = 1. / cells / (2. * c);
      const Statistics lumped = run(bar_prm(2, "N-CS++", cells, tau, 2.5) +
                                    "set Output directory = output-lumped\n");
      const Statistics blended =
        run(bar_prm(2, "N-CS++", cells, tau, 2.5) + blended_prm(0.75) +
            "set Output directory = output-blended\n");
      const double e0 = lumped.column("energy_total")[0];
      lumped_errors.push_back(error_at_end(lumped));
      blended_errors.push_back(error_at_end(blended));
      log() << cells << " cells along, tau = h/(2c): E(0) the lumped mass's: "
            << check(std::abs(blended.column("energy_total")[0] - e0) <=
                     1e-12 * e0)
            << "; error at T: lumped " << fmt(lumped_errors.back(), 2)
            << ", blended " << fmt(blended_errors.back(), 2)
            << " (below 0.75 of it): "
            << check(blended_errors.back() < 0.75 * lumped_errors.back())
            << "\n";
      if (cells == 32)
        {
          log_bar_release_checks(blended, tau, cells, 50);
          const Statistics nci =
            run(bar_prm(2, "N-CI", cells, tau, 2.5) + blended_prm(0.75));
          log() << "  N-CI: E + W non-increasing: "
                << check(max_energy_increase(nci) <= 1e-10 * e0) << "\n";
          // (the projection's CG stops at Linear solver tolerance: at the
          // step tolerance N-CS's energy rose by its residual)
          const Statistics ncs =
            run(bar_prm(2, "N-CS", cells, tau, 2.5) + blended_prm(0.75) +
                "subsection Contact solver\n  set Step solver tolerance = "
                "1e-3\nend\n");
          log() << "  N-CS at Step solver tolerance = 1e-3: E + W "
                   "non-increasing: "
                << check(max_energy_increase(ncs) <= 1e-10 * e0) << "\n";
        }
    }
  const double lumped_rate  = std::log2(lumped_errors[0] / lumped_errors[1]),
               blended_rate = std::log2(blended_errors[0] / blended_errors[1]);
  log() << "rate from 16 to 32 cells: lumped " << fmt(lumped_rate, 2)
        << ", blended " << fmt(blended_rate, 2)
        << " (at least 0.05 more): " << check(blended_rate > lumped_rate + 0.05)
        << "\n";

  // tau = h/(4c): beta = 1/2 + (1/4)^2 against 0.75 and the lumped mass
  {
    const unsigned int cells = 64;
    const double       tau   = 1. / cells / (4. * c);
    const double       lumped =
      error_at_end(run(bar_prm(2, "N-CS++", cells, tau, 2.5) +
                       "set Output directory = output-lumped-4\n"));
    const double formula = error_at_end(
      run(bar_prm(2, "N-CS++", cells, tau, 2.5) + blended_prm(0.5625) +
          "set Output directory = output-formula-4\n"));
    const double other = error_at_end(
      run(bar_prm(2, "N-CS++", cells, tau, 2.5) + blended_prm(0.75) +
          "set Output directory = output-other-4\n"));
    log() << "tau = h/(4c), 64 cells: error at T: lumped " << fmt(lumped, 2)
          << ", beta = 0.5625 " << fmt(formula, 2) << ", beta = 0.75 "
          << fmt(other, 2) << "; the formula's beta the smallest: "
          << check(formula < 0.85 * other && formula < 0.75 * lumped) << "\n";
  }

  // p = 2: matrix-free with the p-multigrid against the assembled S
  {
    const auto prm = [](const std::string &solver) {
      return bar_prm(2, "N-CS++", 8, 1. / 32., 1.) + blended_prm(0.75) +
             tight_steps() +
             "set Polynomial degree = 2\nsubsection Contact solver\n" + solver +
             "end\nset Output directory = output-" +
             std::to_string(solver.size()) + "\n";
    };
    const Statistics assembled  = run(prm(""));
    const Statistics multigrid  = run(prm("  set Step matrix = matrix-free\n"
                                          "  set Preconditioner = multigrid\n"));
    const auto       comparison = compare_solvers(assembled, multigrid);
    log() << "p = 2, matrix-free with the p-multigrid against the assembled "
             "S: statistics within 1e-8: "
          << check(comparison.difference.first <= 1e-8) << "\n";
  }
}
