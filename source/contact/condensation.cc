#include <dyncontact/contact/active_set_solver.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace dyncontact
{
  // The condensation of ActiveSetSolver: the constraints of an active set
  // (a row's eliminated DoF expressed by the others) and the operator and
  // preconditioner of the condensed problem (the iteration is in
  // active_set_iteration.cc).

  void
  ActiveSetSolver::make_constraints(const std::vector<char>   &active,
                                    AffineConstraints<double> &constraints,
                                    const bool homogeneous) const
  {
    // local lines: the relevant DoFs and the rows' DoFs (clear() alone
    // would size the lines' index cache by the global number of DoFs on
    // every rank)
    constraints.reinit(row_operator.ghost_set());
    for (unsigned int p = 0; p < rows->size(); ++p)
      if (active[p])
        {
          const ContactRow      &row = rows->rows[p];
          const global_dof_index i   = row.eliminated_dof();
          const double           c_i = row.entries[row.eliminated].second;
          // c_i v_i + sum_{k != i} c_k v_k = g
          constraints.add_line(i);
          for (unsigned int k = 0; k < row.entries.size(); ++k)
            if (k != row.eliminated)
              constraints.add_entry(i,
                                    row.entries[k].first,
                                    -row.entries[k].second / c_i);
          if (!homogeneous)
            constraints.set_inhomogeneity(i, row.gap / c_i);
        }
    // (the contact lines are not restricted to the mesh constraints' local
    // lines, hence different local lines)
    constraints.merge(mesh_constraints,
                      AffineConstraints<double>::left_object_wins,
                      true);
    constraints.close();
  }



  void
  ActiveSetSolver::Condensation::reinit(
    const AffineConstraints<double> &homogeneous,
    const VectorType                &layout,
    const IndexSet                  &owned,
    const MPI_Comm                   comm,
    const AffineConstraints<double> *inhomogeneous_constraints)
  {
    // (all vectors of the solve have this layout: owned entries only)
    Assert(!layout.has_ghost_elements(), ExcInternalError());
    constraints = &homogeneous;
    rows.clear();
    start.assign(1, 0);
    columns.clear();
    values.clear();
    slots.clear();
    slot_columns.clear();
    const auto &map      = layout.trilinos_vector().Map();
    const auto  local_of = [&](const types::global_dof_index i) {
      return map.LID(static_cast<TrilinosWrappers::types::int_type>(i));
    };
    bool                        all_owned = true;
    std::map<int, unsigned int> slot_of;
    for (const auto &line : homogeneous.get_lines())
      if (owned.is_element(line.index))
        {
          rows.push_back(local_of(line.index));
          for (const auto &[j, c] : line.entries)
            {
              const int column = local_of(j);
              all_owned        = all_owned && column >= 0;
              columns.push_back(column);
              values.push_back(c);
              const auto [at, added] =
                slot_of.emplace(column, slot_columns.size());
              if (added)
                slot_columns.push_back(column);
              slots.push_back(at->second);
            }
          start.push_back(columns.size());
        }
    local = Utilities::MPI::min(all_owned ? 1 : 0, comm) == 1;
    slot_sums.resize(slot_columns.size());

    // the inhomogeneities, where the owned lines are the same (close()
    // resolves chains with the same coefficients whatever the
    // inhomogeneities; checked entry by entry, else deal.II distributes)
    inhomogeneities_local = false;
    inhomogeneities.clear();
    // (local and the argument are the same on every rank)
    if (!local || inhomogeneous_constraints == nullptr)
      return;
    unsigned int l    = 0;
    bool         same = true;
    for (const auto &line : inhomogeneous_constraints->get_lines())
      if (owned.is_element(line.index))
        {
          same = same && l < rows.size() && rows[l] == local_of(line.index) &&
                 line.entries.size() == start[l + 1] - start[l];
          for (unsigned int k = 0; same && k < line.entries.size(); ++k)
            same = columns[start[l] + k] == local_of(line.entries[k].first) &&
                   values[start[l] + k] == line.entries[k].second;
          if (!same)
            break;
          inhomogeneities.push_back(line.inhomogeneity);
          ++l;
        }
    // (on every rank alike: the other path's distribute() is collective)
    if (Utilities::MPI::min((same && l == rows.size()) ? 1 : 0, comm) == 1)
      inhomogeneities_local = true;
    else
      inhomogeneities.clear();
  }



  const ActiveSetSolver::ActiveSetConstraints &
  ActiveSetSolver::constraints_of(const std::vector<char> &active,
                                  const VectorType        &layout) const
  {
    // (the gaps of rigid obstacles that move change with the time)
    const bool same =
      Utilities::MPI::min((last_constraints &&
                           last_constraints->active == active &&
                           last_constraints->gap_version == rows->gap_version) ?
                            1 :
                            0,
                          comm) == 1;
    if (!same)
      {
        last_constraints.reset();
        auto c         = std::make_unique<ActiveSetConstraints>();
        c->active      = active;
        c->gap_version = rows->gap_version;
        make_constraints(active, c->constraints, false);
        make_constraints(active, c->homogeneous_constraints, true);
        c->homogeneous.reinit(c->homogeneous_constraints,
                              layout,
                              locally_owned,
                              comm,
                              &c->constraints);
        // where the local form does all (on every rank), the
        // AffineConstraints are not read again: their memory (lines and an
        // index cache over the relevant DoFs, per solver) is released
        if (c->homogeneous.inhomogeneities_local)
          {
            c->constraints.clear();
            c->homogeneous_constraints.clear();
          }
        last_constraints = std::move(c);
      }
    return *last_constraints;
  }



  void
  ActiveSetSolver::distribute_inhomogeneous(
    const ActiveSetConstraints &constraints,
    VectorType                 &v) const
  {
    const Condensation &homogeneous = constraints.homogeneous;
    if (!homogeneous.inhomogeneities_local)
      {
        constraints.constraints.distribute(v);
        return;
      }
    // v_i = k_i + sum_j v_j c_ij, in the order of
    // AffineConstraints::distribute() (the entries are unconstrained)
    double *const v_local = v.begin();
    for (unsigned int l = 0; l < homogeneous.rows.size(); ++l)
      {
        double value = homogeneous.inhomogeneities[l];
        for (unsigned int k = homogeneous.start[l];
             k < homogeneous.start[l + 1];
             ++k)
          value += v_local[homogeneous.columns[k]] * homogeneous.values[k];
        v_local[homogeneous.rows[l]] = value;
      }
  }



  void
  ActiveSetSolver::transpose_distribute(const Condensation &homogeneous,
                                        VectorType         &z) const
  {
    // z <- T^T z: every owned constrained entry z_i is added, times the
    // coefficient, to the entries z_j it depends on (possibly owned
    // elsewhere), and then set to zero.
    if (homogeneous.local)
      {
        // the same sums as add_to_masters(): per column, the additions in
        // the order of the lines, then added to z_j
        double *const        z_local = z.begin();
        std::vector<double> &sums    = homogeneous.slot_sums;
        std::fill(sums.begin(), sums.end(), 0.);
        for (unsigned int l = 0; l < homogeneous.rows.size(); ++l)
          {
            const double z_i = z_local[homogeneous.rows[l]];
            for (unsigned int k = homogeneous.start[l];
                 k < homogeneous.start[l + 1];
                 ++k)
              sums[homogeneous.slots[k]] += homogeneous.values[k] * z_i;
          }
        for (unsigned int s = 0; s < sums.size(); ++s)
          z_local[homogeneous.slot_columns[s]] += sums[s];
      }
    else
      add_to_masters(*homogeneous.constraints, z);
    zero_constrained(homogeneous, z);
  }



  void
  ActiveSetSolver::add_to_masters(const AffineConstraints<double> &constraints,
                                  VectorType                      &z) const
  {
    additions = 0.;
    for (const auto &line : constraints.get_lines())
      if (locally_owned.is_element(line.index))
        {
          const double z_i = z(line.index);
          for (const auto &entry : line.entries)
            additions(entry.first) += entry.second * z_i;
        }
    additions.compress(VectorOperation::add);
    z += additions;
  }



  void
  ActiveSetSolver::vmult_condensed(const Condensation &homogeneous,
                                   VectorType         &y,
                                   const VectorType   &x) const
  {
    // (Tx takes x's map: between vectors whose maps were made apart,
    // deal.II copies through an Epetra_Import built anew at each copy)
    if (Tx.trilinos_vector().Map().DataPtr() !=
        x.trilinos_vector().Map().DataPtr())
      Tx.reinit(x, true);
    Tx = x;
    if (homogeneous.local)
      {
        // T x: x_i = sum_j c_ij x_j on the constrained entries, summed as
        // AffineConstraints::distribute() does
        double *const Tx_local = Tx.begin();
        for (unsigned int l = 0; l < homogeneous.rows.size(); ++l)
          {
            double value = 0.;
            for (unsigned int k = homogeneous.start[l];
                 k < homogeneous.start[l + 1];
                 ++k)
              value += Tx_local[homogeneous.columns[k]] * homogeneous.values[k];
            Tx_local[homogeneous.rows[l]] = value;
          }
      }
    else
      homogeneous.constraints->distribute(Tx);
    vmult_H(y, Tx);
    transpose_distribute(homogeneous, y);
    // constrained entries: identity scaled by H's diagonal (they stay zero)
    if (homogeneous.local)
      {
        double *const       y_local        = y.begin();
        const double *const x_local        = x.begin();
        const double *const diagonal_local = diagonal.begin();
        for (const int i : homogeneous.rows)
          y_local[i] = diagonal_local[i] * x_local[i];
      }
    else
      {
        for (const auto &line : homogeneous.constraints->get_lines())
          if (locally_owned.is_element(line.index))
            y(line.index) = diagonal(line.index) * x(line.index);
        y.compress(VectorOperation::insert);
      }
  }



  void
  ActiveSetSolver::zero_constrained(const Condensation &homogeneous,
                                    VectorType         &x) const
  {
    if (homogeneous.local)
      {
        double *const x_local = x.begin();
        for (const int i : homogeneous.rows)
          x_local[i] = 0.;
        return;
      }
    for (const auto &line : homogeneous.constraints->get_lines())
      if (locally_owned.is_element(line.index))
        x(line.index) = 0.;
    x.compress(VectorOperation::insert);
  }



  void
  ActiveSetSolver::precondition_condensed(const Condensation &homogeneous,
                                          VectorType         &y,
                                          const VectorType   &x) const
  {
    if (amg)
      amg->vmult(y, x);
    else if (H_preconditioner)
      H_preconditioner(y, x);
    else
      {
        y = x;
        y.scale(inverse_diagonal);
      }
    zero_constrained(homogeneous, y);
  }


} // namespace dyncontact
