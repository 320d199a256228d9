// Unit tests of the time integrators against their formulas computed by
// hand, on a 1-DoF system (mass m, stiffness k, viscosity b, load f, a wall
// u <= g) and a 2-DoF two-body system (two masses on springs, the row
// u0 - u1 <= g): N-CI (11c-d), N-CS (predictor P, displacement step,
// velocity update), N-CS++ (12c-f), and the static problem, each in a step
// that comes into contact and in one that stays free; so that a wrong sign
// or factor in one scheme fails a line that names it. Also: the critical set
// (eq. 40), the velocity correction, the multipliers, the vanishing relative
// normal velocity (eq. 19) and the momentum that the M-projection keeps for
// two bodies. And N-CS++ with Numerical dissipation theta: S = m + (1/4 +
// theta/2) tau^2 k + tau/2 b, r(w) = m w - (1/4 - theta/2) tau^2 k u0 + ...

#include <deal.II/base/mpi.h>

#include <dyncontact/time_stepping/integrators.h>

#include <algorithm>
#include <fstream>
#include <iomanip>
#include <string>

#include "algebra.h"

using namespace algebra;
using namespace dyncontact;

std::ofstream out("output");

void
report(const std::string &what, const bool ok)
{
  out << what << ": " << (ok ? "OK" : "FAILED") << "\n";
}

/// The state after one step of @p scheme from (u0, v0), or after the
/// initial velocity if @p initialize.
struct Outcome
{
  std::vector<double> u, udot;
  StepReport          report;
};

