#ifndef dyncontact_base_vector_copy_h
#define dyncontact_base_vector_copy_h

#include <deal.II/base/exceptions.h>
#include <deal.II/lac/trilinos_vector.h>

#include <algorithm>

namespace dyncontact
{
  /**
   * The owned entries of @p from into those of @p to, between a Trilinos
   * vector and a deal.II LinearAlgebra::distributed::Vector of the same
   * DoFs (in both the owned entries are the owned DoFs in increasing
   * order): how the matrix-free operators and the p-multigrid, which work
   * on deal.II's vectors, read and write the program's Trilinos vectors.
   */
  template <typename To, typename From>
  void
  copy_owned(To &to, const From &from)
  {
    AssertDimension(to.locally_owned_size(), from.locally_owned_size());
    std::copy(from.begin(), from.end(), to.begin());
  }


  /**
   * @p to = @p from, with the parallel layout of @p from. deal.II's
   * assignment of Trilinos vectors of equal global size keeps the target's
   * layout (it imports the values): a vector kept across a mesh adaptation
   * that repartitioned the mesh without changing the number of DoFs would
   * keep the old layout, and the next operation with a vector of the new
   * one fails (Trilinos error -3). Vectors that outlive a mesh are copied
   * with this.
   */
  inline void
  copy_with_layout(dealii::TrilinosWrappers::MPI::Vector       &to,
                   const dealii::TrilinosWrappers::MPI::Vector &from)
  {
    if (to.size() != from.size() ||
        !to.trilinos_vector().Map().SameAs(from.trilinos_vector().Map()))
      to.reinit(from, true);
    to = from;
  }
} // namespace dyncontact

#endif
