#ifndef dyncontact_discretization_elastic_operator_h
#define dyncontact_discretization_elastic_operator_h

#include <deal.II/base/types.h>
#include <deal.II/lac/trilinos_vector.h>

#include <dyncontact/scenes/material.h>

#include <map>
#include <memory>

namespace dealii
{
  template <int dim, int spacedim>
  class DoFHandler;
  template <int dim, int spacedim>
  class Mapping;
  template <typename Number>
  class Vector;
} // namespace dealii

namespace dyncontact
{
  using namespace dealii;

  /**
   * The elastic form a(u, v) = int 2 mu eps(u) : eps(v) + lambda div u div v
   * and the viscous form b(u, v) (the same with mu_v, lambda_v) applied
   * without a matrix (deal.II's MatrixFree, sum factorisation, Gauss
   * quadrature of p + 1 points per direction as in the assembly): A x and
   * B x for the right-hand side and the energy of every step, and
   * a A + b B for a step matrix S that is not assembled
   * ('Contact solver/Step matrix = matrix-free'). A and B are never stored,
   * which saves one value per matrix entry.
   *
   * Without hanging nodes this is the unconstrained operator, as assembled
   * (the constraints are the active-set solver's). With hanging nodes,
   * deal.II 9.4's MatrixFree always applies their constraints: a hanging
   * DoF is read from its parents and its row is added to theirs. For x that
   * satisfies the constraints (every state of a run) that is A x with the
   * hanging rows condensed onto their parents, as the active-set solver
   * condenses its right-hand side anyway, and w^T A x is the same for every
   * such w (tests/elastic_operator).
   */
  template <int dim>
  class ElasticOperator
  {
  public:
    enum class Form
    {
      elastic,
      viscous
    };

    ElasticOperator();
    ~ElasticOperator();

    /// On the current mesh: the moduli of each cell from @p materials by
    /// its material id.
    void
    reinit(const Mapping<dim, dim>                      &mapping,
           const DoFHandler<dim, dim>                   &dof_handler,
           const std::map<types::material_id, Material> &materials);

    /// dst = A src or B src (owned vectors of the DoF handler's layout).
    void
    vmult(TrilinosWrappers::MPI::Vector       &dst,
          const TrilinosWrappers::MPI::Vector &src,
          const Form                           form) const;

    /// dst = (a A + b B) src in one pass over the cells (the elastic form
    /// with the moduli a mu + b mu_v, a lambda + b lambda_v).
    void
    vmult(TrilinosWrappers::MPI::Vector       &dst,
          const TrilinosWrappers::MPI::Vector &src,
          const double                         a,
          const double                         b) const;

    /**
     * Zienkiewicz and Zhu's indicator of @p field (an owned vector of the
     * DoF handler's layout) on each locally owned cell K:
     * eta_K = ||G x - grad x||_{L2(K)}, where the recovered gradient G x is
     * the lumped L2 projection of grad x onto the finite element space (at
     * each node the average of the cells' gradients weighted by
     * int psi_i). It measures the gradient's jumps across faces, as
     * Kelly's indicator does, with two cell loops and no face integrals.
     * An eta_K below 1e-9 |K|^{1/2} x_K / h_K (x_K the root mean square of
     * x on K, h_K = |K|^{1/dim}) is negligible and set to zero, so that a
     * uniform field (the velocity of a free flight, whose eta_K are
     * round-off) flags no cells. (The bound grows with x_K: a displacement
     * with a large rigid translation hides gradient jumps below
     * 1e-9 x_K / h_K.)
     * Sets entry K->active_cell_index() of @p indicators for the locally
     * owned cells and leaves the others unchanged.
     */
    void
    recovery_indicators(const TrilinosWrappers::MPI::Vector &field,
                        Vector<float>                       &indicators) const;

  private:
    struct Data;
    std::unique_ptr<Data> data;
  };
} // namespace dyncontact

#endif
