#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_tools.h>

#include <dyncontact/base/memory_check.h>
#include <dyncontact/contact/contact_setup.h>
#include <dyncontact/discretization/rigid_motions.h>
#include <dyncontact/discretization/semi_discrete_system.h>
#include <dyncontact/problem/discrete_problem.h>
#include <dyncontact/scenes/interface.h>

#include <iomanip>
#include <sstream>

// DiscreteProblem: the checks that stop a run with a message (a singular
// static problem, a mesh too large for the memory) and the cause of a
// failed solve.

namespace dyncontact
{
  template <int dim>
  void
  DiscreteProblem<dim>::check_rigid_motions(const Scene<dim> &scene) const
  {
    std::vector<unsigned int> unheld =
      unheld_rigid_motions(*system, scene.n_bodies());
    // a body between two contacts (e.g. a ball between two blocks): a
    // single free motion is left to them
    std::vector<std::vector<types::boundary_id>> contacts;
    for (const ContactPair &pair : scene.contact_pairs())
      {
        contacts.push_back(pair.first_side);
        contacts.push_back(pair.second_side);
      }
    contacts.push_back(scene.contact_boundary_ids());
    const auto ids = boundary_ids_of_bodies(*triangulation, scene.n_bodies());
    for (unsigned int b = 0; b < unheld.size(); ++b)
      {
        unsigned int n_surfaces = 0;
        for (const auto &surface : contacts)
          n_surfaces += has_any_of(ids[b], surface);
        if (unheld[b] == 1 && n_surfaces >= 2)
          unheld[b] = 0;
      }
    std::string bodies;
    for (unsigned int b = 0; b < unheld.size(); ++b)
      if (unheld[b] > 0)
        bodies += (bodies.empty() ? "body " : ", body ") +
                  std::to_string(b + 1) + " (" + std::to_string(unheld[b]) +
                  (unheld[b] == 1 ? " rigid motion)" : " rigid motions)");
    AssertThrow(bodies.empty(),
                ExcMessage(
                  "The static problem is singular: nothing holds " + bodies +
                  ": no Dirichlet boundary fixes these rigid motions "
                  "(translations, rotations), and no load acts along them "
                  "(a single one along which the load acts, or of a body "
                  "with two contact surfaces, is left to the contact), so "
                  "the position is not determined. Clamp part "
                  "of the boundary (a Dirichlet boundary of the scene, e.g. "
                  "Scene/Gmsh/Dirichlet tags), give the body a load towards "
                  "the obstacle (e.g. Scene/Hertz/Load > 0), or use a "
                  "dynamic scheme."));
  }



  template <int dim>
  bool
  DiscreteProblem<dim>::check_flagged_mesh_fits_in_memory(
    const Scene<dim>  &scene,
    const std::string &remedy,
    const std::string &what) const
  {
    double refined = 0., coarsened = 0.;
    for (const auto &cell : triangulation->active_cell_iterators())
      if (cell->is_locally_owned())
        {
          refined += cell->refine_flag_set();
          coarsened += cell->coarsen_flag_set();
        }
    refined               = Utilities::MPI::sum(refined, comm);
    coarsened             = Utilities::MPI::sum(coarsened, comm);
    const double children = 1 << dim;
    const double n_cells  = triangulation->n_global_active_cells();
    const double growth   = (children - 1.) * (refined - coarsened / children);
    if (growth > 0.)
      check_mesh_fits_in_memory(n_cells + growth,
                                dim,
                                system->get_fe().degree,
                                scene.stores_step_matrix(),
                                scene.n_coarse_cells(),
                                remedy,
                                comm,
                                n_cells,
                                what);
    return refined + coarsened > 0.;
  }



  template <int dim>
  std::string
  DiscreteProblem<dim>::failure_cause(const double       tau,
                                      const std::string &failure) const
  {
    const double speed = udot.linfty_norm();
    const auto   box   = GridTools::compute_bounding_box(*triangulation);
    const double size  = box.get_boundary_points().first.distance(
      box.get_boundary_points().second);
    if (!(speed * tau > size))
      return failure;
    std::ostringstream text;
    text << std::setprecision(3) << "the velocities (up to " << speed
         << " m/s) move the bodies up to " << speed * tau
         << " m in one step of " << tau << " s, " << speed * tau / size
         << " times the size of the whole mesh (" << size
         << " m), so that no contact can be resolved: check the scene's "
            "initial velocities (and loads), or lower Time "
            "integration/Time step; more active-set iterations would not "
            "help ("
         << failure << ")";
    return text.str();
  }



  // (the class is instantiated in discrete_problem.cc)
#define DYNCONTACT_INSTANTIATE(dim)                                           \
  template void DiscreteProblem<dim>::check_rigid_motions(const Scene<dim> &) \
    const;                                                                    \
  template bool DiscreteProblem<dim>::check_flagged_mesh_fits_in_memory(      \
    const Scene<dim> &, const std::string &, const std::string &) const;      \
  template std::string DiscreteProblem<dim>::failure_cause(                   \
    const double, const std::string &) const;
  DYNCONTACT_INSTANTIATE(2)
  DYNCONTACT_INSTANTIATE(3)
#undef DYNCONTACT_INSTANTIATE
} // namespace dyncontact