Outcome
one_step(const std::string                      &scheme,
         const std::vector<std::vector<double>> &M_entries,
         const std::vector<std::vector<double>> &A_entries,
         const std::vector<std::vector<double>> &B_entries,
         const std::vector<double>              &f_values,
         const ContactRow                       &row,
         const double                            tau,
         const std::vector<double>              &u0,
         const std::vector<double>              &v0,
         const bool                              initialize = false,
         const double                            theta      = 0.)
{
  const unsigned int n = u0.size();
  MatrixType         A, B;
  make_matrix(A, A_entries);
  make_matrix(B, B_entries);
  const VectorType f = make_vector(f_values);
  // the lumped mass as its diagonal (M_entries is diagonal)
  std::vector<double> M_diagonal;
  for (unsigned int i = 0; i < n; ++i)
    M_diagonal.push_back(M_entries[i][i]);
  const VectorType M_lumped = make_vector(M_diagonal);
  CachedProduct    A_product;
  A_product.reinit([&A](VectorType &y, const VectorType &x) { A.vmult(y, x); });
  SystemMatrices system;
  system.M_lumped  = &M_lumped;
  system.A_product = &A_product;
  system.B_vmult = [&B](VectorType &y, const VectorType &x) { B.vmult(y, x); };
  system.assemble_stiffness = [&A, &B, &system](MatrixType  &matrix,
                                                const double a,
                                                const double b,
                                                const double m) {
    matrix.copy_from(A);
    matrix *= a;
    matrix.add(b, B);
    system.add_mass(matrix, m);
  };
  system.f     = &f;
  system.f_end = &f;
  ContactRows rows;
  rows.rows                                        = {row};
  const auto                           constraints = no_constraints(n);
  const ActiveSetSolver::Parameters    solver_parameters;
  const ActiveSetSolver::NearNullSpace near_null_space;
  const IndexSet                       dofs = all(n);
  TimeIntegrator                       integrator(scheme_by_name(scheme),
                            theta,
                            tau,
                            {system,
                                                   solver_parameters,
                                                   dofs,
                                                   dofs,
                                                   constraints,
                                                   rows,
                                                   near_null_space,
                                                   MPI_COMM_WORLD});
  VectorType u = make_vector(u0), udot = make_vector(v0);
  Outcome    outcome;
  outcome.report = initialize ? integrator.initialize(tau, u, udot) :
                                integrator.step(tau, true, u, udot);
  for (unsigned int i = 0; i < n; ++i)
    {
      outcome.u.push_back(u(i));
      outcome.udot.push_back(udot(i));
    }
  return outcome;
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  out << std::setprecision(6);

  // ---- one DoF: m u'' + b u' + k u = f, wall u <= g ----
  const double m = 2., k = 50., b = 0.3, f = -1., g = 0.05, tau = 0.1;
  const double S = m + tau * tau / 4. * k + tau / 2. * b;
  // r(w) = m w - tau^2/4 k u0 + tau/2 b u0 + tau^2/2 f
  auto r = [&](const double w, const double u0) {
    return m * w - tau * tau / 4. * k * u0 + tau / 2. * b * u0 +
           tau * tau / 2. * f;
  };
  const ContactRow wall = make_row({0}, {1.}, 1, g);
  auto             run1 = [&](const std::string &scheme,
                  const double       u0,
                  const double       v0,
                  const bool         initialize = false) {
    return one_step(
      scheme, {{m}}, {{k}}, {{b}}, {f}, wall, tau, {u0}, {v0}, initialize);
  };

  for (const auto &[u0, v0, what] :
       {std::make_tuple(0.02, 1., "into contact, rebounding"),
        std::make_tuple(0.02, 0.5, "into contact, persistent"),
        std::make_tuple(0.02, -0.5, "free")})
    {
      out << "1 DoF, a step " << what << " (u0 + tau v0 = " << u0 + tau * v0
          << ", g = " << g << "):\n";
      // N-CI: u1 = argmin_{v<=g} 1/2 S v^2 - r(u0 + tau v0) v
      {
        const double r1 = r(u0 + tau * v0, u0);
        const double u1 = std::min(r1 / S, g);
        const double v1 = 2. / tau * (u1 - u0) - v0;
        const double mu = (r1 / S > g) ? r1 - S * u1 : 0.;
        const auto   o  = run1("N-CI", u0, v0);
        report("  N-CI: u = " + std::to_string(o.u[0]) +
                 ", udot = " + std::to_string(o.udot[0]) +
                 ", mu = " + std::to_string(o.report.multipliers[0]),
               close(o.u[0], u1) && close(o.udot[0], v1) &&
                 close(o.report.multipliers[0], mu) &&
                 o.report.critical[0] == 0 &&
                 o.report.velocity_correction == 0.);
      }
      // N-CS: u_pred = P(u0 + tau v0); u1 = argmin 1/2 S v^2 - r(u_pred) v;
      // udot1 = v0 + 2/tau (u1 - u_pred)
      {
        const double u_pred = std::min(u0 + tau * v0, g);
        const double r1     = r(u_pred, u0);
        const double u1     = std::min(r1 / S, g);
        const double v1     = v0 + 2. / tau * (u1 - u_pred);
        // critical: the predictor's projection active, the step not
        const bool   critical = (u0 + tau * v0 > g) && !(r1 / S > g);
        const double correction =
          std::sqrt(m) * std::abs(u_pred - (u0 + tau * v0)) / tau;
        const auto o = run1("N-CS", u0, v0);
        report("  N-CS: u = " + std::to_string(o.u[0]) +
                 ", udot = " + std::to_string(o.udot[0]) + ", correction = " +
                 std::to_string(o.report.velocity_correction),
               close(o.u[0], u1) && close(o.udot[0], v1) &&
                 o.report.critical[0] == critical &&
                 close(o.report.velocity_correction, correction));
      }
      // N-CS++: (12d) u1 as N-CI; (12e) udot_pred = 2/tau (u1 - u0) - v0;
      // (12f) udot1 = (P(u1 + tau udot_pred) - u1) / tau
      {
        const double r1        = r(u0 + tau * v0, u0);
        const double u1        = std::min(r1 / S, g);
        const double udot_pred = 2. / tau * (u1 - u0) - v0;
        const double v1        = (std::min(u1 + tau * udot_pred, g) - u1) / tau;
        const bool   critical  = (u1 + tau * udot_pred > g) && !(r1 / S > g);
        const double correction = std::sqrt(m) * std::abs(v1 - udot_pred);
        const auto   o          = run1("N-CS++", u0, v0);
        report("  N-CS++: u = " + std::to_string(o.u[0]) +
                 ", udot = " + std::to_string(o.udot[0]) + ", correction = " +
                 std::to_string(o.report.velocity_correction),
               close(o.u[0], u1) && close(o.udot[0], v1) &&
                 o.report.critical[0] == critical &&
                 close(o.report.velocity_correction, correction));
        // eq. (19): where the projection is active, the node leaves the
        // step with zero normal velocity
        if (u1 + tau * udot_pred > g)
          report("  N-CS++: the projection is active and the velocity zero",
                 o.report.projection_active[0] == 1 &&
                   std::abs(o.udot[0]) < 1e-12);
      }
      // (12c): udot0 = (P(u0 + tau v0) - u0) / tau; the others keep v0
      {
        const double v1 = (std::min(u0 + tau * v0, g) - u0) / tau;
        const auto   o  = run1("N-CS++", u0, v0, true);
        const auto   c  = run1("N-CI", u0, v0, true);
        report("  N-CS++ initial velocity (12c): udot0 = " +
                 std::to_string(o.udot[0]) + ", N-CI keeps v0",
               close(o.udot[0], v1) && close(o.u[0], u0) &&
                 close(c.udot[0], v0));
      }
    }

  // N-CS++ with numerical dissipation theta: A acts on (1/2 + theta) u1 +
  // (1/2 - theta) u0
  for (const auto &[u0, v0, what] : {std::make_tuple(0.02, 0.5, "into contact"),
                                     std::make_tuple(0.02, -0.5, "free")})
    {
      const double theta = 0.2;
      const double S_theta =
        m + (0.25 + 0.5 * theta) * tau * tau * k + tau / 2. * b;
      const double r1 = m * (u0 + tau * v0) -
                        (0.25 - 0.5 * theta) * tau * tau * k * u0 +
                        tau / 2. * b * u0 + tau * tau / 2. * f;
      const double u1        = std::min(r1 / S_theta, g);
      const double udot_pred = 2. / tau * (u1 - u0) - v0;
      const double v1        = (std::min(u1 + tau * udot_pred, g) - u1) / tau;
      const auto   o         = one_step("N-CS++",
                              {{m}},
                              {{k}},
                              {{b}},
                              {f},
                              wall,
                              tau,
                              {u0},
                              {v0},
                              false,
                              theta);
      // the step's numerical dissipation theta k (u1 - u0)^2
      const double dissipated = theta * k * (u1 - u0) * (u1 - u0);
      report("1 DoF, N-CS++ with theta = 0.2, a step " + std::string(what) +
               ": u = " + std::to_string(o.u[0]) +
               ", udot = " + std::to_string(o.udot[0]) +
               ", mu = " + std::to_string(o.report.multipliers[0]) +
               ", dissipated " + std::to_string(o.report.numerical_dissipation),
             close(o.u[0], u1) && close(o.udot[0], v1) &&
               close(o.report.numerical_dissipation, dissipated) &&
               close(o.report.multipliers[0],
                     r1 / S_theta > g ? r1 - S_theta * u1 : 0.) &&
               // (theta changes the step)
               !(close(o.u[0], run1("N-CS++", u0, v0).u[0]) &&
                 close(o.report.multipliers[0],
                       run1("N-CS++", u0, v0).report.multipliers[0])));
    }

  // static: min 1/2 k v^2 - f v on v <= g: v = min(f/k, g), udot = 0
  for (const double load : {-1., 10.})
    {
      const auto o =
        one_step("static", {{m}}, {{k}}, {{b}}, {load}, wall, tau, {0.}, {1.});
      const double v = std::min(load / k, g);
      report("static, f = " + std::to_string(load) +
               ": u = " + std::to_string(o.u[0]) +
               ", force = " + std::to_string(o.report.multipliers[0]),
             close(o.u[0], v) && o.udot[0] == 0. &&
               close(o.report.multipliers[0],
                     load > k * g ? load - k * g : 0.));
    }

  // ---- two DoFs: two bodies on springs, row u0 - u1 <= g ----
  {
    const double              m0 = 1., m1 = 3., k0 = 20., k1 = 40., gap = 0.01;
    const std::vector<double> u0 = {0., 0.}, v0 = {0.1, -0.05};
    const ContactRow          pair = make_row({0, 1}, {1., -1.}, 1, gap);
    auto                      run2 = [&](const std::string &scheme) {
      return one_step(scheme,
                      {{m0, 0.}, {0., m1}},
                      {{k0, 0.}, {0., k1}},
                      {{0., 0.}, {0., 0.}},
                      {0., 0.},
                      pair,
                      tau,
                      u0,
                      v0);
    };
    // displacement step: argmin 1/2 v^T S v - r^T v, c.v <= g with S =
    // diag(s0, s1), c = (1, -1): v = S^{-1}(r - mu c), mu from c.v = g
    const double s0 = m0 + tau * tau / 4. * k0, s1 = m1 + tau * tau / 4. * k1;
    const double r0 = m0 * (u0[0] + tau * v0[0]) - tau * tau / 4. * k0 * u0[0];
    const double r1 = m1 * (u0[1] + tau * v0[1]) - tau * tau / 4. * k1 * u0[1];
    const double mu = (r0 / s0 - r1 / s1 - gap) / (1. / s0 + 1. / s1);
    const double w0 = (r0 - mu) / s0, w1 = (r1 + mu) / s1;
    out << "2 DoFs, two bodies (c.(u0 + tau v0) = "
        << u0[0] + tau * v0[0] - u0[1] - tau * v0[1] << ", g = " << gap
        << "):\n";
    {
      const auto o = run2("N-CI");
      report("  N-CI: u = (" + std::to_string(o.u[0]) + ", " +
               std::to_string(o.u[1]) +
               "), mu = " + std::to_string(o.report.multipliers[0]),
             mu > 0. && close(o.u[0], w0) && close(o.u[1], w1) &&
               close(o.report.multipliers[0], mu) &&
               close(o.udot[0], 2. / tau * (w0 - u0[0]) - v0[0]) &&
               close(o.udot[1], 2. / tau * (w1 - u0[1]) - v0[1]));
    }
    {
      // (12f): the M-projection of p = u1 + tau udot_pred onto c.v <= g:
      // v = p - t M^{-1} c, t = (c.p - g) / (1/m0 + 1/m1)
      const double q0 = 2. / tau * (w0 - u0[0]) - v0[0];
      const double q1 = 2. / tau * (w1 - u0[1]) - v0[1];
      const double p0 = w0 + tau * q0, p1 = w1 + tau * q1;
      const double t  = std::max(0., (p0 - p1 - gap) / (1. / m0 + 1. / m1));
      const double x0 = p0 - t / m0, x1 = p1 + t / m1;
      const auto   o = run2("N-CS++");
      report("  N-CS++: udot = (" + std::to_string(o.udot[0]) + ", " +
               std::to_string(o.udot[1]) + ")",
             close(o.u[0], w0) && close(o.u[1], w1) &&
               close(o.udot[0], (x0 - w0) / tau) &&
               close(o.udot[1], (x1 - w1) / tau));
      report("  N-CS++: relative normal velocity zero (eq. 19)",
             std::abs(o.udot[0] - o.udot[1]) < 1e-10);
      report("  N-CS++: the projection (12f) is active (t = " +
               std::to_string(t) + ")",
             t > 0. && o.report.projection_active[0] == 1);
      report("  N-CS++: the projection keeps the momentum of udot_pred (" +
               std::to_string(m0 * q0 + m1 * q1) + ")",
             close(m0 * o.udot[0] + m1 * o.udot[1], m0 * q0 + m1 * q1));
    }
  }
}
