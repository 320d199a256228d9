#ifndef dyncontact_base_vector_copy_h
#define dyncontact_base_vector_copy_h

#include <deal.II/lac/trilinos_vector.h>

namespace dyncontact
{
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
