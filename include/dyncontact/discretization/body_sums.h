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
   * Each body's mass-weighted mean of each of @p xs per component, sum of
   * M x over sum of M 1 (for x = u the displacement of its centre of mass):
   * entry 3 b + d of the vector of each x (one product with M for all).
   */
  template <int dim>
  std::vector<std::vector<double>>
  body_means(const SemiDiscreteSystem<dim>         &system,
             const std::vector<const VectorType *> &xs,
             const unsigned int                     n_bodies,
             const MPI_Comm                         communicator);

  /// body_means() of @p u alone.
  template <int dim>
  std::vector<double>
  body_mean_displacements(const SemiDiscreteSystem<dim> &system,
                          const VectorType              &u,
                          const unsigned int             n_bodies,
                          const MPI_Comm                 communicator);

  /**
   * Adds to each x of @p xs on each body's DoFs of each component a
   * constant that brings its mass-weighted mean (body_means()) to the
   * corresponding entry of @p means (entry 3 b + d), where no DoF of that
   * body and component is held by a Dirichlet constraint (a constant keeps
   * the hanging nodes' constraints, not Dirichlet data): a rigid
   * translation, which changes no strain. The vectors are locally owned;
   * no ghosts are updated.
   */
  template <int dim>
  void
  shift_body_means(const SemiDiscreteSystem<dim>          &system,
                   const std::vector<VectorType *>        &xs,
                   const std::vector<std::vector<double>> &means,
                   const unsigned int                      n_bodies,
                   const MPI_Comm                          communicator);

  /// The largest Euclidean distance between the 3-vectors of a body in
  /// @p a and in @p b (of body_sums() or body_mean_displacements()).
  double
  largest_body_change(const std::vector<double> &a,
                      const std::vector<double> &b);
} // namespace dyncontact

#endif
