#include <deal.II/dofs/dof_tools.h>
#include <deal.II/numerics/vector_tools.h>

#include <dyncontact/base/collective_errors.h>
#include <dyncontact/discretization/semi_discrete_system.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

// The constraints of the mesh (hanging nodes, Dirichlet data) and the
// Dirichlet data that move: which DoFs they prescribe, and their values at
// a time (doc/algorithms.md, "Prescribed displacements").

namespace dyncontact
{
  template <int dim>
  void
  SemiDiscreteSystem<dim>::make_constraints(const Scene<dim> &scene)
  {
    // hanging nodes and homogeneous Dirichlet data
    constraints.clear();
    constraints.reinit(locally_relevant);
    DoFTools::make_hanging_node_constraints(dof_handler, constraints);

    prescribed.reset();
    moving_boundaries.clear();
    relevant_prescribed.clear();
    std::set<types::boundary_id> moving_ids;
    for (const auto &[id, function] : scene.prescribed_displacements())
      moving_ids.insert(id);
    // (the p-multigrid's linear level needs only the constraints)
    const bool with_motion = !moving_ids.empty() && !parameters.multigrid_level;
    AssertThrow(!with_motion || parameters.lumped_mass,
                ExcMessage("Prescribed displacements that move need 'Time "
                           "integration/Mass matrix = lumped' (the step "
                           "solves for the displacement beside them, which "
                           "a consistent or blended mass couples to them)."));
    // the hanging nodes' lines before the Dirichlet data join them
    std::vector<
      std::pair<types::global_dof_index,
                std::vector<std::pair<types::global_dof_index, double>>>>
      hanging;
    if (with_motion)
      for (const auto &line : constraints.get_lines())
        if (locally_owned.is_element(line.index))
          hanging.emplace_back(line.index, line.entries);

    // the boundaries that hold zero first: a node they share with a
    // boundary that moves stays at zero
    const auto dirichlet = scene.dirichlet_boundaries();
    for (const bool moving : {false, true})
      for (const auto &boundary : dirichlet)
        {
          if ((moving_ids.count(boundary.id) > 0) != moving)
            continue;
          std::vector<bool> components(dim);
          for (unsigned int d = 0; d < dim; ++d)
            components[d] = boundary.components[d];
          if (moving && with_motion)
            {
              // the DoFs this boundary is the first to constrain
              std::map<types::global_dof_index, double> on_boundary;
              VectorTools::interpolate_boundary_values(
                mapping,
                dof_handler,
                boundary.id,
                Functions::ZeroFunction<dim>(dim),
                on_boundary,
                ComponentMask(components));
              for (const auto &[dof, value] : on_boundary)
                if (!constraints.is_constrained(dof) &&
                    locally_relevant.is_element(dof))
                  relevant_prescribed.push_back(dof);
              for (const auto &[id, function] :
                   scene.prescribed_displacements())
                if (id == boundary.id)
                  moving_boundaries.push_back({id, function, components});
            }
          VectorTools::interpolate_boundary_values(mapping,
                                                   dof_handler,
                                                   boundary.id,
                                                   Functions::ZeroFunction<dim>(
                                                     dim),
                                                   constraints,
                                                   ComponentMask(components));
        }
    constraints.close();
    if (!with_motion)
      return;

    std::sort(relevant_prescribed.begin(), relevant_prescribed.end());
    relevant_prescribed.erase(std::unique(relevant_prescribed.begin(),
                                          relevant_prescribed.end()),
                              relevant_prescribed.end());
    prescribed = std::make_unique<PrescribedMotion>();
    for (const auto dof : relevant_prescribed)
      if (locally_owned.is_element(dof))
        prescribed->dofs.push_back(dof);
    for (const auto &[child, entries] : hanging)
      {
        std::vector<std::pair<types::global_dof_index, double>> parents;
        for (const auto &entry : entries)
          if (is_prescribed(entry.first))
            parents.push_back(entry);
        if (!parents.empty())
          prescribed->children.emplace_back(child, parents);
      }
    reinit_vector(prescribed->at_end);
    prescribed->part_of = [this](const VectorType &w, VectorType &W) {
      reinit_vector(W);
      for (const auto dof : prescribed->dofs)
        W(dof) = w(dof);
      W.compress(VectorOperation::insert);
      set_children(W);
    };
    prescribed->reaction_of = [this](const VectorType &r, VectorType &R) {
      for (const auto dof : prescribed->dofs)
        R(dof) += r(dof);
      // (a parent on another rank receives its share at compress())
      for (const auto &[child, parents] : prescribed->children)
        for (const auto &[parent, weight] : parents)
          R.add(std::vector<types::global_dof_index>{parent},
                std::vector<double>{weight * r(child)});
      R.compress(VectorOperation::add);
    };
  }



