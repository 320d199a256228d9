#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/vector.h>
#include <deal.II/matrix_free/fe_evaluation.h>
#include <deal.II/matrix_free/matrix_free.h>

#include <dyncontact/base/vector_copy.h>
#include <dyncontact/discretization/elastic_operator.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace dyncontact
{
  template <int dim>
  struct ElasticOperator<dim>::Data
  {
    using Number     = double;
    using Vectorized = VectorizedArray<Number>;
    using LAVector   = LinearAlgebra::distributed::Vector<Number>;

    MatrixFree<dim, Number> matrix_free;
    /// (mu, lambda) of each cell batch, elastic and viscous
    std::vector<std::array<Vectorized, 2>> elastic_moduli;
    std::vector<std::array<Vectorized, 2>> viscous_moduli;
    mutable LAVector                       src;
    mutable LAVector                       dst;
    /// int psi_i of each DoF (the recovery's weights), computed at the
    /// first recovery on the mesh (empty before)
    mutable LAVector recovery_weight;

    /// The stress of the form a A + b B at the quadrature points of
    /// @p phi (its gradients evaluated), submitted for integration:
    /// 2 mu eps + lambda tr(eps) I with mu = a mu_e + b mu_v, lambda =
    /// a lambda_e + b lambda_v.
    void
    submit_stress(FEEvaluation<dim, -1, 0, dim, Number> &phi,
                  const unsigned int                     cell,
                  const double                           a,
                  const double                           b) const
    {
      const Vectorized two_mu =
        2. * (a * elastic_moduli[cell][0] + b * viscous_moduli[cell][0]);
      const Vectorized lambda =
        a * elastic_moduli[cell][1] + b * viscous_moduli[cell][1];
      for (const unsigned int q : phi.quadrature_point_indices())
        {
          SymmetricTensor<2, dim, Vectorized> stress =
            phi.get_symmetric_gradient(q);
          const Vectorized divergence = lambda * trace(stress);
          stress *= two_mu;
          for (unsigned int d = 0; d < dim; ++d)
            stress[d][d] += divergence;
          phi.submit_symmetric_gradient(stress, q);
        }
    }

    void
    apply(const MatrixFree<dim, Number>               &matrix_free,
          LAVector                                    &dst,
          const LAVector                              &src,
          const std::pair<unsigned int, unsigned int> &cells,
          const double                                 a,
          const double                                 b) const
    {
      // runtime degree: deal.II dispatches to its precompiled kernels
      FEEvaluation<dim, -1, 0, dim, Number> phi(matrix_free);
      for (unsigned int cell = cells.first; cell < cells.second; ++cell)
        {
          phi.reinit(cell);
          phi.gather_evaluate(src, EvaluationFlags::gradients);
          submit_stress(phi, cell, a, b);
          phi.integrate_scatter(EvaluationFlags::gradients, dst);
        }
    }
  };



  template <int dim>
  ElasticOperator<dim>::ElasticOperator()
    : data(std::make_unique<Data>())
  {}



  template <int dim>
  ElasticOperator<dim>::~ElasticOperator() = default;



  template <int dim>
  void
  ElasticOperator<dim>::reinit(
    const Mapping<dim, dim>                      &mapping,
    const DoFHandler<dim, dim>                   &dof_handler,
    const std::map<types::material_id, Material> &materials)
  {
    typename MatrixFree<dim, double>::AdditionalData additional_data;
    additional_data.tasks_parallel_scheme =
      MatrixFree<dim, double>::AdditionalData::none;
    additional_data.mapping_update_flags = update_gradients | update_JxW_values;
    // nothing reads the DoF values without the hanging-node constraints
    // (FEEvaluation::read_dof_values_plain), which deal.II would store for
    // every cell with hanging nodes. (deal.II 9.4 needs them with face
    // integrals: DoFInfo::compute_tight_partitioners reads them when
    // face update flags are set.)
    additional_data.store_plain_indices = false;
    // no constraints of ours (hanging nodes: see the class documentation)
    AffineConstraints<double> no_constraints;
    no_constraints.close();
    data->matrix_free.reinit(mapping,
                             dof_handler,
                             no_constraints,
                             QGauss<1>(dof_handler.get_fe().degree + 1),
                             additional_data);
    data->matrix_free.initialize_dof_vector(data->src);
    data->matrix_free.initialize_dof_vector(data->dst);
    data->recovery_weight.reinit(0);

    const unsigned int n_batches = data->matrix_free.n_cell_batches();
    data->elastic_moduli.assign(n_batches, {});
    data->viscous_moduli.assign(n_batches, {});
    for (unsigned int batch = 0; batch < n_batches; ++batch)
      for (unsigned int lane = 0;
           lane < data->matrix_free.n_active_entries_per_cell_batch(batch);
           ++lane)
        {
          const auto cell = data->matrix_free.get_cell_iterator(batch, lane);
          const Material &material = materials.at(cell->material_id());
          data->elastic_moduli[batch][0][lane] = material.mu();
          data->elastic_moduli[batch][1][lane] = material.lambda();
          data->viscous_moduli[batch][0][lane] = material.viscous_shear_modulus;
          data->viscous_moduli[batch][1][lane] = material.viscous_lambda;
        }
  }



  template <int dim>
  void
  ElasticOperator<dim>::vmult(TrilinosWrappers::MPI::Vector       &dst,
                              const TrilinosWrappers::MPI::Vector &src,
                              const Form                           form) const
  {
    // (1 mu_e + 0 mu_v is mu_e exactly, and so on)
    if (form == Form::elastic)
      vmult(dst, src, 1., 0.);
    else
      vmult(dst, src, 0., 1.);
  }



  template <int dim>
  void
  ElasticOperator<dim>::vmult(TrilinosWrappers::MPI::Vector       &dst,
                              const TrilinosWrappers::MPI::Vector &src,
                              const double                         a,
                              const double                         b) const
  {
    copy_owned(data->src, src);
    data->matrix_free
      .template cell_loop<typename Data::LAVector, typename Data::LAVector>(
        [&](const MatrixFree<dim, double>               &matrix_free,
            typename Data::LAVector                     &out,
            const typename Data::LAVector               &in,
            const std::pair<unsigned int, unsigned int> &cells) {
          data->apply(matrix_free, out, in, cells, a, b);
        },
        data->dst,
        data->src,
        true);
    copy_owned(dst, data->dst);
  }



  template <int dim>
  void
  ElasticOperator<dim>::recovery_indicators(
    const TrilinosWrappers::MPI::Vector &field,
    Vector<float>                       &indicators) const
  {
    using LAVector                             = typename Data::LAVector;
    using Vectorized                           = typename Data::Vectorized;
    const MatrixFree<dim, double> &matrix_free = data->matrix_free;
    LAVector                       x;
    matrix_free.initialize_dof_vector(x);
    copy_owned(x, field);
    x.update_ghost_values();

    // int psi_i (once per mesh) and int psi_i d_k x (k < dim), each DoF
    // of the layout
    FEEvaluation<dim, -1, 0, dim, double> phi(matrix_free);
    FEEvaluation<dim, -1, 0, dim, double> psi(matrix_free);
    if (data->recovery_weight.size() == 0)
      {
        matrix_free.initialize_dof_vector(data->recovery_weight);
        Tensor<1, dim, Vectorized> ones;
        for (unsigned int c = 0; c < dim; ++c)
          ones[c] = 1.;
        for (unsigned int batch = 0; batch < matrix_free.n_cell_batches();
             ++batch)
          {
            psi.reinit(batch);
            for (const unsigned int q : psi.quadrature_point_indices())
              psi.submit_value(ones, q);
            psi.integrate_scatter(EvaluationFlags::values,
                                  data->recovery_weight);
          }
        data->recovery_weight.compress(VectorOperation::add);
      }
    const LAVector       &weight = data->recovery_weight;
    std::vector<LAVector> recovered(dim);
    for (auto &g : recovered)
      matrix_free.initialize_dof_vector(g);
    // the gradient of x at the quadrature points, and per cell int x.x
    // and the volume, kept for the second pass (which then reads and
    // evaluates the recovered fields only)
    const unsigned int n_batches = matrix_free.n_cell_batches();
    const unsigned int n_q       = phi.n_q_points;
    std::vector<Tensor<2, dim, Vectorized>> gradients(n_batches * n_q);
    std::vector<Vectorized> values(n_batches), volumes(n_batches);
    for (unsigned int batch = 0; batch < n_batches; ++batch)
      {
        phi.reinit(batch);
        phi.gather_evaluate(x,
                            EvaluationFlags::values |
                              EvaluationFlags::gradients);
        Vectorized value = 0., volume = 0.;
        for (const unsigned int q : phi.quadrature_point_indices())
          {
            gradients[batch * n_q + q] = phi.get_gradient(q);
            value += phi.get_value(q) * phi.get_value(q) * phi.JxW(q);
            volume += phi.JxW(q);
          }
        values[batch]  = value;
        volumes[batch] = volume;
        psi.reinit(batch);
        for (unsigned int k = 0; k < dim; ++k)
          {
            for (const unsigned int q : psi.quadrature_point_indices())
              {
                const auto &gradient = gradients[batch * n_q + q];
                Tensor<1, dim, Vectorized> column;
                for (unsigned int c = 0; c < dim; ++c)
                  column[c] = gradient[c][k];
                psi.submit_value(column, q);
              }
            psi.integrate_scatter(EvaluationFlags::values, recovered[k]);
          }
      }
    for (auto &g : recovered)
      {
        g.compress(VectorOperation::add);
        // a hanging DoF has no weight of its own (its cells' shares went
        // to its parents); it is read from them below. The others' are
        // positive for p <= 3 (int psi_i of FE_Q(p) on Gauss points).
        for (unsigned int i = 0; i < g.locally_owned_size(); ++i)
          {
            Assert(weight.local_element(i) >= 0., ExcInternalError());
            if (weight.local_element(i) > 0.)
              g.local_element(i) /= weight.local_element(i);
          }
        g.update_ghost_values();
      }

    // eta_K^2 = int_K |G x - grad x|^2
    std::vector<FEEvaluation<dim, -1, 0, dim, double>> recovered_values(
      dim, FEEvaluation<dim, -1, 0, dim, double>(matrix_free));
    for (unsigned int batch = 0; batch < n_batches; ++batch)
      {
        for (unsigned int k = 0; k < dim; ++k)
          {
            recovered_values[k].reinit(batch);
            recovered_values[k].gather_evaluate(recovered[k],
                                                EvaluationFlags::values);
          }
        Vectorized squared = 0.;
        for (unsigned int q = 0; q < n_q; ++q)
          {
            const auto &gradient = gradients[batch * n_q + q];
            Vectorized  sum      = 0.;
            for (unsigned int k = 0; k < dim; ++k)
              {
                const auto value = recovered_values[k].get_value(q);
                for (unsigned int c = 0; c < dim; ++c)
                  {
                    const Vectorized difference = value[c] - gradient[c][k];
                    sum += difference * difference;
                  }
              }
            squared += sum * recovered_values[0].JxW(q);
          }
        for (unsigned int lane = 0;
             lane < matrix_free.n_active_entries_per_cell_batch(batch);
             ++lane)
          {
            // negligible: a gradient error below 1e-9 of the field's mean
            // size over the cell size h (round-off, as for the uniform
            // velocity of a free flight, stays below 1e-12 on the bar of
            // tests/adaptive_recovery); the bound 1e-9 mean / h sqrt(|K|)
            // is 1e-9 mean |K|^(1/2 - 1/dim) for h = |K|^(1/dim)
            const double volume = volumes[batch][lane];
            const double mean   = std::sqrt(values[batch][lane] / volume);
            const double eta    = std::sqrt(squared[lane]);
            const double bound =
              1e-9 * mean * (dim == 2 ? 1. : std::cbrt(std::sqrt(volume)));
            indicators[matrix_free.get_cell_iterator(batch, lane)
                         ->active_cell_index()] = (eta > bound) ? eta : 0.;
          }
      }
  }



  template class ElasticOperator<2>;
  template class ElasticOperator<3>;
} // namespace dyncontact
