#ifndef dyncontact_time_stepping_step_multigrid_h
#define dyncontact_time_stepping_step_multigrid_h

#include <deal.II/base/mpi.h>

#include <dyncontact/discretization/semi_discrete_system.h>

#include <memory>

namespace dyncontact
{
  /**
   * The p-multigrid preconditioner of a step matrix S = M + a A + b B that
   * is applied without a matrix ('Contact solver/Preconditioner =
   * multigrid'): one V-cycle of two levels on the same mesh, the run's
   * degree p >= 2 and linear elements. On the fine level, one smoothing
   * step before and one after: deal.II's PreconditionChebyshev of degree
   * 1 on S's diagonal (a Jacobi step damped by CG's estimate of the
   * largest eigenvalue); between
   * the levels, deal.II's MGTwoLevelTransfer (polynomial coarsening, with
   * the hanging-node and Dirichlet constraints of both levels); on the
   * coarse level, S_1 = M_1 + a A_1 + b B_1 of linear elements assembled
   * by a second SemiDiscreteSystem and one V-cycle of AMG on it. The
   * smoothers before and after are the same polynomial and the transfers
   * are each other's transposes, so that the cycle is symmetric, as CG
   * needs. Nothing of the degree p is assembled.
   */
  template <int dim>
  class StepMultigrid
  {
  public:
    /// On the systems of degree p (@p fine) and 1 (@p coarse), which must
    /// outlive this object; AMG with the infinitesimal rotations in its
    /// near-null space if @p rotations, with the smoothed prolongator if
    /// @p smoothed_prolongator ('Contact solver/AMG ...').
    StepMultigrid(const SemiDiscreteSystem<dim> &fine,
                  const SemiDiscreteSystem<dim> &coarse,
                  const bool                     rotations,
                  const bool                     smoothed_prolongator,
                  const MPI_Comm                 comm);
    ~StepMultigrid();

    /// The transfer between the levels and AMG's near-null space, after
    /// both systems were set up on the current mesh.
    void
    reinit();

    /**
     * The preconditioner y = P x of S = M + a A + b B, applied by
     * @p S_vmult, with diagonal @p S_diagonal: assembles S_1 and builds
     * its AMG and the smoother (with its eigenvalue estimate). The
     * returned product owns them.
     */
    Product
    make_preconditioner(const double      a,
                        const double      b,
                        const Product    &S_vmult,
                        const VectorType &S_diagonal) const;

  private:
    struct Transfer;
    const SemiDiscreteSystem<dim> &fine;
    const SemiDiscreteSystem<dim> &coarse;
    const bool                     rotations;
    const bool                     smoothed_prolongator;
    const MPI_Comm                 comm;
    std::shared_ptr<Transfer>      transfer;
  };
} // namespace dyncontact

#endif
