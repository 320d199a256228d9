// Newton's cradle of bars (scene "bar chain", K = 3 bars at rest hit by a
// striker, E = rho = v0 = L = 1, nu = 0, g0 = 0.1, tau = h/(2c)), for the
// three schemes in 2D and N-CS++ in 3D (and on two MPI ranks,
// bar_chain.mpirun=2, with the same output). Against the exact 1D
// solution: each pair k = 1..K carries at least half the pulse's force
// rho c v0/2 A exactly while the exact solution presses it, [g0/v0 + (k-1)
// L/c, g0/v0 + (k+1) L/c], to within 2 tau + h/c at both ends; the last bar
// leaves with its speed within 5% of v0 and at least 90% of the energy,
// every other bar keeps less than 5% of v0; its position at T is within
// (2 tau + h/c) v0 of the exact one; the energy-norm error stays below
// 0.35 sqrt(E(0)) (about 0.2 here; an exact solution whose last bar did not
// leave would give at least 1, its kinetic energy alone); the total momentum
// is conserved to 1e-10 of the striker's; the per-pair active rows and
// forces and the per-body energies add up to the totals; E + W never
// increases (Theorem 3.2); N-CS++ has zero relative normal velocity at
// persistently active nodes (eq. 19).

#include "tests.h"

int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);
  using namespace testing;

  const unsigned int K = 3;
  const double       L = 1., H = 0.1, v0 = 1., g0 = 0.1, c = 1., T = 5.;
  struct Case
  {
    unsigned int dim, along;
    std::string  scheme;
  };
  for (const Case &run_case : {Case{2, 40, "N-CI"},
                               Case{2, 40, "N-CS"},
                               Case{2, 40, "N-CS++"},
                               Case{3, 20, "N-CS++"}})
    {
      const double       h = L / run_case.along, tau = h / (2. * c);
      const double       tolerance = 2. * tau + h / c;
      const double       area      = run_case.dim == 2 ? H : H * H;
      const double       mass      = L * area;
      std::ostringstream prm;
      prm << bar_prm(run_case.dim,
                     run_case.scheme,
                     run_case.along,
                     tau,
                     T,
                     scene_prm("bar chain",
                               "    set Bars in the chain = " +
                                 std::to_string(K) +
                                 "\n    set Cells along length = " +
                                 std::to_string(run_case.along) +
                                 "\n    set Cells across = " +
                                 (run_case.dim == 2 ? "4" : "2") + "\n") +
                       tight_steps())
          // the bars' geometry and the striker's speed and gap
          << scene_entries("Bar chain",
                           "    set Length = 1\n    set Height = 0.1\n"
                           "    set Impact velocity = 1\n"
                           "    set Initial gap = 0.1\n");
      const Statistics s = run(prm.str());
      log() << run_case.dim << "D, " << run_case.scheme << ":\n";

      const auto   time  = s.column("time");
      const double force = 0.5 * c * v0 * area; // rho c v0/2 A
      for (unsigned int k = 1; k <= K; ++k)
        {
          const auto f     = s.column("contact_force_pair" + std::to_string(k));
          double     begin = -1., end = -1.;
          for (unsigned int i = 0; i < f.size(); ++i)
            if (f[i] >= 0.5 * force)
              {
                if (begin < 0.)
                  begin = time[i];
                end = time[i];
              }
          const double exact_begin = g0 / v0 + (k - 1) * L / c,
                       exact_end   = g0 / v0 + (k + 1) * L / c;
          log() << "  pair " << k << " pressed from " << fmt(begin) << " to "
                << fmt(end) << " (exact " << fmt(exact_begin) << " to "
                << fmt(exact_end) << "): "
                << check(std::abs(begin - exact_begin) <= tolerance &&
                         std::abs(end - exact_end) <= tolerance)
                << "\n";
        }

      // bodies 2..K+1 from their columns, the striker from the total
      const auto   momentum = s.column("momentum_x");
      double       rest     = momentum.back();
      double       at_rest  = 0.;
      const double last =
        s.column("momentum_x_body" + std::to_string(K + 1)).back() / mass;
      for (unsigned int b = 2; b <= K + 1; ++b)
        {
          const double p =
            s.column("momentum_x_body" + std::to_string(b)).back();
          rest -= p;
          if (b <= K)
            at_rest = std::max(at_rest, std::abs(p / mass));
        }
      at_rest = std::max(at_rest, std::abs(rest / mass));
      const double kinetic_last =
        s.column("energy_kinetic_body" + std::to_string(K + 1)).back();
      log() << "  last bar leaves at " << fmt(last / v0, 2)
            << " v0: " << check(std::abs(last - v0) <= 0.05 * v0) << ", with "
            << fmt(kinetic_last / (0.5 * mass * v0 * v0), 2)
            << " of the energy: "
            << check(kinetic_last >= 0.9 * 0.5 * mass * v0 * v0)
            << ", the others below 0.05 v0: " << check(at_rest <= 0.05 * v0)
            << "\n";

      const double position =
        s.column("mean_displacement_x_body" + std::to_string(K + 1)).back();
      const double exact_position =
        L / c * v0 + v0 * (T - g0 / v0 - (K + 1) * L / c);
      log() << "  last bar's displacement at T " << fmt(position, 3)
            << " m (exact " << fmt(exact_position, 3) << "): "
            << check(std::abs(position - exact_position) <= tolerance * v0)
            << "\n";

      const double error = max_of(s.column("error_energy_norm")) /
                           std::sqrt(s.column("energy_total")[0]);
      log() << "  energy-norm error at most " << fmt(error, 1)
            << " of sqrt(E(0)) (below 0.35): " << check(error < 0.35) << "\n";

      double drift = 0.;
      for (const double p : momentum)
        drift = std::max(drift, std::abs(p - momentum[0]));
      log() << "  total momentum conserved to 1e-10: "
            << check(drift <= 1e-10 * mass * v0) << "\n";

      // the per-pair and per-body columns add up to the totals
      double pair_mismatch = 0., body_mismatch = 0.;
      for (unsigned int i = 0; i < time.size(); ++i)
        {
          double n_active = 0., pair_force = 0., kinetic = 0., elastic = 0.;
          for (unsigned int k = 1; k <= K; ++k)
            {
              n_active += s.column("active_nodes_pair" + std::to_string(k))[i];
              pair_force +=
                s.column("contact_force_pair" + std::to_string(k))[i];
            }
          for (unsigned int b = 1; b <= K + 1; ++b)
            {
              kinetic += s.column("energy_kinetic_body" + std::to_string(b))[i];
              elastic += s.column("energy_elastic_body" + std::to_string(b))[i];
            }
          pair_mismatch = std::max(
            {pair_mismatch,
             std::abs(n_active - s.column("active_nodes")[i]),
             std::abs(pair_force - s.column("contact_force")[i]) / force});
          body_mismatch =
            std::max({body_mismatch,
                      std::abs(kinetic - s.column("energy_kinetic")[i]),
                      std::abs(elastic - s.column("energy_elastic")[i])});
        }
      log() << "  pairs add up to the contact totals: "
            << check(pair_mismatch <= 1e-12) << ", bodies to the energies: "
            << check(body_mismatch <= 1e-12 * s.column("energy_total")[0])
            << "\n";

      log() << "  E + W non-increasing: "
            << check(max_energy_increase(s) <=
                     1e-10 * s.column("energy_total")[0])
            << "\n";
      if (run_case.scheme == "N-CS++")
        log() << "  relative normal velocity at persistently active nodes "
                 "zero: "
              << check(persistent_normal_velocity(s).first < 1e-8) << "\n";
    }
}
