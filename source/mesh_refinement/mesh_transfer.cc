#include <dyncontact/mesh_refinement/mesh_transfer.h>

#include <algorithm>
#include <iomanip>
#include <sstream>

namespace dyncontact
{
  void
  MeshTransfer::add(const double energy, const double transfer_penetration)
  {
    energy_change += energy;
    penetration = std::max(penetration, transfer_penetration);
  }



  void
  MeshTransfer::add_coarsening(const unsigned int refused,
                               const double       removed,
                               const double       moved)
  {
    coarsening_refused += refused;
    coarsening_removed += removed;
    coarsening_moved += moved;
  }



  void
  MeshTransfer::add_motion(const double momentum, const double displacement)
  {
    momentum_change     = std::max(momentum_change, momentum);
    displacement_change = std::max(displacement_change, displacement);
  }



  void
  MeshTransfer::add_estimate(const double estimate, const unsigned int above)
  {
    estimated_error       = std::max(estimated_error, estimate);
    cells_above_tolerance = std::max(cells_above_tolerance, above);
  }



  void
  MeshTransfer::save(std::map<std::string, std::string> &state) const
  {
    std::ostringstream s;
    s << std::setprecision(17) << energy_change << " " << penetration << " "
      << coarsening_refused << " " << coarsening_removed << " "
      << estimated_error << " " << cells_above_tolerance << " "
      << momentum_change << " " << displacement_change << " "
      << coarsening_moved;
    state["mesh_transfer"] = s.str();
  }



  void
  MeshTransfer::load(const std::map<std::string, std::string> &state)
  {
    std::istringstream s(state.at("mesh_transfer"));
    std::string        energy, transfer_penetration;
    s >> energy >> transfer_penetration;
    energy_change = std::stod(energy);
    penetration   = std::stod(transfer_penetration);
    // (checkpoints written before the coarsening tolerance have two values)
    unsigned int refused = 0;
    double       removed = 0.;
    if (s >> refused >> removed)
      {
        coarsening_refused = refused;
        coarsening_removed = removed;
      }
    // (and those written before the error tolerance four)
    double       estimate = 0.;
    unsigned int above    = 0;
    if (s >> estimate >> above)
      {
        estimated_error       = estimate;
        cells_above_tolerance = above;
      }
    // (and those written before the momentum's change six)
    double momentum = 0., displacement = 0.;
    if (s >> momentum >> displacement)
      {
        momentum_change     = momentum;
        displacement_change = displacement;
      }
    // (and those written before the position tolerance eight)
    double moved = 0.;
    if (s >> moved)
      coarsening_moved = moved;
  }
} // namespace dyncontact
