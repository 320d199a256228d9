#include <deal.II/base/utilities.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>

#include <dyncontact/contact/active_set_solver.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace dyncontact
{
  // The active-set iteration of ActiveSetSolver: the solve on one active
  // set, the multipliers, the update of the set and the damping of cycles
  // (the matrices and preconditioners it uses are set up in
  // active_set_solver.cc).

  void
  ActiveSetSolver::vmult_H(VectorType &y, const VectorType &x) const
  {
    if (H != nullptr)
      H->vmult(y, x);
    else if (H_operator)
      H_operator(y, x);
    else
      {
        y = x;
        y.scale(diagonal);
      }
  }



  ActiveSetSolver::Result
  ActiveSetSolver::solve_pointwise(const VectorType    &r,
                                   VectorType          &v,
                                   std::vector<char>   &active,
                                   std::vector<double> &multipliers) const
  {
    // H diagonal, rows on disjoint unconstrained slave DoFs: the
    // unconstrained minimiser is v = D^{-1} r, and each row is then the
    // projection of its node onto a half-space in the D-norm.
    for (const auto i : locally_owned)
      v(i) = mesh_constraints.is_constrained(i) ? 0. : r(i) / diagonal(i);
    v.compress(VectorOperation::insert);

    for (unsigned int p = 0; p < rows->size(); ++p)
      {
        const ContactRow &row = rows->rows[p];
        double            cv = 0., cDc = 0.;
        for (const auto &entry : row.entries)
          {
            cv += entry.second * v(entry.first);
            cDc += entry.second * entry.second / diagonal(entry.first);
          }
        const double t = (cv - row.gap) / cDc;
        if (t > 0.)
          {
            for (const auto &entry : row.entries)
              v(entry.first) -= t * entry.second / diagonal(entry.first);
            multipliers[p] = t;
            active[p]      = 1;
          }
        else
          active[p] = 0;
      }
    // (the corrections were added: a Debug build checks the operation)
    v.compress(VectorOperation::add);
    Result result;
    result.iterations = 1;
    return result;
  }



  void
  ActiveSetSolver::correct_along_increment(const Condensation &homogeneous,
                                           const VectorType   &b,
                                           VectorType         &x,
                                           Scratch            &scratch) const
  {
    // x = x_o + alpha y, y = x - x_o, alpha minimising 1/2 x^T H x - b^T x
    // on that line: the residual b - H x is then orthogonal to x - x_o, so
    // that it does no work on the step's increment (the energy identity of
    // the step holds whatever CG's tolerance; doc/algorithms.md, "The
    // linear solver's tolerance"). One product with H.
    const VectorType &x_origin = scratch.x_origin;
    VectorType       &y = scratch.direction, &Hy = scratch.residual;
    y = x;
    y -= x_origin;
    vmult_condensed(homogeneous, Hy, y);
    const double yHy = y * Hy;
    if (!(yHy > 0.))
      return;
    // alpha = (y^T b - y^T H x_o) / y^T H y, with y^T H x_o = (H y)^T x_o.
    // The residual's work on the increment is (alpha - 1) y^T H y, at most
    // about 4 (alpha - 1) E: below 1e-12 it is left out, and so is an
    // alpha - 1 below the round-off of the difference it is computed from
    // (y^T b and (H y)^T x_o are of the size of the displacement): such
    // noise would add up over a long free flight, where CG's start is the
    // solution up to round-off.
    const double yb = y * b, Hyxo = Hy * x_origin;
    const double alpha = (yb - Hyxo) / yHy;
    const double noise = 64. * std::numeric_limits<double>::epsilon() *
                         (std::abs(yb) + std::abs(Hyxo)) / yHy;
    if (std::abs(alpha - 1.) > std::max(1e-12, noise))
      x.add(alpha - 1., y);
  }



  bool
  ActiveSetSolver::solve_on_active_set(const std::vector<char> &active,
                                       const bool               any_active,
                                       const VectorType        &r,
                                       const double             r_norm,
                                       const VectorType        *origin,
                                       VectorType              &v,
                                       Result                  &result,
                                       Scratch                 &scratch) const
  {
    const ActiveSetConstraints &constraints = constraints_of(active, r);
    const Condensation         &homogeneous = constraints.homogeneous;

    // k: the inhomogeneities (v = T x + k)
    VectorType &k = scratch.k, &b = scratch.b, &x = scratch.x;
    k = 0.;
    distribute_inhomogeneous(constraints, k);

    // b = T^T (r - H k)
    if (any_active)
      {
        vmult_H(b, k);
        b.sadd(-1., 1., r);
      }
    else
      b = r;
    transpose_distribute(homogeneous, b);

    // warm start: the previous iterate, constrained entries zero
    x = v;
    zero_constrained(homogeneous, x);

    // CG's tolerance: in a time step, relative to the start's residual
    // (the step's correction beyond CG's start; a floor of 1e-14 of the
    // right-hand side, round-off); without an origin, relative to the
    // right-hand side (Step and Linear solver tolerance's documentation)
    const double rhs_norm = std::max(b.l2_norm(), r_norm);
    if (origin != nullptr)
      {
        scratch.x_origin = *origin;
        zero_constrained(homogeneous, scratch.x_origin);
      }
    const bool       step = origin != nullptr;
    ReductionControl control(
      parameters.max_linear_iterations,
      std::max((step ? 1e-14 : parameters.linear_tolerance) * rhs_norm, 1e-300),
      step ? parameters.step_tolerance : 0.);
    SolverCG<VectorType> cg(control);

    struct Operator
    {
      const ActiveSetSolver *solver;
      const Condensation    *homogeneous;
      void
      vmult(VectorType &dst, const VectorType &src) const
      {
        solver->vmult_condensed(*homogeneous, dst, src);
      }
    } op{this, &homogeneous};

    struct Preconditioner
    {
      const ActiveSetSolver *solver;
      const Condensation    *homogeneous;
      void
      vmult(VectorType &dst, const VectorType &src) const
      {
        solver->precondition_condensed(*homogeneous, dst, src);
      }
    } preconditioner{this, &homogeneous};

    try
      {
        cg.solve(op, x, b, preconditioner);
      }
    catch (const SolverControl::NoConvergence &e)
      {
        // reported, not thrown: the step control acts on it
        result.linear_iterations += e.last_step;
        result.linear_residual = e.last_residual;
        result.status          = Status::linear_solver_failed;
        return false;
      }
    result.linear_iterations += control.last_step();

    if (origin != nullptr)
      correct_along_increment(homogeneous, b, x, scratch);
    v = x;
    distribute_inhomogeneous(constraints, v);
    return true;
  }



  void
  ActiveSetSolver::compute_multipliers(const std::vector<char> &active,
                                       const bool               any_active,
                                       const VectorType        &r,
                                       const VectorType        &v,
                                       std::vector<double>     &multipliers,
                                       Scratch                 &scratch) const
  {
    // from the residual r - H v at the slave nodes
    if (!any_active)
      {
        std::fill(multipliers.begin(), multipliers.end(), 0.);
        return;
      }
    VectorType &residual = scratch.residual;
    vmult_H(residual, v);
    residual.sadd(-1., 1., r);
    // the force at a slave node in the equations of the free DoFs, which
    // the solve makes hold: a hanging node's residual belongs, times its
    // weight, to the nodes it hangs on (T^T of the hanging-node
    // constraints), and those may be slave nodes. Without it a row beside
    // a hanging node got a multiplier of the wrong sign, and the active
    // set cycled (2D bar on an adaptive mesh at the release). Without
    // hanging nodes (on every rank) it adds nothing: skipped, with its
    // communication.
    if (mesh_has_hanging_nodes)
      add_to_masters(mesh_constraints, residual);
    const VectorType &ghosted = row_operator.with_row_ghosts(residual);
    for (unsigned int p = 0; p < rows->size(); ++p)
      {
        const ContactRow &row = rows->rows[p];
        multipliers[p]        = 0.;
        if (!active[p])
          continue;
        // a component that Dirichlet data hold (a roller) carries their
        // reaction too: the force mu nu is then read from the free
        // components alone, mu = sum nu_c R_c / sum nu_c^2 over them
        bool   held      = false;
        double free_norm = 0.;
        for (unsigned int c = 0; c < row.n_components; ++c)
          if (row.free[c])
            free_norm += row.normal[c] * row.normal[c];
          else
            held = held || std::abs(row.normal[c]) > 1e-12;
        for (unsigned int c = 0; c < row.n_components; ++c)
          if (!held || row.free[c])
            multipliers[p] += row.normal[c] * ghosted(row.entries[c].first);
        if (held)
          multipliers[p] /= free_norm;
      }
  }



  void
  ActiveSetSolver::change_one_row(const std::vector<char>   &active,
                                  const std::vector<double> &multipliers,
                                  const std::vector<double> &violation,
                                  std::vector<char>         &new_active) const
  {
    unsigned int worst = 0;
    double       size  = -1.;
    for (unsigned int p = 0; p < rows->size(); ++p)
      if (new_active[p] != active[p])
        {
          const double c =
            std::abs(multipliers[p] / row_scaling[p] + violation[p]);
          if (c > size)
            {
              size  = c;
              worst = p;
            }
        }
    // the worst row over all ranks (the first rank among equals)
    const double       largest = Utilities::MPI::max(size, comm);
    const unsigned int my_rank = Utilities::MPI::this_mpi_process(comm);
    const unsigned int owner   = Utilities::MPI::min(
      size == largest ? my_rank : Utilities::MPI::n_mpi_processes(comm), comm);
    new_active = active;
    if (owner == my_rank)
      new_active[worst] = !active[worst];
  }



  std::vector<char>
  ActiveSetSolver::next_active_set(const VectorType          &v,
                                   const std::vector<double> &multipliers,
                                   const std::vector<double> &violation,
                                   double                    &delta,
                                   Result                    &result) const
  {
    double scale = 0.;
    for (const ContactRow &row : rows->rows)
      scale = std::max(scale, std::abs(row.gap));
    scale = std::max(Utilities::MPI::max(scale, comm), v.linfty_norm());
    delta = 1e-11 * scale;
    std::vector<char> new_active(rows->size(), 0);
    for (unsigned int p = 0; p < rows->size(); ++p)
      new_active[p] = (multipliers[p] + row_scaling[p] * violation[p] >
                       row_scaling[p] * delta) ?
                        1 :
                        0;

    result.residual = 0.;
    for (unsigned int p = 0; p < rows->size(); ++p)
      result.residual =
        std::max(result.residual,
                 std::abs(
                   std::min(multipliers[p] / row_scaling[p], -violation[p])));
    result.residual = Utilities::MPI::max(result.residual, comm);
    return new_active;
  }



  ActiveSetSolver::Result
  ActiveSetSolver::solve(const VectorType    &r,
                         VectorType          &v,
                         std::vector<char>   &active,
                         std::vector<double> &multipliers,
                         const VectorType    *origin) const
  {
    Assert(H != nullptr || H_operator || diagonal.size() > 0,
           ExcInternalError());
    active.resize(rows->size(), 0);
    multipliers.assign(rows->size(), 0.);

    if (pointwise)
      return solve_pointwise(r, v, active, multipliers);

    Result result;
    // the local part of every active set visited so far (to detect cycling)
    std::vector<std::vector<char>> visited;
    Scratch                        scratch(r, origin != nullptr);
    const double                   r_norm = r.l2_norm();

    for (result.iterations = 1;; ++result.iterations)
      {
        // without active rows every multiplier is zero
        const bool any_active =
          Utilities::MPI::max(
            std::find(active.begin(), active.end(), 1) != active.end() ? 1 : 0,
            comm) == 1;
        if (!solve_on_active_set(
              active, any_active, r, r_norm, origin, v, result, scratch))
          return result;
        compute_multipliers(active, any_active, r, v, multipliers, scratch);

        const std::vector<double> violation = row_operator.constraint_values(v);
        double                    delta;
        std::vector<char>         new_active =
          next_active_set(v, multipliers, violation, delta, result);
        // converged: the active set is unchanged, or it still changes only
        // on degenerate rows (touching with zero force) while the
        // complementarity conditions hold to the displacement tolerance
        const bool unchanged =
          Utilities::MPI::min(new_active == active ? 1 : 0, comm) == 1;
        if (unchanged || result.residual <= delta)
          break;
        if (result.iterations >= parameters.max_iterations)
          {
            result.status = Status::active_set_not_converged;
            break;
          }
        // cycling between active sets ("ping-pong"): damp the iteration by
        // changing only the row that violates its condition the most
        // (a set was visited if it matches on every rank: one scalar
        // reduction per earlier iterate)
        visited.push_back(active);
        std::vector<unsigned int> matches(visited.size());
        for (unsigned int k = 0; k < visited.size(); ++k)
          matches[k] = (visited[k] == new_active) ? 1 : 0;
        Utilities::MPI::min(matches, comm, matches);
        if (std::find(matches.begin(), matches.end(), 1u) != matches.end())
          {
            result.cycled = true;
            change_one_row(active, multipliers, violation, new_active);
          }
        active = new_active;
      }
    return result;
  }
} // namespace dyncontact
