// The limit on what one adaptation's coarsening may remove: a family of
// cells flagged for coarsening is coarsened only if the energy of what the
// transfer to its parent removes is at most its share of the tolerance.

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <dyncontact/discretization/energy_density.h>
#include <dyncontact/discretization/semi_discrete_system.h>
#include <dyncontact/mesh_refinement/mesh_adaptor.h>
#include <dyncontact/scenes/interface.h>
#include <dyncontact/time_stepping/simulation_control.h>

#include <algorithm>
#include <cmath>
#include <limits>

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

      /// The integral of @p density times the field of the local values
      /// @p x on the cell of the last values.reinit().
      Tensor<1, dim>
      integral(const Vector<double> &x, const double density)
      {
        values[displacement].get_function_values_from_local_dof_values(
          make_array_view(const_cast<Vector<double> &>(x)), w);
        Tensor<1, dim> sum;
        for (unsigned int q = 0; q < quadrature.size(); ++q)
          sum += density * w[q] * values.JxW(q);
        return sum;
      }

      const Scene<dim>                &scene;
      const QGauss<dim>                quadrature;
      const FEValuesExtractors::Vector displacement{0};
      FEValues<dim>                    values;
      std::vector<Tensor<1, dim>>      w;
      std::vector<Tensor<2, dim>>      g;
    };

    /// A family of cells flagged for coarsening: its parent, its body, the
    /// shift of the body's centre of mass at the end time that its
    /// coarsening causes, as in free flight (m), and the energy of what it
    /// removes (J).
    template <int dim>
    struct Family
    {
      typename DoFHandler<dim>::cell_iterator parent;
      unsigned int                            body;
      Tensor<1, dim>                          shift;
      double                                  removed;
    };

    /// Keeps the length of each body's summed shift of @p families within
    /// @p budget: where it exceeds it, the families of the largest shifts
    /// are refused (their coarsening flags cleared), those of one length
    /// together (a symmetric mesh's mirrored families cancel), with a
    /// threshold on the length found by bisection over all ranks. Adds the
    /// families refused, the energy the others remove (this rank's) and
    /// the accepted sums' lengths (all ranks') to @p limit.
    template <int dim, typename Limit>
    void
    limit_motion(const std::vector<Family<dim>> &families,
                 const unsigned int              n_bodies,
                 const double                    budget,
                 const MPI_Comm                  comm,
                 Limit                          &limit)
    {
      // the sums' lengths of the families of a shift of at most theta_b
      const auto kept = [&](const std::vector<double> &theta) {
        std::vector<double> sums(dim * n_bodies, 0.), lengths(n_bodies, 0.);
        for (const auto &f : families)
          if (f.shift.norm() <= theta[f.body])
            for (unsigned int d = 0; d < dim; ++d)
              sums[dim * f.body + d] += f.shift[d];
        Utilities::MPI::sum(sums, comm, sums);
        for (unsigned int b = 0; b < n_bodies; ++b)
          for (unsigned int d = 0; d < dim; ++d)
            lengths[b] += sums[dim * b + d] * sums[dim * b + d];
        for (double &l : lengths)
          l = std::sqrt(l);
        return lengths;
      };
      std::vector<double> high(n_bodies, 0.);
      for (const auto &f : families)
        high[f.body] = std::max(high[f.body], f.shift.norm());
      Utilities::MPI::max(high, comm, high);
      // low: a threshold whose sum is within the budget (0 keeps the
      // families that shift nothing), high one whose is not
      std::vector<double> low(n_bodies, 0.);
      const auto          all = kept(high);
      for (unsigned int b = 0; b < n_bodies; ++b)
        if (all[b] <= budget)
          low[b] = high[b];
      for (unsigned int iteration = 0; iteration < 50; ++iteration)
        {
          std::vector<double> theta(n_bodies);
          for (unsigned int b = 0; b < n_bodies; ++b)
            theta[b] = 0.5 * (low[b] + high[b]);
          const auto lengths = kept(theta);
          for (unsigned int b = 0; b < n_bodies; ++b)
            if (low[b] < high[b])
              (lengths[b] <= budget ? low[b] : high[b]) = theta[b];
        }

      for (const auto &f : families)
        if (f.shift.norm() > low[f.body])
          {
            for (unsigned int c = 0; c < f.parent->n_children(); ++c)
              f.parent->child(c)->clear_coarsen_flag();
            ++limit.refused;
          }
        else
          limit.removed += f.removed;
      for (const double l : kept(low))
        limit.moved += l;
    }
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
  typename MeshAdaptor<dim>::CoarseningLimit
  MeshAdaptor<dim>::limit_coarsening(
    const std::pair<double, double> &energy_state) const
  {
    const SemiDiscreteSystem<dim> &system = this->get_system();
    const DoFHandler<dim>         &dofs   = system.get_dof_handler();
    const FiniteElement<dim>      &fe     = system.get_fe();
    const MPI_Comm                 comm   = this->get_mpi_communicator();
    const Scene<dim>              &scene  = this->get_scene();
    const auto                     u = system.ghosted(this->get_solution()),
               v                     = system.ghosted(this->get_velocity());
    const double tolerance           = get_coarsening_tolerance();
    const auto [total, volume]       = energy_state;
    CellEnergy<dim>    energy(*this);
    const unsigned int n = fe.n_dofs_per_cell();
    Vector<double>     cu(n), cv(n), pu(n), pv(n), tmp(n);

    // with a Position tolerance: each body's mass; the share of
    // the run one adaptation has, and the time its momentum change acts
    const unsigned int       n_bodies = scene.n_bodies();
    std::vector<double>      masses(n_bodies, 0.);
    const SimulationControl &control = this->get_control();
    const double             remaining =
      std::max(0., control.get_end_time() - control.get_time());
    const double run_share =
      control.get_end_time() > 0. ?
        std::min(1.,
                 interval * control.get_timestep() / control.get_end_time()) :
        1.;
    if (position_tolerance > 0.)
      {
        for (const auto &cell : dofs.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              energy.values.reinit(cell);
              const double rho = scene.material(cell->material_id()).density;
              for (unsigned int q = 0; q < energy.quadrature.size(); ++q)
                masses[cell->material_id()] += rho * energy.values.JxW(q);
            }
        Utilities::MPI::sum(masses, comm, masses);
      }

    // each family flagged as a whole: what its parent's values, prolongated
    // back, miss on each child
    CoarseningLimit          limit;
    std::vector<Family<dim>> families;
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
          const unsigned int body    = cell->material_id();
          const double       rho     = scene.material(body).density;
          double             removed = 0., family_volume = 0.;
          // the family's integrals of rho u and rho u_dot: the children's
          // less the parent's after the transfer
          Tensor<1, dim> dq, dp;
          for (unsigned int c = 0; c < parent->n_children(); ++c)
            {
              const auto  child        = parent->child(c);
              const auto &prolongation = fe.get_prolongation_matrix(
                c, RefinementCase<dim>::isotropic_refinement);
              child->get_dof_values(u, cu);
              child->get_dof_values(v, cv);
              energy.values.reinit(child);
              if (position_tolerance > 0.)
                {
                  dq += energy.integral(cu, rho);
                  dp += energy.integral(cv, rho);
                }
              // (the removed part's energy: only for the energy's limit)
              if (tolerance > 0.)
                {
                  prolongation.vmult(tmp, pu);
                  cu -= tmp;
                  prolongation.vmult(tmp, pv);
                  cv -= tmp;
                  const auto [e, vol] = energy.of(child, cu, cv);
                  removed += e;
                  family_volume += vol;
                }
            }
          if (tolerance > 0. &&
              removed > tolerance * total * family_volume / volume)
            {
              for (unsigned int c = 0; c < parent->n_children(); ++c)
                parent->child(c)->clear_coarsen_flag();
              ++limit.refused;
              continue;
            }
          if (position_tolerance > 0.)
            {
              energy.values.reinit(
                typename Triangulation<dim>::cell_iterator(parent));
              dq -= energy.integral(pu, rho);
              dp -= energy.integral(pv, rho);
              families.push_back(
                {parent, body, (dq + remaining * dp) / masses[body], removed});
            }
          else
            limit.removed += removed;
        }
    if (position_tolerance > 0.)
      limit_motion(
        families, n_bodies, position_tolerance * run_share, comm, limit);
    // (limit_motion() sums the shifts over the ranks)
    limit.refused = Utilities::MPI::sum(limit.refused, comm);
    limit.removed = Utilities::MPI::sum(limit.removed, comm);
    return limit;
  }

  template std::pair<double, double>
  MeshAdaptor<2>::energy_and_volume() const;
  template std::pair<double, double>
  MeshAdaptor<3>::energy_and_volume() const;
  template MeshAdaptor<2>::CoarseningLimit
  MeshAdaptor<2>::limit_coarsening(const std::pair<double, double> &) const;
  template MeshAdaptor<3>::CoarseningLimit
  MeshAdaptor<3>::limit_coarsening(const std::pair<double, double> &) const;
} // namespace dyncontact
