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
//
// The viscous Lame parameter: a bar of the Gmsh scene in plane strain
// (E = 5 Pa, nu = 0.25, so lambda = mu = 2 Pa and the P-wave modulus
// M = lambda + 2 mu = 6 Pa; rho = 2 kg/m^3, L = 1.7 m, H = 0.17 m, 40 x 4
// cells), on rollers along its long sides (u_y = 0: 'Dirichlet tags = 10: y,
// 11: y') and at its end x = 0 (u_x = 0: '12: x'), from rest at u = 0 with
// the velocity v0 = 0.3 m/s along it, stays one-dimensional: u_x(x, t) with
// the stress M u_x' + M_v u_x'_t, M_v = lambda_v + 2 mu_v. Its modes
// k_n = (2n - 1) pi / (2L) hold the fraction 8 / ((2n - 1) pi)^2 of
// E0 = rho V v0^2 / 2 and decay as damped oscillators from q = 0, q' = 1:
// e^{-2 alpha t} [(cos w t - alpha/w sin w t)^2 + (w0/w)^2 sin^2 w t],
// alpha = M_v k^2 / (2 rho), w0 = sqrt(M / rho) k. With lambda_v = 0.1 Pa s
// alone, and with lambda_v = mu_v = 0.05 Pa s, E(t) / E0 and W(t) / E0 at
// t = 1, 2, 4 s within 1 % of E(t) (without lambda_v the energy left would
// be the larger value printed). The nodes of the end x = 0 start at rest:
// E(0) lacks their lumped mass's share h / 2L of E0, and W(t) is
// E(0) - E(t).

#include "tests.h"

namespace
{
  const double E = 5., rho = 2., L = 1.7, H = 0.17, eps0 = 0.01,
               pi = 3.14159265358979323846;

  /// E(t) / E0 of a bar of modulus @p modulus and viscous modulus
  /// @p viscous_modulus (the stress modulus u' + viscous_modulus u'_t) in the
  /// modes k = n pi / (2 L) of odd n up to 40001 (a free bar from a uniform
  /// strain if @p from_strain, of wavelengths 2L / m of odd m = n / 2; a bar
  /// fixed at one end from a uniform velocity otherwise, of 4L / n).
  double
  energy_fraction(const double t,
                  const double viscous_modulus,
                  const double modulus     = E,
                  const bool   from_strain = true)
  {
    const double c   = std::sqrt(modulus / rho);
    double       sum = 0.;
    for (unsigned int n = from_strain ? 2 : 1; n <= 40001;
         n += from_strain ? 4 : 2)
      {
        const double m     = from_strain ? n / 2 : n;
        const double k     = n * pi / (2. * L),
                     alpha = viscous_modulus * k * k / (2. * rho), w0 = c * k,
                     share = 8. / (m * m * pi * pi);
        // (from a strain the mode starts at rest, q(0) = 1; from a velocity
        // at q(0) = 0, q'(0) = 1: the sign of the alpha term)
        const double sign = from_strain ? 1. : -1.;
        double       f;
        if (alpha < w0)
          {
            const double w = std::sqrt(w0 * w0 - alpha * alpha);
            const double a =
              std::cos(w * t) + sign * alpha / w * std::sin(w * t);
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
            const double a = ch + sign * alpha / b * sh;
            const double v = w0 / b * sh;
            f              = a * a + v * v;
          }
        sum += share * f;
      }
    return sum;
  }

  /// One line: E(t)/E0 and W(t)/E0 of @p s at time @p t against the closed
  /// form @p exact of E(t)/E0 (and W = @p start - exact, where start is
  /// E(0)/E0), with the energy left under another viscosity, @p other
  /// (after @p other_name), for comparison; OK within 1 % of E(t)/E0.
  void
  compare_decay(const testing::Statistics &s,
                const double               tau,
                const double               t,
                const double               E0,
                const double               start,
                const double               exact,
                const std::string         &other_name,
                const double               other)
  {
    using namespace testing;
    const unsigned int step   = std::lround(t / tau);
    const double       energy = s.column("energy_total")[step] / E0;
    const double       work   = s.column("dissipation_viscous")[step] / E0;
    log() << "  t = " << t << " s: E/E0 " << fmt(energy, 4) << ", W/E0 "
          << fmt(work, 4) << " (closed form " << fmt(exact, 4) << ", "
          << fmt(start - exact, 4) << "; " << other_name << " " << fmt(other, 3)
          << "): "
          << check(std::abs(s.column("time")[step] - t) < 1e-9 &&
                   std::abs(energy - exact) <= 0.01 * exact &&
                   std::abs(work - (start - exact)) <= 0.01 * exact)
          << "\n";
  }
} // namespace

int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);
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
        compare_decay(s,
                      tau,
                      t,
                      E0,
                      1.,
                      energy_fraction(t, 2. * mu_v),
                      "with 2 mu_v",
                      energy_fraction(t, 4. * mu_v));
    }

  // the viscous Lame parameter: the plane-strain bar on rollers
  const double nu = 0.25, M = E * (1. - nu) / ((1. + nu) * (1. - 2. * nu)),
               v0 = 0.3;
  write_block_msh("bar.msh", {Block{0., L, 0., H, 40, 4, 1, 10, 11, 12}});
  for (const auto &[lambda_v, mu_v_gmsh] :
       std::vector<std::pair<double, double>>{{0.1, 0.}, {0.05, 0.05}})
    {
      std::ostringstream prm;
      prm << std::setprecision(17) << "set Dimension = 2\n"
          << "set Output directory = results-rollers\n"
          << scene_prm("gmsh",
                       "    set Mesh file = bar.msh\n    set Bodies = 1\n"
                       "    set Dirichlet tags = 10: y, 11: y, 12: x\n"
                       "    set Initial velocities = " +
                         fmt(v0, 17) + ", 0\n")
          << "subsection Material\n  set Young's modulus = " << E
          << "\n  set Poisson's ratio = " << nu << "\n  set Density = " << rho
          << "\n  set Viscous shear modulus = " << mu_v_gmsh
          << "\n  set Viscous Lame parameter = " << lambda_v << "\nend\n"
          << "subsection Time integration\n  set Scheme = N-CS++\n"
          << "  set Time step = " << tau << "\n  set End time = 4\nend\n"
          << "subsection Output\n  set Write vtu = false\nend\n";
      const Statistics s = run(prm.str());
      // (the nodes of the end x = 0 start at rest: the lumped mass h / 2L
      // of the bar's has no energy at t = 0)
      const double E0 = 0.5 * rho * L * H * v0 * v0, start = 1. - 1. / 80.;
      const double Mv = lambda_v + 2. * mu_v_gmsh;
      log() << "plane strain on rollers, lambda_v = " << lambda_v
            << ", mu_v = " << mu_v_gmsh
            << ": E(0) = (1 - h / 2L) rho V v0^2 / 2 (1e-10): "
            << check(std::abs(s.column("energy_total")[0] / E0 - start) <=
                     1e-10)
            << ", no motion across (1e-12): "
            << check(max_of(s.column("momentum_y")) <= 1e-12 * E0 &&
                     min_of(s.column("momentum_y")) >= -1e-12 * E0)
            << "\n";
      for (const double t : {1., 2., 4.})
        compare_decay(s,
                      tau,
                      t,
                      E0,
                      start,
                      energy_fraction(t, Mv, M, false),
                      "without lambda_v",
                      energy_fraction(t, 2. * mu_v_gmsh, M, false));
    }
}
