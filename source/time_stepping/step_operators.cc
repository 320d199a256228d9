#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <dyncontact/time_stepping/step_operators.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <memory>
#include <sstream>

// The operators a step is written with: S per tau (cached per level), r(w),
// the displacement step, the projection P and the mass norm (the schemes are
// in integrators.cc).

namespace dyncontact
{
  namespace
  {
    /// A solve's origin less the prescribed part @p shift (stored in
    /// @p storage), as the solve's unknown is; nullptr without an origin.
    const VectorType *
    without(const VectorType *origin,
            const VectorType &shift,
            VectorType       &storage)
    {
      if (origin == nullptr)
        return nullptr;
      storage = *origin;
      storage -= shift;
      return &storage;
    }

    /// max(1, max_i H_ii / D_ii) over the D_ii > 0 of all ranks, for the
    /// diagonals @p H_diagonal and @p D of two matrices; infinite without
    /// @p D. With H >= M and a diagonal D <= M (the lumped mass, a blended
    /// mass's lumped part; none for a consistent mass) the factor of the
    /// bound of H's Jacobi-scaled condition number
    /// (ActiveSetSolver::set_matrix()).
    double
    largest_ratio(const VectorType &H_diagonal,
                  const VectorType *D,
                  const MPI_Comm    comm)
    {
      if (D == nullptr)
        return std::numeric_limits<double>::infinity();
      const double *H_ii = H_diagonal.begin(), *D_ii = D->begin();
      double        ratio = 1.;
      for (unsigned int k = 0; k < H_diagonal.locally_owned_size(); ++k)
        if (D_ii[k] > 0.)
          ratio = std::max(ratio, H_ii[k] / D_ii[k]);
      return Utilities::MPI::max(ratio, comm);
    }
  } // namespace

  StepOperators::StepOperators(const bool                is_static,
                               const double              numerical_dissipation,
                               const double              tau,
                               const StepOperatorInputs &inputs)
    : displacement_active(inputs.rows.size(), 0)
    , projection_active(inputs.rows.size(), 0)
    , is_static(is_static)
    , move_obstacles(inputs.move_obstacles)
    , theta(is_static ? 0. : numerical_dissipation)
    , system(inputs.system)
    , solver_parameters(inputs.solver_parameters)
    , locally_owned(inputs.locally_owned)
    , locally_relevant(inputs.locally_relevant)
    , mesh_constraints(&inputs.mesh_constraints)
    , near_null_space(inputs.near_null_space)
    , comm(inputs.comm)
    , projection_solver(inputs.solver_parameters, inputs.comm)
    , rows(&inputs.rows)
  {
    if (is_static)
      // start with every row active: the bodies are held by the contact
      displacement_active.assign(inputs.rows.size(), 1);
    set_time_step(tau, true);
    projection_solver.reinit(locally_owned,
                             locally_relevant,
                             inputs.mesh_constraints,
                             inputs.rows);
    if (system.lumped_mass())
      projection_solver.set_diagonal_matrix(*system.M_lumped);
    else
      projection_solver.set_matrix(*system.M,
                                   nullptr,
                                   largest_ratio(matrix_diagonal(*system.M),
                                                 system.M_lower,
                                                 comm));
  }



  std::unique_ptr<StepOperators::StepMatrix>
  StepOperators::make_step_matrix(const double tau) const
  {
    auto step_matrix = std::make_unique<StepMatrix>();
    step_matrix->tau = tau;
    step_matrix->solver =
      std::make_unique<ActiveSetSolver>(solver_parameters, comm);
    ActiveSetSolver &solver = *step_matrix->solver;
    MatrixType      &S      = step_matrix->S;
    solver.reinit(locally_owned, locally_relevant, *mesh_constraints, *rows);
    solver.set_near_null_space(near_null_space);
    if (is_static)
      {
        // H = A; AMG gets A + eps M, which stays SPD without Dirichlet data.
        // A body held only by the contact rows is free in A: the smaller
        // eps, the larger AMG's inverse along its rigid motion, which the
        // condensed operator does not have. 3D ball on block, static, 18e3
        // and 96e3 DoFs: 2366 and 3304 CG iterations at eps = 1e-6, 1020
        // and 1390 at 1e-2, 2010 at 1e-1 (96e3).
        system.assemble_stiffness(S, 1., 0., 0.);
        MatrixType &preconditioner = step_matrix->preconditioner;
        preconditioner.copy_from(S);
        system.add_mass(preconditioner,
                        1e-2 * S.linfty_norm() / system.mass_linfty_norm());
        solver.set_matrix(S, &preconditioner);
        step_matrix->diagonal  = matrix_diagonal(S);
        step_matrix->S_product = [&S](VectorType &y, const VectorType &x) {
          S.vmult(y, x);
        };
      }
    else
      {
        // S = M + (1/4 + theta/2) tau^2 A + tau/2 B
        const double a = (0.25 + 0.5 * theta) * tau * tau,
                     b = system.viscous() ? tau / 2. : 0.;
        const VectorType M_diagonal =
          system.lumped_mass() ? *system.M_lumped : matrix_diagonal(*system.M);
        VectorType &S_diagonal = step_matrix->diagonal;
        if (matrix_free())
          {
            // applied cell by cell: (a A + b B) x + M x
            S_diagonal.reinit(locally_owned, comm);
            system.stiffness_combination_diagonal(S_diagonal, a, b);
            S_diagonal += M_diagonal;
            step_matrix->stiffness_part.reinit(locally_owned, comm);
            StepMatrix *const step    = step_matrix.get();
            const Product     S_vmult = [this, step, a, b](VectorType       &y,
                                                       const VectorType &x) {
              system.stiffness_combination_vmult(step->stiffness_part, x, a, b);
              system.mass_vmult(y, x);
              y += step->stiffness_part;
            };
            step_matrix->S_product = S_vmult;
            // p-multigrid, or Jacobi
            solver.set_operator(
              S_vmult,
              S_diagonal,
              system.step_preconditioner ?
                system.step_preconditioner(a, b, S_vmult, S_diagonal) :
                Product());
          }
        else
          {
            // assembled cell by cell
            system.assemble_stiffness(S, a, b, 1.);
            S_diagonal             = matrix_diagonal(S);
            step_matrix->S_product = [&S](VectorType &y, const VectorType &x) {
              S.vmult(y, x);
            };
          }
        // how far the stiffness and viscosity outweigh the mass in S
        step_matrix->inertia_ratio =
          largest_ratio(S_diagonal, &M_diagonal, comm);
        // (the bound of S's Jacobi-scaled condition number needs a diagonal
        // D <= M: a lumped mass, whose ratio that is, or a blended mass's
        // lumped part)
        if (!matrix_free())
          solver.set_matrix(S,
                            nullptr,
                            system.lumped_mass() ?
                              step_matrix->inertia_ratio :
                              largest_ratio(S_diagonal, system.M_lower, comm));
      }
    return step_matrix;
  }



