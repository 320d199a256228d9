// The limit on what one adaptation's coarsening may remove: a family of
// cells flagged for coarsening is coarsened only if the energy of what the
// transfer to its parent removes is at most its share of the tolerance.

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <dyncontact/discretization/energy_density.h>
#include <dyncontact/discretization/semi_discrete_system.h>
#include <dyncontact/mesh_refinement/mesh_adaptor.h>
#include <dyncontact/scenes/interface.h>

namespace dyncontact
{
  template <int dim>
  std::pair<unsigned int, double>
  MeshAdaptor<dim>::limit_coarsening() const
  {
    const SemiDiscreteSystem<dim> &system = this->get_system();
    const DoFHandler<dim>         &dofs   = system.get_dof_handler();
    const FiniteElement<dim>      &fe     = system.get_fe();
    const Scene<dim>              &scene  = this->get_scene();
    const MPI_Comm                 comm   = this->get_mpi_communicator();
    const auto                     u = system.ghosted(this->get_solution()),
               v                     = system.ghosted(this->get_velocity());

    const QGauss<dim>                quadrature(fe.degree + 1);
    const FEValuesExtractors::Vector displacement(0);
    FEValues<dim>                    values(this->get_mapping(),
                         fe,
                         quadrature,
                         update_values | update_gradients | update_JxW_values);
    std::vector<Tensor<1, dim>>      w(quadrature.size());
    std::vector<Tensor<2, dim>>      g(quadrature.size());
    // 1/2 rho |v|^2 + 1/2 sigma(u) : eps(u) on the cell values is reinit on,
    // of the local values @p cu, @p cv; and the cell's volume
    const auto energy = [&](const auto           &cell,
                            const Vector<double> &cu,
                            const Vector<double> &cv) {
      values[displacement].get_function_values_from_local_dof_values(
        make_array_view(const_cast<Vector<double> &>(cv)), w);
      values[displacement].get_function_gradients_from_local_dof_values(
        make_array_view(const_cast<Vector<double> &>(cu)), g);
      const Material &material = scene.material(cell->material_id());
      double          e = 0., volume = 0.;
      for (unsigned int q = 0; q < quadrature.size(); ++q)
        {
          e += energy_density(material, w[q], g[q]) * values.JxW(q);
          volume += values.JxW(q);
        }
      return std::make_pair(e, volume);
    };

    // the energy and volume of the bodies
    const unsigned int n = fe.n_dofs_per_cell();
    Vector<double>     cu(n), cv(n), pu(n), pv(n), tmp(n);
    double             total = 0., volume = 0.;
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          values.reinit(cell);
          cell->get_dof_values(u, cu);
          cell->get_dof_values(v, cv);
          const auto [e, vol] = energy(cell, cu, cv);
          total += e;
          volume += vol;
        }
    total  = Utilities::MPI::sum(total, comm);
    volume = Utilities::MPI::sum(volume, comm);

    // each family flagged as a whole: what its parent's values, prolongated
    // back, miss on each child
    unsigned int refused = 0;
    double       lost    = 0.;
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned() && cell->coarsen_flag_set() &&
          cell->level() > 0 && cell->parent()->child(0) == cell)
        {
          const auto parent = cell->parent();
          bool       whole  = true;
          for (unsigned int c = 0; c < parent->n_children(); ++c)
            whole = whole && parent->child(c)->is_active() &&
                    parent->child(c)->is_locally_owned() &&
                    parent->child(c)->coarsen_flag_set();
          if (!whole)
            continue;
          parent->get_interpolated_dof_values(u, pu);
          parent->get_interpolated_dof_values(v, pv);
          double removed = 0., family_volume = 0.;
          for (unsigned int c = 0; c < parent->n_children(); ++c)
            {
              const auto  child        = parent->child(c);
              const auto &prolongation = fe.get_prolongation_matrix(
                c, RefinementCase<dim>::isotropic_refinement);
              child->get_dof_values(u, cu);
              child->get_dof_values(v, cv);
              prolongation.vmult(tmp, pu);
              cu -= tmp;
              prolongation.vmult(tmp, pv);
              cv -= tmp;
              values.reinit(child);
              const auto [e, vol] = energy(child, cu, cv);
              removed += e;
              family_volume += vol;
            }
          if (removed > coarsening_tolerance * total * family_volume / volume)
            {
              for (unsigned int c = 0; c < parent->n_children(); ++c)
                parent->child(c)->clear_coarsen_flag();
              ++refused;
            }
          else
            lost += removed;
        }
    return {Utilities::MPI::sum(refused, comm),
            Utilities::MPI::sum(lost, comm)};
  }

  template std::pair<unsigned int, double>
  MeshAdaptor<2>::limit_coarsening() const;
  template std::pair<unsigned int, double>
  MeshAdaptor<3>::limit_coarsening() const;
} // namespace dyncontact
