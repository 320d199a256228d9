#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>
#include <deal.II/distributed/grid_refinement.h>
#include <deal.II/grid/grid_refinement.h>

#include <dyncontact/base/triangulation.h>
#include <dyncontact/mesh_refinement/cell_distance.h>
#include <dyncontact/mesh_refinement/mesh_adaptor.h>
#include <dyncontact/scenes/interface.h>
#include <dyncontact/time_stepping/simulation_control.h>

#include <cmath>
#include <iomanip>
#include <limits>
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
    prm.declare_entry(
      "Refinement interval without contact",
      "0",
      Patterns::Integer(0),
      "While no contact is near, the mesh adapts only after the steps that "
      "are multiples of this many steps, instead of every Refinement "
      "interval steps: at a step due by Refinement interval, the "
      "adaptation is skipped unless the step is such a multiple, or a "
      "slave node was in contact at the last step (the active sets of the "
      "displacement and of the L2 projection), or its gap closes and can "
      "come into the contact zone before the next step due by Refinement "
      "interval (the gap, less the distance that the node's normal "
      "velocity and a moving obstacle's own motion close in Refinement "
      "interval steps, is smaller than the gap and at most Contact "
      "zone/Distance or below two cell sizes at the node), so that the "
      "contact zone is marked at the same steps of an approach as without "
      "this entry. A node in the zone whose gap does not close, as after a "
      "release, does not count: its cells keep the refinement of the last "
      "adaptation. In "
      "a free flight no "
      "contact force acts, and with Keep body motion the transfers do not "
      "move the bodies: the mesh then resolves only the waves inside the "
      "bodies, which it follows less closely, and which a later contact "
      "meets (Front widening and Position tolerance still count with "
      "Refinement interval). A lasting or resting contact keeps every "
      "adaptation. A multiple of Refinement "
      "interval, or 0: Refinement "
      "interval always.");
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
    prm.declare_entry(
      "Front widening",
      "0",
      Patterns::Double(0., 100.),
      "Cells of level l within w c tau n max(1, Maximum level - l) of a "
      "cell the indicators refine are refined too, and none of them "
      "coarsened, where w is this value, c the fastest wave speed "
      "sqrt((lambda + 2 mu)/rho) of the bodies, tau the Time step (the "
      "Maximum time step with adaptive tau) and n the Refinement interval: "
      "w = 1 widens the refined zone by the distance a wave front travels "
      "until the next adaptation (times the levels a cell still has to "
      "climb, one per adaptation), so that the front stays inside it. "
      "Dimensionless, 0 to 100; 0: no widening.");
    prm.declare_entry(
      "Coarsening tolerance",
      "0",
      Patterns::Double(0., 1.),
      "The largest share of the energy (kinetic and elastic, J) that one "
      "adaptation's coarsening may remove: a family of cells flagged for "
      "coarsening is coarsened only if what the transfer to its parent "
      "removes (u and u_dot interpolated to the parent and prolongated "
      "back; its energy 1/2 ||v||^2_L2(rho) + 1/2 a(u, u)) is at most this "
      "value times the energy times the family's share of the bodies' "
      "volume, so that the energy of all that one adaptation's coarsening "
      "removes is at most this share of the energy (the energy itself may "
      "change by up to about 2 sqrt(value) times it, through the removed "
      "part's cross term with the rest: statistics column "
      "energy_transfer). Dimensionless, 0 to 1; 0: no limit. Statistics "
      "columns coarsening_refused (families) and coarsening_removed (J, the "
      "removed part's energy) when > 0.");
    prm.declare_entry(
      "Position tolerance",
      "0",
      Patterns::Double(0.),
      "The largest shift of a body's centre of mass at the end time T that "
      "the coarsening of the whole run may cause (m), estimated as in free "
      "flight: each family of cells flagged for coarsening shifts its body "
      "by (dq + (T - t) dp) / m_b, where dp and dq are the changes of the "
      "integrals of rho u_dot and rho u over the family (its cells against "
      "their parent after the transfer, on the parent's geometry: a curved "
      "boundary's coarsening changes the body's mass), m_b the body's mass "
      "and t the adaptation's time; where the vector sum of one "
      "adaptation's shifts of a body exceeds this value times the "
      "adaptation's share of the run (Refinement interval times the time "
      "step over T), the families of the largest shifts keep their cells "
      "until it does not. A wave that carries a body's motion then stays "
      "fine. The estimate leaves out the hanging nodes' constraints on the "
      "neighbours and the contact forces' response; a resume that changes "
      "End time is warned of. In m, 0 or more; 0: no "
      "limit. Statistics columns coarsening_refused (families refused by "
      "this or Coarsening tolerance) and coarsening_moved (m, the accepted "
      "shifts' sums over the bodies) when > 0.");
    prm.declare_entry(
      "Keep body motion",
      "false",
      Patterns::Bool(),
      "true: each transfer of the state to an adapted mesh adds to every "
      "body the rigid translations of u and u_dot that bring its centre of "
      "mass (the mass-weighted mean of u) and the mean of u_dot back to "
      "their values before the transfer, component by component, where no "
      "Dirichlet data hold the body's component: the transfer then changes "
      "neither a free body's position nor its momentum (the momentum "
      "exactly where the mass does not change: a curved boundary's "
      "refinement changes it), which an interpolation to coarser cells "
      "changes by what the removed waves carried; those kicks add up over "
      "a long flight. The strains are unchanged; a displacement shifted "
      "into the obstacle is projected back as after any transfer. false: "
      "the interpolation alone.");
    prm.declare_entry(
      "Error tolerance",
      "0",
      Patterns::Double(0., 1.),
      "Marking by a tolerance delta instead of the fractions: the "
      "estimated error energy of each cell K, eta_K = 1/2 rho h_K^2 "
      "k_K(u_dot)^2 + 1/2 (lambda + 2 mu) k_K(u)^2 (J; the criterion energy "
      "error; k_K: Zienkiewicz and Zhu's indicator, the estimate of the "
      "gradient's error on K), summed over the cells, S, is compared with "
      "delta^2 E (E: the kinetic and elastic energy, J): where S exceeds it, "
      "the cells below Maximum level of the largest eta_K are refined whose "
      "sum brings S to about half of delta^2 E (a refinement divides a "
      "cell's error energy by about 4^p), but for the cells of the smallest "
      "eta_K that sum to less than a quarter of delta^2 E (where the share "
      "reaches into them, for p = 1 whenever S > 1.25 delta^2 E, they are "
      "neither refined nor coarsened); every other cell is coarsened where "
      "the coarsening limit allows (Coarsening tolerance, or delta^2 / 4 "
      "without one), so that the estimated error in the energy norm "
      "relative to sqrt(E), "
      "sqrt(S / E), stays about delta. Refine fraction, Coarsen fraction "
      "and the indicators of Criteria are then not used (the contact "
      "zone's and the curved boundary's flags are). Dimensionless, 0 to 1; 0: the fractions. "
      "Statistics columns estimated_error (sqrt(S / E) at the adaptations, "
      "before they refine) and cells_above_tolerance (cells at Maximum "
      "level that the tolerance would refine without the level limit) when "
      "> 0.");
    prm.declare_entry(
      "Error tolerance split",
      "global",
      Patterns::Selection("global|by volume"),
      "How Error tolerance splits delta^2 E over the cells: global: the "
      "cells of the largest estimates are refined until their sum would be "
      "about half of it (Doerfler's marking: the fewest cells for the whole "
      "run's energy-norm error); by volume: every cell K whose estimate "
      "exceeds delta^2 E |K| / |bodies| is refined (the error's density "
      "kept below delta^2 E / |bodies| everywhere: it refines the contact "
      "zone's steep strains to Maximum level, where the contact force is "
      "decided).");
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
      "Refinement criteria, in the order they run (indicators of several "
      "criteria are added): " +
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
    interval = prm.get_integer("Refinement interval");
    interval_without_contact =
      prm.get_integer("Refinement interval without contact");
    min_level            = prm.get_integer("Minimum level");
    max_level            = prm.get_integer("Maximum level");
    refine_fraction      = prm.get_double("Refine fraction");
    coarsen_fraction     = prm.get_double("Coarsen fraction");
    initial_refinements  = prm.get_integer("Initial contact refinements");
    front_widening       = prm.get_double("Front widening");
    coarsening_tolerance = prm.get_double("Coarsening tolerance");
    error_tolerance      = prm.get_double("Error tolerance");
    position_tolerance   = prm.get_double("Position tolerance");
    keep_motion          = prm.get_bool("Keep body motion");
    split_by_volume      = prm.get("Error tolerance split") == "by volume";
    const auto selected  = Utilities::split_string_list(prm.get("Criteria"));
    // (the contact zone's Distance, which contact_near() reads with or
    // without the contact zone criterion)
    prm.enter_subsection("Contact zone");
    zone_distance = prm.get_double("Distance");
    prm.leave_subsection();
    prm.leave_subsection();
    AssertThrow(min_level <= max_level,
                ExcMessage("Mesh refinement/Minimum level (" +
                           std::to_string(min_level) +
                           ") must not exceed Mesh refinement/Maximum level (" +
                           std::to_string(max_level) + ")."));
    AssertThrow(error_tolerance == 0. || error_tolerance >= 1e-100,
                ExcMessage("Mesh refinement/Error tolerance must be 0 (the "
                           "fractions) or in [1e-100, 1] (its square must "
                           "not vanish)."));
    AssertThrow(refine_fraction + coarsen_fraction <= 1.,
                ExcMessage("Mesh refinement: Refine fraction + Coarsen "
                           "fraction must not exceed 1."));
    std::ostringstream widening; // 6 digits
    widening << front_widening;
    AssertThrow(front_widening == 0. || interval > 0,
                ExcMessage(
                  "Mesh refinement/Front widening = " + widening.str() +
                  " widens the refinement of a mesh that adapts "
                  "during the run: it needs Mesh "
                  "refinement/Refinement interval > 0 (got 0)."));
    AssertThrow(interval_without_contact == 0 || interval > 0,
                ExcMessage("Mesh refinement/Refinement interval without "
                           "contact = " +
                           std::to_string(interval_without_contact) +
                           " spaces the adaptations of a mesh that adapts "
                           "during the run: it needs Mesh "
                           "refinement/Refinement interval > 0 (got 0); or "
                           "set it to 0."));
    AssertThrow(interval_without_contact % std::max(interval, 1u) == 0,
                ExcMessage("Mesh refinement/Refinement interval without "
                           "contact must be 0 or a multiple of Mesh "
                           "refinement/Refinement interval (" +
                           std::to_string(interval) + "), got " +
                           std::to_string(interval_without_contact) + "."));
    AssertThrow(interval == 0 || !selected.empty(),
                ExcMessage("Mesh refinement/Criteria must name at least one "
                           "criterion when the mesh adapts."));

    // the criteria in the order of the list, each once
    criteria.clear();
    criterion_names.clear();
    for (const auto &name : selected)
      if (std::find(criterion_names.begin(), criterion_names.end(), name) ==
          criterion_names.end())
        {
          const auto *info =
            PluginRegistry<MeshRefinement::Interface>::find(name);
          Assert(info != nullptr, ExcInternalError()); // (the pattern)
          criteria.push_back(info->template create<dim>());
          criteria.back()->parse_parameters(prm);
          criterion_names.push_back(name);
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



  namespace
  {
    /**
     * Flags for refinement every active cell of level l that comes within
     * @p distance times max(1, @p max_level - l) of a cell flagged for
     * refinement, and clears the coarsen flags of those cells: a cell is
     * refined by one level per adaptation, so a cell k levels below the
     * maximum must be refined k adaptations before a front arrives. The
     * distances are MeshRefinement::distance_from_cells()'s, as far as the
     * coarsest cell's limit. Returns the widening of the coarsest cells and
     * the mesh's extent (the distance of its outermost cell centres).
     */
    template <int dim>
    std::pair<double, double>
    widen_refinement(Triangulation<dim> &triangulation,
                     const double        distance,
                     const unsigned int  max_level)
    {
      const MPI_Comm    comm = triangulation.get_communicator();
      std::vector<bool> flagged(triangulation.n_active_cells(), false);
      const auto        limit = [&](const int level) {
        return distance * std::max(1, int(max_level) - level);
      };
      int coarsest = int(max_level);
      // the largest x_d and -x_d of the cell centres
      std::vector<double> bounds(2 * dim, -std::numeric_limits<double>::max());
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            coarsest = std::min(coarsest, cell->level());
            for (unsigned int d = 0; d < dim; ++d)
              {
                bounds[d]       = std::max(bounds[d], cell->center()[d]);
                bounds[dim + d] = std::max(bounds[dim + d], -cell->center()[d]);
              }
            flagged[cell->active_cell_index()] = cell->refine_flag_set();
          }
      const double spread = limit(Utilities::MPI::min(coarsest, comm));
      const std::vector<double> reach =
        MeshRefinement::distance_from_cells(triangulation, flagged, spread);
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->is_locally_owned() &&
            reach[cell->active_cell_index()] <= limit(cell->level()))
          {
            cell->clear_coarsen_flag();
            cell->set_refine_flag();
          }
      Utilities::MPI::max(bounds, comm, bounds);
      double extent = 0.; // between the mesh's outermost cell centres
      for (unsigned int d = 0; d < dim; ++d)
        extent += Utilities::fixed_power<2>(bounds[d] + bounds[dim + d]);
      return {spread, std::sqrt(extent)};
    }


    /**
     * Flags the top @p refine_fraction and the bottom @p coarsen_fraction of
     * the cells of @p triangulation by @p indicators: on p4est's
     * triangulation with deal.II's function for it, on the serial one with
     * the same thresholds (deal.II's bisection between the smallest and the
     * largest indicator), so that both mark the same cells.
     */
    template <int dim>
    void
    refine_and_coarsen_fixed_number(Triangulation<dim>  &triangulation,
                                    const Vector<float> &indicators,
                                    const double         refine_fraction,
                                    const double         coarsen_fraction)
    {
      if (auto *distributed = as_distributed(triangulation))
        {
          parallel::distributed::GridRefinement::
            refine_and_coarsen_fixed_number(*distributed,
                                            indicators,
                                            refine_fraction,
                                            coarsen_fraction);
          return;
        }
      namespace Thresholds = internal::parallel::distributed::GridRefinement;
      const auto                      n_cells = triangulation.n_active_cells();
      const std::pair<double, double> fractions =
        GridRefinement::adjust_refine_and_coarsen_number_fraction<dim>(
          n_cells,
          std::numeric_limits<types::global_cell_index>::max(),
          refine_fraction,
          coarsen_fraction);
      const std::pair<double, double> min_max(
        Thresholds::compute_global_min_and_max_at_root(indicators,
                                                       MPI_COMM_SELF));
      const double top =
        Thresholds::RefineAndCoarsenFixedNumber::compute_threshold(
          indicators,
          min_max,
          static_cast<types::global_cell_index>(fractions.first * n_cells),
          MPI_COMM_SELF);
      const double bottom =
        fractions.second > 0 ?
          Thresholds::RefineAndCoarsenFixedNumber::compute_threshold(
            indicators,
            min_max,
            static_cast<types::global_cell_index>(
              std::ceil((1. - fractions.second) * n_cells)),
            MPI_COMM_SELF) :
          std::numeric_limits<float>::lowest();
      GridRefinement::refine(triangulation, indicators, top);
      GridRefinement::coarsen(triangulation, indicators, bottom);
    }
  } // namespace



  template <int dim>
  void
  MeshAdaptor<dim>::mark_cells(Triangulation<dim> &triangulation) const
  {
    // the state's energy and the bodies' volume, once for the tolerance
    // and the coarsening limit
    const bool                      limited = get_coarsening_tolerance() > 0.;
    const std::pair<double, double> energy =
      error_tolerance > 0. || limited ? energy_and_volume() :
                                        std::pair<double, double>(0., 0.);
    const bool moving = position_tolerance > 0.;
    // by the tolerance, or by the indicators of all criteria, each scaled
    // to maximum 1, added
    Vector<float> indicators(triangulation.n_active_cells());
    if (error_tolerance > 0.)
      tolerance_marked = mark_by_tolerance(triangulation, energy);
    else
      for (const auto &criterion : criteria)
        criterion->execute(indicators);
    if (error_tolerance == 0. &&
        Utilities::MPI::max(double(indicators.linfty_norm()),
                            this->get_mpi_communicator()) > 0.)
      {
        refine_and_coarsen_fixed_number(triangulation,
                                        indicators,
                                        refine_fraction,
                                        coarsen_fraction);
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
    const double distance = widening_distance();
    if (distance > 0.)
      {
        const auto [spread, extent] =
          widen_refinement(triangulation, distance, max_level);
        if (spread >= extent && !widening_warned)
          {
            widening_warned = true;
            this->get_pcout()
              << std::setprecision(3) << "   warning: Mesh refinement/Front "
              << "widening = " << front_widening << " widens a marked cell "
              << "by up to " << spread
              << " m on the coarsest cells (w c tau n (Maximum level - "
              << "level), with Maximum level = " << max_level
              << "), more than the mesh's extent of " << extent
              << " m: every adaptation refines the whole mesh by a level. "
                 "Set Maximum level to the finest level the run needs, or "
                 "lower Front widening."
              << std::endl;
          }
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
    coarsening_limited =
      limited || moving ? limit_coarsening(energy) : CoarseningLimit();
  }



  template <int dim>
  double
  MeshAdaptor<dim>::widening_distance() const
  {
    if (front_widening == 0. || interval == 0)
      return 0.;
    const auto &scene      = this->get_scene();
    double      wave_speed = 0.;
    for (unsigned int body = 0; body < scene.n_bodies(); ++body)
      {
        const Material &material = scene.material(body);
        wave_speed = std::max(wave_speed, material.p_wave_speed());
      }
    const SimulationControl &control = this->get_control();
    const double tau = control.is_adaptive() ? control.get_maximum_timestep() :
                                               control.get_timestep();
    return front_widening * wave_speed * tau * interval;
  }



  template <int dim>
  void
  MeshAdaptor<dim>::mark_contact_zone() const
  {
    contact_zone->tag_additional_cells();
  }



  template <int dim>
  const MeshRefinement::Interface<dim> *
  MeshAdaptor<dim>::curved_boundary() const
  {
    if (interval > 0 || initial_refinements > 0)
      for (unsigned int c = 0; c < criteria.size(); ++c)
        if (criterion_names[c] == "curved boundary")
          return criteria[c].get();
    return nullptr;
  }



  template class MeshAdaptor<2>;
  template class MeshAdaptor<3>;
} // namespace dyncontact
