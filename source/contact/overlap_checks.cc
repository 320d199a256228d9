// ContactSetup: the checks for slave nodes without a row that pass into
// another body or the obstacle, at t = 0 and during the run (the set-up
// is in contact_setup.cc).

#include <deal.II/base/mpi.h>

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
    // nodes that kept the row of a master nearer than an obstacle (the
    // obstacles' pair indices follow the two-body pairs)
    for (unsigned int k = 0; k < rigid_obstacles.size(); ++k)
      if (n_unmatched_in_pair[search_radii.size() + k] > 0)
        for (const auto &node : unmatched)
          if (node.pair == search_radii.size() + k)
            {
              // (a moving obstacle where set_obstacle_time() put it)
              Point<dim> y =
                node.x - rigid_obstacles[k].displacement(obstacle_time, k + 1);
              for (unsigned int d = 0; d < dim; ++d)
                y[d] += ghosted(node.dofs[d]);
              const double depth = -rigid_obstacles[k].gap_and_normal(y).first;
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



  // (the class is instantiated in contact_setup.cc)
#define DYNCONTACT_INSTANTIATE(dim)                                           \
  template ContactSetup<dim>::Penetration                                     \
  ContactSetup<dim>::unmatched_penetration(const VectorType &) const;         \
  template void ContactSetup<dim>::refuse_initial_overlap(const VectorType &) \
    const;                                                                    \
  template void ContactSetup<dim>::refuse_unmatched_overlap(                  \
    const VectorType &) const;
  DYNCONTACT_INSTANTIATE(2)
  DYNCONTACT_INSTANTIATE(3)
#undef DYNCONTACT_INSTANTIATE
} // namespace dyncontact
