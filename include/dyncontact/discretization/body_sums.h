#ifndef dyncontact_discretization_body_sums_h
#define dyncontact_discretization_body_sums_h

#include <deal.II/base/mpi.h>
#include <deal.II/lac/trilinos_vector.h>

#include <vector>

namespace dyncontact
{
  using namespace dealii;
  using VectorType = TrilinosWrappers::MPI::Vector;

  template <int dim>
  class SemiDiscreteSystem;

  /**
   * Sums of (M x)_i over each body's DoFs of each component, over all
   * ranks: entry 3 b + d for body b and component d (z: 0 in 2D). With
   * x = udot, each body's linear momentum (Theorem 3.1).
   */
  template <int dim>
  std::vector<double>
  body_sums(const SemiDiscreteSystem<dim> &system,
            const VectorType              &x,
            const unsigned int             n_bodies,
            const MPI_Comm                 communicator);

  /**
   * Each body's mass-weighted mean of @p u per component, sum of M u over
   * sum of M 1 (the displacement of its centre of mass): entry 3 b + d.
   */
  template <int dim>
  std::vector<double>
  body_mean_displacements(const SemiDiscreteSystem<dim> &system,
                          const VectorType              &u,
                          const unsigned int             n_bodies,
                          const MPI_Comm                 communicator);

  /**
   * Adds to @p x on each body's DoFs of each component a constant that
   * brings its mass-weighted mean (as body_mean_displacements() computes
   * it) to @p means (entry 3 b + d), where no DoF of that body and
   * component is held by a Dirichlet constraint (a constant keeps the
   * hanging nodes' constraints, not Dirichlet data): a rigid translation,
   * which changes neither strain nor contact forces of the body's own
   * motion. @p x is locally owned; its ghosts are not updated.
   */
  template <int dim>
  void
  shift_body_means(const SemiDiscreteSystem<dim> &system,
                   VectorType                    &x,
                   const std::vector<double>     &means,
                   const unsigned int             n_bodies,
                   const MPI_Comm                 communicator);

  /// The largest Euclidean distance between the 3-vectors of a body in
  /// @p a and in @p b (of body_sums() or body_mean_displacements()).
  double
  largest_body_change(const std::vector<double> &a,
                      const std::vector<double> &b);
} // namespace dyncontact

#endif
