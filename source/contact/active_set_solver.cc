#include <deal.II/base/array_view.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_index_access.h>

#include <dyncontact/contact/active_set_solver.h>

#include <Epetra_CrsMatrix.h>
#include <Epetra_MultiVector.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace dyncontact
{
  VectorType
  matrix_diagonal(const MatrixType &matrix)
  {
    VectorType              diagonal(matrix.locally_owned_range_indices(),
                        matrix.get_mpi_communicator());
    const Epetra_CrsMatrix &epetra = matrix.trilinos_matrix();
    const int               n_rows = epetra.NumMyRows();
    // Where the column map begins with the row map (Epetra makes its column
    // maps so, and so does SemiDiscreteSystem), row k's diagonal entry is
    // in local column k, found by a binary search in the row (sorted since
    // FillComplete()).
    // (Epetra's ExtractDiagonalCopy() compares global indices: 0.2 s at
    // 1e6 DoFs.)
    const auto *row_ids = TrilinosWrappers::my_global_elements(epetra.RowMap());
    const auto *column_ids =
      TrilinosWrappers::my_global_elements(epetra.ColMap());
    bool leading = epetra.ColMap().NumMyElements() >= n_rows;
    for (int k = 0; leading && k < n_rows; ++k)
      leading = (row_ids[k] == column_ids[k]);
    if (!leading)
      {
        const int error =
          epetra.ExtractDiagonalCopy(*diagonal.trilinos_vector()(0));
        AssertThrow(error == 0,
                    ExcMessage("extracting a matrix's diagonal failed "
                               "(Epetra error " +
                               std::to_string(error) + ")"));
        return diagonal;
      }
    double *d = diagonal.begin();
    for (int k = 0; k < n_rows; ++k)
      {
        int     length  = 0;
        double *values  = nullptr;
        int    *indices = nullptr;
        epetra.ExtractMyRowView(k, length, values, indices);
        const int *begin = indices, *end = indices + length;
        const int *entry = std::lower_bound(begin, end, k);
        if (entry == end || *entry != k)
          // (a row not sorted)
          entry = std::find(begin, end, k);
        d[k] = (entry != end) ? values[entry - indices] : 0.;
      }
    return diagonal;
  }



  ContactRowOperator::ContactRowOperator(const MPI_Comm comm)
    : comm(comm)
  {}



  void
  ContactRowOperator::reinit(const IndexSet    &owned,
                             const IndexSet    &relevant,
                             const ContactRows &rows)
  {
    locally_owned = owned;
    ghosts        = relevant;
    std::vector<types::global_dof_index> touched;
    // the rows' DoFs and the component-0 DoFs of the master nodes at their
    // images (the contact-zone criterion marks these; a zero coefficient,
    // e.g. of a vertical normal, leaves them out of the entries)
    for (const ContactRow &row : rows.rows)
      {
        for (const auto &entry : row.entries)
          touched.push_back(entry.first);
        for (const auto &node : row.master_nodes)
          touched.push_back(node.first);
      }
    std::sort(touched.begin(), touched.end());
    touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
    ghosts.add_indices(touched.begin(), touched.end());
    ghosts.compress();
    // apply() reads only the rows' own DoFs: a ghosted vector with just
    // those, made once per mesh
    IndexSet row_dofs(owned.size());
    row_dofs.add_indices(touched.begin(), touched.end());
    row_dofs.compress();
    ghosted_row_dofs.reinit(owned, row_dofs, comm);
    contact_rows = &rows;
  }



  const VectorType &
  ContactRowOperator::with_row_ghosts(const VectorType &v) const
  {
    ghosted_row_dofs = v;
    return ghosted_row_dofs;
  }



  std::vector<double>
  ContactRowOperator::apply(const VectorType &v) const
  {
    const VectorType   &ghosted = with_row_ghosts(v);
    std::vector<double> values(size(), 0.);
    for (unsigned int p = 0; p < values.size(); ++p)
      for (const auto &entry : contact_rows->rows[p].entries)
        values[p] += entry.second * ghosted(entry.first);
    return values;
  }



  std::vector<double>
  ContactRowOperator::constraint_values(const VectorType &v) const
  {
    std::vector<double> values = apply(v);
    for (unsigned int p = 0; p < values.size(); ++p)
      values[p] -= contact_rows->rows[p].gap;
    return values;
  }



  std::string
  ActiveSetSolver::Result::failure() const
  {
    std::ostringstream text;
    switch (status)
      {
        case Status::converged:
          break;
        case Status::active_set_not_converged:
          text << "the active-set iteration did not converge within "
                  "'Contact solver/Maximum active-set iterations' "
                  "(complementarity residual "
               << std::setprecision(3) << residual << " m)";
          break;
        case Status::linear_solver_failed:
          text << "the CG solver did not converge within 'Contact "
                  "solver/Maximum linear iterations' (residual "
               << std::setprecision(3) << linear_residual << ")";
          break;
      }
    return text.str();
  }



  void
  ActiveSetSolver::Parameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact solver");
    prm.declare_entry(
      "Maximum active-set iterations",
      "50",
      Patterns::Integer(1),
      "Largest number of primal-dual active-set iterations per constrained "
      "problem (one displacement step or one L2 projection). A problem that "
      "has not converged then stops the run with a message. Dimensionless.");
    prm.declare_entry(
      "Linear solver tolerance",
      "1e-12",
      Patterns::Double(0.),
      "Relative tolerance of the CG solver for each condensed linear system: "
      "it stops when the l2 norm of the residual is below this times the "
      "larger of the norms of the right-hand side and of the condensed "
      "right-hand side. Dimensionless, in (0, 1).");
    prm.declare_entry("Maximum linear iterations",
                      "2000",
                      Patterns::Integer(1),
                      "Largest number of CG iterations per linear system.");
    prm.declare_entry("Initial penetration",
                      "reject",
                      Patterns::Selection("reject|project"),
                      "What to do with an initial configuration that "
                      "penetrates (a slave node inside the obstacle or the "
                      "master body): reject it with a message, or project "
                      "the initial displacement onto K_h (the M-projection) "
                      "with a warning that says by how much.");
    prm.declare_entry(
      "AMG near null space",
      "translations",
      Patterns::Selection("translations|rigid body motions"),
      "The near-null space the algebraic multigrid preconditioner of the "
      "displacement systems is built on: the rigid translations only, or "
      "all rigid body motions (the translations and the infinitesimal "
      "rotations about the origin, 1 in 2D, 3 in 3D). Measured: about 15% "
      "fewer CG iterations in 3D time steps where the stiffness dominates "
      "(tau c/h of 3 and more); no gain in 2D, nor in the static "
      "problems.");
    prm.declare_entry(
      "AMG prolongator",
      "unsmoothed",
      Patterns::Selection("unsmoothed|smoothed"),
      "The prolongator of the algebraic multigrid preconditioner (Trilinos "
      "ML, aggregation): 'unsmoothed' uses the aggregates' near-null-space "
      "vectors as they are (ML's 'aggregation: damping factor' = 0), "
      "'smoothed' smooths them with one damped Jacobi step (damping factor "
      "4/3, ML's default for elliptic problems). Measured on the 3D bar "
      "(282 123 DoFs): unsmoothed needs the same CG iterations at tau c/h = "
      "1/2 and 2, and 8% fewer at tau c/h = 8, with a third less set-up time "
      "and 0.7 kB per DoF less memory (smoothed aggregation's coarse "
      "matrices are much denser). Static problems, where S is the "
      "stiffness, can go the other way: the ball on block with 4 "
      "contact-zone refinements needs 1711 CG iterations unsmoothed and "
      "1379 smoothed (38 s and 35 s).");
    prm.declare_entry(
      "Preconditioner",
      "automatic",
      Patterns::Selection("automatic|AMG|Jacobi"),
      "The preconditioner of CG for the displacement systems: 'Jacobi' (the "
      "diagonal of the step matrix S = M + tau^2/4 A + tau/2 B), 'AMG' "
      "(Trilinos ML, the settings above), or 'automatic': Jacobi where the "
      "mass is lumped and a bound of the condition number of S scaled by "
      "its diagonal is at most 100, AMG otherwise and for static problems. "
      "The bound is Gershgorin's max_i sum_j |S_ij|/S_ii times the largest "
      "S_ii/M_ii (for linear elements at tau = h/2c about 1.5; it grows like "
      "(tau c/h)^2, and with viscosity like tau mu_v/(rho h^2)). Below it "
      "the number of Jacobi-CG iterations does not grow with the mesh (for "
      "the system without active rows, at most about 150 for a relative "
      "tolerance of 1e-12), and one costs a third to a fifth of an AMG-CG "
      "iteration, without AMG's set-up. The L2 projection with a consistent "
      "mass keeps AMG.");
    prm.leave_subsection();
  }

  void
  ActiveSetSolver::Parameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact solver");
    max_iterations        = prm.get_integer("Maximum active-set iterations");
    linear_tolerance      = prm.get_double("Linear solver tolerance");
    max_linear_iterations = prm.get_integer("Maximum linear iterations");
    project_initial_penetration = (prm.get("Initial penetration") == "project");
    amg_rotations = (prm.get("AMG near null space") == "rigid body motions");
    amg_smoothed_prolongator = (prm.get("AMG prolongator") == "smoothed");
    const std::string choice = prm.get("Preconditioner");
    preconditioner           = choice == "AMG"    ? Preconditioner::amg :
                               choice == "Jacobi" ? Preconditioner::jacobi :
                                                    Preconditioner::automatic;
    prm.leave_subsection();
    AssertThrow(linear_tolerance > 0. && linear_tolerance < 1.,
                ExcMessage("Contact solver/Linear solver tolerance must lie in "
                           "(0, 1); got " +
                           Utilities::to_string(linear_tolerance) + "."));
  }



  ActiveSetSolver::ActiveSetSolver(const Parameters &parameters,
                                   const MPI_Comm    comm)
    : parameters(parameters)
    , comm(comm)
    , row_operator(comm)
  {}



  void
  ActiveSetSolver::reinit(const IndexSet                  &owned,
                          const IndexSet                  &relevant,
                          const AffineConstraints<double> &constraints,
                          const ContactRows               &contact_rows)
  {
    locally_owned = owned;
    row_operator.reinit(owned, relevant, contact_rows);
    mesh_constraints.clear();
    mesh_constraints.copy_from(constraints);
    rows = &contact_rows;
    Tx.reinit(locally_owned, comm);
    additions.reinit(locally_owned, row_operator.ghost_set(), comm, true);
    H = nullptr;
  }



  double
  ActiveSetSolver::gershgorin_bound(const MatrixType &matrix) const
  {
    // max_i sum_j |H_ij| / H_ii over the locally owned rows (Epetra's
    // local row k is the k-th locally owned DoF, as in the vectors)
    const Epetra_CrsMatrix &epetra = matrix.trilinos_matrix();
    double                  bound  = 0.;
    for (int k = 0; k < epetra.NumMyRows(); ++k)
      {
        int     length  = 0;
        double *values  = nullptr;
        int    *indices = nullptr;
        epetra.ExtractMyRowView(k, length, values, indices);
        double sum = 0.;
        for (int j = 0; j < length; ++j)
          sum += std::abs(values[j]);
        bound = std::max(bound, sum / diagonal.trilinos_vector()[0][k]);
      }
    return Utilities::MPI::max(bound, comm);
  }



  void
  ActiveSetSolver::set_matrix(const MatrixType &matrix,
                              const MatrixType *preconditioner_matrix,
                              const double      lumped_mass_ratio)
  {
    H        = &matrix;
    diagonal = matrix_diagonal(matrix);
    set_diagonal_data(false);
    amg.reset();

    condition_bound = std::numeric_limits<double>::infinity();
    if (parameters.preconditioner == Parameters::Preconditioner::automatic &&
        std::isfinite(lumped_mass_ratio))
      condition_bound = gershgorin_bound(matrix) * lumped_mass_ratio;
    if (parameters.preconditioner == Parameters::Preconditioner::jacobi ||
        condition_bound <= Parameters::jacobi_condition_bound)
      {
        set_inverse_diagonal();
        return;
      }
    inverse_diagonal.clear();

    TrilinosWrappers::PreconditionAMG::AdditionalData data;
    data.elliptic              = true;
    data.higher_order_elements = false;
    data.smoother_sweeps       = 2;
    // no dropping: S = M + tau^2/4 A + tau/2 B is dominated by its
    // diagonal at tau ~ h/c, and with a threshold of 0.02 ML dropped
    // every coupling and fell back to one level, a direct solve of the
    // whole matrix (3D bar, 5e4 DoFs: 10 s set-up instead of 0.3 s)
    data.aggregation_threshold = 0.;
    if (near_null_space != nullptr)
      data.constant_modes = near_null_space->translations;
    amg = std::make_unique<TrilinosWrappers::PreconditionAMG>();
    const MatrixType &amg_matrix =
      preconditioner_matrix ? *preconditioner_matrix : matrix;
    // deal.II's ML parameters, then what its AdditionalData cannot say
    Teuchos::ParameterList              list;
    std::unique_ptr<Epetra_MultiVector> translations;
    data.set_parameters(list, translations, amg_matrix);
    if (!parameters.amg_smoothed_prolongator)
      list.set("aggregation: damping factor", 0.);
    // the rotations after the translations as deal.II passes them to ML
    // (ML reads the vectors during initialize())
    std::unique_ptr<Epetra_MultiVector> modes;
    if (near_null_space != nullptr && !near_null_space->rotations.empty())
      {
        const auto &rotations      = near_null_space->rotations;
        const int   n_translations = data.constant_modes.size();
        modes                      = std::make_unique<Epetra_MultiVector>(
          amg_matrix.trilinos_matrix().OperatorDomainMap(),
          n_translations + rotations.size());
        for (int m = 0; m < n_translations; ++m)
          for (int i = 0; i < modes->MyLength(); ++i)
            (*modes)[m][i] = (*translations)[m][i];
        for (unsigned int r = 0; r < rotations.size(); ++r)
          for (int i = 0; i < modes->MyLength(); ++i)
            (*modes)[n_translations + r][i] =
              rotations[r].trilinos_vector()[0][i];
        list.set("null space: type", "pre-computed");
        list.set("null space: dimension", modes->NumVectors());
        list.set("null space: vectors", modes->Values());
      }
    amg->initialize(amg_matrix, list);
  }



  void
  ActiveSetSolver::set_diagonal_matrix(const VectorType &d)
  {
    H        = nullptr;
    diagonal = d;
    set_inverse_diagonal();
    amg.reset();
    set_diagonal_data(true);
  }



  void
  ActiveSetSolver::set_inverse_diagonal()
  {
    // Jacobi: x_i / H_ii as x_i * (1 / H_ii)
    inverse_diagonal = diagonal;
    for (auto &value : inverse_diagonal)
      value = 1. / value;
  }



  void
  ActiveSetSolver::set_diagonal_data(const bool is_diagonal)
  {
    // the scaling of the active-set criterion for each row: H's diagonal at
    // the eliminated DoF (owned, as the row's slave node)
    row_scaling.assign(rows->size(), 0.);
    for (unsigned int p = 0; p < rows->size(); ++p)
      row_scaling[p] = diagonal(rows->rows[p].eliminated_dof());

    // A pointwise projection is possible if H is diagonal, no row has
    // master entries, and the only mesh constraints are Dirichlet lines
    // (no entries) that touch no row's DoFs.
    pointwise = is_diagonal;
    for (const ContactRow &row : rows->rows)
      {
        // (a row without master entries has only its slave node's DoFs,
        // which this rank's constraints know)
        if (row.has_master_entries())
          pointwise = false;
        else
          for (const auto &entry : row.entries)
            if (mesh_constraints.is_constrained(entry.first))
              pointwise = false;
      }
    for (const auto &line : mesh_constraints.get_lines())
      if (!line.entries.empty())
        pointwise = false;
    pointwise = (Utilities::MPI::min(pointwise ? 1 : 0, comm) == 1);
  }



  void
  ActiveSetSolver::vmult_H(VectorType &y, const VectorType &x) const
  {
    if (H != nullptr)
      H->vmult(y, x);
    else
      {
        y = x;
        y.scale(diagonal);
      }
  }



  void
  ActiveSetSolver::make_constraints(const std::vector<char>   &active,
                                    AffineConstraints<double> &constraints,
                                    const bool homogeneous) const
  {
    // local lines: the relevant DoFs and the rows' DoFs (clear() alone
    // would size the lines' index cache by the global number of DoFs on
    // every rank)
    constraints.reinit(row_operator.ghost_set());
    for (unsigned int p = 0; p < rows->size(); ++p)
      if (active[p])
        {
          const ContactRow      &row = rows->rows[p];
          const global_dof_index i   = row.eliminated_dof();
          const double           c_i = row.entries[row.eliminated].second;
          // c_i v_i + sum_{k != i} c_k v_k = g
          constraints.add_line(i);
          for (unsigned int k = 0; k < row.entries.size(); ++k)
            if (k != row.eliminated)
              constraints.add_entry(i,
                                    row.entries[k].first,
                                    -row.entries[k].second / c_i);
          if (!homogeneous)
            constraints.set_inhomogeneity(i, row.gap / c_i);
        }
    // (the contact lines are not restricted to the mesh constraints' local
    // lines, hence different local lines)
    constraints.merge(mesh_constraints,
                      AffineConstraints<double>::left_object_wins,
                      true);
    constraints.close();
  }



  void
  ActiveSetSolver::transpose_distribute(
    const AffineConstraints<double> &homogeneous,
    VectorType                      &z) const
  {
    // z <- T^T z: every owned constrained entry z_i is added, times the
    // coefficient, to the entries z_j it depends on (possibly owned
    // elsewhere), and then set to zero.
    additions = 0.;
    for (const auto &line : homogeneous.get_lines())
      if (locally_owned.is_element(line.index))
        {
          const double z_i = z(line.index);
          for (const auto &entry : line.entries)
            additions(entry.first) += entry.second * z_i;
        }
    additions.compress(VectorOperation::add);
    z += additions;
    for (const auto &line : homogeneous.get_lines())
      if (locally_owned.is_element(line.index))
        z(line.index) = 0.;
    z.compress(VectorOperation::insert);
  }



  void
  ActiveSetSolver::vmult_condensed(const AffineConstraints<double> &homogeneous,
                                   VectorType                      &y,
                                   const VectorType                &x) const
  {
    Tx = x;
    homogeneous.distribute(Tx);
    vmult_H(y, Tx);
    transpose_distribute(homogeneous, y);
    // constrained entries: identity scaled by H's diagonal (they stay zero)
    for (const auto &line : homogeneous.get_lines())
      if (locally_owned.is_element(line.index))
        y(line.index) = diagonal(line.index) * x(line.index);
    y.compress(VectorOperation::insert);
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
    v.compress(VectorOperation::insert);
    Result result;
    result.iterations = 1;
    return result;
  }



  ActiveSetSolver::Result
  ActiveSetSolver::solve(const VectorType    &r,
                         VectorType          &v,
                         std::vector<char>   &active,
                         std::vector<double> &multipliers) const
  {
    Assert(H != nullptr || diagonal.size() > 0, ExcInternalError());
    active.resize(rows->size(), 0);
    multipliers.assign(rows->size(), 0.);

    if (pointwise)
      return solve_pointwise(r, v, active, multipliers);

    Result result;
    // the local part of every active set visited so far (to detect cycling)
    std::vector<std::vector<char>> visited;
    AffineConstraints<double>      constraints, homogeneous;
    VectorType                     x(r), b(r), k(r), residual(r);
    const double                   r_norm = r.l2_norm();

    for (result.iterations = 1;; ++result.iterations)
      {
        make_constraints(active, constraints, false);
        make_constraints(active, homogeneous, true);
        // without active rows k = 0 and every multiplier is zero
        const bool any_active =
          Utilities::MPI::max(
            std::find(active.begin(), active.end(), 1) != active.end() ? 1 : 0,
            comm) == 1;

        // k: the inhomogeneities (v = T x + k)
        k = 0.;
        constraints.distribute(k);

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
        for (const auto &line : homogeneous.get_lines())
          if (locally_owned.is_element(line.index))
            x(line.index) = 0.;
        x.compress(VectorOperation::insert);

        const double tolerance =
          std::max(parameters.linear_tolerance * std::max(b.l2_norm(), r_norm),
                   1e-300);
        SolverControl control(parameters.max_linear_iterations, tolerance);
        SolverCG<VectorType> cg(control);

        struct Operator
        {
          const ActiveSetSolver           *solver;
          const AffineConstraints<double> *homogeneous;
          void
          vmult(VectorType &dst, const VectorType &src) const
          {
            solver->vmult_condensed(*homogeneous, dst, src);
          }
        } op{this, &homogeneous};

        struct Preconditioner
        {
          const ActiveSetSolver           *solver;
          const AffineConstraints<double> *homogeneous;
          void
          vmult(VectorType &dst, const VectorType &src) const
          {
            if (solver->amg)
              solver->amg->vmult(dst, src);
            else
              {
                dst = src;
                dst.scale(solver->inverse_diagonal);
              }
            for (const auto &line : homogeneous->get_lines())
              if (solver->locally_owned.is_element(line.index))
                dst(line.index) = 0.;
            dst.compress(VectorOperation::insert);
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
            return result;
          }
        result.linear_iterations += control.last_step();

        v = x;
        constraints.distribute(v);

        // multipliers from the residual r - H v at the slave nodes
        if (any_active)
          {
            vmult_H(residual, v);
            residual.sadd(-1., 1., r);
            const VectorType &ghosted = row_operator.with_row_ghosts(residual);
            for (unsigned int p = 0; p < rows->size(); ++p)
              {
                const ContactRow &row = rows->rows[p];
                multipliers[p]        = 0.;
                if (active[p])
                  for (unsigned int c = 0; c < row.n_components; ++c)
                    multipliers[p] +=
                      row.normal[c] * ghosted(row.entries[c].first);
              }
          }
        else
          std::fill(multipliers.begin(), multipliers.end(), 0.);

        // new active set: mu_p + c_p (C v - g)_p > 0
        // (a displacement tolerance delta keeps round-off from flipping rows
        // that sit exactly on the constraint)
        const std::vector<double> violation = row_operator.constraint_values(v);
        double                    scale     = 0.;
        for (const ContactRow &row : rows->rows)
          scale = std::max(scale, std::abs(row.gap));
        scale = std::max(Utilities::MPI::max(scale, comm), v.linfty_norm());
        const double      delta = 1e-11 * scale;
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
                     std::abs(std::min(multipliers[p] / row_scaling[p],
                                       -violation[p])));
        result.residual = Utilities::MPI::max(result.residual, comm);
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
            result.cycled      = true;
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
            const unsigned int owner =
              Utilities::MPI::min(size == largest ?
                                    my_rank :
                                    Utilities::MPI::n_mpi_processes(comm),
                                  comm);
            new_active = active;
            if (owner == my_rank)
              new_active[worst] = !active[worst];
          }
        active = new_active;
      }
    return result;
  }
} // namespace dyncontact
