#include <deal.II/base/array_view.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>
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
      "Relative tolerance of the CG solver for the static problem's "
      "condensed linear systems and for the L2 projection (12f) of the "
      "dynamic schemes with a consistent or blended mass (an inexact "
      "projection breaks N-CS's energy inequality by its residual): it "
      "stops when the l2 norm of the residual "
      "is below this times the larger of the norms of the right-hand side "
      "and of the condensed right-hand side. (The time steps of the dynamic "
      "schemes use 'Step solver tolerance'.) Dimensionless, in (0, 1).");
    prm.declare_entry(
      "Step solver tolerance",
      "1e-6",
      Patterns::Double(0.),
      "Relative tolerance of the CG solver in the displacement step of the "
      "dynamic schemes and in their L2 projection with a lumped mass (a "
      "solve with two bodies or hanging nodes): CG stops when the l2 norm of "
      "the residual is below "
      "this times that of its start (uⁿ + tau u̇ⁿ, or the last active-set "
      "iterate), i.e. relative to the step's correction beyond the start, "
      "not to the whole right-hand side (a floor of 1e-14 times that, "
      "round-off). The solution is then moved along the line from the "
      "step's origin (the last displacement; for a projection the "
      "displacement it projects from) to where its residual is orthogonal "
      "to the increment (one more product with the matrix), so that the "
      "residual does no work on the step: the energy identity of Theorem "
      "3.2 holds to round-off at any tolerance, and the energy monitor's "
      "tolerance is 1e-2 times this one, within [1e-9, 1e-4]. Momentum, "
      "and two runs that differ by round-off (one rank against two, "
      "another preconditioner), agree to about this tolerance times the "
      "velocity change: lower it (1e-12) to compare them closer (on "
      "prm/punch.prm the punch's force differs from that at 1e-12 by 6e-7 "
      "of it at 1e-6, 9e-4 at 1e-3, 2e-2 at 1e-1). 1e-6: about 5 CG "
      "iterations per step for linear elements at tau = h/(2c) "
      "(doc/results.md, \"CG iterations per time step\"). Dimensionless, "
      "in (0, 1).");
    prm.declare_entry("Maximum linear iterations",
                      "2000",
                      Patterns::Integer(1),
                      "Largest number of CG iterations per linear system.");
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
      Patterns::Selection("automatic|AMG|Jacobi|multigrid"),
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
      "mass keeps AMG. With 'Step matrix = matrix-free', 'automatic' is "
      "Jacobi, and 'AMG' is refused. 'multigrid' (only with 'Step matrix "
      "= matrix-free' and Polynomial degree >= 2): a two-level "
      "p-multigrid V-cycle: a damped Jacobi step on S (before and "
      "after), and on the same mesh with linear elements S assembled and "
      "one AMG V-cycle (the settings above). It needs no matrix of the "
      "run's degree, and its CG iterations grow far less with tau c/h "
      "than Jacobi's; one costs about three products with S. Take it "
      "where the banner's largest S_ii/M_ii is above about 50 (about "
      "1 + 4.5 (tau c/h)^2 for Q2 and 1 + 19 (tau c/h)^2 for Q3, h the "
      "cell size: tau c/h above about 3.3 and 1.6): on the 3D bar with Q2 "
      "(2.3e5 DoFs) a step took 0.52 of Jacobi's time at tau = 8 h/c, "
      "1.08 times at tau = 2 h/c and 2.2 times at tau = h/2c "
      "(doc/results.md). The L2 projection with a consistent mass takes "
      "AMG.");
    prm.declare_entry(
      "Step matrix",
      "assembled",
      Patterns::Selection("assembled|matrix-free"),
      "How CG applies the step matrix S = M + (1/4 + theta/2) tau^2 A + "
      "tau/2 B of the dynamic schemes (theta: Time integration/Numerical "
      "dissipation, 0 by default). 'assembled': S is built as a sparse matrix for "
      "each time step size (and AMG on it, if chosen). 'matrix-free': A "
      "and B are applied cell by cell by sum factorisation (deal.II's "
      "MatrixFree) and M as its matrix or lumped diagonal, with Jacobi on "
      "S's diagonal, which is computed without a matrix (the L2 projection "
      "with a consistent mass keeps AMG on M): nothing is "
      "assembled but the mass, and with a lumped mass no sparsity pattern "
      "is built, so that a mesh adaptation or a new tau costs less, and "
      "higher degrees cost less per DoF. The solution is the same to the "
      "solver's tolerance. "
      "Jacobi's iteration count grows with tau c/h and with the "
      "viscosity: where 'automatic' would take AMG for the assembled S "
      "(the banner's bound of the condition number above 100, tau c/h "
      "above about 7 for linear elements), keep 'assembled' for linear "
      "elements, and take 'Preconditioner = multigrid' for p >= 2. Not for "
      "the static problem (S = A).");
    prm.leave_subsection();
  }

  void
  ActiveSetSolver::Parameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact solver");
    max_iterations        = prm.get_integer("Maximum active-set iterations");
    linear_tolerance      = prm.get_double("Linear solver tolerance");
    step_tolerance        = prm.get_double("Step solver tolerance");
    max_linear_iterations = prm.get_integer("Maximum linear iterations");
    amg_rotations = (prm.get("AMG near null space") == "rigid body motions");
    amg_smoothed_prolongator = (prm.get("AMG prolongator") == "smoothed");
    const std::string choice = prm.get("Preconditioner");
    preconditioner           = choice == "AMG"       ? Preconditioner::amg :
                               choice == "Jacobi"    ? Preconditioner::jacobi :
                               choice == "multigrid" ? Preconditioner::multigrid :
                                                       Preconditioner::automatic;
    matrix_free_step         = (prm.get("Step matrix") == "matrix-free");
    prm.leave_subsection();
    AssertThrow(!(matrix_free_step && preconditioner == Preconditioner::amg),
                ExcMessage("Contact solver/Preconditioner = AMG needs an "
                           "assembled step matrix, but Contact solver/Step "
                           "matrix = matrix-free: set 'Preconditioner' to "
                           "automatic or Jacobi, or 'Step matrix' to "
                           "assembled."));
    AssertThrow(matrix_free_step || preconditioner != Preconditioner::multigrid,
                ExcMessage("Contact solver/Preconditioner = multigrid is the "
                           "p-multigrid of a step matrix applied without a "
                           "matrix, but Contact solver/Step matrix = "
                           "assembled: set 'Step matrix' to matrix-free, or "
                           "'Preconditioner' to AMG for the assembled "
                           "matrix. (The static scheme has no step matrix "
                           "to apply without a matrix: there, set "
                           "'Preconditioner' to automatic or AMG.)"));
    AssertThrow(linear_tolerance > 0. && linear_tolerance < 1.,
                ExcMessage("Contact solver/Linear solver tolerance must lie in "
                           "(0, 1); got " +
                           Utilities::to_string(linear_tolerance) + "."));
    AssertThrow(step_tolerance > 0. && step_tolerance < 1.,
                ExcMessage("Contact solver/Step solver tolerance must lie in "
                           "(0, 1); got " +
                           Utilities::to_string(step_tolerance) + "."));
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
    bool hanging = false;
    for (const auto &line : mesh_constraints.get_lines())
      hanging |= locally_owned.is_element(line.index) && !line.entries.empty();
    mesh_has_hanging_nodes = Utilities::MPI::logical_or(hanging, comm);
    rows                   = &contact_rows;
    Tx.reinit(locally_owned, comm);
    additions.reinit(locally_owned, row_operator.ghost_set(), comm, true);
    H                = nullptr;
    H_operator       = nullptr;
    H_preconditioner = nullptr;
    last_constraints.reset();
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
    H                = &matrix;
    H_operator       = nullptr;
    H_preconditioner = nullptr;
    diagonal         = matrix_diagonal(matrix);
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

    amg = make_amg(preconditioner_matrix ? *preconditioner_matrix : matrix,
                   near_null_space,
                   parameters.amg_smoothed_prolongator);
  }



  void
  ActiveSetSolver::set_operator(const Operator   &vmult,
                                const VectorType &d,
                                const Operator   &preconditioner)
  {
    H                = nullptr;
    H_operator       = vmult;
    H_preconditioner = preconditioner;
    diagonal         = d;
    condition_bound  = std::numeric_limits<double>::infinity();
    set_inverse_diagonal();
    amg.reset();
    set_diagonal_data(false);
  }



  void
  ActiveSetSolver::set_diagonal_matrix(const VectorType &d)
  {
    H                = nullptr;
    H_operator       = nullptr;
    H_preconditioner = nullptr;
    diagonal         = d;
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



  std::unique_ptr<TrilinosWrappers::PreconditionAMG>
  make_amg(const MatrixType                     &matrix,
           const ActiveSetSolver::NearNullSpace *modes_in,
           const bool                            smoothed_prolongator)
  {
    TrilinosWrappers::PreconditionAMG::AdditionalData data;
    data.elliptic              = true;
    data.higher_order_elements = false;
    data.smoother_sweeps       = 2;
    // no dropping: S = M + tau^2/4 A + tau/2 B is dominated by its
    // diagonal at tau ~ h/c, and with a threshold of 0.02 ML dropped
    // every coupling and fell back to one level, a direct solve of the
    // whole matrix (3D bar, 5e4 DoFs: 10 s set-up instead of 0.3 s)
    data.aggregation_threshold = 0.;
    if (modes_in != nullptr)
      data.constant_modes = modes_in->translations;
    // deal.II's ML parameters, then what its AdditionalData cannot say
    Teuchos::ParameterList              list;
    std::unique_ptr<Epetra_MultiVector> translations;
    data.set_parameters(list, translations, matrix);
    if (!smoothed_prolongator)
      list.set("aggregation: damping factor", 0.);
    // the rotations after the translations as deal.II passes them to ML
    // (ML reads the vectors during initialize())
    std::unique_ptr<Epetra_MultiVector> modes;
    if (modes_in != nullptr && !modes_in->rotations.empty())
      {
        const auto &rotations      = modes_in->rotations;
        const int   n_translations = data.constant_modes.size();
        modes                      = std::make_unique<Epetra_MultiVector>(
          matrix.trilinos_matrix().OperatorDomainMap(),
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
    auto amg = std::make_unique<TrilinosWrappers::PreconditionAMG>();
    amg->initialize(matrix, list);
    return amg;
  }


} // namespace dyncontact