  void
  StepOperators::set_time_step(const double tau, const bool is_level)
  {
    if (current != nullptr && current->tau == tau)
      return;
    for (auto level = levels.begin(); level != levels.end(); ++level)
      if ((*level)->tau == tau)
        {
          // most recently used last
          std::rotate(level, level + 1, levels.end());
          current = levels.back().get();
          return;
        }
    ++n_step_matrices_built;
    if (is_level)
      {
        if (levels.size() == n_cached_levels)
          levels.erase(levels.begin());
        levels.push_back(make_step_matrix(tau));
        current = levels.back().get();
      }
    else
      {
        shortened.reset();
        shortened = make_step_matrix(tau);
        current   = shortened.get();
      }
  }



  void
  StepOperators::rhs(const VectorType &w,
                     const VectorType &u,
                     VectorType       &r) const
  {
    // r(w) = M w - (1/4 - theta/2) tau^2 A u + tau/2 B u + tau^2/2 f
    const double tau = current->tau;
    system.mass_vmult(r, w);
    r.add(-(0.25 - 0.5 * theta) * tau * tau, system.stiffness_vmult(u));
    if (system.viscous())
      {
        VectorType tmp(u);
        system.B_vmult(tmp, u);
        r.add(tau / 2., tmp);
      }
    r.add(tau * tau / 2., *system.f);
  }



  void
  StepOperators::solve_displacement(const VectorType &r,
                                    VectorType       &v,
                                    StepReport       &report,
                                    const VectorType *origin)
  {
    const PrescribedMotion *prescribed = system.prescribed;
    if (prescribed == nullptr)
      {
        report.displacement_solve = current->solver->solve(
          r, v, displacement_active, report.multipliers, origin);
        report.active = displacement_active;
        return;
      }
    // Dirichlet data that move: v = v~ + G, v~ with the homogeneous
    // constraints for r - S G (doc/algorithms.md, "Prescribed
    // displacements")
    const VectorType &G = prescribed->at_end;
    VectorType        r_free(r), S_x(r);
    current->S_product(S_x, G);
    r_free -= S_x;
    v -= G;
    VectorType origin_free;
    report.displacement_solve =
      current->solver->solve(r_free,
                             v,
                             displacement_active,
                             report.multipliers,
                             without(origin, G, origin_free));
    v += G;
    report.active = displacement_active;
    // the force of the prescribed DoFs on the body: the residual there,
    // scaled as the contact force (eq. 13)
    current->S_product(S_x, v);
    S_x -= r;
    S_x *= is_static ? 1. : 2. / (current->tau * current->tau);
    reaction.reinit(r, false);
    prescribed->reaction_of(S_x, reaction);
  }



  void
  StepOperators::project(const VectorType &w,
                         VectorType       &v,
                         StepReport       &report,
                         const VectorType *origin)
  {
    // Dirichlet data that move: the projection keeps w there (the lumped
    // M couples no DoFs) and projects the rest
    VectorType W;
    if (system.prescribed != nullptr)
      system.prescribed->part_of(w, W);
    VectorType          r(w);
    std::vector<double> multipliers;
    v = w;
    if (system.prescribed != nullptr)
      v -= W;
    system.mass_vmult(r, v);
    // with a consistent or blended mass no origin: CG stops at Linear
    // solver tolerance (an inexact projection raises N-CS's energy by its
    // residual, which no correction along a line removes; with the step
    // tolerance and Jacobi on the blend, 3e-6 of E at 1e-3)
    if (!system.lumped_mass())
      origin = nullptr;
    VectorType origin_free;
    if (system.prescribed != nullptr)
      origin = without(origin, W, origin_free);
    report.projection_solve =
      projection_solver.solve(r, v, projection_active, multipliers, origin);
    if (system.prescribed != nullptr)
      v += W;
    report.projection_active = projection_active;
    if (obstacles_move())
      report.projection_multipliers = multipliers;
  }



  double
  StepOperators::mass_norm(const VectorType &x) const
  {
    VectorType Mx(x);
    system.mass_vmult(Mx, x);
    return std::sqrt(Mx * x);
  }



} // namespace dyncontact
