// Scales: the bar impact with E = 5 Pa, rho = 2 kg/m^3, v0 = 0.3 m/s,
// L = 1.7 m, H = 0.17 m and g0 = 0.05 m (c = sqrt(E/rho)), all different
// from 1 and from each other, against the same bar in the units of the
// problem (E = rho = v0 = L = 1, H = 0.1, g0 = g0 c/(v0 L), tau c/L): the
// equations of elastodynamics with contact are invariant under that change
// of units, so every statistic, made dimensionless by its natural size, is
// the same in both runs, step by step, to round-off: the time by L/c, the
// energies by E0 = rho V v0^2/2, the momentum by rho V v0, the contact force
// by rho c v0 A (A = H, H^2 in 3D) and the pressure by rho c v0, the mean
// displacement by v0 L/c, and the energy-norm error against the exact
// solution by sqrt(E0). A density, a modulus or a velocity that enters
// anywhere with a wrong power (the mass without its density, the exact
// solution with the wrong wave speed) breaks it. In 2D and 3D, elastic
// (nu = 0, with the error norm) and viscous (nu = 0.25, viscosities
// mu_v = 0.2, lambda_v = 0.1 Pa s, in the unit run scaled by c/(E L)).

#include <map>

#include "tests.h"

namespace
{
  struct Units
  {
    double E, rho, v0, L, H, g0, nu, mu_v, lambda_v;
  };

  /// The bar of @p u with @p cells along, tau = h/(2c), to t = 2.6 L/c.
  std::string
  bar(const unsigned int dim, const unsigned int cells, const Units &u)
  {
    const double       c = std::sqrt(u.E / u.rho);
    std::ostringstream s;
    s << std::setprecision(17)
      << testing::scene_entries(
           "Bar impact",
           "    set Length = " + testing::fmt(u.L, 17) +
             "\n    set Height = " + testing::fmt(u.H, 17) +
             "\n    set Impact velocity = " + testing::fmt(u.v0, 17) +
             "\n    set Initial gap = " + testing::fmt(u.g0, 17) + "\n")
      << "subsection Material\n  set Young's modulus = " << u.E
      << "\n  set Density = " << u.rho << "\n  set Poisson's ratio = " << u.nu
      << "\n  set Viscous shear modulus = " << u.mu_v
      << "\n  set Viscous Lame parameter = " << u.lambda_v << "\nend\n";
    const double tau = u.L / cells / (2. * c);
    return testing::bar_prm(
      dim, "N-CS++", cells, tau, 2.6 * cells * 2. * tau, s.str());
  }
} // namespace

int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);
  using namespace testing;

  for (const unsigned int dim : {2u, 3u})
    for (const bool viscous : {false, true})
      {
        Units scaled{5., 2., 0.3, 1.7, 0.17, 0.05, 0., 0., 0.};
        if (viscous)
          {
            scaled.nu       = 0.25;
            scaled.mu_v     = 0.2;
            scaled.lambda_v = 0.1;
          }
        const double       c = std::sqrt(scaled.E / scaled.rho);
        Units              unit{1.,
                   1.,
                   1.,
                   1.,
                   scaled.H / scaled.L,
                   scaled.g0 * c / (scaled.v0 * scaled.L),
                   scaled.nu,
                   scaled.mu_v * c / (scaled.E * scaled.L),
                   scaled.lambda_v * c / (scaled.E * scaled.L)};
        const unsigned int cells = dim == 2 ? 20 : 10;
        const Statistics   a     = run(bar(dim, cells, scaled));
        const Statistics   b     = run(bar(dim, cells, unit));

        // the natural size of each column, in the scaled and the unit run
        const auto sizes = [&](const Units &u) {
          const double A  = dim == 2 ? u.H : u.H * u.H;
          const double V  = u.L * A;
          const double cu = std::sqrt(u.E / u.rho);
          const double E0 = 0.5 * u.rho * V * u.v0 * u.v0;
          return std::map<std::string, double>{
            {"time", u.L / cu},
            {"energy_kinetic", E0},
            {"energy_elastic", E0},
            {"energy_total", E0},
            {"dissipation_viscous", E0},
            {"momentum_x", u.rho * V * u.v0},
            {"contact_force", u.rho * cu * u.v0 * A},
            {"max_contact_pressure", u.rho * cu * u.v0},
            {"mean_displacement_x", u.v0 * u.L / cu},
            {"error_energy_norm", std::sqrt(E0)},
            {"active_nodes", 1.}};
        };
        const auto   size_a = sizes(scaled), size_b = sizes(unit);
        double       worst = a.rows.size() == b.rows.size() ? 0. : 1e300;
        std::string  worst_column;
        unsigned int compared = 0;
        for (const auto &[name, size] : size_a)
          {
            if (!a.has_column(name) || !b.has_column(name))
              continue;
            ++compared;
            const auto x = a.column(name), y = b.column(name);
            for (unsigned int i = 0; i < x.size() && i < y.size(); ++i)
              if (std::isfinite(x[i]) || std::isfinite(y[i]))
                {
                  const double d =
                    std::abs(x[i] / size - y[i] / size_b.at(name));
                  if (!(d <= worst))
                    {
                      worst        = d;
                      worst_column = name;
                    }
                }
          }
        const double contact_time =
          contact_interval(a).first / size_a.at("time");
        log() << dim << "D, " << (viscous ? "viscous" : "elastic") << ", "
              << a.rows.size() - 1 << " steps, " << compared
              << " columns: the scaled and the unit run agree in units of "
                 "their natural sizes to 1e-8: "
              << check(worst <= 1e-8 && compared == (viscous ? 10u : 11u))
              << " (contact at " << fmt(contact_time, 3) << " L/c, peak "
              << fmt(max_of(a.column("max_contact_pressure")) /
                       size_a.at("max_contact_pressure"),
                     2)
              << " rho c v0)\n";
        if (!(worst <= 1e-8))
          std::cout << "largest difference " << worst << " in " << worst_column
                    << std::endl;
      }
}
