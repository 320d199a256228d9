#ifndef dyncontact_mesh_refinement_mesh_transfer_h
#define dyncontact_mesh_refinement_mesh_transfer_h

#include <map>
#include <string>

namespace dyncontact
{
  /**
   * What the transfers of the state to adapted meshes did since the last
   * statistics row: an event the simulator publishes after each adaptation
   * and clears after each row; statistics read it through
   * SimulatorAccess::get_mesh_transfer().
   */
  struct MeshTransfer
  {
    /// Energy change of the transfers (J).
    double energy_change = 0.;
    /// Largest violation of K_h they left before the projection (m).
    double penetration = 0.;

    /// One transfer changed the energy by @p energy and left the violation
    /// @p violation.
    void
    add(const double energy, const double violation);

    void
    save(std::map<std::string, std::string> &state) const;
    void
    load(const std::map<std::string, std::string> &state);
  };
} // namespace dyncontact

#endif
