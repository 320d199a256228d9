#include <deal.II/base/exceptions.h>

#include <dyncontact/time_integrator.h>

#include <cmath>

namespace dyncontact
{
  Scheme
  scheme_from_string(const std::string &name)
  {
    if (name == "N-CI")
      return Scheme::contact_implicit;
    if (name == "N-CS")
      return Scheme::contact_stabilized;
    if (name == "N-CS++")
      return Scheme::improved_contact_stabilized;
    if (name == "static")
      return Scheme::quasi_static;
    AssertThrow(false,
                ExcMessage("Time integration/Scheme must be one of N-CI, "
                           "N-CS, N-CS++, static; got '" +
                           name + "'."));
    return Scheme::contact_implicit;
  }



  std::string
  to_string(const Scheme scheme)
  {
    switch (scheme)
      {
        case Scheme::contact_implicit:
          return "N-CI";
        case Scheme::contact_stabilized:
          return "N-CS";
        case Scheme::improved_contact_stabilized:
          return "N-CS++";
        case Scheme::quasi_static:
          return "static";
      }
    return "";
  }



  TimeIntegrator::TimeIntegrator(
    const Scheme                          scheme,
    const double                          tau,
    const SemiDiscreteSystem             &system,
    const ActiveSetSolver::Parameters    &solver_parameters,
    const IndexSet                       &locally_owned,
    const IndexSet                       &locally_relevant,
    const AffineConstraints<double>      &mesh_constraints,
    const ContactRows                    &rows,
    const std::vector<std::vector<bool>> &constant_modes,
    const MPI_Comm                        comm)
    : scheme(scheme)
    , tau(tau)
    , system(system)
    , displacement_solver(solver_parameters, comm)
    , projection_solver(solver_parameters, comm)
    , rows(&rows)
    , displacement_active(rows.size(), 0)
    , projection_active(rows.size(), 0)
  {
    displacement_solver.reinit(locally_owned,
                               locally_relevant,
                               mesh_constraints,
                               rows);
    displacement_solver.set_constant_modes(constant_modes);
    if (scheme == Scheme::quasi_static)
      {
        // H = A; AMG gets A + eps M, which stays SPD without Dirichlet data
        S.copy_from(*system.A);
        preconditioner_matrix.copy_from(*system.A);
        preconditioner_matrix.add(1e-6 * system.A->linfty_norm() /
                                    system.M->linfty_norm(),
                                  *system.M);
        displacement_solver.set_matrix(S, false, &preconditioner_matrix);
        // start with every row active: the bodies are held by the contact
        displacement_active.assign(rows.size(), 1);
      }
    else
      {
        // S = M + tau^2/4 A + tau/2 B, formed from the assembled matrices
        S.copy_from(*system.M);
        S.add(tau * tau / 4., *system.A);
        if (system.B != nullptr)
          S.add(tau / 2., *system.B);
        displacement_solver.set_matrix(S, false);
      }
    projection_solver.reinit(locally_owned,
                             locally_relevant,
                             mesh_constraints,
                             rows);
    projection_solver.set_matrix(*system.M, system.lumped_mass);
  }



  void
  TimeIntegrator::make_rhs(const VectorType &w,
                           const VectorType &u,
                           VectorType       &r) const
  {
    // r(w) = M w - tau^2/4 A u + tau/2 B u + tau^2/2 f
    VectorType tmp(u);
    system.M->vmult(r, w);
    system.A->vmult(tmp, u);
    r.add(-tau * tau / 4., tmp);
    if (system.B != nullptr)
      {
        system.B->vmult(tmp, u);
        r.add(tau / 2., tmp);
      }
    r.add(tau * tau / 2., *system.f);
  }



  void
  TimeIntegrator::solve_displacement(const VectorType &r,
                                     VectorType       &v,
                                     StepReport       &report)
  {
    report.displacement_solve =
      displacement_solver.solve(r, v, displacement_active, report.multipliers);
    report.active = displacement_active;
  }



  void
  TimeIntegrator::project(const VectorType &w,
                          VectorType       &v,
                          StepReport       &report)
  {
    VectorType          r(w);
    std::vector<double> multipliers;
    system.M->vmult(r, w);
    v = w;
    report.projection_solve =
      projection_solver.solve(r, v, projection_active, multipliers);
    report.projection_active = projection_active;
  }



