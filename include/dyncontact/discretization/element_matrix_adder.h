#ifndef dyncontact_discretization_element_matrix_adder_h
#define dyncontact_discretization_element_matrix_adder_h

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <vector>

class Epetra_CrsMatrix;

namespace dyncontact
{
  using namespace dealii;

  /**
   * Adds element matrices into a Trilinos matrix whose sparsity pattern
   * holds them. A locally owned row goes straight into Epetra's row (its
   * column indices are local, and sorted once the pattern is complete:
   * one merge with the element's sorted columns finds every entry),
   * instead of deal.II's add(), which has Epetra look up every entry's
   * global column (3D bar at 1e6 DoFs: 1.5 s of the step matrix's
   * assembly). Other rows, an entry the merge does not find, and a
   * matrix whose pattern is not complete go through deal.II's add().
   */
  class ElementMatrixAdder
  {
  public:
    explicit ElementMatrixAdder(TrilinosWrappers::SparseMatrix &matrix);

    /// Adds @p element_matrix at the rows and columns @p dofs.
    void
    add(const std::vector<types::global_dof_index> &dofs,
        const FullMatrix<double>                   &element_matrix);

  private:
    TrilinosWrappers::SparseMatrix &matrix;
    Epetra_CrsMatrix               &epetra;
    const bool                      direct;
    std::vector<int>                rows, columns;
    std::vector<unsigned int>       order;
    /// where each column of the element was found in the row before
    std::vector<int> positions;
  };
} // namespace dyncontact

#endif
