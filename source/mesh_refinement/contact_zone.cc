// The contact zone: the cells at slave nodes whose current gap g_p - (C u)_p
// is at most the contact-zone distance, and at the master nodes of their
// images, are refined (on both bodies, up to the maximum level) whatever
// the indicators say; the cells within the keep distance of those in
// contact are not coarsened.

#include <deal.II/base/parameter_handler.h>

#include <dyncontact/contact/contact_setup.h>
#include <dyncontact/discretization/semi_discrete_system.h>
#include <dyncontact/mesh_refinement/cell_distance.h>
#include <dyncontact/mesh_refinement/interface.h>
#include <dyncontact/mesh_refinement/mesh_adaptor.h>
#include <dyncontact/time_stepping/step_operators.h>

#include <algorithm>
#include <cmath>

namespace dyncontact
{
  namespace MeshRefinement
  {
    template <int dim>
    class ContactZone : public Interface<dim>
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.enter_subsection("Mesh refinement");
        prm.enter_subsection("Contact zone");
        prm.declare_entry("Distance",
                          "0",
                          Patterns::Double(0.),
                          "A slave node is in the contact zone when its "
                          "current gap is at most this distance (up to a "
                          "round-off of 1e-10 of it, so that a gap equal to "
                          "the distance is in) or below two cell sizes at "
                          "the node, in m; 0: two cell sizes.");
        prm.declare_entry(
          "Keep distance",
          "0",
          Patterns::Double(0.),
          "No cell within this distance of a cell at a node in contact "
          "(a slave node of the last step's active set, or a master node "
          "of its image) is coarsened, in m (the distance of the two "
          "cells' boxes along the line of their centres): the bodies near "
          "a lasting contact keep the cells that decide its force, where "
          "the coarsening's transfers would perturb it. 0 or more; 0: "
          "only the contact zone's own cells are kept.");
        prm.leave_subsection();
        prm.leave_subsection();
      }

      void
      parse_parameters(ParameterHandler &prm) override
      {
        prm.enter_subsection("Mesh refinement");
        prm.enter_subsection("Contact zone");
        distance      = prm.get_double("Distance");
        keep_distance = prm.get_double("Keep distance");
        prm.leave_subsection();
        prm.leave_subsection();
      }

      void
      tag_additional_cells() const override
      {
        // the zone as a nodal indicator: this rank marks its slave nodes
        // and the master nodes of their images (possibly owned elsewhere),
        // and every rank then reads it on its locally relevant DoFs
        const SemiDiscreteSystem<dim> &system = this->get_system();
        const MPI_Comm                 comm   = this->get_mpi_communicator();
        const ContactRows             &rows   = this->get_contact().get_rows();
        const auto &row_operator = this->get_contact().get_row_operator();
        // (and the nodes in contact, for the keep distance)
        VectorType marks, touching;
        marks.reinit(system.locally_owned_dofs(),
                     row_operator.ghost_set(),
                     comm,
                     true);
        if (keep_distance > 0.)
          touching.reinit(marks);
        const auto violation =
          row_operator.constraint_values(this->get_solution());
        const std::vector<char> &active = this->get_step_report().active;
        const auto mark = [&](VectorType &v, const unsigned int p) {
          v(rows.rows[p].entries[0].first) += 1.;
          for (const auto &[dof0, N] : rows.rows[p].master_nodes)
            v(dof0) += 1.;
        };
        for (unsigned int p = 0; p < rows.size(); ++p)
          {
            if (in_contact_zone<dim>(-violation[p],
                                     distance,
                                     rows.rows[p].weight))
              mark(marks, p);
            // (the report is the last step's, on these rows; none before
            // the first step)
            if (keep_distance > 0. && active.size() == rows.size() && active[p])
              mark(touching, p);
          }
        marks.compress(VectorOperation::add);
        VectorType zone(system.locally_owned_dofs(),
                        system.locally_relevant_dofs(),
                        comm);
        zone = marks;
        if (keep_distance > 0.)
          {
            touching.compress(VectorOperation::add);
            VectorType in_contact(zone);
            in_contact = touching;
            keep_near(in_contact);
          }

        const unsigned int max_level = this->get_mesh_adaptor().get_max_level();
        const std::vector<bool> in_zone = cells_at(zone);
        for (const auto &cell :
             system.get_dof_handler().active_cell_iterators())
          if (cell->is_locally_owned() && in_zone[cell->active_cell_index()])
            {
              cell->clear_coarsen_flag();
              if (cell->level() < int(max_level))
                cell->set_refine_flag();
            }
      }

    private:
      /// Whether each locally owned active cell (by its index) has a node
      /// where the ghosted nodal vector @p marks is > 0.
      std::vector<bool>
      cells_at(const VectorType &marks) const
      {
        const SemiDiscreteSystem<dim> &system = this->get_system();
        std::vector<bool>              at(
          system.get_dof_handler().get_triangulation().n_active_cells(), false);
        std::vector<types::global_dof_index> dofs(
          system.get_fe().n_dofs_per_cell());
        for (const auto &cell :
             system.get_dof_handler().active_cell_iterators())
          if (cell->is_locally_owned())
            {
              cell->get_dof_indices(dofs);
              for (const auto &node : system.get_node_system_indices())
                if (marks(dofs[node[0]]) > 0.)
                  {
                    at[cell->active_cell_index()] = true;
                    break;
                  }
            }
        return at;
      }

      /// Clears the coarsen flags of the cells within the keep distance of
      /// a cell with a node of @p in_contact (> 0).
      void
      keep_near(const VectorType &in_contact) const
      {
        const SemiDiscreteSystem<dim> &system = this->get_system();
        const auto                    &triangulation =
          system.get_dof_handler().get_triangulation();
        const std::vector<bool> seeds = cells_at(in_contact);
        const bool              any =
          std::find(seeds.begin(), seeds.end(), true) != seeds.end();
        if (!Utilities::MPI::logical_or(any, this->get_mpi_communicator()))
          return;
        const std::vector<double> reach =
          distance_from_cells(triangulation, seeds, keep_distance);
        for (const auto &cell :
             system.get_dof_handler().active_cell_iterators())
          if (cell->is_locally_owned() &&
              reach[cell->active_cell_index()] <= keep_distance)
            cell->clear_coarsen_flag();
      }

      double distance      = 0.;
      double keep_distance = 0.;
    };

    DYNCONTACT_REGISTER_REFINEMENT_CRITERION(ContactZone,
                                             "contact zone",
                                             "the cells near slave nodes "
                                             "close to contact and at their "
                                             "images, always refined")
  } // namespace MeshRefinement
} // namespace dyncontact
