#include <dyncontact/base/vector_copy.h>
#include <dyncontact/discretization/semi_discrete_system.h>

#include <Epetra_CrsMatrix.h>
#include <Epetra_Vector.h>

#include <cstring>

// The products of the system's operators that the schemes use (y = A x
// cached, M x for a lumped or consistent M).

namespace dyncontact
{
  void
  CachedProduct::reinit(const Product &product)
  {
    this->product = product;
    valid         = false;
  }



  const VectorType &
  CachedProduct::vmult(const VectorType &x) const
  {
    Assert(product, ExcInternalError());
    bool hit = valid &&
               x_last.locally_owned_elements() == x.locally_owned_elements() &&
               std::memcmp(x_last.begin(),
                           x.begin(),
                           x.locally_owned_size() * sizeof(double)) == 0;
    hit = (Utilities::MPI::min(hit ? 1 : 0, x.get_mpi_communicator()) == 1);
    if (!hit)
      {
        copy_with_layout(x_last, x);
        y_last.reinit(x, true);
        product(y_last, x);
        valid = true;
      }
    return y_last;
  }



  void
  SystemMatrices::mass_vmult(VectorType &y, const VectorType &x) const
  {
    if (M != nullptr)
      {
        y.reinit(x, true);
        M->vmult(y, x);
      }
    else
      {
        y = x;
        y.scale(*M_lumped);
      }
  }



  double
  SystemMatrices::mass_linfty_norm() const
  {
    return M != nullptr ? M->linfty_norm() : M_lumped->linfty_norm();
  }



  void
  SystemMatrices::add_mass(MatrixType &matrix, const double factor) const
  {
    if (M != nullptr)
      {
        matrix.add(factor, *M);
        return;
      }
    // the diagonal of the Epetra matrix, changed in place (deal.II's wrapper
    // gives only a const view of the matrix it owns)
    auto &epetra = const_cast<Epetra_CrsMatrix &>(matrix.trilinos_matrix());
    Epetra_Vector diagonal(epetra.RowMap());
    int           error = epetra.ExtractDiagonalCopy(diagonal);
    if (error == 0)
      error = diagonal.Update(factor, M_lumped->trilinos_vector(), 1.);
    if (error == 0)
      error = epetra.ReplaceDiagonalValues(diagonal);
    AssertThrow(error == 0,
                ExcMessage("adding the lumped mass to a matrix's diagonal "
                           "failed (Epetra error " +
                           std::to_string(error) + ")"));
  }
} // namespace dyncontact
