// Marking by a tolerance: each cell's estimated error, in the energy of the
// physical energy norm, against its share of the tolerance.

#include <deal.II/grid/tria.h>

#include <dyncontact/discretization/semi_discrete_system.h>
#include <dyncontact/mesh_refinement/mesh_adaptor.h>
#include <dyncontact/scenes/interface.h>

#include <cmath>

namespace dyncontact
{
  /**
   * The estimate of a cell K: eta_K = 1/2 rho h_K^2 k_K(u_dot)^2 + 1/2
   * (lambda + 2 mu) k_K(u)^2 (J, or J/m in 2D), where k_K is Zienkiewicz
   * and Zhu's indicator ||G x - grad x||_L2(K), G x the recovered gradient
   * (it estimates the gradient's error on K, ||grad e||_L2(K)), computed by
   * two matrix-free cell loops:
   * the elastic part of the energy of the error, and the kinetic part,
   * whose L2 error is h_K times the gradient's. Cells with eta_K > delta^2
   * E |K| / |bodies| are refined (at Maximum level they are counted), all
   * others flagged for coarsening, which limit_coarsening() then refuses
   * to every family whose coarsening would remove more than delta^2 / 4 of
   * its share of E (or Coarsening tolerance).
   */
  template <int dim>
  std::pair<double, unsigned int>
  MeshAdaptor<dim>::mark_by_tolerance(Triangulation<dim> &triangulation) const
  {
    const Scene<dim> &scene = this->get_scene();
    Vector<float>     ku(triangulation.n_active_cells()),
      kv(triangulation.n_active_cells());
    const SemiDiscreteSystem<dim> &system = this->get_system();
    system.recovery_indicators(this->get_solution(), ku);
    system.recovery_indicators(this->get_velocity(), kv);
    const auto [total, volume] = energy_and_volume();
    const double density =
      error_tolerance * error_tolerance * total / (volume > 0. ? volume : 1.);
    double       sum   = 0.;
    unsigned int above = 0;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const Material    &material = scene.material(cell->material_id());
          const unsigned int i        = cell->active_cell_index();
          const double       h        = cell->diameter();
          const double       eta =
            0.5 * (material.density * h * h * kv[i] * kv[i] +
                   (material.lambda() + 2. * material.mu()) * ku[i] * ku[i]);
          sum += eta;
          if (eta > density * cell->measure())
            {
              if (cell->level() < int(max_level))
                cell->set_refine_flag();
              else
                ++above;
            }
          else
            cell->set_coarsen_flag();
        }
    const MPI_Comm comm = this->get_mpi_communicator();
    sum                 = Utilities::MPI::sum(sum, comm);
    return {total > 0. ? std::sqrt(sum / total) : 0.,
            Utilities::MPI::sum(above, comm)};
  }

  template std::pair<double, unsigned int>
  MeshAdaptor<2>::mark_by_tolerance(Triangulation<2> &) const;
  template std::pair<double, unsigned int>
  MeshAdaptor<3>::mark_by_tolerance(Triangulation<3> &) const;
} // namespace dyncontact
