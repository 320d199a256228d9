#ifndef dyncontact_mesh_refinement_mesh_transfer_h
#define dyncontact_mesh_refinement_mesh_transfer_h

#include <map>
#include <string>

namespace dyncontact
{
  /**
   * What the transfers of the state to adapted meshes did since the last
   * statistics row: MeshAdaptor's record, which it adds to after each
   * adaptation and clears after each row; statistics read it through
   * SimulatorAccess::get_mesh_transfer().
   */
  struct MeshTransfer
  {
    /// Energy change of the transfers (J).
    double energy_change = 0.;
    /// Largest penetration of K_h they left before the projection (m).
    double penetration = 0.;
    /// Families of cells whose coarsening "Coarsening tolerance" or
    /// "Position tolerance" refused.
    unsigned int coarsening_refused = 0;
    /// Energy of what the accepted coarsening removed (J), in the norm
    /// 1/2 ||v||^2_{L2(rho)} + 1/2 a(u, u) of the difference.
    double coarsening_removed = 0.;
    /// With a "Position tolerance": the sum over the accepted families of
    /// the estimated shift of their body's centre of mass at the end time
    /// (m; CoarseningLimit::moved).
    double coarsening_moved = 0.;
    /// With an "Error tolerance": the largest estimated relative error
    /// sqrt(sum eta_K / E) at an adaptation (0: none since the last row).
    double       estimated_error       = 0.;
    unsigned int cells_above_tolerance = 0;
    /// The largest change of a body's momentum (the momentum columns'
    /// units) and of its mean displacement (m) in one transfer.
    double momentum_change     = 0.;
    double displacement_change = 0.;

    /// One transfer changed the energy by @p energy and left the
    /// penetration @p transfer_penetration.
    void
    add(const double energy, const double transfer_penetration);

    /// One adaptation's coarsening: @p refused families refused, @p removed
    /// J removed by the others, which shift their bodies by @p moved m.
    void
    add_coarsening(const unsigned int refused,
                   const double       removed,
                   const double       moved);

    /// One transfer changed a body's momentum by @p momentum and its mean
    /// displacement by @p displacement at most.
    void
    add_motion(const double momentum, const double displacement);

    /// One adaptation marked by the tolerance: the estimated relative error
    /// @p estimate, @p above cells to refine at Maximum level.
    void
    add_estimate(const double estimate, const unsigned int above);

    void
    save(std::map<std::string, std::string> &state) const;
    void
    load(const std::map<std::string, std::string> &state);
  };
} // namespace dyncontact

#endif
