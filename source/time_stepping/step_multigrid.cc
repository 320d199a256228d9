#include <deal.II/lac/diagonal_matrix.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/precondition.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/multigrid/mg_transfer_global_coarsening.h>

#include <dyncontact/base/vector_copy.h>
#include <dyncontact/contact/active_set_solver.h>
#include <dyncontact/time_stepping/step_multigrid.h>

namespace dyncontact
{
  // (a named namespace, not an anonymous one: the preconditioner's closure,
  // a member of StepMultigrid's, holds a Cycle, which GCC would warn about
  // in the unity build, where this file is not the main file)
  namespace step_multigrid
  {
    using LAVector = LinearAlgebra::distributed::Vector<double>;

    /// S of the fine level for deal.II's Chebyshev smoother, which works
    /// on deal.II's vectors.
    struct FineOperator : public Subscriptor
    {
      Product            S;
      mutable VectorType x, y;

      types::global_dof_index
      m() const
      {
        return x.size();
      }

      /// (Chebyshev reads the diagonal from here only when it is given
      /// none; it is given S's)
      double
      el(const types::global_dof_index, const types::global_dof_index) const
      {
        AssertThrow(false, ExcNotImplemented());
        return 0.;
      }

      void
      vmult(LAVector &dst, const LAVector &src) const
      {
        copy_owned(x, src);
        S(y, x);
        copy_owned(dst, y);
      }
    };

    using Smoother =
      PreconditionChebyshev<FineOperator, LAVector, DiagonalMatrix<LAVector>>;

    /// What one preconditioner owns: S_1 and its AMG, the smoother and the
    /// work vectors of the cycle.
    struct Cycle
    {
      MatrixType                                         S_coarse;
      std::unique_ptr<TrilinosWrappers::PreconditionAMG> amg;
      FineOperator                                       fine_operator;
      Smoother                                           smoother;
      LAVector   r_fine, y_fine, t_fine, r_coarse;
      VectorType r_trilinos_coarse, e_trilinos_coarse;
    };
  } // namespace step_multigrid



  template <int dim>
  struct StepMultigrid<dim>::Transfer
  {
    MGTwoLevelTransfer<dim, step_multigrid::LAVector> two_level;
    /// AMG's near-null space on the linear level
    ActiveSetSolver::NearNullSpace modes;
  };



  template <int dim>
  StepMultigrid<dim>::StepMultigrid(const SemiDiscreteSystem<dim> &fine,
                                    const SemiDiscreteSystem<dim> &coarse,
                                    const bool                     rotations,
                                    const bool     smoothed_prolongator,
                                    const MPI_Comm comm)
    : fine(fine)
    , coarse(coarse)
    , rotations(rotations)
    , smoothed_prolongator(smoothed_prolongator)
    , comm(comm)
  {}



  template <int dim>
  StepMultigrid<dim>::~StepMultigrid() = default;



  template <int dim>
  void
  StepMultigrid<dim>::reinit()
  {
    // a new object for each mesh: a preconditioner of the mesh before
    // keeps its own
    transfer = std::make_shared<Transfer>();
    transfer->two_level.reinit_polynomial_transfer(fine.get_dof_handler(),
                                                   coarse.get_dof_handler(),
                                                   fine.get_constraints(),
                                                   coarse.get_constraints());
    transfer->modes.translations = coarse.get_constant_modes();
    if (rotations)
      transfer->modes.rotations = coarse.rotation_modes();
  }



  template <int dim>
  Product
  StepMultigrid<dim>::make_preconditioner(const double      a,
                                          const double      b,
                                          const Product    &S_vmult,
                                          const VectorType &S_diagonal) const
  {
    Assert(transfer != nullptr, ExcInternalError());
    auto cycle = std::make_shared<step_multigrid::Cycle>();

    // the coarse level: S_1 assembled, and its AMG
    coarse.assemble_stiffness_matrix(cycle->S_coarse, a, b, 1.);
    cycle->amg =
      make_amg(cycle->S_coarse, &transfer->modes, smoothed_prolongator);

    // the fine level: Chebyshev on S's diagonal
    cycle->fine_operator.S = S_vmult;
    cycle->fine_operator.x.reinit(fine.locally_owned_dofs(), comm);
    cycle->fine_operator.y.reinit(fine.locally_owned_dofs(), comm);
    for (step_multigrid::LAVector *v :
         {&cycle->r_fine, &cycle->y_fine, &cycle->t_fine})
      v->reinit(fine.locally_owned_dofs(), comm);
    cycle->r_coarse.reinit(coarse.locally_owned_dofs(), comm);
    cycle->r_trilinos_coarse.reinit(coarse.locally_owned_dofs(), comm);
    cycle->e_trilinos_coarse.reinit(coarse.locally_owned_dofs(), comm);

    typename step_multigrid::Smoother::AdditionalData data;
    data.preconditioner =
      std::make_shared<DiagonalMatrix<step_multigrid::LAVector>>();
    step_multigrid::LAVector &inverse = data.preconditioner->get_vector();
    inverse.reinit(fine.locally_owned_dofs(), comm);
    copy_owned(inverse, S_diagonal);
    for (auto &value : inverse)
      value = 1. / value;
    // degree 1, a Jacobi step damped by the estimate of S's largest
    // eigenvalue: measured on the 3D bar of benchmarks/step_operator.py
    // with Q2 and 60 cells along (2.3e5 DoFs), tau = 8 h/c, End time 6
    // tau (7 steps, the contact event located inside one): 216 CG
    // iterations and 21.7 s, against 212 and 36.5 s with degree 2 and 1422
    // and 56.4 s with Jacobi alone
    data.degree              = 1;
    data.smoothing_range     = 20.;
    data.eig_cg_n_iterations = 12;
    cycle->smoother.initialize(cycle->fine_operator, data);
    // (now, not in the first solve)
    cycle->smoother.estimate_eigenvalues(cycle->r_fine);

    const std::shared_ptr<const Transfer> two_level = transfer;
    return [cycle, two_level](VectorType &y, const VectorType &x) {
      step_multigrid::Cycle &c = *cycle;
      copy_owned(c.r_fine, x);
      // pre-smoothing from zero
      c.smoother.vmult(c.y_fine, c.r_fine);
      // the residual to the coarse level
      c.fine_operator.vmult(c.t_fine, c.y_fine);
      c.t_fine.sadd(-1., 1., c.r_fine);
      c.r_coarse = 0.;
      two_level->two_level.restrict_and_add(c.r_coarse, c.t_fine);
      copy_owned(c.r_trilinos_coarse, c.r_coarse);
      c.amg->vmult(c.e_trilinos_coarse, c.r_trilinos_coarse);
      copy_owned(c.r_coarse, c.e_trilinos_coarse);
      // its correction back
      two_level->two_level.prolongate_and_add(c.y_fine, c.r_coarse);
      // post-smoothing, the same polynomial
      c.smoother.step(c.y_fine, c.r_fine);
      copy_owned(y, c.y_fine);
    };
  }



  template class StepMultigrid<2>;
  template class StepMultigrid<3>;
} // namespace dyncontact
