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
  namespace
  {
    /// The integration of the energy density over cells: values.reinit(cell)
    /// first, then of(cell, cu, cv) gives the energy of the local values
    /// @p cu (displacement) and @p cv (velocity) on the cell and its volume.
    template <int dim>
    class CellEnergy
    {
    public:
      CellEnergy(const SimulatorAccess<dim> &access)
        : scene(access.get_scene())
        , quadrature(access.get_system().get_fe().degree + 1)
        , values(access.get_mapping(),
                 access.get_system().get_fe(),
                 quadrature,
                 update_values | update_gradients | update_JxW_values)
        , w(quadrature.size())
        , g(quadrature.size())
      {}

      template <typename Cell>
      std::pair<double, double>
      of(const Cell &cell, const Vector<double> &cu, const Vector<double> &cv)
      {
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
        return {e, volume};
      }

      const Scene<dim>                &scene;
      const QGauss<dim>                quadrature;
      const FEValuesExtractors::Vector displacement{0};
      FEValues<dim>                    values;
      std::vector<Tensor<1, dim>>      w;
      std::vector<Tensor<2, dim>>      g;
    };
  } // namespace



  template <int dim>
  std::pair<double, double>
  MeshAdaptor<dim>::energy_and_volume() const
  {
    const SemiDiscreteSystem<dim> &system = this->get_system();
    const auto                     u = system.ghosted(this->get_solution()),
               v                     = system.ghosted(this->get_velocity());
    CellEnergy<dim>    energy(*this);
    const unsigned int n = system.get_fe().n_dofs_per_cell();
    Vector<double>     cu(n), cv(n);
    double             total = 0., volume = 0.;
    for (const auto &cell : system.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          energy.values.reinit(cell);
          cell->get_dof_values(u, cu);
          cell->get_dof_values(v, cv);
          const auto [e, vol] = energy.of(cell, cu, cv);
          total += e;
          volume += vol;
        }
    const MPI_Comm comm = this->get_mpi_communicator();
    return {Utilities::MPI::sum(total, comm),
            Utilities::MPI::sum(volume, comm)};
  }



  template <int dim>
  std::pair<unsigned int, double>
  MeshAdaptor<dim>::limit_coarsening(
    const std::pair<double, double> &energy_state) const
  {
    const SemiDiscreteSystem<dim> &system = this->get_system();
    const DoFHandler<dim>         &dofs   = system.get_dof_handler();
    const FiniteElement<dim>      &fe     = system.get_fe();
    const MPI_Comm                 comm   = this->get_mpi_communicator();
    const auto                     u = system.ghosted(this->get_solution()),
               v                     = system.ghosted(this->get_velocity());
    const double tolerance           = get_coarsening_tolerance();
    const auto [total, volume]       = energy_state;
    CellEnergy<dim>    energy(*this);
    const unsigned int n = fe.n_dofs_per_cell();
    Vector<double>     cu(n), cv(n), pu(n), pv(n), tmp(n);

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
              energy.values.reinit(child);
              const auto [e, vol] = energy.of(child, cu, cv);
              removed += e;
              family_volume += vol;
            }
          if (removed > tolerance * total * family_volume / volume)
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

  template std::pair<double, double>
  MeshAdaptor<2>::energy_and_volume() const;
  template std::pair<double, double>
  MeshAdaptor<3>::energy_and_volume() const;
  template std::pair<unsigned int, double>
  MeshAdaptor<2>::limit_coarsening(const std::pair<double, double> &) const;
  template std::pair<unsigned int, double>
  MeshAdaptor<3>::limit_coarsening(const std::pair<double, double> &) const;
} // namespace dyncontact
