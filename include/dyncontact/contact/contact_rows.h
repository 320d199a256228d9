#ifndef dyncontact_contact_rows_h
#define dyncontact_contact_rows_h

#include <deal.II/base/types.h>

#include <array>
#include <functional>
#include <utility>
#include <vector>

namespace dyncontact
{
  using dealii::types::global_dof_index;

  /**
   * One linearised non-penetration constraint c_p . v <= g_p
   * (ALGORITHMS.md section 2, the paper's eq. (10)) for the slave node p:
   *
   *   c_p . v = nu_p . v_S(x_p) - sum_j N_j(phi_h(x_p)) nu_p . v_M(j).
   *
   * The first n_components entries are the slave node's DoFs with the
   * components of nu_p; master entries (two-body contact) follow with
   * coefficients -N_j nu_p,k. A rigid obstacle has no master entries.
   */
  struct ContactRow
  {
    unsigned int n_components = 0;
    /// (global DoF, coefficient) pairs; slave components first.
    std::vector<std::pair<global_dof_index, double>> entries;
    /// The unit normal nu_p (only n_components entries are used).
    std::array<double, 3> normal{{0., 0., 0.}};
    /// Reference position x_p of the slave node.
    std::array<double, 3> position{{0., 0., 0.}};
    /// The gap g_p (eq. 2) in m; against a rigid obstacle that moves, at
    /// the time of ContactRows::set_time().
    double gap = 0.;
    /// Against a rigid obstacle that moves: the gap at the obstacle's
    /// position d(0) (m).
    double reference_gap = 0.;
    /// The boundary weight w_p = int_{Gamma_C} psi_p ds (m^{d-1}).
    double weight = 0.;
    /// The contact pair of the row: its index in Scene::contact_pairs(); the
    /// rows against the rigid obstacle come after the pairs (index = the
    /// number of pairs).
    unsigned int pair = 0;
    /// Which slave component an active row eliminates (largest |nu_i|
    /// among the components without other constraints).
    unsigned int eliminated = 0;
    /// Master nodes at the image point: (component-0 DoF, N_j), for the
    /// master-side contact pressure; empty for a rigid obstacle.
    std::vector<std::pair<global_dof_index, double>> master_nodes;

    global_dof_index
    eliminated_dof() const
    {
      return entries[eliminated].first;
    }

    bool
    has_master_entries() const
    {
      return entries.size() > n_components;
    }
  };

  /**
   * The contact rows of one MPI rank: those of its locally owned slave
   * nodes (distributed: no rank holds another rank's rows, and a global
   * figure is a reduction). Obstacles and the two-body mapping produce the
   * same rows, so the solver and the time integrators never ask which one
   * they have.
   */
  struct ContactRows
  {
    std::vector<ContactRow> rows;

    /// Rigid obstacles that move: per pair index, d(t) - d(0) of the
    /// obstacle of that pair (an empty function for the pairs that do not
    /// move); empty if none moves.
    std::vector<std::function<std::array<double, 3>(double)>> motions;

    /// Counts the changes of the gaps by set_time() (the active-set
    /// solvers' constraints are made anew after one).
    unsigned long gap_version = 0;

    /// Whether a rigid obstacle moves (the gaps depend on t).
    bool
    obstacles_move() const
    {
      return !motions.empty();
    }

    /// The gaps of the rows against moving obstacles at time @p t:
    /// g_p(t) = g_p(0) + nu_p . (d(t) - d(0)) (the obstacle moved by
    /// d(t) - d(0) opens the gap along nu_p, which points into it).
    void
    set_time(const double t)
    {
      ++gap_version;
      std::vector<std::array<double, 3>> d(motions.size());
      for (unsigned int k = 0; k < motions.size(); ++k)
        if (motions[k])
          d[k] = motions[k](t);
      for (ContactRow &row : rows)
        if (row.pair < motions.size() && motions[row.pair])
          {
            row.gap = row.reference_gap;
            for (unsigned int c = 0; c < row.n_components; ++c)
              row.gap += row.normal[c] * d[row.pair][c];
          }
    }

    std::size_t
    size() const
    {
      return rows.size();
    }

    bool
    empty() const
    {
      return rows.empty();
    }
  };

} // namespace dyncontact

#endif
