// A small 3D bar impact with N-CS++ (and, as bar_impact_3d.mpirun=2, the
// same on two MPI ranks with the same output): contact timing, pressure,
// rebound and energy as in 2D; persistency; the energy-norm error; the
// printed statistics agree between the serial and the parallel run.

#include "tests.h"

int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);
  using namespace testing;

  const unsigned int cells = 20;
  const double       h = 1. / cells, tau = h / 2., L = 1., H = 0.1;
  const Statistics   s = run(bar_prm(3, "N-CS++", cells, tau, 2.5));

  const auto [begin, end] = contact_interval(s);
  const double tolerance  = 2. * tau + h;
  log() << "contact from " << fmt(begin) << " to " << fmt(end) << ": "
        << check(std::abs(begin - 0.1) <= tolerance &&
                 std::abs(end - 2.1) <= tolerance)
        << "\n";
  const double ratio = max_of(s.column("max_contact_pressure"));
  log() << "max pressure / (rho c v0) = " << fmt(ratio, 2) << ": "
        << check(std::abs(ratio - 1.) <= 0.15) << "\n";
  const double rebound = s.column("momentum_x").back() / (L * H * H);
  log() << "rebound velocity / v0 = " << fmt(rebound, 2) << ": "
        << check(std::abs(rebound - 1.) <= 0.05) << "\n";
  log() << "E_total non-increasing: "
        << check(max_energy_increase(s) <= 1e-10 * s.column("energy_total")[0])
        << "\n";
  const double vn_max = persistent_normal_velocity(s).first;
  log() << "normal velocity at persistently active nodes below 1e-8: "
        << check(vn_max < 1e-8) << "\n";
  log() << "max penetration below 1e-10: "
        << check(max_of(s.column("max_penetration")) < 1e-10) << "\n";

  // a few rows of the statistics, rounded
  for (const unsigned int step : {4u, 10u, 40u, 80u, 100u})
    log() << "step " << step << ": E_total "
          << fmt(s.column("energy_total")[step], 5) << ", momentum_x "
          << fmt(s.column("momentum_x")[step], 5) << ", active nodes "
          << s.column("active_nodes")[step] << ", contact force "
          << fmt(s.column("contact_force")[step], 4) << ", error "
          << fmt(s.column("error_energy_norm")[step], 4) << "\n";
}
