// Helpers of the unit tests of the algebra (active_set_solver,
// integrators): tiny Trilinos matrices and vectors on one rank, and
// constraint rows written by hand.
#ifndef dyncontact_tests_algebra_h
#define dyncontact_tests_algebra_h

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <dyncontact/contact/active_set_solver.h>

#include <cmath>
#include <vector>

namespace algebra
{
  using namespace dealii;
  using dyncontact::ContactRow;
  using dyncontact::ContactRows;
  using dyncontact::MatrixType;
  using dyncontact::VectorType;

  inline IndexSet
  all(const unsigned int n)
  {
    IndexSet set(n);
    set.add_range(0, n);
    return set;
  }

  /// A dense n x n Trilinos matrix with the given entries (row by row).
  inline void
  make_matrix(MatrixType &matrix, const std::vector<std::vector<double>> &a)
  {
    const unsigned int     n = a.size();
    DynamicSparsityPattern dsp(n, n);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        dsp.add(i, j);
    matrix.reinit(all(n), all(n), dsp, MPI_COMM_WORLD);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        matrix.set(i, j, a[i][j]);
    matrix.compress(VectorOperation::insert);
  }

  inline VectorType
  make_vector(const std::vector<double> &values)
  {
    VectorType v(all(values.size()), MPI_COMM_WORLD);
    for (unsigned int i = 0; i < values.size(); ++i)
      v(i) = values[i];
    v.compress(VectorOperation::insert);
    return v;
  }

  /// The row sum_k coefficients[k] v_{dofs[k]} <= gap; the first
  /// @p n_slave entries are the slave node's components (its normal).
  inline ContactRow
  make_row(const std::vector<unsigned int> &dofs,
           const std::vector<double>       &coefficients,
           const unsigned int               n_slave,
           const double                     gap)
  {
    ContactRow row;
    row.n_components = n_slave;
    for (unsigned int k = 0; k < dofs.size(); ++k)
      row.entries.emplace_back(dofs[k], coefficients[k]);
    for (unsigned int c = 0; c < n_slave; ++c)
      row.normal[c] = coefficients[c];
    // eliminate the slave component with the largest |nu_i|
    for (unsigned int c = 1; c < n_slave; ++c)
      if (std::abs(coefficients[c]) > std::abs(coefficients[row.eliminated]))
        row.eliminated = c;
    row.gap    = gap;
    row.weight = 1.;
    return row;
  }

  /// No hanging nodes, no Dirichlet data.
  inline AffineConstraints<double>
  no_constraints(const unsigned int n)
  {
    AffineConstraints<double> constraints;
    constraints.reinit(all(n));
    constraints.close();
    return constraints;
  }

  inline bool
  close(const double a, const double b, const double tolerance = 1e-10)
  {
    return std::abs(a - b) <= tolerance * std::max(1., std::abs(b));
  }
} // namespace algebra

#endif
