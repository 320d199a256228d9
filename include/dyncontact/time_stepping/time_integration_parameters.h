#ifndef dyncontact_time_stepping_time_integration_parameters_h
#define dyncontact_time_stepping_time_integration_parameters_h

#include <string>

namespace dealii
{
  class ParameterHandler;
}

namespace dyncontact
{
  /**
   * The one owner of subsection 'Time integration' (as ASPECT's Parameters
   * own its global subsections): it declares and reads every entry, and the
   * components that use them are handed the values: the scheme to
   * TimeIntegrator::scheme_by_name(), Mass matrix to SemiDiscreteSystem,
   * Numerical dissipation to DiscreteProblem (and through it to the
   * integrator's StepOperators), End time, the time step and its control
   * to SimulationControl (which checks them).
   */
  struct TimeIntegrationParameters
  {
    /// Scheme: one of the names of schemes().
    std::string scheme = "N-CS++";
    /// Mass matrix = lumped (Gauss-Lobatto), else consistent or blended.
    bool lumped_mass = true;
    /// The consistent part beta of a mass that is not lumped: 1 for Mass
    /// matrix = consistent, Consistent mass fraction for blended.
    double consistent_mass_fraction = 1.;
    /// Mass matrix = blended.
    bool blended_mass = false;
    /// Numerical dissipation theta (dimensionless, 0: the paper's schemes).
    double numerical_dissipation = 0.;
    /// End time T, in s.
    double end_time = 2.5;
    /// Time step tau, in s.
    double time_step = 0.0125;
    /// Time step adaptation: retry a failed step with tau/2.
    bool time_step_adaptation = false;
    /// Time step control = adaptive.
    bool adaptive = false;
    /// Event location: onset and separation, every row or none.
    std::string event_location = "onset and separation";
    /// Minimum, Maximum time step (s; 0: the defaults), Time step tolerance.
    double minimum_time_step = 0.;
    double maximum_time_step = 0.;
    double tolerance         = 1e-2;

    static void
    declare_parameters(dealii::ParameterHandler &prm);

    void
    parse_parameters(dealii::ParameterHandler &prm);

    /// Throws if Consistent mass fraction is above 1 (a mass beyond the
    /// consistent one) with Polynomial degree @p degree other than 1, or
    /// with a mesh that adapts during the run (@p mesh_adapts) or Time
    /// step control = adaptive.
    void
    check_mass_fraction(const unsigned int degree,
                        const bool         mesh_adapts) const;
  };
} // namespace dyncontact

#endif
