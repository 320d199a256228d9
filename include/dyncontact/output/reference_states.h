#ifndef dyncontact_output_reference_states_h
#define dyncontact_output_reference_states_h

#include <dyncontact/core/simulator_access.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace dyncontact
{
  /**
   * Reference states (subsection "Reference solution"): a reference run
   * writes its mesh, u and udot at fixed times (write_state_file());
   * another run of the same coarse mesh, on the same mesh or a coarser one
   * (uniform or adapted, any polynomial degree, any number of ranks), reads
   * them at the same times and reports the error in the physical energy
   * norm ||(e, edot)||_E^2 = 1/2 ||edot||^2_{L2(rho)} + 1/2 a(e, e) (eqs.
   * 22-24, without the viscous time integral), integrated on the
   * reference's mesh (StateComparison).
   */
  template <int dim>
  class StateComparison;

  template <int dim>
  class ReferenceStates : public SimulatorAccess<dim>
  {
  public:
    ReferenceStates();
    ~ReferenceStates();

    /// The entries a run that neither writes nor compares states does not
    /// read.
    std::vector<std::pair<std::string, std::string>>
    unread_entries() const
    {
      if (write_states || compare_states)
        return {};
      const std::string why = "neither Write states nor Compare with states "
                              "is true";
      return {{"Reference solution/Directory", why},
              {"Reference solution/Interval", why}};
    }

    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

    /// Whether this run writes reference states.
    bool
    writes() const
    {
      return write_states;
    }

    /// Reference states need steps that reach their times (@p control
    /// stops there). Nothing if the run neither writes nor compares.
    void
    constrain(SimulationControl &control) const;

    /// Whether this run compares with reference states.
    bool
    compares() const
    {
      return compare_states;
    }

    /// Writes the current state if @p time is a reference time.
    void
    write(const double time) const;

    /// Whether this run compares with reference states and @p time is a
    /// reference time.
    bool
    at_reference_time(const double time) const
    {
      return compare_states && reference_index(time) >= 0;
    }

    /// The error against the reference state at @p time, NaN if @p time is
    /// no reference time.
    double
    error(const double time) const;

  private:
    /// The index of the reference time @p time, or -1.
    int
    reference_index(const double time) const;

    bool        write_states   = false;
    bool        compare_states = false;
    std::string directory      = "reference";
    double      interval       = 0.1;
    /// The comparison with states on other meshes (made at the first
    /// comparison: it holds a copy of the coarse mesh).
    mutable std::unique_ptr<StateComparison<dim>> comparison;
    /// A writer's flag that the mesh changed since it was last written
    /// (set by the triangulation's signal), and the file it was written to.
    mutable std::shared_ptr<bool> mesh_changed;
    mutable std::string           mesh_name, mesh_checksum;
    /// A comparing run's last mesh file whose checksum it checked.
    mutable std::string checked_mesh;
  };
} // namespace dyncontact

#endif
