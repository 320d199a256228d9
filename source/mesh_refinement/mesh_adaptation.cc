// MeshAdaptor's execution of a mesh adaptation: the refinement of the
// initial contact zone and curved boundary, the adaptation after a step and
// its record, kept in checkpoints (the marking is in mesh_adaptor.cc).

#include <dyncontact/contact/contact_setup.h>
#include <dyncontact/mesh_refinement/mesh_adaptor.h>
#include <dyncontact/problem/discrete_problem.h>
#include <dyncontact/scenes/interface.h>
#include <dyncontact/time_stepping/simulation_control.h>

#include <algorithm>
#include <iomanip>
#include <sstream>
#include <string>

namespace dyncontact
{
  template <int dim>
  void
  MeshAdaptor<dim>::refine_initial_contact_zone(DiscreteProblem<dim> &problem,
                                                TimerOutput          &timer)
  {
    const Scene<dim> &scene = this->get_scene();
    // one round: tag() flags cells, and the mesh is refined where they fit
    // in memory; false where no cell was flagged (or they would not fit)
    const auto refine_round = [&](const auto &tag, const char *what) {
      tag();
      if (!problem.check_flagged_mesh_fits_in_memory(scene,
                                                     memory_remedy(true),
                                                     what))
        return false;
      problem.get_triangulation().execute_coarsening_and_refinement();
      problem.setup(scene, timer);
      return true;
    };
    for (unsigned int k = 0; k < initial_refinements; ++k)
      if (!refine_round(
            [&]() {
              // (the zone is of the initial state's gaps)
              problem.interpolate_initial_values(scene);
              mark_contact_zone();
            },
            "the mesh refined at the contact zone"))
        {
          // (nothing more would change)
          this->get_pcout()
            << "   warning: Mesh refinement/Initial contact refinements "
               "= "
            << initial_refinements << ": "
            << (k == 0 ?
                  std::string("no cell was refined") :
                  "only " + std::to_string(k) + " of them refined cells") +
                 ": no slave node is in the contact zone at t = 0 "
                 "(its gap at most Mesh refinement/Contact zone/Distance "
                 "or below two cell sizes), as at the start of an impact "
                 "across a gap, or its cells are at Mesh "
                 "refinement/Maximum level (now "
            << max_level << ")." << std::endl;
          break;
        }
    // then the curved boundary's cells to Maximum level, a level a round
    // (by the geometry alone: the state is interpolated at the start)
    if (const auto *curved = curved_boundary())
      for (unsigned int k = 0; k < max_level; ++k)
        if (!refine_round([&]() { curved->tag_additional_cells(); },
                          "the mesh refined at the curved boundary"))
          break; // (all at Maximum level)
  }



  template <int dim>
  void
  MeshAdaptor<dim>::save(std::map<std::string, std::string> &state) const
  {
    record.save(state);
    if (position_tolerance > 0.)
      {
        std::ostringstream s;
        s << std::setprecision(17) << this->get_control().get_end_time();
        state["position_tolerance_end_time"] = s.str();
      }
  }



  template <int dim>
  void
  MeshAdaptor<dim>::load(const std::map<std::string, std::string> &state)
  {
    record.load(state);
    const auto   saved = state.find("position_tolerance_end_time");
    const double end   = this->get_control().get_end_time();
    if (position_tolerance > 0. && saved != state.end() &&
        std::stod(saved->second) != end)
      this->get_pcout()
        << "   warning: Mesh refinement/Position tolerance: the run resumes "
           "with End time = "
        << end << " instead of " << std::stod(saved->second)
        << ": the coarsening before the checkpoint was limited for the "
           "shift at the earlier End time, and the tolerance does not bound "
           "the whole run's estimate."
        << std::endl;
  }



