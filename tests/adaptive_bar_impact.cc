// Adaptive meshes during the dynamics (N-CS++, Kelly indicators of u and
// udot plus the contact zone, every 2 steps, levels 0 to 2 over a coarse
// mesh of 10 cells along): the bar impact and two bars with non-matching
// meshes meet the acceptance of the uniform runs (contact timing within
// 2 tau + h/c, pressure within 15% of rho c v0, rebound within 5% of v0)
// with fewer DoFs on average than the uniform mesh of the finest level; the
// energy change of every transfer is recorded and small (below 1% of the
// energy); E_total + dissipation minus the transfers' changes never increases
// (Theorem 3.2); nothing penetrates after a transfer. Also on two MPI ranks
// (adaptive_bar_impact.mpirun=2), where the bar's contact ends at 2.12
// instead of 2.14.
// Last, two bars with 4 and 5 cells across the coarse mesh, adapted by the
// recovery indicator of the velocity up to one level, to t = 0.8 s: the
// finer side of the interface changes during the run, but the slave side
// chosen at t = 0 is kept at every set-up (when the sides were swapped at
// t = 0.63 s, the master nodes, which the rows do not hold, stood 0.004 m
// inside the other bar and the pressure jumped to 2.5 rho c v0).

#include "tests.h"

int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);
  using namespace testing;

  const std::string adaptive = "subsection Mesh refinement\n"
                               "  set Refinement interval = 2\n"
                               "  set Minimum level = 0\n"
                               "  set Maximum level = 2\n"
                               "  set Refine fraction = 0.3\n"
                               "  set Coarsen fraction = 0.1\n"
                               "  set Criteria = kelly displacement, kelly "
                               "velocity, contact zone\n"
                               "  set Initial contact refinements = 2\n"
                               "end\n";
  const double      h = 1. / 40., tau = h / 2., g0 = 0.1, L = 1., H = 0.1;

  struct Case
  {
    std::string name, scene;
    double      uniform_dofs; // the uniform mesh of the finest level
  };
  for (const Case &c : {Case{"bar impact", "", 41. * 5. * 2.},
                        Case{"two bars, 2 and 3 cells across (coarse)",
                             scene_prm("two bars",
                                       "    set Cells across = 2\n"
                                       "    set Cells across body 2 = 3\n"),
                             41. * 9. * 2. + 41. * 13. * 2.}})
    {
      const Statistics s =
        run(bar_prm(2, "N-CS++", 10, tau, 2.5, c.scene + adaptive));
      log() << c.name << ":\n";
      const auto [begin, end] = contact_interval(s);
      log() << "  contact from " << fmt(begin) << " to " << fmt(end) << ": "
            << check(std::abs(begin - g0) <= 2. * tau + h &&
                     std::abs(end - (g0 + 2. * L)) <= 2. * tau + h)
            << "\n";
      const double p = max_of(s.column("max_contact_pressure"));
      log() << "  max pressure / (rho c v0) = " << fmt(p, 2) << ": "
            << check(std::abs(p - 1.) <= 0.15) << "\n";
      const double p_end = s.has_column("momentum_x_body2") ?
                             s.column("momentum_x_body2").back() :
                             s.column("momentum_x").back();
      // (not printed: the refinement breaks ties between equal Kelly
      // indicators of the symmetric mesh by round-off, which moves the
      // rebound velocity by about 1%)
      log() << "  rebound velocity within 5% of v0: "
            << check(std::abs(p_end / (L * H) - 1.) <= 0.05) << "\n";

      const double mean = mean_of(s.column("dofs"));
      // (the adapted meshes differ slightly between 1 and 2 ranks: the
      // parallel marking finds its thresholds by bisection; print checks)
      log() << "  fewer DoFs on average than the uniform finest mesh: "
            << check(mean < c.uniform_dofs) << "\n";

      const auto e         = s.column("energy_total"),
                 jump      = s.column("energy_transfer");
      const double largest = largest_transfer(s);
      double       sum     = 0.;
      unsigned int n       = 0;
      for (unsigned int i = 1; i < e.size(); ++i)
        {
          sum += jump[i];
          n += (jump[i] != 0.);
        }
      log() << "  transfers changed the energy (each below 1% of E0, all "
               "together below 2%): "
            << check(n > 0 && largest <= 0.01 * e[0] &&
                     std::abs(sum) <= 0.02 * e[0])
            << "\n";
      std::cout << c.name << ": " << n << " transfers changed the energy; the "
                << "largest by " << 100. * largest / e[0]
                << "% of E0, all together by " << 100. * sum / e[0]
                << "%; mean DoFs / uniform finest DoFs = "
                << mean / c.uniform_dofs << std::endl;
      log() << "  E_total + dissipation - transfers non-increasing: "
            << check(max_energy_increase_of_steps(s) <= 1e-10 * e[0]) << "\n";
      log() << "  no penetration, also after transfers: "
            << check(max_of(s.column("max_penetration")) <= 1e-12 &&
                     max_of(s.column("transfer_penetration")) <= 1e-12)
            << "\n";
    }

  // (one process: the program's log says which side is the slave at each
  // set-up)
  if (testing::this_rank() == 0)
    {
      std::ofstream("two_bars_recovery.prm")
        << bar_prm(2, "N-CS++", 40, 1. / 160., 0.8, recovery_two_bars_prm())
        << "set Output directory = output-two-bars-recovery\n";
      const std::string text = run_clean(std::string(DYNCONTACT_EXECUTABLE) +
                                         " two_bars_recovery.prm");
      unsigned int      sides[2] = {0, 0};
      for (std::size_t at = text.find("slave is side ");
           at != std::string::npos;
           at = text.find("slave is side ", at + 1))
        ++sides[text[at + 14] == '2'];
      log() << "two bars, recovery indicator, to t = 0.8 s:\n  the slave "
               "side chosen at t = 0 (side 2, the finer) kept at every "
               "set-up: "
            << check(sides[1] > 20 && sides[0] == 0 &&
                     text.find("command failed") == std::string::npos)
            << "\n";
    }
}
