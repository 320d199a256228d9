// Marking by a tolerance: the estimated energy of the error, summed over
// the cells, against the tolerance's share delta^2 E of the energy; the
// cells below Maximum level with the largest estimates are refined until
// the sum would be below half of it (Doerfler's marking, deal.II's fixed
// fraction of the error), or each cell above its share by volume; the
// others coarsened where the coarsening limit allows.

#include <deal.II/distributed/grid_refinement.h>
#include <deal.II/fe/fe.h>
#include <deal.II/grid/tria.h>

#include <dyncontact/discretization/semi_discrete_system.h>
#include <dyncontact/mesh_refinement/interface.h>
#include <dyncontact/mesh_refinement/mesh_adaptor.h>

#include <cmath>
#include <limits>

namespace dyncontact
{
  /**
   * The estimate of a cell K: eta_K = 1/2 rho h_K^2 k_K(u_dot)^2 + 1/2
   * (lambda + 2 mu) k_K(u)^2 (J, or J/m in 2D;
   * MeshRefinement::energy_error_indicators()), summed: S. Split
   * "globally": if S exceeds
   * T = delta^2 E, the cells below Maximum level with the largest eta_K
   * are refined whose sum is at least (S - T/2) / (1 - 4^-p): refining a
   * cell divides its error energy by about 4^p, so that S falls to about
   * T/2, but for those of the smallest eta_K whose sum is below T/4 (the
   * cells of S's last quarter of T need no refinement, however far off S
   * is); where the share reaches into them, they are kept as they are.
   * Split "by volume": the cells with eta_K > delta^2 E |K| / |bodies| are
   * refined. Cells at Maximum level that the rule would refine without the
   * level limit are counted instead. All other cells (where the share
   * reaches into the last quarter: those of a zero estimate) are flagged
   * for coarsening, which limit_coarsening() then
   * refuses to every family whose coarsening would remove more than
   * delta^2 / 4 of its share of E (or Coarsening tolerance).
   */
  template <int dim>
  std::pair<double, unsigned int>
  MeshAdaptor<dim>::mark_by_tolerance(
    Triangulation<dim>              &triangulation,
    const std::pair<double, double> &energy) const
  {
    namespace Thresholds = internal::parallel::distributed::GridRefinement;
    const MPI_Comm comm  = this->get_mpi_communicator();
    Vector<float>  eta(triangulation.n_active_cells());
    MeshRefinement::energy_error_indicators(*this, eta);
    const auto [total, volume] = energy;

    // this rank's estimates, and those of the cells below Maximum level
    // (which a refinement can reduce); their sums over all ranks, and
    // whether a cell at Maximum level has a nonzero estimate on any
    std::vector<float> owned, refinable;
    double             sum = 0., sum_refinable = 0.;
    bool               at_limit = false;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const float e = eta[cell->active_cell_index()];
          owned.push_back(e);
          sum += e;
          if (cell->level() < int(max_level))
            {
              refinable.push_back(e);
              sum_refinable += e;
            }
          else
            at_limit = at_limit || e > 0.f;
        }
    sum           = Utilities::MPI::sum(sum, comm);
    sum_refinable = Utilities::MPI::sum(sum_refinable, comm);
    at_limit      = Utilities::MPI::logical_or(at_limit, comm);

    // global: the threshold above which the refinable cells hold the share
    // of S to refine; by volume: each cell's share of delta^2 E
    const double       allowed     = error_tolerance * error_tolerance * total;
    const unsigned int p           = this->get_system().get_fe().degree;
    const double       gain        = 1. - std::pow(4., -double(p));
    double             threshold   = std::numeric_limits<double>::max();
    double             counted     = threshold;
    bool               refine_none = false, far_off = false;
    // the threshold above which the cells of @p estimates hold @p share of
    // S (over all ranks)
    const auto threshold_of = [&](const std::vector<float> &estimates,
                                  const double              share) {
      const Vector<float> local(estimates.begin(), estimates.end());
      return Thresholds::RefineAndCoarsenFixedFraction::compute_threshold(
        local,
        Thresholds::compute_global_min_and_max_at_root(local, comm),
        share,
        comm);
    };
    if (split_by_volume)
      threshold = counted = allowed / (volume > 0. ? volume : 1.); // per m^dim
    else if (sum > allowed)
      {
        // what the refinement must remove, taken from the refinable cells
        // only, but for the smallest estimates whose sum is below a quarter
        // of delta^2 E: they need no refinement for the tolerance, however
        // far off it is (all cells of a nonzero estimate refined would
        // refine wherever a wave has reached in round-off). Where the share
        // reaches into them (for p = 1 whenever S > 1.25 delta^2 E, sooner
        // with cells at Maximum level), the mesh is too coarse for the
        // tolerance to coarsen them either.
        const double needed = (sum - 0.5 * allowed) / gain;
        const double share  = std::min(needed, sum_refinable - 0.25 * allowed);
        far_off             = needed > share;
        refine_none         = share <= 0.;
        threshold = refine_none ? -1. : threshold_of(refinable, share);
        // the cells at Maximum level counted: those that the same rule
        // would refine without the level limit (none to count if none has
        // an estimate)
        if (at_limit)
          counted = threshold_of(owned, std::min(needed, sum - 0.25 * allowed));
      }

    unsigned int above = 0;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const double eta_K = eta[cell->active_cell_index()];
          // above a threshold: by volume, the cell's share; globally, as
          // deal.II's refine() reads compute_threshold()'s result, which is
          // capped at the largest estimate (where cells of equal estimates
          // hold the share, the threshold is their value)
          const auto above_threshold = [&](const double t) {
            return eta_K > 0. &&
                   (split_by_volume ? eta_K > t * cell->measure() : eta_K >= t);
          };
          const bool at_maximum = cell->level() >= int(max_level);
          if (at_maximum && above_threshold(counted))
            ++above;
          if (above_threshold(threshold))
            {
              if (!at_maximum && !refine_none)
                cell->set_refine_flag();
            }
          else if (!far_off || eta_K <= 0.)
            cell->set_coarsen_flag();
        }
    return {total > 0. ? std::sqrt(sum / total) : 0.,
            Utilities::MPI::sum(above, comm)};
  }

  template std::pair<double, unsigned int>
  MeshAdaptor<2>::mark_by_tolerance(Triangulation<2> &,
                                    const std::pair<double, double> &) const;
  template std::pair<double, unsigned int>
  MeshAdaptor<3>::mark_by_tolerance(Triangulation<3> &,
                                    const std::pair<double, double> &) const;
} // namespace dyncontact