  template <int dim>
  bool
  MeshAdaptor<dim>::adapt(DiscreteProblem<dim> &problem,
                          const double          tau,
                          TimerOutput          &timer)
  {
    // (in a free flight, only every "Refinement interval without contact"
    // steps)
    if (interval_without_contact > interval &&
        this->get_control().get_step() % interval_without_contact != 0)
      {
        TimerOutput::Scope t(timer, "adaptation: test of a near contact");
        if (!contact_near(problem, tau))
          return false;
      }
    const auto adaptation = problem.adapt_mesh(
      this->get_scene(),
      [&]() { mark_cells(problem.get_triangulation()); },
      memory_remedy(false),
      tau,
      timer,
      keep_motion);
    record.add(adaptation.energy_change, adaptation.penetration);
    record.add_motion(adaptation.momentum_change,
                      adaptation.displacement_change);
    record.add_coarsening(coarsening_limited.refused,
                          coarsening_limited.removed,
                          coarsening_limited.moved);
    if (error_tolerance > 0.)
      record.add_estimate(tolerance_marked.first, tolerance_marked.second);
    return adaptation.changed;
  }



  template <int dim>
  bool
  MeshAdaptor<dim>::contact_near(const DiscreteProblem<dim> &problem,
                                 const double                tau) const
  {
    const ContactRows &rows   = problem.get_contact().get_rows();
    const auto        &report = problem.get_report();
    bool               near   = false;
    // (the report is the last step's, on these rows; none before the
    // first step)
    for (const std::vector<char> *active :
         {&report.active, &report.projection_active})
      if (active->size() == rows.size())
        near = near || std::any_of(active->begin(),
                                   active->end(),
                                   [](const char a) { return a != 0; });
    const MPI_Comm comm = this->get_mpi_communicator();
    if (Utilities::MPI::logical_or(near, comm))
      return true;
    // (the rows are this rank's; reading their entries is collective)
    const auto &row_operator = problem.get_contact().get_row_operator();
    const std::vector<double> violation =
      row_operator.constraint_values(problem.get_solution());
    const std::vector<double> normal_velocity =
      row_operator.apply(problem.get_velocity());
    // (until the next step due by Refinement interval, which asks again)
    const double flight = interval * tau;
    // a moving obstacle's own motion along the rows' normals until then,
    // which opens the gap (as in a step: ContactRows::normal_motion())
    const double              t = this->get_control().get_time();
    const std::vector<double> obstacle_motion =
      rows.obstacles_move() ? rows.normal_motion(t, t + flight) :
                              std::vector<double>(rows.size(), 0.);
    for (unsigned int p = 0; p < rows.size() && !near; ++p)
      {
        // how far the gap closes until then
        const double closes = flight * normal_velocity[p] - obstacle_motion[p];
        // a node whose gap does not close comes no nearer before that step
        // (a receding one after a release: its cells keep the zone's
        // refinement of the last adaptation, as nothing is adapted)
        if (closes > 0.)
          near = MeshRefinement::in_contact_zone<dim>(-violation[p] - closes,
                                                      zone_distance,
                                                      rows.rows[p].weight);
      }
    return Utilities::MPI::logical_or(near, comm);
  }



  // (the class is instantiated in mesh_adaptor.cc)
  template void
  MeshAdaptor<2>::refine_initial_contact_zone(DiscreteProblem<2> &,
                                              TimerOutput &);
  template void
  MeshAdaptor<3>::refine_initial_contact_zone(DiscreteProblem<3> &,
                                              TimerOutput &);
  template bool
  MeshAdaptor<2>::adapt(DiscreteProblem<2> &, const double, TimerOutput &);
  template bool
  MeshAdaptor<2>::contact_near(const DiscreteProblem<2> &, const double) const;
  template bool
  MeshAdaptor<3>::contact_near(const DiscreteProblem<3> &, const double) const;
  template bool
  MeshAdaptor<3>::adapt(DiscreteProblem<3> &, const double, TimerOutput &);
  template void
  MeshAdaptor<2>::save(std::map<std::string, std::string> &) const;
  template void
  MeshAdaptor<3>::save(std::map<std::string, std::string> &) const;
  template void
  MeshAdaptor<2>::load(const std::map<std::string, std::string> &);
  template void
  MeshAdaptor<3>::load(const std::map<std::string, std::string> &);
} // namespace dyncontact
