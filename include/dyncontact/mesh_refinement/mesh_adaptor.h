#ifndef dyncontact_mesh_refinement_mesh_adaptor_h
#define dyncontact_mesh_refinement_mesh_adaptor_h

#include <dyncontact/core/simulator_access.h>
#include <dyncontact/mesh_refinement/interface.h>
#include <dyncontact/mesh_refinement/mesh_transfer.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace dyncontact
{
  template <int dim>
  class DiscreteProblem;

  /**
   * When and where the mesh adapts during the dynamics (subsection "Mesh
   * refinement"): every "Refinement interval" steps the cells are marked by
   * the chosen criteria (plugins: the indicators of all criteria are added,
   * the top fraction refined and the bottom fraction coarsened, then each
   * criterion flags the cells it insists on), within the level bounds.
   * With an "Error tolerance" delta > 0 the cells are marked by their
   * estimated errors against delta^2 E instead of the fractions
   * (mark_by_tolerance()).
   * With "Front widening" w > 0, every cell of level l within w c tau n
   * max(1, Maximum level - l) of a cell the indicators refine (c the
   * fastest wave speed of the bodies, n the interval) is refined too and
   * none of them coarsened: the distance a wave front travels until the
   * next adaptation, times the adaptations a cell needs to reach the
   * maximum level.
   * Before t = 0 the contact zone is refined "Initial contact refinements"
   * times.
   *
   * The one place of mesh adaptation: it marks the cells, has the
   * DiscreteProblem refine its mesh and transfer its state (adapt()), and
   * keeps the record of what the transfers did (MeshTransfer) until the
   * next statistics row.
   */
  template <int dim>
  class MeshAdaptor : public SimulatorAccess<dim>
  {
  public:
    /// Declares subsection "Mesh refinement" with every criterion's entries.
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

    void
    initialize_simulator(const Simulator<dim> &simulator) override;

    /// Whether the mesh changes at all (during the run or before t = 0).
    bool
    is_adaptive() const
    {
      return interval > 0 || initial_refinements > 0;
    }

    /// Whether the mesh adapts during the run.
    bool
    adapts_during_run() const
    {
      return interval > 0;
    }

    /// Refinement interval (steps; 0: the mesh does not adapt during the
    /// run), for SimulationControl, which decides the steps after which it
    /// adapts.
    unsigned int
    get_refinement_interval() const
    {
      return interval;
    }

    unsigned int
    n_initial_refinements() const
    {
      return initial_refinements;
    }

    unsigned int
    get_max_level() const
    {
      return max_level;
    }

    /// The limit on what one adaptation's coarsening removes, as a share
    /// of the energy: "Coarsening tolerance", or without it, with an "Error
    /// tolerance" delta, delta^2 / 4 (0: no limit).
    double
    get_coarsening_tolerance() const
    {
      return coarsening_tolerance > 0. ?
               coarsening_tolerance :
               0.25 * error_tolerance * error_tolerance;
    }

    /// "Position tolerance" (m; 0: no limit by the bodies' motion).
    double
    get_position_tolerance() const
    {
      return position_tolerance;
    }

    /// "Error tolerance" (0: the cells are marked by the fractions).
    double
    get_error_tolerance() const
    {
      return error_tolerance;
    }

    /// Whether the coarsening limit is the Error tolerance's delta^2 / 4
    /// (no Coarsening tolerance given).
    bool
    coarsening_limit_of_error_tolerance() const
    {
      return coarsening_tolerance == 0. && error_tolerance > 0.;
    }

    /// Whether "Error tolerance split" is by volume (else global).
    bool
    error_tolerance_split_by_volume() const
    {
      return split_by_volume;
    }

    /// Before t = 0: refines the contact zone of @p problem's initial
    /// state "Initial contact refinements" times (fewer, with a warning,
    /// where no cell is flagged), setting the problem up on each mesh.
    void
    refine_initial_contact_zone(DiscreteProblem<dim> &problem,
                                TimerOutput          &timer);

    /// After a step whose moments say so: marks the cells of @p problem's
    /// mesh, has it adapt its mesh (with an integrator for the step @p tau)
    /// and records what the transfer did. Returns whether the mesh changed.
    bool
    adapt(DiscreteProblem<dim> &problem, const double tau, TimerOutput &timer);

    /// What the transfers did since the last clear_record().
    const MeshTransfer &
    get_record() const
    {
      return record;
    }

    /// After each statistics row.
    void
    clear_record()
    {
      record = MeshTransfer();
    }

    /// The record, for a checkpoint; with a Position tolerance also the End
    /// time its estimates were made for (a resume to another End time is
    /// warned of).
    void
    save(std::map<std::string, std::string> &state) const;
    void
    load(const std::map<std::string, std::string> &state);

    /// Flags the cells of @p triangulation by the criteria (collective).
    void
    mark_cells(Triangulation<dim> &triangulation) const;

    /// Flags the cells of the contact zone of the current state (the
    /// refinement before t = 0).
    void
    mark_contact_zone() const;

    /// The criterion curved boundary if Criteria names it and the mesh
    /// adapts during the run or before it (Initial contact refinements);
    /// nullptr otherwise.
    const MeshRefinement::Interface<dim> *
    curved_boundary() const;

    /// The entries of subsection Mesh refinement that a run of the static
    /// problem (@p is_static) or with these settings does not read: (full
    /// name, why).
    std::vector<std::pair<std::string, std::string>>
    unread_entries(const bool is_static) const;

    /// The parameters that a refinement too large for the memory should
    /// reduce, with their values (for the message): of the refinements
    /// during the run, or of the @p initial contact refinements.
    std::string
    memory_remedy(const bool initial) const;

    /// The distance, in m, by which the refined zone is widened: "Front
    /// widening" times the distance the fastest wave, sqrt((lambda + 2 mu) /
    /// rho) of the stiffest body, travels in "Refinement interval" steps of
    /// the time step (the Maximum time step with adaptive tau); 0 without
    /// widening.
    double
    widening_distance() const;

  private:
    /// Whether a contact is near, over all ranks: a slave node of the last
    /// step's active sets (the displacement's or the L2 projection's), or
    /// one whose gap closes (by the node's normal velocity and a moving
    /// obstacle's own motion) and, less the distance it closes in
    /// "Refinement interval" steps of @p tau (until the next step that asks
    /// again), is in the contact zone (at most its Distance, or below two
    /// cell sizes at the node).
    bool
    contact_near(const DiscreteProblem<dim> &problem, const double tau) const;

    /// The kinetic and elastic energy of the state (J) and the bodies'
    /// volume, over all ranks.
    std::pair<double, double>
    energy_and_volume() const;

    /// What limit_coarsening() refused and let pass, over all ranks.
    struct CoarseningLimit
    {
      /// families refused
      unsigned int refused = 0;
      /// the energy of what the accepted families remove (J)
      double removed = 0.;
      /// the accepted families' estimated shifts of a body's centre of
      /// mass at the end time, summed (m)
      double moved = 0.;
    };

    /// Clears the coarsening flags of every family of cells whose
    /// coarsening would remove more than its share of
    /// get_coarsening_tolerance() times the energy (the family's share of the
    /// bodies' volume; @p energy: energy_and_volume()), or would shift its
    /// body's centre of mass at the end time by more than its share of
    /// "Position tolerance".
    CoarseningLimit
    limit_coarsening(const std::pair<double, double> &energy) const;

    /// With an "Error tolerance" delta: flags for refinement the cells of
    /// the largest estimated errors eta_K (J) that bring their sum S to
    /// about half of delta^2 E where S exceeds it, and every other cell for
    /// coarsening (limit_coarsening() decides which families are). Returns
    /// the estimated relative error sqrt(S / E) and the cells to refine
    /// that are at Maximum level, over all ranks (@p energy:
    /// energy_and_volume()).
    std::pair<double, unsigned int>
    mark_by_tolerance(Triangulation<dim>              &triangulation,
                      const std::pair<double, double> &energy) const;

    unsigned int interval = 0;
    /// "Refinement interval without contact" (0: interval always)
    unsigned int interval_without_contact = 0;
    /// Contact zone/Distance (m), for contact_near()
    double       zone_distance        = 0.;
    unsigned int min_level            = 0;
    unsigned int max_level            = 10;
    double       refine_fraction      = 0.2;
    double       coarsen_fraction     = 0.3;
    unsigned int initial_refinements  = 0;
    double       front_widening       = 0.;
    double       coarsening_tolerance = 0.;
    double       error_tolerance      = 0.;
    double       position_tolerance   = 0.;
    bool         keep_motion          = false;
    /// "Error tolerance split" = by volume (else global)
    bool split_by_volume = false;
    /// limit_coarsening()'s result of the last marking
    mutable CoarseningLimit coarsening_limited;
    /// mark_by_tolerance()'s result of the last marking
    mutable std::pair<double, unsigned int> tolerance_marked;
    /// whether the warning of a widening beyond the mesh was printed
    mutable bool             widening_warned = false;
    std::vector<std::string> criterion_names;

    std::vector<std::unique_ptr<MeshRefinement::Interface<dim>>> criteria;
    /// The contact-zone criterion of the refinement before t = 0.
    std::unique_ptr<MeshRefinement::Interface<dim>> contact_zone;
    /// get_record()
    MeshTransfer record;
  };
} // namespace dyncontact

#endif
