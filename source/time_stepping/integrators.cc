#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <dyncontact/time_stepping/integrators.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <memory>
#include <sstream>

namespace dyncontact
{
  // ---------------------------------------------------------------------
  // The schemes. Each reads like its equations in the paper; schemes()
  // lists them.
  // ---------------------------------------------------------------------

  namespace
  {
    /// With rigid obstacles that move: this rank's rows at time @p t, and
    /// the obstacles' motion from @p s to @p t along their normals,
    /// nu_p . (d(t) - d(s)) (doc/algorithms.md, "Rigid obstacles that
    /// move").
    std::vector<double>
    gap_change(const StepOperators &ops, const double s, const double t)
    {
      ops.constraints_at(t);
      return ops.contact_rows().normal_motion(s, t);
    }



    /// -factor sum_p multipliers_p change_p: the work of a moving
    /// obstacle's contact forces (this rank's rows).
    double
    obstacle_work(const std::vector<double> &multipliers,
                  const std::vector<double> &change,
                  const double               factor)
    {
      double work = 0.;
      for (unsigned int p = 0; p < change.size(); ++p)
        work -= factor * multipliers[p] * change[p];
      return work;
    }



    /// (11c) and (12d): argmin_K 1/2 v^T S v - r(u + tau udot)^T v, K at
    /// t_{n+1}.
    VectorType
    implicit_displacement(StepOperators    &ops,
                          const VectorType &u,
                          const VectorType &udot,
                          StepReport       &report)
    {
      std::vector<double> change;
      if (ops.obstacles_move())
        change = gap_change(ops, ops.step_start(), ops.step_end());
      VectorType w(u), r(u);
      w.add(ops.tau(), udot);
      ops.rhs(w, u, r);
      VectorType u_new(w);
      ops.solve_displacement(r, u_new, report, &u);
      if (ops.obstacles_move())
        report.obstacle_work +=
          obstacle_work(report.multipliers, change, report.force_factor);
      return u_new;
    }



    /// (11d) and (12e): @p udot becomes 2/tau (u_new - u) - udot.
    void
    newmark_velocity(const double      tau,
                     const VectorType &u,
                     const VectorType &u_new,
                     VectorType       &udot)
    {
      udot.sadd(-1., 2. / tau, u_new);
      udot.add(-2. / tau, u);
    }



    /// (12c) and (12f): @p velocity = (P(x + tau v) - x) / tau (@p v may
    /// be @p velocity), K at the time of x + tau v, t_{n+1} + tau.
    void
    projected_velocity(StepOperators    &ops,
                       const VectorType &x,
                       const VectorType &v,
                       VectorType       &velocity,
                       StepReport       &report)
    {
      const double        tau = ops.tau();
      std::vector<double> change;
      if (ops.obstacles_move())
        change = gap_change(ops, ops.step_end(), ops.step_end() + tau);
      VectorType w(x), projected(x);
      w.add(tau, v);
      ops.project(w, projected, report, &x);
      if (ops.obstacles_move())
        {
          // (the kinetic energy's change: 1/2 |P(w) - x|_M^2 / tau^2 ...)
          report.obstacle_work += obstacle_work(report.projection_multipliers,
                                                change,
                                                1. / (tau * tau));
          ops.constraints_at(ops.step_end());
        }
      velocity = projected;
      velocity -= x;
      velocity /= tau;
    }



    void
    step_nci(StepOperators &ops,
             VectorType    &u,
             VectorType    &udot,
             StepReport    &report)
    {
      // (11c): u^{n+1} = argmin_K 1/2 v^T S v - r(u^n + tau udot^n)^T v
      const VectorType u_new = implicit_displacement(ops, u, udot, report);
      // (11d): udot^{n+1} = 2/tau (u^{n+1} - u^n) - udot^n
      newmark_velocity(ops.tau(), u, u_new, udot);
      u = u_new;
    }



    void
    step_ncs(StepOperators &ops,
             VectorType    &u,
             VectorType    &udot,
             StepReport    &report)
    {
      const double tau = ops.tau();
      // u_pred = P(u^n + tau udot^n), K at t_{n+1}
      std::vector<double> change;
      if (ops.obstacles_move())
        change = gap_change(ops, ops.step_start(), ops.step_end());
      VectorType w(u), u_pred(u), r(u);
      w.add(tau, udot);
      ops.project(w, u_pred, report, &u);
      VectorType correction(u_pred);
      correction -= w;
      report.velocity_correction = ops.mass_norm(correction) / tau;
      // u^{n+1} = argmin_K 1/2 v^T S v - r(u_pred)^T v
      ops.rhs(u_pred, u, r);
      VectorType u_new(u_pred);
      ops.solve_displacement(r, u_new, report, &u);
      if (ops.obstacles_move())
        // (the displacement step's share only: the predictor moves u)
        report.obstacle_work +=
          obstacle_work(report.multipliers, change, report.force_factor);
      // udot^{n+1} = udot^n + 2/tau (u^{n+1} - u_pred)
      udot.add(2. / tau, u_new);
      udot.add(-2. / tau, u_pred);
      u = u_new;
    }



