#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <dyncontact/discretization/rigid_motions.h>
#include <dyncontact/discretization/semi_discrete_system.h>

#include <cmath>

namespace dyncontact
{
  namespace
  {
    /// Calls @p f(body, x, c, dof, fixed) once for each locally owned DoF:
    /// its body, support point, vector component, and whether Dirichlet
    /// data fix it (a constraint without entries).
    template <int dim, typename Function>
    void
    for_each_owned_dof(const SemiDiscreteSystem<dim> &system,
                       const Mapping<dim>            &mapping,
                       Function                       f)
    {
      const auto       &fe          = system.get_fe();
      const auto       &constraints = system.get_constraints();
      const IndexSet   &owned       = system.locally_owned_dofs();
      FEValues<dim>     values(mapping,
                           fe,
                           Quadrature<dim>(fe.get_unit_support_points()),
                           update_quadrature_points);
      std::vector<bool> done(owned.n_elements(), false);
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      for (const auto &cell : system.get_dof_handler().active_cell_iterators())
        if (cell->is_locally_owned())
          {
            values.reinit(cell);
            cell->get_dof_indices(dofs);
            for (unsigned int i = 0; i < dofs.size(); ++i)
              if (owned.is_element(dofs[i]) &&
                  !done[owned.index_within_set(dofs[i])])
                {
                  done[owned.index_within_set(dofs[i])] = true;
                  f(cell->material_id(),
                    values.quadrature_point(i),
                    fe.system_to_component_index(i).first,
                    dofs[i],
                    constraints.is_constrained(dofs[i]) &&
                      constraints.get_constraint_entries(dofs[i])->empty());
                }
          }
    }



    /// Per body: the point the rotations turn about, the centroid of the
    /// support points of its fixed DoFs (of all its DoFs if none is fixed).
    template <int dim>
    std::vector<Point<dim>>
    rotation_centers(const SemiDiscreteSystem<dim> &system,
                     const Mapping<dim>            &mapping,
                     const unsigned int             n_bodies)
    {
      // per body: sum of the fixed points and their number, then of all
      std::vector<double> sums(n_bodies * 2 * (dim + 1), 0.);
      for_each_owned_dof(system,
                         mapping,
                         [&](const unsigned int body,
                             const Point<dim>  &x,
                             const unsigned int,
                             const types::global_dof_index,
                             const bool fixed) {
                           for (const unsigned int set : {0u, 1u})
                             if (set == 1 || fixed)
                               {
                                 double *s =
                                   &sums[(2 * body + set) * (dim + 1)];
                                 for (unsigned int d = 0; d < dim; ++d)
                                   s[d] += x[d];
                                 s[dim] += 1.;
                               }
                         });
      Utilities::MPI::sum(sums,
                          system.get_dof_handler().get_communicator(),
                          sums);
      std::vector<Point<dim>> centers(n_bodies);
      for (unsigned int body = 0; body < n_bodies; ++body)
        {
          const double *fixed = &sums[2 * body * (dim + 1)];
          const double *s     = fixed[dim] > 0. ? fixed : fixed + dim + 1;
          for (unsigned int d = 0; d < dim; ++d)
            centers[body][d] = s[dim] > 0. ? s[d] / s[dim] : 0.;
        }
      return centers;
    }



    /// How many of the k rigid motions the fixed DoFs leave free, from the
    /// sums @p s of one body: the Gram matrix of the motions over the fixed
    /// DoFs (k x k), over all DoFs (k x k), the load's components along
    /// the motions (k) and |f|^2. A single free motion along which the load
    /// acts is not counted.
    unsigned int
    n_unheld(const double *s, const unsigned int k)
    {
      // each motion scaled to norm 1 on the fixed DoFs (0: free there)
      std::vector<double> scale(k);
      for (unsigned int j = 0; j < k; ++j)
        scale[j] = s[j * k + j] > 0. ? 1. / std::sqrt(s[j * k + j]) : 0.;
      LAPACKFullMatrix<double> held(k, k);
      for (unsigned int j = 0; j < k; ++j)
        for (unsigned int l = 0; l < k; ++l)
          held(j, l) = s[j * k + l] * scale[j] * scale[l];
      Vector<double>     eigenvalues;
      FullMatrix<double> motions;
      held.compute_eigenvalues_symmetric(
        -1., 1e-10, 1e-14, eigenvalues, motions);
      if (eigenvalues.size() != 1)
        return eigenvalues.size();
      // the free motion, in the unscaled motions: zero where a motion
      // vanishes on the fixed DoFs (scale 0) counts fully
      std::vector<double> v(k);
      for (unsigned int j = 0; j < k; ++j)
        v[j] = scale[j] > 0. ? motions(j, 0) * scale[j] : motions(j, 0);
      double along = 0., norm2 = 0.;
      for (unsigned int j = 0; j < k; ++j)
        {
          along += v[j] * s[2 * k * k + j];
          for (unsigned int l = 0; l < k; ++l)
            norm2 += v[j] * v[l] * s[k * k + j * k + l];
        }
      return std::abs(along) > 1e-8 * std::sqrt(s[2 * k * k + k] * norm2) ? 0 :
                                                                            1;
    }
  } // namespace



  template <int dim>
  std::vector<unsigned int>
  unheld_rigid_motions(const SemiDiscreteSystem<dim> &system,
                       const unsigned int             n_bodies)
  {
    constexpr unsigned int n_rotations = (dim == 2 ? 1 : 3);
    constexpr unsigned int k           = dim + n_rotations;
    const MappingQ1<dim>   mapping;
    const auto        centers = rotation_centers(system, mapping, n_bodies);
    const VectorType &f       = system.get_load();
    // per body: see n_unheld()
    const unsigned int  per_body = 2 * k * k + k + 1;
    std::vector<double> sums(n_bodies * per_body, 0.);
    for_each_owned_dof(system,
                       mapping,
                       [&](const unsigned int            body,
                           const Point<dim>             &x,
                           const unsigned int            c,
                           const types::global_dof_index dof,
                           const bool                    fixed) {
                         double r[k];
                         for (unsigned int j = 0; j < dim; ++j)
                           r[j] = (j == c) ? 1. : 0.;
                         for (unsigned int m = 0; m < n_rotations; ++m)
                           r[dim + m] = rotation_component<dim>(
                             m, c, Point<dim>(x - centers[body]));
                         double *s = &sums[body * per_body];
                         for (unsigned int j = 0; j < k; ++j)
                           {
                             for (unsigned int l = 0; l < k; ++l)
                               {
                                 s[k * k + j * k + l] += r[j] * r[l];
                                 if (fixed)
                                   s[j * k + l] += r[j] * r[l];
                               }
                             s[2 * k * k + j] += f(dof) * r[j];
                           }
                         s[2 * k * k + k] += f(dof) * f(dof);
                       });
    Utilities::MPI::sum(sums,
                        system.get_dof_handler().get_communicator(),
                        sums);
    std::vector<unsigned int> unheld(n_bodies);
    for (unsigned int body = 0; body < n_bodies; ++body)
      unheld[body] = n_unheld(&sums[body * per_body], k);
    return unheld;
  }

  template std::vector<unsigned int>
  unheld_rigid_motions<2>(const SemiDiscreteSystem<2> &, const unsigned int);
  template std::vector<unsigned int>
  unheld_rigid_motions<3>(const SemiDiscreteSystem<3> &, const unsigned int);
} // namespace dyncontact
