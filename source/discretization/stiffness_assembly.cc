#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>
#include <deal.II/fe/fe_values.h>

#include <dyncontact/discretization/cell_assembly.h>
#include <dyncontact/discretization/element_matrix_adder.h>
#include <dyncontact/discretization/semi_discrete_system.h>

#include <algorithm>
#include <tuple>

// The matrix a A + b B + m M of the step
// (SemiDiscreteSystem::assemble_stiffness_matrix()) or only the diagonal of
// a A + b B (stiffness_diagonal()), from the scalar gradients.

namespace dyncontact
{
  using namespace CellAssembly;

  namespace
  {
    /// The moduli (mu, lambda) of the form a A + b B for @p material.
    std::pair<double, double>
    combined_moduli(const Material &material, const double a, const double b)
    {
      return {a * material.mu() +
                (b != 0. ? b * material.viscous_shear_modulus : 0.),
              a * material.lambda() +
                (b != 0. ? b * material.viscous_lambda : 0.)};
    }



    /**
     * The element matrix mu (2 eps : eps) + lambda (div div) of FE_Q^dim
     * from the scalar gradients (a third of the work of the vector
     * element's FEValues): with H^ab_kl = int d_a phi_k d_b phi_l,
     *   2 mu eps(phi_k e_c) : eps(phi_l e_d) = mu (delta_cd sum_a H^aa_kl
     *                                              + H^dc_kl),
     *   div(phi_k e_c) div(phi_l e_d)        = H^cd_kl.
     */
    template <int dim>
    class ElasticElement
    {
    public:
      explicit ElasticElement(const FESystem<dim> &fe)
        : n_nodes(fe.base_element(0).n_dofs_per_cell())
        , gradient_products(dim * dim * n_nodes * n_nodes)
        , laplace(n_nodes * n_nodes)
        , gradients(n_nodes)
      {
        std::tie(component, node) = components_and_nodes(fe);
      }

      /// H and the scalar Laplacian sum_c H^cc_kl of the cell in
      /// @p fe_values (of the scalar element, with gradients).
      void
      compute_products(const FEValues<dim> &fe_values)
      {
        std::fill(gradient_products.begin(), gradient_products.end(), 0.);
        for (unsigned int q = 0; q < fe_values.n_quadrature_points; ++q)
          {
            const double JxW = fe_values.JxW(q);
            for (unsigned int k = 0; k < n_nodes; ++k)
              gradients[k] = fe_values.shape_grad(k, q);
            for (unsigned int c = 0; c < dim; ++c)
              for (unsigned int d = 0; d < dim; ++d)
                {
                  double *H =
                    &gradient_products[(c * dim + d) * n_nodes * n_nodes];
                  for (unsigned int k = 0; k < n_nodes; ++k)
                    {
                      const double left = gradients[k][c] * JxW;
                      for (unsigned int l = 0; l < n_nodes; ++l)
                        H[k * n_nodes + l] += left * gradients[l][d];
                    }
                }
          }
        std::fill(laplace.begin(), laplace.end(), 0.);
        for (unsigned int c = 0; c < dim; ++c)
          for (unsigned int kl = 0; kl < n_nodes * n_nodes; ++kl)
            laplace[kl] +=
              gradient_products[(c * dim + c) * n_nodes * n_nodes + kl];
      }

      /// @p matrix = the element matrix with the moduli @p mu, @p lambda.
      void
      fill(FullMatrix<double> &matrix,
           const double        mu,
           const double        lambda) const
      {
        const auto H = [&](const unsigned int c,
                           const unsigned int d,
                           const unsigned int k,
                           const unsigned int l) {
          return gradient_products[(c * dim + d) * n_nodes * n_nodes +
                                   k * n_nodes + l];
        };
        for (unsigned int i = 0; i < component.size(); ++i)
          {
            const unsigned int c = component[i], k = node[i];
            for (unsigned int j = 0; j < component.size(); ++j)
              {
                const unsigned int d = component[j], l = node[j];
                const double       shear =
                  (c == d ? laplace[k * n_nodes + l] : 0.) + H(d, c, k, l);
                matrix(i, j) = mu * shear + lambda * H(c, d, k, l);
              }
          }
      }

    private:
      const unsigned int n_nodes;
      /// H^ab_kl at [(a * dim + b) * n_nodes * n_nodes + k * n_nodes + l]
      std::vector<double>         gradient_products;
      std::vector<double>         laplace;
      std::vector<Tensor<1, dim>> gradients;
      std::vector<unsigned int>   component, node;
    };
  } // namespace



