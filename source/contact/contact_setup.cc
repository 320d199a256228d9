#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <dyncontact/base/collective_errors.h>
#include <dyncontact/base/input_checks.h>
#include <dyncontact/contact/contact_setup.h>
#include <dyncontact/scenes/body_overlap.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

namespace dyncontact
{
  template <int dim>
  void
  ContactSetup<dim>::Parameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    prm.declare_entry("Slave side",
                      "auto",
                      Patterns::Selection("auto|1|2"),
                      "Two-body scenes: which side of the contact pair is the "
                      "slave (its nodes carry the constraint rows): auto (the "
                      "scene's choice if it makes one, as the Hertz scenes "
                      "with 'Block mesh = matched' do, else the finer side, "
                      "by mean face size, of the mesh at t = 0, kept when "
                      "the mesh adapts), 1 or 2.");
    prm.declare_entry("Search radius",
                      "0",
                      Patterns::Double(0.),
                      "Two-body scenes: slave nodes farther than this from "
                      "the master surface (in the reference configuration) "
                      "get no constraint row, in m; 0 = the scene's default "
                      "(the gmsh scene has none). A pair given its own "
                      "radius (Scene/Gmsh/Contact pairs 'slave : master : "
                      "radius') keeps it.");
    prm.declare_entry("Initial penetration",
                      "reject",
                      Patterns::Selection("reject|project"),
                      "What to do with an initial configuration that "
                      "penetrates (a slave node inside the obstacle or the "
                      "master body): reject it with a message, or project "
                      "the initial displacement onto K_h (the M-projection) "
                      "with a warning that says by how much.");
    prm.declare_entry("Pair without rows",
                      "refuse",
                      Patterns::Selection("refuse|warn"),
                      "What to do with a contact pair (or the rigid "
                      "obstacle) none of whose slave nodes gets a "
                      "constraint row at t = 0 (all of them clamped, or "
                      "none within the search radius of the master "
                      "surface), whose bodies could pass through each other "
                      "unseen: refuse the run with a message naming the "
                      "pair and why, or run it with a warning (the "
                      "penetration of such nodes is still measured in "
                      "max_penetration).");
    prm.leave_subsection();
  }



  template <int dim>
  void
  ContactSetup<dim>::Parameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    const std::string slave = prm.get("Slave side");
    slave_side              = (slave == "auto") ? -1 : (slave == "1" ? 0 : 1);
    search_radius           = prm.get_double("Search radius");
    project_initial_penetration = (prm.get("Initial penetration") == "project");
    refuse_pair_without_rows    = (prm.get("Pair without rows") == "refuse");
    prm.leave_subsection();
  }



  template <int dim>
  ContactSetup<dim>::ContactSetup(const Parameters &parameters,
                                  const MPI_Comm    comm)
    : parameters(parameters)
    , comm(comm)
    , unpaired_bodies(comm)
    , row_operator(comm)
  {}



  template <int dim>
  std::vector<ContactPair>
  ContactSetup<dim>::contact_pairs(const Scene<dim> &scene) const
  {
    std::vector<ContactPair> pairs = scene.contact_pairs();
    for (ContactPair &pair : pairs)
      {
        if (parameters.slave_side >= 0 && !pair.own_slave_side)
          pair.slave_side = parameters.slave_side;
        if (parameters.search_radius > 0. && !pair.own_search_radius)
          pair.search_radius = parameters.search_radius;
      }
    return pairs;
  }



  template <int dim>
  void
  ContactSetup<dim>::check(const Scene<dim> &scene) const
  {
    for (const ContactPair &pair : scene.contact_pairs())
      AssertThrow(parameters.slave_side < 0 || !pair.own_slave_side,
                  ExcMessage("Contact/Slave side = " +
                             std::to_string(parameters.slave_side + 1) +
                             " would override the 'slave : master' order of "
                             "Scene/Gmsh/Contact pairs, which names each "
                             "pair's slave: leave Contact/Slave side at auto, "
                             "and write the pair the other way round to "
                             "swap its sides."));
    for (const ContactPair &pair : contact_pairs(scene))
      AssertThrow(pair.search_radius > 0.,
                  ExcMessage("Contact/Search radius must be > 0 (m) for the "
                             "scene '" +
                             scene.name() + "': it has no default" +
                             (scene.name() == "gmsh" ?
                                " (or give each pair its own: Scene/Gmsh/"
                                "Contact pairs 'slave : master : radius')." :
                                std::string("."))));
  }



  template <int dim>
  void
  ContactSetup<dim>::setup(const Scene<dim>              &scene,
                           const SemiDiscreteSystem<dim> &system,
                           const Mapping<dim>            &mapping,
                           const ConditionalOStream      &pcout)
  {
    rows.rows.clear();
    unmatched.clear();
    master_surfaces.clear();
    pairs_without_rows.clear();
    coarse_mesh                = &system.get_dof_handler().get_triangulation();
    locally_owned              = system.locally_owned_dofs();
    locally_relevant           = system.locally_relevant_dofs();
    const VectorType w_ghosted = system.ghosted(system.get_boundary_weights());

    const auto pairs = contact_pairs(scene);
    search_radii.clear();
    pair_sides.clear();
    for (const ContactPair &pair : pairs)
      {
        search_radii.push_back(pair.search_radius);
        pair_sides.push_back({{pair.first_side, pair.second_side}});
      }
    n_bodies = scene.n_bodies();
    side_bodies.clear();
    several_pairs = pairs.size() + (scene.obstacle() ? 1 : 0) > 1;
    // the bodies of the contact boundary ids @p ids, as "1+3", for the
    // banner
    std::vector<std::set<types::boundary_id>> ids_of_bodies;
    const auto bodies_on = [&](const std::vector<types::boundary_id> &ids) {
      std::string bodies;
      for (unsigned int b = 0; b < ids_of_bodies.size(); ++b)
        if (has_any_of(ids_of_bodies[b], ids))
          bodies += (bodies.empty() ? "" : "+") + std::to_string(b + 1);
      return bodies;
    };
    if (several_pairs)
      {
        ids_of_bodies =
          boundary_ids_of_bodies(system.get_dof_handler().get_triangulation(),
                                 scene.n_bodies());
        for (const ContactPair &pair : pairs)
          side_bodies.push_back(
            {{bodies_on(pair.first_side), bodies_on(pair.second_side)}});
      }
    if (const auto obstacle = scene.obstacle())
      add_obstacle_rows(*obstacle,
                        pairs.size(),
                        boundary_nodes(system,
                                       mapping,
                                       scene.contact_boundary_ids()),
                        w_ghosted,
                        system.get_constraints());
    const types::global_dof_index n_obstacle_rows =
      Utilities::MPI::sum<types::global_dof_index>(rows.size(), comm);
    for (unsigned int pair_index = 0; pair_index < pairs.size(); ++pair_index)
      add_pair_rows(scene,
                    pairs[pair_index],
                    pair_index,
                    system,
                    mapping,
                    w_ghosted,
                    pcout);
    // (the counts of the rows per pair only at t = 0, where a pair without
    // rows is refused: an adaptation's set-up makes no collective calls
    // for them)
    const bool at_start = kept_slave_sides.empty();
    if (several_pairs && at_start)
      {
        // a pair that had rows, all of which a nearer master of another pair
        // took: nothing of it holds its bodies apart at t = 0
        std::vector<types::global_dof_index> before(pairs.size() + 1, 0);
        for (const auto &row : rows.rows)
          ++before[row.pair];
        Utilities::MPI::sum(before, comm, before);
        keep_nearest_rows();
        std::vector<types::global_dof_index> after(pairs.size() + 1, 0);
        for (const auto &row : rows.rows)
          ++after[row.pair];
        Utilities::MPI::sum(after, comm, after);
        for (unsigned int k = 0; k < pairs.size(); ++k)
          if (before[k] > 0 && after[k] == 0)
            add_pair_without_rows(
              pair_name(k),
              "each of its " + std::to_string(before[k]) +
                " slave nodes near its master keeps the row of a nearer "
                "master of another pair",
              "Check that the pair's contact tags name the faces that "
              "meet (a pair whose slave faces look away from its master "
              "is taken by the other pairs).");
      }
    else if (several_pairs)
      keep_nearest_rows();
    if (scene.obstacle() && several_pairs)
      {
        unsigned int n_kept = 0;
        for (const auto &row : rows.rows)
          n_kept += (row.pair == pairs.size());
        n_kept = Utilities::MPI::sum(n_kept, comm);
        pcout << "   contact pair " << pairs.size() + 1 << ": slave body "
              << bodies_on(scene.contact_boundary_ids()) << " ("
              << n_obstacle_rows << " nodes";
        if (n_kept < n_obstacle_rows)
          pcout << ", " << n_kept << " with obstacle rows, the others "
                << "nearer to a master of another pair";
        pcout << "), master the rigid obstacle" << std::endl;
      }

    // the penetration check of the slave nodes without a row keeps this
    // rank's master faces, but only if there are such nodes
    n_unmatched_nodes =
      Utilities::MPI::sum<types::global_dof_index>(unmatched.size(), comm);
    obstacle_plane = scene.obstacle();
    n_unmatched_in_pair.assign(pairs.size() + 1, 0);
    for (const auto &node : unmatched)
      ++n_unmatched_in_pair[node.pair];
    Utilities::MPI::sum(n_unmatched_in_pair, comm, n_unmatched_in_pair);
    if (n_unmatched_nodes == 0)
      master_surfaces.clear();

    row_operator.reinit(locally_owned, locally_relevant, rows);
    unpaired_bodies.setup(pairs, scene.n_bodies(), system, mapping);

    double measure = 0.;
    for (const auto &row : rows.rows)
      measure += row.weight;
    measure = Utilities::MPI::sum(measure, comm);
    n_global_row_count =
      Utilities::MPI::sum<types::global_dof_index>(rows.size(), comm);
    pcout << "   contact rows: " << n_global_row_count
          << ", measure of the slave contact boundary: " << measure
          << std::endl;
  }



  template <int dim>
  void
  ContactSetup<dim>::keep_nearest_rows()
  {
    // a slave node with rows in two pairs (or a pair and the obstacle)
    // keeps the row of the nearer master: two active rows of one node
    // would eliminate the same component
    std::map<types::global_dof_index, unsigned int> nearest;
    for (unsigned int r = 0; r < rows.size(); ++r)
      {
        const auto [it, inserted] =
          nearest.emplace(rows.rows[r].entries[0].first, r);
        if (!inserted && rows.rows[r].gap < rows.rows[it->second].gap)
          it->second = r;
      }
    if (nearest.size() == rows.size())
      return;
    ContactRows kept;
    for (unsigned int r = 0; r < rows.size(); ++r)
      if (nearest[rows.rows[r].entries[0].first] == r)
        kept.rows.push_back(rows.rows[r]);
      else
        {
          // the farther master can still come nearer later (the rows are
          // chosen on the mesh's reference configuration): the node is
          // watched against it by unmatched_penetration()
          const ContactRow &row = rows.rows[r];
          UnmatchedNode     node;
          node.pair          = row.pair;
          node.nearer_master = true;
          for (unsigned int d = 0; d < dim; ++d)
            {
              node.x[d]    = row.position[d];
              node.dofs[d] = row.entries[d].first;
            }
          unmatched.push_back(node);
        }
    rows = std::move(kept);
  }



  template <int dim>
  std::vector<typename ContactSetup<dim>::BoundaryNode>
  ContactSetup<dim>::boundary_nodes(
    const SemiDiscreteSystem<dim>         &system,
    const Mapping<dim>                    &mapping,
    const std::vector<types::boundary_id> &ids) const
  {
    const auto                          &fe        = system.get_fe();
    const auto                          &scalar_fe = system.get_scalar_fe();
    std::vector<BoundaryNode>            nodes;
    std::set<types::global_dof_index>    seen;
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    const auto &unit_points = scalar_fe.get_unit_support_points();
    for (const auto &cell : system.get_dof_handler().active_cell_iterators())
      {
        if (cell->is_locally_owned())
          for (const unsigned int face : cell->face_indices())
            if (cell->face(face)->at_boundary() &&
                std::find(ids.begin(),
                          ids.end(),
                          cell->face(face)->boundary_id()) != ids.end())
              {
                cell->get_dof_indices(dofs);
                for (unsigned int node = 0; node < scalar_fe.n_dofs_per_cell();
                     ++node)
                  {
                    if (!scalar_fe.has_support_on_face(node, face))
                      continue;
                    std::array<types::global_dof_index, dim> node_dofs;
                    for (unsigned int d = 0; d < dim; ++d)
                      node_dofs[d] =
                        dofs[system.get_node_system_indices()[node][d]];
                    if (!locally_owned.is_element(node_dofs[0]) ||
                        seen.count(node_dofs[0]))
                      continue;
                    seen.insert(node_dofs[0]);
                    nodes.push_back(
                      {mapping.transform_unit_to_real_cell(cell,
                                                           unit_points[node]),
                       node_dofs});
                  }
              }
      }
    return nodes;
  }



  namespace
  {
    /// Whether Dirichlet data (a constraint without entries) fix every
    /// component of @p row's node that its normal has.
    bool
    fixed_by_dirichlet_data(const ContactRow                &row,
                            const AffineConstraints<double> &constraints)
    {
      for (unsigned int d = 0; d < row.normal.size(); ++d)
        if (std::abs(row.normal[d]) > 1e-12 &&
            !(constraints.is_constrained(row.entries[d].first) &&
              constraints.get_constraint_entries(row.entries[d].first)
                ->empty()))
          return false;
      return true;
    }



    /// Stops if any rank found slave nodes of pair @p pair_index (slave
    /// side @p slave) that Dirichlet data fix (they get no rows).
    void
    refuse_clamped_slave_nodes(unsigned int       n_clamped,
                               const unsigned int pair_index,
                               const unsigned int slave,
                               const bool         own_slave_side,
                               const MPI_Comm     comm)
    {
      n_clamped = Utilities::MPI::sum(n_clamped, comm);
      AssertThrow(n_clamped == 0,
                  ExcMessage(
                    "Contact pair " + std::to_string(pair_index + 1) + ": " +
                    std::to_string(n_clamped) + " slave nodes (side " +
                    std::to_string(slave + 1) +
                    ") lie on a Dirichlet boundary: they get no "
                    "contact rows, and the master body would pass "
                    "through them. Make the clamped side the master "
                    "(" +
                    (own_slave_side ?
                       std::string("write the pair the other way round") :
                       "Contact/Slave side = " + std::to_string(2 - slave)) +
                    "), or take the contact boundary out of the "
                    "Dirichlet boundaries."));
    }
  } // namespace



  template <int dim>
  void
  ContactSetup<dim>::add_row(ContactRow                      &row,
                             const VectorType                &w_ghosted,
                             const AffineConstraints<double> &constraints)
  {
    // the eliminated component: the free one with the largest |nu_i|; no
    // row for a node without one (a hanging node, or a node fixed by
    // Dirichlet data)
    row.weight = w_ghosted(row.entries[0].first);
    int best   = -1;
    for (unsigned int d = 0; d < dim; ++d)
      if (!constraints.is_constrained(row.entries[d].first) &&
          std::abs(row.normal[d]) > 1e-12 &&
          (best < 0 || std::abs(row.normal[d]) > std::abs(row.normal[best])))
        best = d;
    row.eliminated = std::max(best, 0);
    if (best >= 0)
      rows.rows.push_back(row);
  }



  template <int dim>
  void
  ContactSetup<dim>::add_obstacle_rows(
    const RigidObstacle<dim>        &obstacle,
    const unsigned int               pair_index,
    const std::vector<BoundaryNode> &nodes,
    const VectorType                &w_ghosted,
    const AffineConstraints<double> &constraints)
  {
    // a rigid obstacle: nu = -n, g = (x - x0) . n, no master entries
    std::string       penetration;
    const std::size_t n_rows_before = rows.size();
    for (const BoundaryNode &node : nodes)
      {
        const Point<dim> &x = node.x;
        ContactRow        row;
        row.n_components = dim;
        row.pair         = pair_index;
        for (unsigned int d = 0; d < dim; ++d)
          {
            row.entries.emplace_back(node.dofs[d], -obstacle.normal[d]);
            row.normal[d]   = -obstacle.normal[d];
            row.position[d] = x[d];
          }
        row.gap = (x - obstacle.point) * obstacle.normal;
        AssertThrow(std::isfinite(row.gap),
                    ExcMessage("The gap of the node at (" +
                               Utilities::to_string(x[0]) + ", " +
                               Utilities::to_string(x[1]) +
                               ", ...) to the obstacle is not finite."));
        if (!parameters.project_initial_penetration &&
            row.gap < -1e-12 * (std::abs(row.gap) + 1.) && penetration.empty())
          penetration =
            "The initial configuration penetrates the "
            "obstacle" +
            (several_pairs ?
               " (contact pair " + std::to_string(pair_index + 1) + ")" :
               std::string()) +
            ": the node at (" + Utilities::to_string(x[0]) + ", " +
            Utilities::to_string(x[1]) + ", ...) lies " +
            Utilities::to_string(-row.gap) +
            " m inside it. Correct the scene, or set "
            "'Contact/Initial penetration = project'.";
        add_row(row, w_ghosted, constraints);
      }
    // (every rank stops, also those without such a node)
    stop_with_any_message(penetration, comm);
    if (!kept_slave_sides.empty())
      return; // (a pair without rows is refused at t = 0 only)
    const types::global_dof_index n_nodes =
      Utilities::MPI::sum<types::global_dof_index>(nodes.size(), comm);
    const types::global_dof_index n_rows =
      Utilities::MPI::sum<types::global_dof_index>(rows.size() - n_rows_before,
                                                   comm);
    if (n_rows == 0)
      add_pair_without_rows(
        "pair " + std::to_string(pair_index + 1) + " (the rigid obstacle)",
        n_nodes == 0 ? "no boundary face carries its contact tags" :
                       "all " + std::to_string(n_nodes) +
                         " of its slave nodes lie on a Dirichlet boundary",
        "Take the contact tags off the clamped faces, or the clamped faces "
        "out of the Dirichlet tags.");
  }



  template <int dim>
  std::string
  ContactSetup<dim>::pair_name(const unsigned int k) const
  {
    if (!several_pairs)
      return "pair (slave side " + std::to_string(slave_sides[k] + 1) + ")";
    return "pair " + std::to_string(k + 1) +
           (k < side_bodies.size() ?
              " (slave body " + side_bodies[k][slave_sides[k]] +
                ", master body " + side_bodies[k][1 - slave_sides[k]] + ")" :
              std::string());
  }



  template <int dim>
  void
  ContactSetup<dim>::add_pair_without_rows(const std::string &pair,
                                           const std::string &reason,
                                           const std::string &remedy)
  {
    pairs_without_rows.push_back(
      "Contact " + pair + " has no constraint row at t = 0: " + reason +
      ", so its bodies could pass through each other unseen. " + remedy);
  }


  template <int dim>
  unsigned int
  ContactSetup<dim>::finer_side(
    const std::array<std::vector<MasterFace<dim>>, 2> &sides,
    const double                                       search_radius) const
  {
    // compare the mean size of the faces that face the other side (their
    // centre has an image on it), so that a coarse far field does not count
    std::array<double, 2> size{{0., 0.}};
    for (unsigned int s = 0; s < 2; ++s)
      {
        std::vector<Point<dim>> centres;
        for (const auto &face : sides[s])
          {
            Point<dim> centre;
            for (const auto &v : face.vertices)
              centre += v / double(face.vertices.size());
            centres.push_back(centre);
          }
        const ContactMapping<dim> other(
          faces_near(sides[1 - s], centres, search_radius, comm),
          search_radius);
        double n = 0.;
        for (unsigned int f = 0; f < centres.size(); ++f)
          if (other.find_image(centres[f]))
            {
              size[s] +=
                sides[s][f].vertices[0].distance(sides[s][f].vertices.back());
              n += 1.;
            }
        size[s] = Utilities::MPI::sum(size[s], comm);
        n       = Utilities::MPI::sum(n, comm);
        size[s] = (n > 0) ? size[s] / n : 1e300;
      }
    return (size[1] < size[0] * (1. - 1e-12)) ? 1 : 0;
  }



  template <int dim>
  void
  ContactSetup<dim>::add_pair_rows(const Scene<dim>              &scene,
                                   const ContactPair             &pair,
                                   const unsigned int             pair_index,
                                   const SemiDiscreteSystem<dim> &system,
                                   const Mapping<dim>            &mapping,
                                   const VectorType              &w_ghosted,
                                   const ConditionalOStream      &pcout)
  {
    // the mortar-like mapping phi_h onto the master faces near this rank's
    // slave nodes (a parallel search: no rank holds the whole master
    // surface)
    const std::array<std::vector<MasterFace<dim>>, 2> sides = {
      {local_faces(system, pair.first_side, scene.symmetry_boundary_ids()),
       local_faces(system, pair.second_side, scene.symmetry_boundary_ids())}};
    const std::array<types::global_dof_index, 2> n_faces = {
      {Utilities::MPI::sum<types::global_dof_index>(sides[0].size(), comm),
       Utilities::MPI::sum<types::global_dof_index>(sides[1].size(), comm)}};
    const unsigned int slave = pair.slave_side >= 0 ?
                                 pair.slave_side :
                                 (pair_index < kept_slave_sides.size() ?
                                    kept_slave_sides[pair_index] :
                                    finer_side(sides, pair.search_radius));
    if (slave_sides.size() <= pair_index)
      slave_sides.resize(pair_index + 1, 0);
    slave_sides[pair_index] = slave;

    // this rank's slave nodes, then the master faces near them
    const std::vector<BoundaryNode> nodes =
      boundary_nodes(system,
                     mapping,
                     slave == 0 ? pair.first_side : pair.second_side);
    std::vector<Point<dim>> slave_points;
    for (const BoundaryNode &node : nodes)
      slave_points.push_back(node.x);
    const ContactMapping<dim> phi(
      faces_near(sides[1 - slave], slave_points, pair.search_radius, comm),
      pair.search_radius);
    // slave nodes that Dirichlet data fix in every direction of their row
    unsigned int n_clamped = 0;
    // (for a pair without rows: slave nodes fixed in every direction, and
    // those that find a master face)
    // (counted at t = 0 only, where such a pair is refused)
    const bool              at_start = kept_slave_sides.empty();
    types::global_dof_index n_fixed = 0, n_imaged = 0;
    const std::size_t       n_rows_before = rows.size();
    std::string             penetration;
    for (const BoundaryNode &node : nodes)
      {
        const Point<dim> &x     = node.x;
        const auto        image = phi.find_image(x);
        if (at_start)
          {
            bool fixed = true;
            for (unsigned int d = 0; d < dim; ++d)
              fixed = fixed &&
                      system.get_constraints().is_constrained(node.dofs[d]) &&
                      system.get_constraints()
                        .get_constraint_entries(node.dofs[d])
                        ->empty();
            n_fixed += fixed;
          }
        if (!image)
          {
            unmatched.push_back({x, node.dofs, pair_index});
            continue;
          }
        ++n_imaged;
        auto       projection = *image;
        const bool inside     = (x - image->point) * image->master_normal <
                            -1e-10 * pair.search_radius;
        if (inside && !parameters.project_initial_penetration &&
            penetration.empty())
          penetration =
            "The initial configuration penetrates" +
            (several_pairs ?
               " (contact pair " + std::to_string(pair_index + 1) + ")" :
               std::string()) +
            ": the slave node at (" + Utilities::to_string(x[0]) + ", " +
            Utilities::to_string(x[1]) +
            ", ...) lies inside the master body by " +
            Utilities::to_string(image->gap) +
            " m. Correct the mesh, or set "
            "'Contact/Initial penetration = project'.";
        if (inside)
          {
            // a negative gap along the master's normal: the row asks for
            // the node to be moved out
            projection.normal = -image->master_normal;
            projection.gap    = -image->gap;
          }
        ContactRow row           = make_two_body_row<dim>(x,
                                                node.dofs,
                                                projection,
                                                phi.faces()[image->face],
                                                system.get_fe().degree);
        row.pair                 = pair_index;
        const std::size_t n_rows = rows.size();
        add_row(row, w_ghosted, system.get_constraints());
        if (rows.size() == n_rows &&
            fixed_by_dirichlet_data(row, system.get_constraints()))
          ++n_clamped;
      }
    // (every rank stops, also those without such a node)
    stop_with_any_message(penetration, comm);
    refuse_clamped_slave_nodes(
      n_clamped, pair_index, slave, pair.own_slave_side, comm);
    std::vector<types::global_dof_index> counts = {
      static_cast<types::global_dof_index>(nodes.size()),
      n_fixed,
      n_imaged,
      static_cast<types::global_dof_index>(rows.size() - n_rows_before)};
    if (at_start)
      Utilities::MPI::sum(counts, comm, counts);
    if (at_start && counts[3] == 0)
      {
        std::ostringstream radius; // 6 digits
        radius << pair.search_radius;
        const std::string name = pair_name(pair_index);
        if (counts[0] == 0)
          add_pair_without_rows(
            name,
            "no boundary face of its slave side carries its contact tags",
            "Check the contact tags of the scene.");
        else if (counts[1] == counts[0])
          add_pair_without_rows(
            name,
            "all " + std::to_string(counts[0]) +
              " of its slave nodes lie on a Dirichlet boundary",
            std::string("Take the contact tags off the clamped faces, or "
                        "make the clamped side the master (") +
              (pair.own_slave_side ?
                 "write the pair the other way round" :
                 "Contact/Slave side = " + std::to_string(2 - slave)) +
              ").");
        else if (counts[2] == 0)
          add_pair_without_rows(
            name,
            "none of its " + std::to_string(counts[0]) +
              " slave nodes lies within the search radius (" + radius.str() +
              " m) of a master face",
            std::string("Raise ") +
              (pair.own_search_radius ?
                 "the pair's own radius (Scene/Gmsh/Contact pairs 'slave : "
                 "master : radius')" :
                 "Contact/Search radius") +
              " above the gap the bodies close during the run, and check "
              "that the contact tags name the faces that meet.");
        else
          add_pair_without_rows(
            name,
            "its slave nodes within the search radius of a master face "
            "are fixed by Dirichlet data or hanging",
            "Check the contact and Dirichlet tags of the scene.");
      }
    pcout << "   contact pair"
          << (several_pairs ? " " + std::to_string(pair_index + 1) :
                              std::string())
          << ": slave is side " << slave + 1 << " ("
          << (pair_index < side_bodies.size() ?
                "body " + side_bodies[pair_index][slave] + ", " :
                std::string())
          << n_faces[slave] << " faces), master side " << 2 - slave << " ("
          << (pair_index < side_bodies.size() ?
                "body " + side_bodies[pair_index][1 - slave] + ", " :
                std::string())
          << n_faces[1 - slave] << " faces)" << std::endl;
    master_surfaces.push_back(sides[1 - slave]);
  }



  template <int dim>
  typename ContactSetup<dim>::Penetration
  ContactSetup<dim>::unmatched_penetration(const VectorType &u) const
  {
    Penetration deepest;
    if (n_unmatched_nodes == 0)
      return deepest;
    VectorType ghosted(locally_owned, locally_relevant, comm);
    ghosted = u;
    for (unsigned int pair = 0; pair < master_surfaces.size(); ++pair)
      {
        if (n_unmatched_in_pair[pair] == 0)
          continue;
        // this rank's faces of the deformed master surface (their vertex
        // DoFs are locally relevant)
        std::vector<MasterFace<dim>> deformed = master_surfaces[pair];
        deform(deformed, ghosted);
        std::vector<Point<dim>> points;
        for (const auto &node : unmatched)
          if (node.pair == pair)
            {
              Point<dim> y = node.x;
              for (unsigned int d = 0; d < dim; ++d)
                y[d] += ghosted(node.dofs[d]);
              points.push_back(y);
            }
        const ContactMapping<dim> phi(closest_faces(deformed, points, comm),
                                      0.);
        unsigned int              p = 0;
        for (const auto &node : unmatched)
          if (node.pair == pair)
            {
              const Point<dim> &y     = points[p++];
              const auto        image = phi.find_closest(y);
              if (image && (y - image->point) * image->master_normal < 0. &&
                  image->gap > deepest.depth)
                {
                  deepest.depth         = image->gap;
                  deepest.position      = node.x;
                  deepest.pair          = pair;
                  deepest.nearer_master = node.nearer_master;
                }
            }
      }
    // nodes that kept the row of a master nearer than the obstacle
    // (the obstacle's pair index: the number of two-body pairs)
    const unsigned int obstacle_pair = search_radii.size();
    if (obstacle_plane && n_unmatched_in_pair[obstacle_pair] > 0)
      for (const auto &node : unmatched)
        if (node.pair == obstacle_pair)
          {
            Point<dim> y = node.x;
            for (unsigned int d = 0; d < dim; ++d)
              y[d] += ghosted(node.dofs[d]);
            const double depth =
              -((y - obstacle_plane->point) * obstacle_plane->normal);
            // (round-off of a node on the surface is no penetration)
            if (depth > deepest.depth && depth > 1e-12 * (1. + y.norm()))
              {
                deepest.depth         = depth;
                deepest.position      = node.x;
                deepest.pair          = node.pair;
                deepest.nearer_master = node.nearer_master;
              }
          }
    // the deepest over all ranks, with its position
    std::vector<double> position(dim + 2, 0.);
    for (unsigned int d = 0; d < dim; ++d)
      position[d] = deepest.position[d];
    position[dim]     = deepest.pair;
    position[dim + 1] = deepest.nearer_master ? 1. : 0.;
    deepest_over_ranks(deepest.depth, position, comm);
    for (unsigned int d = 0; d < dim; ++d)
      deepest.position[d] = position[d];
    deepest.pair          = std::lround(position[dim]);
    deepest.nearer_master = position[dim + 1] > 0.5;
    return deepest;
  }



  template <int dim>
  void
  ContactSetup<dim>::refuse_initial_overlap(const VectorType &u) const
  {
    refuse_unmatched_overlap(u);
    for (const std::string &text : pairs_without_rows)
      {
        AssertThrow(!parameters.refuse_pair_without_rows,
                    ExcMessage(text + " (Contact/Pair without rows = warn "
                                      "runs it anyway.)"));
        if (Utilities::MPI::this_mpi_process(comm) == 0)
          std::cout << "   warning: " << text << std::endl;
      }
  }



  template <int dim>
  void
  ContactSetup<dim>::refuse_unmatched_overlap(const VectorType &u) const
  {
    const Penetration deepest = unmatched_penetration(u);
    if (deepest.depth <= 0.)
      return;
    std::ostringstream where;
    for (unsigned int d = 0; d < dim; ++d)
      where << (d > 0 ? ", " : "") << deepest.position[d];
    const std::string pair = std::to_string(deepest.pair + 1);
    // (at t = 0 every slave node of the obstacle got a row, which refused
    // it inside: only a node that kept another pair's row and was not
    // projected, Initial penetration = project, can be)
    AssertThrow(deepest.pair < search_radii.size() ||
                  deepest.depth <= 1e-12 * (deepest.depth + 1.),
                ExcMessage("A body lies inside the rigid obstacle at t = 0 "
                           "(contact pair " +
                           pair + "): the slave node at (" + where.str() +
                           ") lies " + Utilities::to_string(deepest.depth) +
                           " m inside it, and kept the row of a master of "
                           "another pair, nearer in the reference "
                           "configuration, so that 'Contact/Initial "
                           "penetration = project' did not move it out. "
                           "Correct the mesh or the initial displacement."));
    if (deepest.pair >= search_radii.size() ||
        deepest.depth <= 1e-10 * search_radius(deepest.pair))
      return;
    const std::string node = "the slave node at (" + where.str() + ") lies " +
                             format_number(deepest.depth) + " m ";
    const std::string no_row =
      deepest.nearer_master ?
        std::string("It kept the row of a master of another pair, nearer in "
                    "the reference configuration, so that no row of this "
                    "pair could reject or project it.") :
        "It lies farther than the pair's search radius (" +
          format_number(search_radius(deepest.pair)) +
          " m: Contact/Search radius, or the pair's own) from the master "
          "surface, so that it got no row that could reject or project it.";
    // inside the master? (the scenes whose pairs can overlap start
    // undisplaced: the node's reference position is where it is at t = 0)
    std::set<types::material_id> masters;
    if (coarse_mesh)
      {
        const auto ids = boundary_ids_of_bodies(*coarse_mesh, n_bodies);
        for (unsigned int b = 0; b < n_bodies; ++b)
          if (has_any_of(
                ids[b],
                pair_sides[deepest.pair][1 - slave_sides[deepest.pair]]))
            masters.insert(b);
      }
    const std::optional<bool> inside =
      coarse_mesh ? inside_a_body(*coarse_mesh, deepest.position, masters) :
                    std::optional<bool>();
    AssertThrow(inside.value_or(true),
                ExcMessage(
                  "The master's contact tags of contact pair " + pair +
                  " name faces on its far side, which look away from the "
                  "slave: " +
                  node +
                  "behind the nearest master face (on the side its outward "
                  "normal points away from), but inside no body at t = 0. "
                  "Tag the faces of the master that meet the slave (its "
                  "contact tags, e.g. Scene/Gmsh/Contact tags)."));
    AssertThrow(!inside.has_value(),
                ExcMessage("The bodies overlap at t = 0 (contact pair " + pair +
                           "): the slave node at (" + where.str() +
                           ") lies inside the other body (" +
                           format_number(deepest.depth) +
                           " m behind the nearest face of the master "
                           "surface). " +
                           no_row +
                           " Correct the mesh or the initial displacement."));
    AssertThrow(false,
                ExcMessage(
                  "The bodies overlap at t = 0 (contact pair " + pair +
                  "): " + node + "inside the other body. " + no_row +
                  " (It lies behind the nearest master face, on the side "
                  "its outward normal points away from.) Correct the mesh "
                  "or the initial displacement; or, if the bodies do not "
                  "overlap, the master's contact tags name faces on its far "
                  "side, which look away from the slave: tag the faces "
                  "that meet."));
  }



  template <int dim>
  std::vector<MasterFace<dim>>
  ContactSetup<dim>::local_faces(
    const SemiDiscreteSystem<dim>         &system,
    const std::vector<types::boundary_id> &ids,
    const std::vector<types::boundary_id> &symmetry_ids) const
  {
    const auto                   sides            = face_sides<dim>();
    const auto                  &fe               = system.get_fe();
    const auto                  &mesh_constraints = system.get_constraints();
    std::vector<MasterFace<dim>> local;
    std::vector<types::global_dof_index> face_dofs(fe.n_dofs_per_face());
    for (const auto &cell : system.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              std::find(ids.begin(), ids.end(), cell->face(f)->boundary_id()) !=
                ids.end())
            {
              const auto      face = cell->face(f);
              MasterFace<dim> master;
              for (const unsigned int v : face->vertex_indices())
                master.vertices.push_back(face->vertex(v));
              master.cell_center         = cell->center();
              const unsigned int n_nodes = fe.n_dofs_per_face() / dim;
              master.node_dofs.resize(n_nodes);
              master.node_dof0.assign(n_nodes, numbers::invalid_dof_index);
              face->get_dof_indices(face_dofs);
              master.vertex_dofs.assign(face->n_vertices() * dim,
                                        numbers::invalid_dof_index);
              for (unsigned int i = 0; i < face_dofs.size(); ++i)
                {
                  const auto [c, node] = fe.face_system_to_component_index(i);
                  const auto dof       = face_dofs[i];
                  if (node < face->n_vertices())
                    master.vertex_dofs[node * dim + c] = dof;
                  auto &entries = master.node_dofs[node][c];
                  if (mesh_constraints.is_constrained(dof))
                    {
                      // hanging: its parents; Dirichlet: nothing (fixed)
                      for (const auto &entry :
                           *mesh_constraints.get_constraint_entries(dof))
                        entries.push_back(entry);
                    }
                  else
                    {
                      entries.emplace_back(dof, 1.);
                      if (c == 0)
                        master.node_dof0[node] = dof;
                    }
                }
              // a side shared with a face of the same cell on a plane of
              // symmetry lies on that plane
              for (const unsigned int f2 : cell->face_indices())
                if (f2 != f && cell->face(f2)->at_boundary() &&
                    std::find(symmetry_ids.begin(),
                              symmetry_ids.end(),
                              cell->face(f2)->boundary_id()) !=
                      symmetry_ids.end())
                  {
                    std::set<unsigned int> plane;
                    for (const unsigned int v :
                         cell->face(f2)->vertex_indices())
                      plane.insert(cell->face(f2)->vertex_index(v));
                    for (unsigned int s = 0; s < sides.size(); ++s)
                      if (plane.count(face->vertex_index(sides[s][0])) &&
                          plane.count(face->vertex_index(sides[s][1])))
                        master.on_symmetry_plane[s] = true;
                  }
              local.push_back(master);
            }
    return local;
  }

  template <int dim>
  void
  ContactSetup<dim>::keep_slave_sides()
  {
    kept_slave_sides = slave_sides;
  }



  template <int dim>
  void
  ContactSetup<dim>::save(std::map<std::string, std::string> &state) const
  {
    std::ostringstream s;
    for (const unsigned int side : kept_slave_sides)
      s << side << ' ';
    state["contact_slave_sides"] = s.str();
  }



  template <int dim>
  void
  ContactSetup<dim>::load(const std::map<std::string, std::string> &state)
  {
    const auto entry = state.find("contact_slave_sides");
    if (entry == state.end())
      return;
    kept_slave_sides.clear();
    std::istringstream s(entry->second);
    unsigned int       side;
    while (s >> side)
      {
        AssertThrow(side <= 1,
                    ExcMessage("Checkpointing/Resume: the checkpoint's "
                               "contact_slave_sides entry is damaged: '" +
                               entry->second + "'."));
        kept_slave_sides.push_back(side);
      }
    AssertThrow(s.eof(),
                ExcMessage("Checkpointing/Resume: the checkpoint's "
                           "contact_slave_sides entry is damaged: '" +
                           entry->second + "'."));
  }



  template class ContactSetup<2>;
  template class ContactSetup<3>;
} // namespace dyncontact
