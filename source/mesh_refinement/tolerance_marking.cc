// Marking by a tolerance: each cell's estimated error, in the energy of the
// physical energy norm, against its share of the tolerance.

#include <deal.II/grid/tria.h>

#include <dyncontact/mesh_refinement/interface.h>
#include <dyncontact/mesh_refinement/mesh_adaptor.h>

#include <cmath>

namespace dyncontact
{
  /**
   * The estimate of a cell K: eta_K = 1/2 rho h_K^2 k_K(u_dot)^2 + 1/2
   * (lambda + 2 mu) k_K(u)^2 (J, or J/m in 2D;
   * MeshRefinement::energy_error_indicators()). Cells with eta_K > delta^2
   * E |K| / |bodies| are refined (at Maximum level they are counted), all
   * others flagged for coarsening, which limit_coarsening() then refuses
   * to every family whose coarsening would remove more than delta^2 / 4 of
   * its share of E (or Coarsening tolerance).
   */
  template <int dim>
  std::pair<double, unsigned int>
  MeshAdaptor<dim>::mark_by_tolerance(Triangulation<dim> &triangulation) const
  {
    Vector<float> eta(triangulation.n_active_cells());
    MeshRefinement::energy_error_indicators(*this, eta);
    const auto [total, volume] = energy_and_volume();
    const double density =
      error_tolerance * error_tolerance * total / (volume > 0. ? volume : 1.);
    double       sum   = 0.;
    unsigned int above = 0;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const double eta_K = eta[cell->active_cell_index()];
          sum += eta_K;
          if (eta_K > density * cell->measure())
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