  template <int dim>
  void
  SemiDiscreteSystem<dim>::stiffness_diagonal(VectorType  &diagonal,
                                              const double a,
                                              const double b) const
  {
    // the diagonal entries of ElasticElement::fill(): for the shape
    // function phi_k e_c, mu (sum_a H^aa_kk + H^cc_kk) + lambda H^cc_kk,
    // summed over the cells as the assembled matrix's entries are
    diagonal.reinit(locally_owned, comm);
    OwnedAdder         adder(diagonal, locally_owned);
    const QGauss<dim>  quadrature(fe.degree + 1);
    FEValues<dim>      fe_values(mapping,
                            scalar_fe,
                            quadrature,
                            update_gradients | update_JxW_values);
    const unsigned int dofs_per_cell = fe.n_dofs_per_cell();
    const unsigned int n_nodes       = scalar_fe.n_dofs_per_cell();
    const auto [component, node]     = components_and_nodes(fe);
    std::vector<double>                  H(n_nodes * dim), laplace(n_nodes);
    Vector<double>                       cell_diagonal(dofs_per_cell);
    std::vector<types::global_dof_index> dof_indices(dofs_per_cell);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const auto [mu, lambda] =
            combined_moduli(materials.at(cell->material_id()), a, b);
          fe_values.reinit(typename Triangulation<dim>::cell_iterator(cell));
          // H^cc_kk = int (d_c phi_k)^2; a translation of the previous cell
          // has its gradients and JxW (FEValues keeps them), hence its H
          if (fe_values.get_cell_similarity() != CellSimilarity::translation)
            {
              std::fill(H.begin(), H.end(), 0.);
              for (unsigned int q = 0; q < quadrature.size(); ++q)
                {
                  const double JxW = fe_values.JxW(q);
                  for (unsigned int k = 0; k < n_nodes; ++k)
                    {
                      const Tensor<1, dim> &gradient =
                        fe_values.shape_grad(k, q);
                      for (unsigned int c = 0; c < dim; ++c)
                        H[c * n_nodes + k] += gradient[c] * JxW * gradient[c];
                    }
                }
              std::fill(laplace.begin(), laplace.end(), 0.);
              for (unsigned int c = 0; c < dim; ++c)
                for (unsigned int k = 0; k < n_nodes; ++k)
                  laplace[k] += H[c * n_nodes + k];
            }
          for (unsigned int i = 0; i < dofs_per_cell; ++i)
            {
              const double H_cc = H[component[i] * n_nodes + node[i]];
              cell_diagonal(i) = mu * (laplace[node[i]] + H_cc) + lambda * H_cc;
            }
          cell->get_dof_indices(dof_indices);
          // (a locally owned cell's DoFs may be owned elsewhere)
          adder.add(dof_indices, cell_diagonal);
        }
    diagonal.compress(VectorOperation::add);
  }



  template <int dim>
  void
  SemiDiscreteSystem<dim>::assemble_stiffness_matrix(MatrixType  &matrix,
                                                     const double a,
                                                     const double b,
                                                     const double m) const
  {
    reinit_matrix(matrix);
    // a lumped m M goes onto the diagonal in the first cell of each owned
    // row (a locally owned DoF lies on a locally owned cell)
    const bool lumped_mass_in_cells = (m != 0. && parameters.lumped_mass);
    std::vector<bool> mass_added(
      lumped_mass_in_cells ? locally_owned.n_elements() : 0, false);
    const QGauss<dim>  quadrature(fe.degree + 1);
    FEValues<dim>      fe_values(mapping,
                            scalar_fe,
                            quadrature,
                            update_gradients | update_JxW_values);
    const unsigned int dofs_per_cell = fe.n_dofs_per_cell();
    FullMatrix<double> cell_matrix(dofs_per_cell, dofs_per_cell);
    std::vector<types::global_dof_index> dof_indices(dofs_per_cell);
    ElasticElement<dim>                  element(fe);
    bool                                 have_products = false;
    // the element matrix a A + b B of the cell before, and its moduli
    FullMatrix<double> element_matrix(dofs_per_cell, dofs_per_cell);
    double             element_mu = 0., element_lambda = 0.;
    ElementMatrixAdder adder(matrix);

    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const auto [mu, lambda] =
            combined_moduli(materials.at(cell->material_id()), a, b);
          fe_values.reinit(typename Triangulation<dim>::cell_iterator(cell));

          // a translation of the cell before has the same H (deal.II's
          // FEValues recognises it on a mapping of degree 1), and with the
          // same moduli the same element matrix
          const bool same_products =
            have_products &&
            fe_values.get_cell_similarity() == CellSimilarity::translation;
          if (!same_products)
            element.compute_products(fe_values);
          if (!same_products || mu != element_mu || lambda != element_lambda)
            {
              element.fill(element_matrix, mu, lambda);
              element_mu     = mu;
              element_lambda = lambda;
            }
          have_products = true;
          // (an entry-wise copy: FullMatrix's assignment frees and
          // allocates its storage anew, once per cell)
          std::copy(&element_matrix(0, 0),
                    &element_matrix(0, 0) + dofs_per_cell * dofs_per_cell,
                    &cell_matrix(0, 0));
          cell->get_dof_indices(dof_indices);
          if (lumped_mass_in_cells)
            for (unsigned int i = 0; i < dofs_per_cell; ++i)
              if (locally_owned.is_element(dof_indices[i]))
                {
                  const auto row =
                    locally_owned.index_within_set(dof_indices[i]);
                  if (!mass_added[row])
                    {
                      cell_matrix(i, i) +=
                        m * lumped_mass_diagonal(dof_indices[i]);
                      mass_added[row] = true;
                    }
                }
          adder.add(dof_indices, cell_matrix);
        }
    matrix.compress(VectorOperation::add);
    if (m != 0. && !parameters.lumped_mass)
      matrix.add(m, mass_matrix);
  }



#define DYNCONTACT_INSTANTIATE(dim)                                       \
  template void SemiDiscreteSystem<dim>::stiffness_diagonal(VectorType &, \
                                                            const double, \
                                                            const double) \
    const;                                                                \
  template void SemiDiscreteSystem<dim>::assemble_stiffness_matrix(       \
    MatrixType &, const double, const double, const double) const;
  DYNCONTACT_INSTANTIATE(2)
  DYNCONTACT_INSTANTIATE(3)
#undef DYNCONTACT_INSTANTIATE
} // namespace dyncontact
