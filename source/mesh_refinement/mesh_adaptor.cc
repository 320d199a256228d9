#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>
#include <deal.II/distributed/grid_refinement.h>

#include <dyncontact/mesh_refinement/mesh_adaptor.h>

#include <iomanip>
#include <sstream>

namespace dyncontact
{
  template class PluginRegistry<MeshRefinement::Interface>;



  void
  MeshRefinement::add_scaled(const Vector<float> &eta,
                             Vector<float>       &indicators,
                             const MPI_Comm       comm)
  {
    const double maximum = Utilities::MPI::max(double(eta.linfty_norm()), comm);
    if (maximum > 0.)
      indicators.add(1. / maximum, eta);
  }



  template <int dim>
  void
  MeshAdaptor<dim>::declare_parameters(ParameterHandler &prm)
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
    std::string documentation;
    for (const auto &info :
         PluginRegistry<MeshRefinement::Interface>::plugins())
      documentation += (documentation.empty() ? "" : "; ") + info.name + ": " +
                       info.description;
    prm.declare_entry(
      "Criteria",
      "kelly velocity, contact zone",
      Patterns::MultipleSelection(
        PluginRegistry<MeshRefinement::Interface>::names("|")),
      "Refinement criteria (indicators of several criteria are added): " +
        documentation + ".");
    prm.declare_entry("Initial contact refinements",
                      "0",
                      Patterns::Integer(0, 20),
                      "Refinements of the contact zone before t = 0.");
    prm.leave_subsection();
    PluginRegistry<MeshRefinement::Interface>::declare_parameters(prm);
  }



  template <int dim>
  void
  MeshAdaptor<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh refinement");
    interval            = prm.get_integer("Refinement interval");
    min_level           = prm.get_integer("Minimum level");
    max_level           = prm.get_integer("Maximum level");
    refine_fraction     = prm.get_double("Refine fraction");
    coarsen_fraction    = prm.get_double("Coarsen fraction");
    initial_refinements = prm.get_integer("Initial contact refinements");
    const auto selected = Utilities::split_string_list(prm.get("Criteria"));
    prm.leave_subsection();
    AssertThrow(min_level <= max_level,
                ExcMessage("Mesh refinement/Minimum level (" +
                           std::to_string(min_level) +
                           ") must not exceed Mesh refinement/Maximum level (" +
                           std::to_string(max_level) + ")."));
    AssertThrow(refine_fraction + coarsen_fraction <= 1.,
                ExcMessage("Mesh refinement: Refine fraction + Coarsen "
                           "fraction must not exceed 1."));
    AssertThrow(interval == 0 || !selected.empty(),
                ExcMessage("Mesh refinement/Criteria must name at least one "
                           "criterion when the mesh adapts."));

    // the criteria in their registered order
    criteria.clear();
    criterion_names.clear();
    for (const auto &info :
         PluginRegistry<MeshRefinement::Interface>::plugins())
      if (std::find(selected.begin(), selected.end(), info.name) !=
          selected.end())
        {
          criteria.push_back(info.template create<dim>());
          criteria.back()->parse_parameters(prm);
          criterion_names.push_back(info.name);
        }
    const auto *zone =
      PluginRegistry<MeshRefinement::Interface>::find("contact zone");
    Assert(zone != nullptr, ExcInternalError());
    contact_zone = zone->template create<dim>();
    contact_zone->parse_parameters(prm);
  }



  template <int dim>
  void
  MeshAdaptor<dim>::initialize_simulator(const Simulator<dim> &simulator)
  {
    SimulatorAccess<dim>::initialize_simulator(simulator);
    for (auto &criterion : criteria)
      criterion->initialize_simulator(simulator);
    contact_zone->initialize_simulator(simulator);
  }



  template <int dim>
  void
  MeshAdaptor<dim>::mark_cells(
    parallel::distributed::Triangulation<dim> &triangulation) const
  {
    // indicators of all criteria, each scaled to maximum 1, added
    Vector<float> indicators(triangulation.n_active_cells());
    for (const auto &criterion : criteria)
      criterion->execute(indicators);
    if (Utilities::MPI::max(double(indicators.linfty_norm()),
                            this->get_mpi_communicator()) > 0.)
      {
        parallel::distributed::GridRefinement::refine_and_coarsen_fixed_number(
          triangulation, indicators, refine_fraction, coarsen_fraction);
        // where every indicator is zero (a uniform field) there is nothing
        // to refine. When fewer cells than the refine fraction have
        // non-zero indicators, the fraction's threshold is zero and
        // deal.II's marking flags every such cell for refinement (and so
        // none for coarsening): those cells are left as they are. When
        // more have, such cells are the lowest and may be coarsened.
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned() &&
              indicators[cell->active_cell_index()] == 0.f)
            cell->clear_refine_flag();
      }
    for (const auto &criterion : criteria)
      criterion->tag_additional_cells();
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          if (cell->level() >= int(max_level))
            cell->clear_refine_flag();
          if (cell->level() <= int(min_level))
            cell->clear_coarsen_flag();
        }
  }



  template <int dim>
  void
  MeshAdaptor<dim>::mark_contact_zone() const
  {
    contact_zone->tag_additional_cells();
  }



  template class MeshAdaptor<2>;
  template class MeshAdaptor<3>;
} // namespace dyncontact
