// The gradient-recovery indicator of the velocity on the adaptive bar (H =
// 0.25, 32 cells along, levels 0 to 2, adapted every 2 steps, tau = h_min /
// 2c, N-CS++ with the lumped mass), against the uniform mesh of its finest
// level (128 cells along), to t = 0.6 s (the impact at 0.1 s, the front
// half-way along the bar):
// - before the impact the velocity is uniform: the indicators are zero (not
//   round-off, which the fixed fractions would turn into a random
//   refinement, as Kelly's indicators do), no cell is marked and the mesh
//   stays as it is and is not rebuilt (summary.txt: the adaptations that
//   changed the mesh, the calls of 'adaptation: constraints restored' and
//   of 'adaptation: DoFs and sparsity', are fewer than those that computed
//   indicators by at least the adaptations before the impact, and only
//   these evaluate the energy before and after the transfer, 'adaptation:
//   energy transfer');
// - the adaptive mesh has the error of the uniform mesh within 15 % (1.11
//   times it; the uniform mesh of 32 cells along, which an indicator that
//   missed the front would leave, has 1.32 times it) with less than half
//   its DoFs on average;
// - no penetration, and the energy of the steps does not grow.
// Also on two MPI ranks (adaptive_recovery.mpirun=2).

#include "tests.h"

int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);
  using namespace testing;

  const double      tau = 1. / 256., g0 = 0.1, end = 0.6;
  const std::string height =
    scene_entries("Bar impact", "    set Height = 0.25\n");
  const Statistics uniform = run(bar_prm(2, "N-CS++", 128, tau, end, height));
  const Statistics adaptive =
    run(bar_prm(2,
                "N-CS++",
                32,
                tau,
                end,
                height + "subsection Mesh refinement\n"
                         "  set Refinement interval = 2\n"
                         "  set Maximum level = 2\n"
                         "  set Initial contact refinements = 2\n"
                         "  set Criteria = recovery velocity\n"
                         "end\n"));

  const auto time               = adaptive.column("time");
  const auto cells              = adaptive.column("cells");
  bool       kept               = true;
  double     last_before_impact = 0.;
  for (unsigned int i = 0; i < time.size(); ++i)
    if (time[i] < g0 - tau)
      {
        kept &= (cells[i] == cells[0]);
        last_before_impact = time[i];
      }
  log() << "mesh kept until t = " << fmt(last_before_impact, 2) << " ("
        << cells[0] << " cells): " << check(kept) << "\n";
  // (every 2 steps: the adaptations before the impact)
  const unsigned int before  = static_cast<unsigned int>(g0 / tau) / 2;
  const std::string  summary = "output-N-CS++-32/summary.txt";
  const unsigned int attempts =
    timer_calls(summary, "adaptation: indicators and flags");
  const unsigned int changes =
    timer_calls(summary, "adaptation: constraints restored");
  log() << "no adaptation before the impact rebuilt anything (" << before
        << " of them): "
        << check(
             attempts > before && attempts - changes >= before &&
             timer_calls(summary, "adaptation: DoFs and sparsity") == changes &&
             timer_calls(summary, "adaptation: energy transfer") == 2 * changes)
        << "\n";
  log() << "refined after the impact: " << check(max_of(cells) > 1.5 * cells[0])
        << "\n";

  const double error_uniform  = uniform.column("error_energy_norm").back();
  const double error_adaptive = adaptive.column("error_energy_norm").back();
  log() << "error at t = " << end << " within 15 % of the uniform mesh's: "
        << check(error_adaptive <= 1.15 * error_uniform) << "\n";
  log() << "mean DoFs below half the uniform mesh's: "
        << check(mean_of(adaptive.column("dofs")) <
                 0.5 * mean_of(uniform.column("dofs")))
        << "\n";
  log() << "no penetration, also after transfers: "
        << check(max_of(adaptive.column("max_penetration")) <= 1e-12 &&
                 max_of(adaptive.column("transfer_penetration")) <= 1e-12)
        << "\n";
  const double e0 = adaptive.column("energy_total")[0];
  log() << "E_total + dissipation - transfers non-increasing: "
        << check(max_energy_increase_of_steps(adaptive) <= 1e-10 * e0) << "\n";
}
