// Hertz contact in 2D plane strain, static scheme: a half-cylinder (R = 1,
// E = 1, nu = 0.3) pressed into an elastic block by a load P = 0.005 per unit
// thickness; by symmetry half of it is meshed, refined towards the contact.
// The computed contact half-width (the measure of the active set) and peak
// pressure are within 10% of Hertz's b = sqrt(4PR/(pi E*)) and
// p0 = 2P/(pi b); the normal contact forces carry the load (P/2 on the
// half model); nothing penetrates. The same with R = 2.3, E = 7 and
// P = 0.005 E R, the problem in other units: its ratios to Hertz's agree as
// well, and b/R, p0/E, the force over P and the potential energy over
// P^2/E equal the unit run's to round-off. Run also on two MPI ranks with the
// same output.

#include "tests.h"

int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);
  using namespace testing;

  // the half-cylinder of radius R on a block 4R wide and deep, both of
  // modulus E, pressed by P
  const auto prm = [](const double R, const double E, const double P) {
    std::ostringstream s;
    s << std::setprecision(17) << "set Dimension = 2\n"
      << "set Output directory = results-hertz\n"
      << "subsection Scene\n  set Name = hertz\n  subsection Hertz\n"
      << "    set Initial gap = 0\n    set Load = " << P
      << "\n    set Radius = " << R << "\n    set Block width = " << 4. * R
      << "\n    set Block depth = " << 4. * R
      << "\n    set Contact zone refinements = 4\n  end\nend\n"
      << "subsection Mesh\n  set Initial global refinements = 2\nend\n";
    for (const std::string material : {"Material", "Material of body 2"})
      s << "subsection " << material << "\n  set Young's modulus = " << E
        << "\n  set Poisson's ratio = 0.3\nend\n";
    s << "subsection Time integration\n  set Scheme = static\nend\n"
      << "subsection Output\n  set Write vtu = false\nend\n";
    return s.str();
  };
  const Statistics s = run(prm(1., 1., 0.005));

  const double P = 0.005, R = 1., E_star = 1. / (2. * (1. - 0.3 * 0.3));
  const double b  = std::sqrt(4. * P * R / (M_PI * E_star));
  const double p0 = 2. * P / (M_PI * b);

  const double b_h   = s.column("active_measure").back();
  const double p0_h  = s.column("max_contact_pressure").back();
  const double force = s.column("contact_force").back();
  log() << "contact half-width / Hertz's b = " << fmt(b_h / b, 3) << ": "
        << check(std::abs(b_h / b - 1.) <= 0.1) << "\n";
  log() << "peak pressure / Hertz's p0 = " << fmt(p0_h / p0, 3) << ": "
        << check(std::abs(p0_h / p0 - 1.) <= 0.1) << "\n";
  // the sum of the normal forces: the normals of the rows point to the
  // closest points on the curved cylinder, so they tilt slightly and the
  // sum of their magnitudes exceeds the vertical load a little
  log() << "sum of normal contact forces / (P/2) = " << fmt(force / (P / 2.), 3)
        << ": "
        << check(force >= P / 2. * (1. - 1e-8) && force <= P / 2. * 1.01)
        << "\n";
  log() << "no penetration: "
        << check(s.column("max_penetration").back() <= 1e-12) << "\n";
  log() << "active-set iterations: "
        << check(s.column("active_set_iterations").back() < 30) << "\n";

  // the same contact with R = 2.3 m, E = 7 Pa and P = 0.005 E R: the
  // problem in other units (lengths by R, stresses by E), so that b/R,
  // p0/E, the force over P and the energy over P^2/E are those of the unit
  // run to round-off, and within 10% of Hertz's as there
  {
    const double     R2 = 2.3, E2 = 7., P2 = 0.005 * E2 * R2;
    const Statistics t       = run(prm(R2, E2, P2));
    const double     E2_star = E2 / (2. * (1. - 0.3 * 0.3));
    const double     b2      = std::sqrt(4. * P2 * R2 / (M_PI * E2_star));
    const double     p2      = 2. * P2 / (M_PI * b2);
    const double     b2_h    = t.column("active_measure").back();
    const double     p2_h    = t.column("max_contact_pressure").back();
    const double     force2  = t.column("contact_force").back();
    // (the potential energy in units of P^2 / E)
    const double u  = s.column("energy_elastic").back() / (P * P / 1.);
    const double u2 = t.column("energy_elastic").back() / (P2 * P2 / E2);
    log() << "R = 2.3, E = 7, P = 0.005 E R: half-width / b = "
          << fmt(b2_h / b2, 3) << ", peak pressure / p0 = " << fmt(p2_h / p2, 3)
          << ": "
          << check(std::abs(b2_h / b2 - 1.) <= 0.1 &&
                   std::abs(p2_h / p2 - 1.) <= 0.1)
          << "; b/R, p0/E, force/P and the energy over P^2/E as in the unit "
             "run (1e-8): "
          << check(std::abs(b2_h / R2 - b_h) <= 1e-8 * b_h &&
                   std::abs(p2_h / E2 - p0_h) <= 1e-8 * p0_h &&
                   std::abs(force2 / P2 - force / P) <= 1e-8 &&
                   std::abs(u2 - u) <= 1e-8 * std::abs(u) && std::abs(u) > 0.)
          << "\n";
  }
}
