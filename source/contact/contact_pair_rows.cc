// ContactSetup: the rows of one pair, of a body and the rigid obstacle or
// of two bodies through phi_h (the set-up and the checkpoints are in
// contact_setup.cc, the checks for overlaps without rows in
// overlap_checks.cc).

#include <deal.II/base/mpi.h>

#include <dyncontact/base/collective_errors.h>
#include <dyncontact/base/input_checks.h>
#include <dyncontact/contact/contact_setup.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

namespace dyncontact
{
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
  ContactSetup<dim>::add_obstacle_rows(
    const RigidObstacle<dim>        &obstacle,
    const unsigned int               obstacle_number,
    const unsigned int               pair_index,
    const std::vector<BoundaryNode> &nodes,
    const VectorType                &w_ghosted,
    const AffineConstraints<double> &constraints)
  {
    // a rigid obstacle: nu = -n, g of the closest point of its surface
    // (for a half-space (x - x0) . n), no master entries
    std::string          penetration;
    const std::size_t    n_rows_before = rows.size();
    const Tensor<1, dim> d0 = obstacle.displacement(0., obstacle_number);
    for (const BoundaryNode &node : nodes)
      {
        const Point<dim> &x = node.x;
        ContactRow        row;
        row.n_components = dim;
        row.pair         = pair_index;
        // (a moving obstacle: its surface at d(0), to which set_time()
        // adds the motion since)
        const auto [gap, normal] = obstacle.gap_and_normal(x - d0);
        for (unsigned int d = 0; d < dim; ++d)
          {
            row.entries.emplace_back(node.dofs[d], -normal[d]);
            row.normal[d]   = -normal[d];
            row.position[d] = x[d];
          }
        row.gap = gap;
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



  // (the class is instantiated in contact_setup.cc)
#define DYNCONTACT_INSTANTIATE(dim)                                            \
  template void ContactSetup<dim>::add_obstacle_rows(                          \
    const RigidObstacle<dim> &,                                                \
    const unsigned int,                                                        \
    const unsigned int,                                                        \
    const std::vector<ContactSetup<dim>::BoundaryNode> &,                      \
    const VectorType &,                                                        \
    const AffineConstraints<double> &);                                        \
  template std::string ContactSetup<dim>::pair_name(const unsigned int) const; \
  template void ContactSetup<dim>::add_pair_without_rows(const std::string &,  \
                                                         const std::string &,  \
                                                         const std::string &); \
  template unsigned int ContactSetup<dim>::finer_side(                         \
    const std::array<std::vector<MasterFace<dim>>, 2> &, const double) const;  \
  template void ContactSetup<dim>::add_pair_rows(                              \
    const Scene<dim> &,                                                        \
    const ContactPair &,                                                       \
    const unsigned int,                                                        \
    const SemiDiscreteSystem<dim> &,                                           \
    const Mapping<dim> &,                                                      \
    const VectorType &,                                                        \
    const ConditionalOStream &);
  DYNCONTACT_INSTANTIATE(2)
  DYNCONTACT_INSTANTIATE(3)
#undef DYNCONTACT_INSTANTIATE
} // namespace dyncontact
