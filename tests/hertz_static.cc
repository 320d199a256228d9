// Hertz contact in 2D plane strain, static scheme: a half-cylinder (R = 1,
// E = 1, nu = 0.3) pressed into an elastic block by a load P = 0.005 per unit
// thickness; by symmetry half of it is meshed, refined towards the contact.
// The computed contact half-width (the measure of the active set) and peak
// pressure are within 10% of Hertz's b = sqrt(4PR/(pi E*)) and
// p0 = 2P/(pi b); the normal contact forces carry the load (P/2 on the
// half model); nothing penetrates. Run also on two MPI ranks with the same
// output.

#include "tests.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  using namespace testing;

  const std::string prm = "set Dimension = 2\n"
                          "set Output directory = results-hertz\n"
                          "subsection Scene\n"
                          "  set Name = hertz\n"
                          "  subsection Hertz\n"
                          "    set Initial gap = 0\n"
                          "    set Load = 0.005\n"
                          "    set Contact zone refinements = 4\n"
                          "  end\n"
                          "end\n"
                          "subsection Mesh\n"
                          "  set Initial global refinements = 2\n"
                          "end\n"
                          "subsection Material\n"
                          "  set Poisson's ratio = 0.3\n"
                          "end\n"
                          "subsection Material of body 2\n"
                          "  set Poisson's ratio = 0.3\n"
                          "end\n"
                          "subsection Time integration\n"
                          "  set Scheme = static\n"
                          "end\n"
                          "subsection Output\n"
                          "  set Write vtu = false\n"
                          "end\n";
  const Statistics  s   = run(prm);

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
}
