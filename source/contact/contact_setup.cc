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
    moving_contact_nodes = false;
    rows_system          = &system;
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
    const auto obstacles = scene.obstacles();
    several_pairs        = pairs.size() + obstacles.size() > 1;
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
    // each obstacle a pair, numbered after the two-body pairs
    std::vector<types::global_dof_index> n_obstacle_rows;
    for (unsigned int k = 0; k < obstacles.size(); ++k)
      {
        const std::size_t before = rows.size();
        add_obstacle_rows(obstacles[k],
                          k + 1,
                          pairs.size() + k,
                          boundary_nodes(system,
                                         mapping,
                                         obstacles[k].boundary_ids),
                          w_ghosted,
                          system.get_constraints());
        n_obstacle_rows.push_back(
          Utilities::MPI::sum<types::global_dof_index>(rows.size() - before,
                                                       comm));
      }
    for (unsigned int pair_index = 0; pair_index < pairs.size(); ++pair_index)
      add_pair_rows(scene,
                    pairs[pair_index],
                    pair_index,
                    system,
                    mapping,
                    w_ghosted,
                    pcout);
    if (system.has_prescribed_motion())
      {
        // the linearised constraint would need a gap that moves with them
        bool moves = moving_contact_nodes;
        for (const auto &row : rows.rows)
          for (const auto &entry : row.entries)
            moves = moves ||
                    (entry.second != 0. && system.is_prescribed(entry.first));
        AssertThrow(!Utilities::MPI::logical_or(moves, comm),
                    ExcMessage("A contact surface shares nodes with a "
                               "boundary whose displacement is prescribed "
                               "and moves (Scene/Gmsh/Prescribed "
                               "displacements): a contact row would move "
                               "with it, which is not supported. Give the "
                               "contact surface and the moving boundary no "
                               "common node."));
      }
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
    if (several_pairs)
      for (unsigned int k = 0; k < obstacles.size(); ++k)
        {
          unsigned int n_kept = 0;
          for (const auto &row : rows.rows)
            n_kept += (row.pair == pairs.size() + k);
          n_kept = Utilities::MPI::sum(n_kept, comm);
          pcout << "   contact pair " << pairs.size() + k + 1 << ": slave body "
                << bodies_on(obstacles[k].boundary_ids) << " ("
                << n_obstacle_rows[k] << " nodes";
          if (n_kept < n_obstacle_rows[k])
            pcout << ", " << n_kept << " with obstacle rows, the others "
                  << "nearer to a master of another pair";
          pcout << "), master the rigid obstacle"
                << (obstacles.size() > 1 ? " " + std::to_string(k + 1) : "")
                << std::endl;
        }

    // the penetration check of the slave nodes without a row keeps this
    // rank's master faces, but only if there are such nodes
    n_unmatched_nodes =
      Utilities::MPI::sum<types::global_dof_index>(unmatched.size(), comm);
    rigid_obstacles = obstacles;
    n_unmatched_in_pair.assign(pairs.size() + obstacles.size(), 0);
    for (const auto &node : unmatched)
      ++n_unmatched_in_pair[node.pair];
    Utilities::MPI::sum(n_unmatched_in_pair, comm, n_unmatched_in_pair);
    if (n_unmatched_nodes == 0)
      master_surfaces.clear();

    // rigid obstacles that move: their rows' gaps at the current time
    rows.motions.clear();
    for (unsigned int k = 0; k < obstacles.size(); ++k)
      if (obstacles[k].motion != nullptr)
        {
          rows.motions.resize(pairs.size() + obstacles.size());
          const RigidObstacle<dim> obstacle = obstacles[k];
          auto                    &motion   = rows.motions[pairs.size() + k];
          motion.displacement               = [obstacle, k](const double t) {
            const Tensor<1, dim> d = obstacle.displacement(t, k + 1) -
                                     obstacle.displacement(0., k + 1);
            std::array<double, 3> shift{{0., 0., 0.}};
            for (unsigned int c = 0; c < dim; ++c)
              shift[c] = d[c];
            return shift;
          };
          motion.gap_and_normal = [obstacle, k](const std::array<double, 3> &x,
                                                const double t) {
            Point<dim> y;
            for (unsigned int c = 0; c < dim; ++c)
              y[c] = x[c];
            const auto [gap, n] =
              obstacle.gap_and_normal(y - obstacle.displacement(t, k + 1));
            std::array<double, 3> normal{{0., 0., 0.}};
            for (unsigned int c = 0; c < dim; ++c)
              normal[c] = n[c];
            return std::make_pair(gap, normal);
          };
        }
    set_obstacle_time(obstacle_time);

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
    // (a slave node that moves with prescribed data along the row's
    // normal: refused in setup(), whether it gets a row or not)
    if (rows_system != nullptr && rows_system->has_prescribed_motion())
      for (unsigned int d = 0; d < dim; ++d)
        if (std::abs(row.normal[d]) > 1e-12 &&
            rows_system->is_prescribed(row.entries[d].first))
          moving_contact_nodes = true;
    for (unsigned int d = 0; d < dim; ++d)
      row.free[d] = !constraints.is_constrained(row.entries[d].first);
    if (row.choose_eliminated())
      rows.rows.push_back(row);
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
              const auto face = cell->face(f);
              // a normal of the (flat) face
              Tensor<1, dim> face_normal;
              if constexpr (dim == 2)
                {
                  const Tensor<1, dim> t = face->vertex(1) - face->vertex(0);
                  face_normal[0]         = t[1];
                  face_normal[1]         = -t[0];
                }
              else
                face_normal =
                  cross_product_3d(face->vertex(3) - face->vertex(0),
                                   face->vertex(2) - face->vertex(1));
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
                  // (a node that moves with prescribed data along the
                  // face's normal: refused in setup())
                  if (system.has_prescribed_motion() &&
                      system.is_prescribed(dof) &&
                      std::abs(face_normal[c]) > 1e-12 * face_normal.norm())
                    moving_contact_nodes = true;
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
