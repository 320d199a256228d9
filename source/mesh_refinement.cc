// The adaptive mesh during the dynamics: marking, state transfer, and the
// restoration of K_h after a transfer (Simulator<dim>::adapt_mesh and
// friends), and the parameters of subsection "Mesh refinement".

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>
#include <deal.II/distributed/grid_refinement.h>
#include <deal.II/distributed/solution_transfer.h>
#include <deal.II/numerics/error_estimator.h>

#include <dyncontact/mesh_refinement.h>
#include <dyncontact/simulator.h>

#include <cmath>
#include <set>

namespace dyncontact
{
  void
  MeshRefinementParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh refinement");
    prm.declare_entry("Refinement interval",
                      "0",
                      Patterns::Integer(0),
                      "Adapt the mesh every this many time steps; 0: never "
                      "(a fixed mesh).");
    prm.declare_entry("Minimum level",
                      "0",
                      Patterns::Integer(0, 20),
                      "Cells are not coarsened below this refinement level "
                      "(0 = the scene's coarse mesh).");
    prm.declare_entry("Maximum level",
                      "10",
                      Patterns::Integer(0, 20),
                      "Cells are not refined beyond this refinement level.");
    prm.declare_entry("Refine fraction",
                      "0.2",
                      Patterns::Double(0., 1.),
                      "Fraction of the cells with the largest indicators that "
                      "are refined at each adaptation, in [0, 1].");
    prm.declare_entry("Coarsen fraction",
                      "0.3",
                      Patterns::Double(0., 1.),
                      "Fraction of the cells with the smallest indicators "
                      "that are coarsened at each adaptation, in [0, 1].");
    prm.declare_entry("Criteria",
                      "kelly velocity, contact zone",
                      Patterns::MultipleSelection(
                        "kelly displacement|kelly velocity|contact zone"),
                      "Refinement criteria: the Kelly indicators of the "
                      "displacement and of the velocity (scaled to the same "
                      "maximum and added), and the contact zone (always "
                      "refined, on both bodies, up to the maximum level).");
    prm.declare_entry("Contact zone distance",
                      "0",
                      Patterns::Double(0.),
                      "A slave node is in the contact zone when its current "
                      "gap is below this distance, in m; 0: two cell sizes at "
                      "the node.");
    prm.declare_entry("Initial contact refinements",
                      "0",
                      Patterns::Integer(0, 20),
                      "Refinements of the contact zone before t = 0.");
    prm.leave_subsection();
  }



  void
  MeshRefinementParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh refinement");
    interval               = prm.get_integer("Refinement interval");
    min_level              = prm.get_integer("Minimum level");
    max_level              = prm.get_integer("Maximum level");
    refine_fraction        = prm.get_double("Refine fraction");
    coarsen_fraction       = prm.get_double("Coarsen fraction");
    const std::string crit = prm.get("Criteria");
    contact_distance       = prm.get_double("Contact zone distance");
    initial_refinements    = prm.get_integer("Initial contact refinements");
    prm.leave_subsection();
    kelly_displacement = crit.find("kelly displacement") != std::string::npos;
    kelly_velocity     = crit.find("kelly velocity") != std::string::npos;
    contact_zone       = crit.find("contact zone") != std::string::npos;
    AssertThrow(min_level <= max_level,
                ExcMessage("Mesh refinement/Minimum level (" +
                           std::to_string(min_level) +
                           ") must not exceed Mesh refinement/Maximum level (" +
                           std::to_string(max_level) + ")."));
    AssertThrow(refine_fraction + coarsen_fraction <= 1.,
                ExcMessage("Mesh refinement: Refine fraction + Coarsen "
                           "fraction must not exceed 1."));
    AssertThrow(interval == 0 || kelly_displacement || kelly_velocity ||
                  contact_zone,
                ExcMessage("Mesh refinement/Criteria must name at least one "
                           "criterion when the mesh adapts."));
  }



  template <int dim>
  void
  Simulator<dim>::mark_contact_zone(const VectorType &displacement)
  {
    // slave nodes whose current gap g_p - (C u)_p is small, and the master
    // nodes of their images: every cell at one of these nodes is marked
    std::set<types::global_dof_index> zone;
    const auto violation = row_evaluator->constraint_values(displacement);
    for (unsigned int p = 0; p < rows.size(); ++p)
      {
        const double size = std::pow(rows.rows[p].weight, 1. / (dim - 1));
        const double distance =
          std::max(parameters.refinement.contact_distance, 2. * size);
        if (-violation[p] < distance)
          {
            zone.insert(rows.rows[p].entries[0].first);
            for (const auto &[dof0, N] : rows.rows[p].master_nodes)
              zone.insert(dof0);
          }
      }
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(dofs);
          for (unsigned int node = 0; node < scalar_fe.n_dofs_per_cell();
               ++node)
            if (zone.count(dofs[fe.component_to_system_index(0, node)]))
              {
                cell->clear_coarsen_flag();
                if (cell->level() < int(parameters.refinement.max_level))
                  cell->set_refine_flag();
                break;
              }
        }
  }



  template <int dim>
  void
  Simulator<dim>::initial_refinement()
  {
    // before t = 0: refine the contact zone of the initial state
    for (unsigned int k = 0; k < parameters.refinement.initial_refinements; ++k)
      {
        set_initial_values();
        mark_contact_zone(u);
        triangulation.execute_coarsening_and_refinement();
        setup_system();
        assemble_system();
        make_contact_rows();
      }
  }



  template <int dim>
  void
  Simulator<dim>::adapt_mesh()
  {
    const MeshRefinementParameters &refinement    = parameters.refinement;
    const double                    energy_before = total_energy();

    VectorType u_ghosted(locally_owned, locally_relevant, comm);
    VectorType v_ghosted(locally_owned, locally_relevant, comm);
    u_ghosted = u;
    v_ghosted = udot;
    parallel::distributed::SolutionTransfer<dim, VectorType> transfer(
      dof_handler);
    {
      TimerOutput::Scope t(*timer, "mesh adaptation");

      // indicators: Kelly of u and/or udot, each scaled to maximum 1
      Vector<float> indicators(triangulation.n_active_cells());
      for (const auto &[use, vector] :
           {std::make_pair(refinement.kelly_displacement, &u_ghosted),
            std::make_pair(refinement.kelly_velocity, &v_ghosted)})
        if (use)
          {
            Vector<float> kelly(triangulation.n_active_cells());
            KellyErrorEstimator<dim>::estimate(mapping,
                                               dof_handler,
                                               QGauss<dim - 1>(fe.degree + 1),
                                               {},
                                               *vector,
                                               kelly);
            const double maximum =
              Utilities::MPI::max(double(kelly.linfty_norm()), comm);
            if (maximum > 0.)
              indicators.add(1. / maximum, kelly);
          }
      if (indicators.linfty_norm() > 0. ||
          Utilities::MPI::max(double(indicators.linfty_norm()), comm) > 0.)
        parallel::distributed::GridRefinement::refine_and_coarsen_fixed_number(
          triangulation,
          indicators,
          refinement.refine_fraction,
          refinement.coarsen_fraction);
      if (refinement.contact_zone)
        mark_contact_zone(u);
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            if (cell->level() >= int(refinement.max_level))
              cell->clear_refine_flag();
            if (cell->level() <= int(refinement.min_level))
              cell->clear_coarsen_flag();
          }

      // transfer u and udot to the new mesh (p4est repartitions it)
      triangulation.prepare_coarsening_and_refinement();
      transfer.prepare_for_coarsening_and_refinement(
        std::vector<const VectorType *>{&u_ghosted, &v_ghosted});
      triangulation.execute_coarsening_and_refinement();
    }

    // a new mesh: DoFs, constraints, matrices, contact rows, integrator
    setup_system();
    {
      TimerOutput::Scope        t(*timer, "mesh adaptation");
      std::vector<VectorType *> out = {&u, &udot};
      transfer.interpolate(out);
      mesh_constraints.distribute(u);
      mesh_constraints.distribute(udot);
    }
    assemble_system();
    make_contact_rows();
    make_integrator();

    // the transferred displacement may violate the new K_h (new nodes on a
    // curved surface, coarsened nodes): M-project it back and record by how
    // much it was violated
    TimerOutput::Scope t(*timer, "mesh adaptation");
    const auto         violation     = row_evaluator->constraint_values(u);
    double             max_violation = 0.;
    for (const double v : violation)
      max_violation = std::max(max_violation, v);
    double scale = 1.;
    for (const auto &row : rows.rows)
      scale = std::max(scale, std::abs(row.gap));
    if (max_violation > 1e-12 * scale)
      integrator->project_onto_constraints(u);
    transfer_penetration = std::max(transfer_penetration, max_violation);

    // the active set restarts from the transferred state: rows that touch
    std::vector<char> active(rows.size(), 0);
    const auto        after = row_evaluator->constraint_values(u);
    for (unsigned int p = 0; p < rows.size(); ++p)
      active[p] = (after[p] > -1e-10 * scale);
    integrator->warm_start(active);

    energy_transfer += total_energy() - energy_before;
  }



  template void
  Simulator<2>::mark_contact_zone(const VectorType &);
  template void
  Simulator<3>::mark_contact_zone(const VectorType &);
  template void
  Simulator<2>::initial_refinement();
  template void
  Simulator<3>::initial_refinement();
  template void
  Simulator<2>::adapt_mesh();
  template void
  Simulator<3>::adapt_mesh();
} // namespace dyncontact
