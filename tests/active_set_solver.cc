// Unit tests of the active-set solver (min 1/2 v^T H v - r^T v, C v <= g) on
// tiny problems with solutions known by hand: one row; two coupled rows; a
// row that starts active and must leave the active set; a degenerate row
// (touching with zero force); an oblique normal; a two-body row with a
// master entry; each by CG + AMG and, where H is diagonal and the rows have
// no master entries, by the pointwise projection. A CG that runs out of
// iterations and an active set that does not settle come back as a status
// naming the limit, not as an exception.

#include <deal.II/base/mpi.h>

#include <fstream>
#include <iomanip>
#include <string>

#include "algebra.h"

using namespace algebra;
using dyncontact::ActiveSetSolver;

std::ofstream out("output");

struct Expected
{
  std::vector<double> v;
  std::vector<double> mu;
  /// 1: active, 0: inactive, 2: either (a degenerate row)
  std::vector<char> active;
};

/// Solves and compares with @p expected; prints one line.
ActiveSetSolver::Result
check(const std::string                      &name,
      const std::vector<std::vector<double>> &H_entries,
      const bool                              diagonal,
      const std::vector<double>              &r_values,
      const std::vector<ContactRow>          &row_list,
      const Expected                         &expected,
      std::vector<char>                       active     = {},
      ActiveSetSolver::Parameters             parameters = {})
{
  const unsigned int n = r_values.size();
  MatrixType         H;
  make_matrix(H, H_entries);
  ContactRows rows;
  rows.rows = row_list;
  ActiveSetSolver solver(parameters, MPI_COMM_WORLD);
  solver.reinit(all(n), all(n), no_constraints(n), rows);
  // a diagonal H as its diagonal (a lumped mass), otherwise the matrix
  std::vector<double> H_diagonal;
  for (unsigned int i = 0; i < n; ++i)
    H_diagonal.push_back(H_entries[i][i]);
  const VectorType d = make_vector(H_diagonal);
  if (diagonal)
    solver.set_diagonal_matrix(d);
  else
    solver.set_matrix(H);
  const VectorType    r = make_vector(r_values);
  VectorType          v(r);
  std::vector<double> mu;
  active.resize(rows.size(), 0);
  const auto result = solver.solve(r, v, active, mu);

  bool ok = result.converged();
  for (unsigned int i = 0; i < n; ++i)
    ok = ok && close(v(i), expected.v[i]);
  for (unsigned int p = 0; p < rows.size(); ++p)
    ok = ok && close(mu[p], expected.mu[p]) &&
         (expected.active[p] == 2 || active[p] == expected.active[p]);
  out << std::setprecision(6) << name << (diagonal ? " (pointwise)" : "")
      << ": v = (";
  for (unsigned int i = 0; i < n; ++i)
    out << (i ? ", " : "") << (std::abs(v(i)) < 1e-12 ? 0. : v(i));
  out << "), mu = (";
  for (unsigned int p = 0; p < rows.size(); ++p)
    out << (p ? ", " : "") << (std::abs(mu[p]) < 1e-12 ? 0. : mu[p]);
  out << "), " << result.iterations
      << " iteration(s): " << (ok ? "OK" : "FAILED") << "\n";
  return result;
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize       mpi(argc, argv, 1);
  const std::vector<std::vector<double>> diag23   = {{2., 0.}, {0., 3.}};
  const std::vector<std::vector<double>> identity = {{1., 0.}, {0., 1.}};
  const std::vector<std::vector<double>> laplace  = {{2., -1., 0.},
                                                     {-1., 2., -1.},
                                                     {0., -1., 2.}};

  // one row v0 <= 1; unconstrained v = (2, 1): v = (1, 1), mu = 4 - 2 = 2
  for (const bool diagonal : {false, true})
    check("one row",
          diag23,
          diagonal,
          {4., 3.},
          {make_row({0}, {1.}, 1, 1.)},
          {{1., 1.}, {2.}, {1}});

  // two coupled rows v0 <= 1, v2 <= 1 with H = tridiag(-1, 2, -1), r = 1:
  // unconstrained (1.5, 2, 1.5); v = (1, 1.5, 1), mu = 1 - (2 - 1.5) = 0.5
  check("two coupled rows",
        laplace,
        false,
        {1., 1., 1.},
        {make_row({0}, {1.}, 1, 1.), make_row({2}, {1.}, 1, 1.)},
        {{1., 1.5, 1.}, {0.5, 0.5}, {1, 1}});

  // a row that starts active but is not binding (v0 = -1 < 1): it leaves
  for (const bool diagonal : {false, true})
    check("a row that must leave the active set",
          identity,
          diagonal,
          {-1., 0.},
          {make_row({0}, {1.}, 1, 1.)},
          {{-1., 0.}, {0.}, {0}},
          {1});

  // degenerate: the unconstrained minimiser touches the constraint, mu = 0
  for (const bool diagonal : {false, true})
    check("a degenerate row",
          identity,
          diagonal,
          {1., 0.},
          {make_row({0}, {1.}, 1, 1.)},
          {{1., 0.}, {0.}, {2}},
          {1});

  // oblique normal nu = (0.6, 0.8), g = 1, H = I, r = (1, 2): c.r = 2.2,
  // v = r - 1.2 nu = (0.28, 1.04), mu = 1.2
  for (const bool diagonal : {false, true})
    check("an oblique normal",
          identity,
          diagonal,
          {1., 2.},
          {make_row({0, 1}, {0.6, 0.8}, 2, 1.)},
          {{0.28, 1.04}, {1.2}, {1}});

  // two bodies: v0 - v1 <= 0.5 (slave DoF 0, master DoF 1), H = diag(1, 2),
  // r = (2, 0): v0 = 2 - mu, v1 = mu/2, v0 - v1 = 0.5: mu = 1, v = (1, 0.5)
  for (const bool diagonal : {false, true})
    check("a two-body row",
          {{1., 0.}, {0., 2.}},
          diagonal,
          {2., 0.},
          {make_row({0, 1}, {1., -1.}, 1, 0.5)},
          {{1., 0.5}, {1.}, {1}});

  // failures come back as a status: a CG with one iteration on a 1D
  // Laplacian of 200 DoFs (AMG is not exact there), and an active set
  // that needs two iterations but may take one
  auto failing = [](const std::string                 &name,
                    const unsigned int                 n,
                    const ActiveSetSolver::Parameters &parameters,
                    const ActiveSetSolver::Status      expected) {
    std::vector<std::vector<double>> a(n, std::vector<double>(n, 0.));
    for (unsigned int i = 0; i < n; ++i)
      {
        a[i][i] = 2.;
        if (i > 0)
          a[i][i - 1] = a[i - 1][i] = -1.;
      }
    MatrixType H;
    make_matrix(H, a);
    ContactRows rows;
    rows.rows = {make_row({0}, {1.}, 1, 1.)};
    ActiveSetSolver solver(parameters, MPI_COMM_WORLD);
    solver.reinit(all(n), all(n), no_constraints(n), rows);
    solver.set_matrix(H);
    const VectorType    r = make_vector(std::vector<double>(n, -1.));
    VectorType          v(r);
    std::vector<char>   active = {1};
    std::vector<double> mu;
    const auto          result = solver.solve(r, v, active, mu);
    out << name << ": reported, not thrown: "
        << (result.status == expected ? "OK" : "FAILED")
        << "\n  "
        // the message without the residual's digits
        << result.failure().substr(0, result.failure().find(" (")) << "\n";
  };
  {
    ActiveSetSolver::Parameters parameters;
    parameters.max_linear_iterations = 1;
    failing("CG with 1 iteration allowed",
            200,
            parameters,
            ActiveSetSolver::Status::linear_solver_failed);
  }
  {
    ActiveSetSolver::Parameters parameters;
    parameters.max_iterations = 1;
    failing("a row that must leave, 1 active-set iteration allowed",
            2,
            parameters,
            ActiveSetSolver::Status::active_set_not_converged);
  }
}
