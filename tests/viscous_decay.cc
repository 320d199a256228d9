// Viscosity against theory: a free bar (E = 5 Pa, rho = 2 kg/m^3, nu = 0,
// L = 1.7 m, H = 0.17 m, far from the wall) released from a uniform axial
// strain eps0 = 0.01 vibrates in its odd longitudinal modes k_n = n pi / L,
// which hold the fraction 8 / (n pi)^2 of the energy E0 = E eps0^2 V / 2.
// With the viscous shear modulus mu_v = 0.05 Pa s (and no viscous Lame
// parameter, so that the bar stays one-dimensional: the viscous stress is
// 2 mu_v times the strain rate along it) each mode is a damped oscillator,
// rho a'' + 2 mu_v k^2 a' + E k^2 a = 0, from rest: its energy decays by
// e^{-2 alpha t} [(cos w t + alpha/w sin w t)^2 + (w0/w)^2 sin^2 w t],
// alpha = mu_v k^2 / rho, w0 = c k, w^2 = w0^2 - alpha^2 (cosh and sinh
// where the mode is overdamped). The statistics must follow the sum over
// the modes: E(t) / E0 and the viscous work W(t) / E0 = 1 - E(t) / E0 at
// t = 1, 2, 4, 8 s within 1 % of E(t), in 2D (40 cells along) and 3D (20);
// twice the viscosity would give a decay several times faster (printed).
// (The viscous Lame parameter is checked by no closed form here.)

#include "tests.h"

namespace
{
  const double E = 5., rho = 2., L = 1.7, H = 0.17, eps0 = 0.01,
               pi = 3.14159265358979323846;

  /// E(t) / E0 of the bar of viscous shear modulus @p mu_v (the sum over
  /// the odd modes up to n = 20001).
  double
  energy_fraction(const double t, const double mu_v)
  {
    const double c   = std::sqrt(E / rho);
    double       sum = 0.;
    for (unsigned int n = 1; n <= 20001; n += 2)
      {
        const double k = n * pi / L, alpha = mu_v * k * k / rho, w0 = c * k,
                     share = 8. / (n * n * pi * pi);
        double f;
        if (alpha < w0)
          {
            const double w = std::sqrt(w0 * w0 - alpha * alpha);
            const double a = std::cos(w * t) + alpha / w * std::sin(w * t);
            const double v = w0 / w * std::sin(w * t);
            f              = std::exp(-2. * alpha * t) * (a * a + v * v);
          }
        else
          {
            const double b = std::sqrt(alpha * alpha - w0 * w0);
            // (e^{-alpha t} cosh(b t) etc. without overflow)
            const double ep = std::exp((b - alpha) * t),
                         em = std::exp(-(b + alpha) * t);
            const double ch = 0.5 * (ep + em), sh = 0.5 * (ep - em);
            const double a = ch + alpha / b * sh;
            const double v = w0 / b * sh;
            f              = a * a + v * v;
          }
        sum += share * f;
      }
    return sum;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  using namespace testing;

  const double mu_v = 0.05, tau = 0.01;
  for (const unsigned int dim : {2u, 3u})
    {
      const unsigned int cells = dim == 2 ? 40 : 20;
      std::ostringstream extra;
      extra << std::setprecision(17)
            << scene_entries("Bar impact",
                             "    set Length = 1.7\n    set Height = 0.17\n"
                             "    set Impact velocity = 0\n"
                             "    set Initial gap = 100\n"
                             "    set Initial strain = 0.01\n")
            << "subsection Material\n  set Young's modulus = " << E
            << "\n  set Density = " << rho
            << "\n  set Poisson's ratio = 0\n  set Viscous shear modulus = "
            << mu_v << "\nend\n";
      const Statistics s =
        run(bar_prm(dim, "N-CS++", cells, tau, 8., extra.str()));
      const double V  = L * (dim == 2 ? H : H * H);
      const double E0 = 0.5 * E * eps0 * eps0 * V;
      log() << dim << "D, " << cells << " cells along: E(0) = E eps0^2 V / 2 "
            << "(1e-10): "
            << check(std::abs(s.column("energy_total")[0] / E0 - 1.) <= 1e-10)
            << "\n";
      for (const double t : {1., 2., 4., 8.})
        {
          const unsigned int step   = std::lround(t / tau);
          const double       exact  = energy_fraction(t, mu_v);
          const double       energy = s.column("energy_total")[step] / E0;
          const double       work = s.column("dissipation_viscous")[step] / E0;
          log() << "  t = " << t << " s: E/E0 " << fmt(energy, 4) << ", W/E0 "
                << fmt(work, 4) << " (closed form " << fmt(exact, 4) << ", "
                << fmt(1. - exact, 4) << "; with 2 mu_v "
                << fmt(energy_fraction(t, 2. * mu_v), 3) << "): "
                << check(std::abs(s.column("time")[step] - t) < 1e-9 &&
                         std::abs(energy - exact) <= 0.01 * exact &&
                         std::abs(work - (1. - exact)) <= 0.01 * exact)
                << "\n";
        }
    }
}