  template <int dim>
  bool
  SemiDiscreteSystem<dim>::is_prescribed(
    const types::global_dof_index dof) const
  {
    return std::binary_search(relevant_prescribed.begin(),
                              relevant_prescribed.end(),
                              dof);
  }



  template <int dim>
  void
  SemiDiscreteSystem<dim>::set_children(VectorType &G) const
  {
    const VectorType parents = ghosted(G);
    for (const auto &[child, entries] : prescribed->children)
      {
        double value = 0.;
        for (const auto &[parent, weight] : entries)
          value += weight * parents(parent);
        G(child) = value;
      }
    G.compress(VectorOperation::insert);
  }



  template <int dim>
  void
  SemiDiscreteSystem<dim>::prescribed_values(const double t,
                                             VectorType  &G,
                                             const bool   finite) const
  {
    reinit_vector(G);
    std::string problem;
    // (a node shared by two boundaries that move follows the first, the
    // lowest tag, which constrained it)
    std::vector<bool> set(prescribed->dofs.size(), false);
    for (const MovingBoundary &boundary : moving_boundaries)
      {
        boundary.function->set_time(t);
        std::map<types::global_dof_index, double> values;
        VectorTools::interpolate_boundary_values(mapping,
                                                 dof_handler,
                                                 boundary.id,
                                                 *boundary.function,
                                                 values,
                                                 ComponentMask(
                                                   boundary.components));
        for (const auto &[dof, value] : values)
          if (locally_owned.is_element(dof))
            {
              const auto at = std::lower_bound(prescribed->dofs.begin(),
                                               prescribed->dofs.end(),
                                               dof);
              if (at == prescribed->dofs.end() || *at != dof ||
                  set[at - prescribed->dofs.begin()])
                continue;
              set[at - prescribed->dofs.begin()] = true;
              G(dof)                             = value;
              if (finite && problem.empty() && !(std::abs(value) <= 1e15))
                {
                  std::ostringstream text;
                  text << "The prescribed displacement of tag " << boundary.id
                       << " is " << value
                       << " m (not finite, or beyond 1e15 in magnitude) at "
                          "t = "
                       << t
                       << " s. Check its expression "
                          "(Scene/Gmsh/Prescribed displacements; the "
                          "velocity of the moving nodes takes it also a "
                          "thousandth of the time step around t, or after t "
                          "where it is not finite before).";
                  problem = text.str();
                }
            }
      }
    stop_with_any_message(problem, comm);
    G.compress(VectorOperation::insert);
    set_children(G);
  }



  template <int dim>
  void
  SemiDiscreteSystem<dim>::set_prescribed_state(const double t,
                                                const double delta_t,
                                                VectorType  &u,
                                                VectorType  *udot)
  {
    if (!prescribed)
      return;
    if (delta_t > 0.)
      prescribed_delta = delta_t;
    // x += D with D = (values - x) on the prescribed DoFs, which moves
    // their hanging children by their share of it (x stays conforming)
    const auto set = [this](const VectorType &values, VectorType &x) {
      VectorType change;
      reinit_vector(change);
      for (const auto dof : prescribed->dofs)
        change(dof) = values(dof) - x(dof);
      change.compress(VectorOperation::insert);
      set_children(change);
      x += change;
    };
    VectorType G;
    prescribed_values(t, G);
    set(G, u);
    if (udot != nullptr)
      {
        AssertThrow(prescribed_delta > 0., ExcInternalError());
        // central differences, or where g is not finite before t (defined
        // for t >= 0 only) one-sided of second order
        VectorType rate, other;
        prescribed_values(t - prescribed_delta, other, false);
        if (std::isfinite(other.l2_norm()))
          {
            prescribed_values(t + prescribed_delta, rate);
            rate -= other;
          }
        else
          {
            prescribed_values(t + prescribed_delta, rate);
            rate *= 4.;
            prescribed_values(t, other);
            rate.add(-3., other);
            prescribed_values(t + 2. * prescribed_delta, other);
            rate -= other;
          }
        rate /= 2. * prescribed_delta;
        set(rate, *udot);
      }
  }



#define DYNCONTACT_INSTANTIATE(dim)                                            \
  template void SemiDiscreteSystem<dim>::make_constraints(const Scene<dim> &); \
  template bool SemiDiscreteSystem<dim>::is_prescribed(                        \
    const types::global_dof_index) const;                                      \
  template void SemiDiscreteSystem<dim>::set_children(VectorType &) const;     \
  template void SemiDiscreteSystem<dim>::prescribed_values(const double,       \
                                                           VectorType &,       \
                                                           const bool) const;  \
  template void SemiDiscreteSystem<dim>::set_prescribed_state(const double,    \
                                                              const double,    \
                                                              VectorType &,    \
                                                              VectorType *);
  DYNCONTACT_INSTANTIATE(2)
  DYNCONTACT_INSTANTIATE(3)
#undef DYNCONTACT_INSTANTIATE
} // namespace dyncontact