    void
    initialize_ncspp(StepOperators &ops,
                     VectorType    &u,
                     VectorType    &udot,
                     StepReport    &report)
    {
      // (12c): udot^0 = (P(u^0 + tau udot_0) - u^0) / tau
      projected_velocity(ops, u, udot, udot, report);
    }



    void
    step_ncspp(StepOperators &ops,
               VectorType    &u,
               VectorType    &udot,
               StepReport    &report)
    {
      // (12d): u^{n+1} = argmin_K 1/2 v^T S v - r(u^n + tau udot^n)^T v
      const VectorType u_new = implicit_displacement(ops, u, udot, report);
      // (12e): udot_pred = 2/tau (u^{n+1} - u^n) - udot^n
      VectorType udot_pred(udot);
      newmark_velocity(ops.tau(), u, u_new, udot_pred);
      // (12f): udot^{n+1} = (P(u^{n+1} + tau udot_pred) - u^{n+1}) / tau
      projected_velocity(ops, u_new, udot_pred, udot, report);
      VectorType correction(udot);
      correction -= udot_pred;
      report.velocity_correction = ops.mass_norm(correction);
      u                          = u_new;
    }



    void
    step_static(StepOperators &ops,
                VectorType    &u,
                VectorType    &udot,
                StepReport    &report)
    {
      // min 1/2 v^T A v - f^T v on K_h (at End time)
      ops.constraints_at(ops.step_end());
      ops.solve_displacement(ops.load(), u, report);
      udot = 0.;
    }
  } // namespace



  const std::vector<Scheme> &
  schemes()
  {
    static const std::vector<Scheme> list = {
      {"N-CI",
       "the contact-implicit Newmark method, Kane et al., eq. (11)",
       false,
       nullptr,
       &step_nci},
      {"N-CS",
       "the contact-stabilized Newmark method, Deuflhard, Krause and Ertel",
       false,
       nullptr,
       &step_ncs},
      {"N-CS++",
       "the improved contact-stabilized Newmark method, eq. (12)",
       false,
       &initialize_ncspp,
       &step_ncspp},
      {"static",
       "the quasi-static limit: min 1/2 v^T A v - f^T v on K_h, solved once",
       true,
       nullptr,
       &step_static}};
    return list;
  }



  const Scheme &
  scheme_by_name(const std::string &name)
  {
    std::string names;
    for (const Scheme &scheme : schemes())
      {
        if (scheme.name == name)
          return scheme;
        names += (names.empty() ? "" : ", ") + scheme.name;
      }
    AssertThrow(false,
                ExcMessage("Time integration/Scheme must be one of " + names +
                           "; got '" + name + "'."));
    return schemes().front();
  }



  TimeIntegrator::TimeIntegrator(const Scheme &scheme,
                                 const double  numerical_dissipation,
                                 const double  tau,
                                 const StepOperatorInputs &inputs)
    : scheme(scheme)
    , operators(scheme.is_static, numerical_dissipation, tau, inputs)
    , comm(inputs.comm)
  {}



  StepReport
  TimeIntegrator::empty_report(const double tau) const
  {
    StepReport report;
    report.tau          = tau;
    report.force_factor = scheme.is_static ? 1. : 2. / (tau * tau);
    const std::size_t n = operators.n_rows();
    report.active.assign(n, 0);
    report.multipliers.assign(n, 0.);
    report.projection_active.assign(n, 0);
    report.critical.assign(n, 0);
    return report;
  }



  StepReport
  TimeIntegrator::initialize(const double tau, VectorType &u, VectorType &udot)
  {
    operators.set_time_step(tau, true);
    StepReport report = empty_report(tau);
    if (scheme.initialize != nullptr)
      scheme.initialize(operators, u, udot, report);
    return report;
  }



