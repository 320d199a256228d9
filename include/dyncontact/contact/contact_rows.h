#ifndef dyncontact_contact_rows_h
#define dyncontact_contact_rows_h

#include <deal.II/base/types.h>

#include <array>
#include <cmath>
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
    /// Which slave components no other constraint (Dirichlet data) holds.
    std::array<bool, 3> free{{true, true, true}};
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

    /// Sets the eliminated component: the free one with the largest
    /// |nu_i|; false (and eliminated unchanged) if there is none.
    bool
    choose_eliminated()
    {
      int best = -1;
      for (unsigned int c = 0; c < n_components; ++c)
        if (free[c] && std::abs(normal[c]) > 1e-12 &&
            (best < 0 || std::abs(normal[c]) > std::abs(normal[best])))
          best = c;
      if (best >= 0)
        eliminated = best;
      return best >= 0;
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

    /// A rigid obstacle that moves: its displacement d(t) - d(0) (m), and
    /// the gap of a point to it at time t with its outward unit normal
    /// there (RigidObstacle::gap_and_normal() of the moved obstacle).
    struct ObstacleMotion
    {
      std::function<std::array<double, 3>(double)> displacement;
      std::function<
        std::pair<double, std::array<double, 3>>(const std::array<double, 3> &,
                                                 double)>
        gap_and_normal;
    };

    /// Per pair index, the motion of the obstacle of that pair (empty
    /// functions for the pairs that do not move); empty if none moves.
    std::vector<ObstacleMotion> motions;

    /// Counts the changes of the gaps by set_time() (the active-set
    /// solvers' constraints are made anew after one).
    unsigned long gap_version = 0;

    /// Whether a rigid obstacle moves (the gaps depend on t).
    bool
    obstacles_move() const
    {
      return !motions.empty();
    }

    /// The rows against moving obstacles at time @p t: the gap and the
    /// normal of the node's reference position to the obstacle where it
    /// is at t (the constraint linearised there), and the eliminated
    /// component the free one with the largest |nu_i|.
    void
    set_time(const double t)
    {
      ++gap_version;
      for (ContactRow &row : rows)
        if (row.pair < motions.size() && motions[row.pair].gap_and_normal)
          {
            const auto [gap, n] =
              motions[row.pair].gap_and_normal(row.position, t);
            row.gap = gap;
            // (no normal on a ball's centre or a cylinder's axis: the
            // row keeps its last one)
            if (n[0] == 0. && n[1] == 0. && n[2] == 0.)
              continue;
            for (unsigned int c = 0; c < row.n_components; ++c)
              {
                row.normal[c]         = -n[c];
                row.entries[c].second = -n[c];
              }
            row.choose_eliminated();
          }
    }

    /// nu_p . (d(t) - d(s)) of each row against a moving obstacle (zero
    /// for the others): the obstacle's motion along the row's normal.
    std::vector<double>
    normal_motion(const double s, const double t) const
    {
      std::vector<double>                motion(rows.size(), 0.);
      std::vector<std::array<double, 3>> d(motions.size());
      for (unsigned int k = 0; k < motions.size(); ++k)
        if (motions[k].displacement)
          {
            const auto a = motions[k].displacement(s),
                       b = motions[k].displacement(t);
            for (unsigned int c = 0; c < 3; ++c)
              d[k][c] = b[c] - a[c];
          }
      for (unsigned int p = 0; p < rows.size(); ++p)
        if (rows[p].pair < motions.size() && motions[rows[p].pair].displacement)
          for (unsigned int c = 0; c < rows[p].n_components; ++c)
            motion[p] += rows[p].normal[c] * d[rows[p].pair][c];
      return motion;
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