  void
  TimeIntegrator::project_onto_constraints(VectorType &u)
  {
    StepReport report;
    VectorType projected(u);
    project(u, projected, report);
    u = projected;
  }



  void
  TimeIntegrator::warm_start(const std::vector<char> &active,
                             const std::vector<char> &projection)
  {
    if (active.size() == rows->size())
      displacement_active = active;
    const std::vector<char> &p = projection.empty() ? active : projection;
    if (p.size() == rows->size())
      projection_active = p;
  }



  StepReport
  TimeIntegrator::initialize(const VectorType &u, VectorType &udot)
  {
    StepReport report;
    report.active.assign(rows->size(), 0);
    report.multipliers.assign(rows->size(), 0.);
    report.projection_active.assign(rows->size(), 0);
    report.critical.assign(rows->size(), 0);
    if (scheme == Scheme::improved_contact_stabilized)
      {
        // (12c): udot^0 = (P(u^0 + tau udot_pred^0) - u^0) / tau
        VectorType w(u), projected(u);
        w.add(tau, udot);
        project(w, projected, report);
        udot = projected;
        udot -= u;
        udot /= tau;
      }
    return report;
  }



  StepReport
  TimeIntegrator::step(VectorType &u, VectorType &udot)
  {
    StepReport report;
    VectorType w(u), r(u), u_new(u);

    switch (scheme)
      {
        case Scheme::quasi_static:
          {
            // min 1/2 v^T A v - f^T v on K_h
            solve_displacement(*system.f, u_new, report);
            udot = 0.;
            report.projection_active.assign(rows->size(), 0);
            break;
          }

        case Scheme::contact_implicit:
          {
            // (11c): u^{n+1} = argmin_K 1/2 v^T S v - r(u^n + tau udot^n)^T v
            w.add(tau, udot);
            make_rhs(w, u, r);
            u_new = w;
            solve_displacement(r, u_new, report);
            // (11d): udot^{n+1} = 2/tau (u^{n+1} - u^n) - udot^n
            udot.sadd(-1., 2. / tau, u_new);
            udot.add(-2. / tau, u);
            report.projection_active.assign(rows->size(), 0);
            break;
          }

        case Scheme::contact_stabilized:
          {
            // u_pred = P(u^n + tau udot^n)
            w.add(tau, udot);
            VectorType u_pred(u);
            project(w, u_pred, report);
            {
              VectorType correction(u_pred);
              correction -= w;
              VectorType Mc(correction);
              system.M->vmult(Mc, correction);
              report.velocity_correction = std::sqrt(Mc * correction) / tau;
            }
            // u^{n+1} = argmin_K 1/2 v^T S v - r(u_pred)^T v
            make_rhs(u_pred, u, r);
            u_new = u_pred;
            solve_displacement(r, u_new, report);
            // udot^{n+1} = udot^n + 2/tau (u^{n+1} - u_pred)
            udot.add(2. / tau, u_new);
            udot.add(-2. / tau, u_pred);
            break;
          }

        case Scheme::improved_contact_stabilized:
          {
            // (12d): u^{n+1} = argmin_K 1/2 v^T S v - r(u^n + tau udot^n)^T v
            w.add(tau, udot);
            make_rhs(w, u, r);
            u_new = w;
            solve_displacement(r, u_new, report);
            // (12e): udot_pred = 2/tau (u^{n+1} - u^n) - udot^n
            VectorType udot_pred(udot);
            udot_pred.sadd(-1., 2. / tau, u_new);
            udot_pred.add(-2. / tau, u);
            // (12f): udot^{n+1} = (P(u^{n+1} + tau udot_pred) - u^{n+1})/tau
            VectorType predicted(u_new), projected(u_new);
            predicted.add(tau, udot_pred);
            projected = u_new; // initial guess: a point of K_h
            project(predicted, projected, report);
            udot = projected;
            udot -= u_new;
            udot /= tau;
            VectorType correction(udot), Mc(udot);
            correction -= udot_pred;
            system.M->vmult(Mc, correction);
            report.velocity_correction = std::sqrt(Mc * correction);
            break;
          }
      }

    // Gamma*_{h,C} (eq. 40): rows where the projection was active but the
    // displacement step was not
    report.critical.assign(rows->size(), 0);
    for (unsigned int p = 0; p < rows->size(); ++p)
      report.critical[p] = report.projection_active[p] && !report.active[p];

    u = u_new;
    return report;
  }
} // namespace dyncontact