  StepReport
  TimeIntegrator::step(const double tau,
                       const bool   is_level,
                       VectorType  &u,
                       VectorType  &udot)
  {
    operators.set_time_step(tau, is_level);
    StepReport   report = empty_report(tau);
    const double theta  = operators.numerical_dissipation();
    VectorType   u_old, A_u_old;
    if (theta > 0.)
      {
        // A u^n, which the step's right-hand side needs (and then finds in
        // the cache)
        u_old   = u;
        A_u_old = operators.stiffness_product(u);
      }
    scheme.step(operators, u, udot, report);
    // A u^{n+1}, which the next step's right-hand side needs, now: the
    // energy after this step reads it from the cache (CachedProduct)
    if (!scheme.is_static)
      {
        const VectorType &A_u = operators.stiffness_product(u);
        if (theta > 0.)
          {
            // theta du^T A du = theta du^T (A u^{n+1} - A u^n), from the two
            // products the steps need anyway
            VectorType &A_du = A_u_old;
            A_du.sadd(-1., 1., A_u);
            u_old.sadd(-1., 1., u);
            report.numerical_dissipation = theta * (u_old * A_du);
          }
      }

    if (operators.obstacles_move())
      report.obstacle_work = Utilities::MPI::sum(report.obstacle_work, comm);
    // Gamma*_{h,C} (eq. 40): rows where the projection was active but the
    // displacement step was not
    for (unsigned int p = 0; p < operators.n_rows(); ++p)
      report.critical[p] = report.projection_active[p] && !report.active[p];
    return report;
  }



  void
  TimeIntegrator::project_onto_constraints(VectorType &u)
  {
    StepReport report;
    VectorType projected(u);
    operators.project(u, projected, report);
    u = projected;
  }



  double
  TimeIntegrator::restore_constraints(VectorType               &u,
                                      const ContactRowOperator &row_operator)
  {
    const auto violation     = row_operator.constraint_values(u);
    double     max_violation = 0.;
    for (const double v : violation)
      max_violation = std::max(max_violation, v);
    double scale = 1.;
    for (const auto &row : row_operator.rows().rows)
      scale = std::max(scale, std::abs(row.gap));
    max_violation = Utilities::MPI::max(max_violation, comm);
    scale         = Utilities::MPI::max(scale, comm);
    if (max_violation > 1e-12 * scale)
      project_onto_constraints(u);

    // the active set restarts from the transferred state: rows that touch
    std::vector<char> active(row_operator.size(), 0);
    const auto        after = row_operator.constraint_values(u);
    for (unsigned int p = 0; p < active.size(); ++p)
      active[p] = (after[p] > -1e-10 * scale);
    warm_start(active);
    return max_violation;
  }



  void
  TimeIntegrator::warm_start(const std::vector<char> &active,
                             const std::vector<char> &projection)
  {
    if (active.size() == operators.n_rows())
      operators.displacement_active = active;
    const std::vector<char> &p = projection.empty() ? active : projection;
    if (p.size() == operators.n_rows())
      operators.projection_active = p;
  }



  void
  TimeIntegrator::save_active_sets(VectorType &flags) const
  {
    flags                   = 0.;
    const ContactRows &rows = operators.contact_rows();
    for (unsigned int p = 0; p < rows.size(); ++p)
      flags(rows.rows[p].eliminated_dof()) =
        (operators.displacement_active[p] ? 1. : 0.) +
        (operators.projection_active[p] ? 2. : 0.);
    flags.compress(VectorOperation::insert);
  }



  std::pair<std::vector<char>, std::vector<char>>
  TimeIntegrator::decode_active_sets(const ContactRows &rows,
                                     const VectorType  &flags)
  {
    std::vector<char> active(rows.size()), projection(rows.size());
    for (unsigned int p = 0; p < rows.size(); ++p)
      {
        const int flag =
          static_cast<int>(std::lround(flags(rows.rows[p].eliminated_dof())));
        active[p]     = (flag & 1) ? 1 : 0;
        projection[p] = (flag & 2) ? 1 : 0;
      }
    return {active, projection};
  }



  void
  TimeIntegrator::load_active_sets(const VectorType &flags)
  {
    const auto [active, projection] =
      decode_active_sets(operators.contact_rows(), flags);
    warm_start(active, projection);
  }


  std::string
  TimeIntegrator::inertia_warning() const
  {
    // in double precision, S = M + (1/4 + theta/2) tau^2 A + tau/2 B keeps
    // the mass only to about eps * max S_ii/M_ii
    const double inertia_accuracy =
      std::numeric_limits<double>::epsilon() * inertia_ratio();
    if (!(inertia_accuracy > 1e-6))
      return "";
    std::ostringstream text;
    text << std::setprecision(3)
         << "   warning: in the step matrix S = M + (1/4 + theta/2) tau^2 A + "
            "tau/2 B (theta: Time integration/Numerical dissipation) "
            "the stiffness and viscosity outweigh the mass by a factor "
         << inertia_ratio()
         << " (largest S_ii/M_ii), so in double precision S keeps the "
            "mass only to a relative accuracy of about "
         << inertia_accuracy
         << ": momentum and energy are conserved only to about that "
            "per step. Reduce 'Time integration/Time step' (the factor "
            "grows as tau^2 E/(rho h^2) + tau mu_v/(rho h^2))."
         << std::endl;
    return text.str();
  }
} // namespace dyncontact
