#include <deal.II/base/parameter_handler.h>

#include <dyncontact/time_stepping/integrators.h>
#include <dyncontact/time_stepping/time_integration_parameters.h>

namespace dyncontact
{
  void
  TimeIntegrationParameters::declare_parameters(ParameterHandler &prm)
  {
    std::string names, documentation;
    for (const Scheme &scheme : schemes())
      {
        names += (names.empty() ? "" : "|") + scheme.name;
        documentation += (documentation.empty() ? "" : ", ") + scheme.name +
                         " (" + scheme.description + ")";
      }
    prm.enter_subsection("Time integration");
    prm.declare_entry("Scheme",
                      "N-CS++",
                      Patterns::Selection(names),
                      "Time integrator: " + documentation + ".");
    prm.declare_entry("Mass matrix",
                      "lumped",
                      Patterns::Selection("lumped|consistent|blended"),
                      "lumped: diagonal, by Gauss-Lobatto (nodal) quadrature; "
                      "consistent: by Gauss quadrature; blended: cell by "
                      "cell (1 - beta) times the lumped plus beta times the "
                      "consistent element matrix, beta = Consistent mass "
                      "fraction (a sparse matrix like the consistent one).");
    prm.declare_entry(
      "Consistent mass fraction",
      "0.75",
      Patterns::Double(0., 1.5),
      "beta (dimensionless, 0 to 1, and for Polynomial degree = 1 below "
      "1.5) of Mass matrix = blended. The lumped mass with the trapezoidal "
      "rule propagates short waves too slowly, the consistent mass too "
      "fast; for linear elements beta = 1/2 + (c tau / h)^2 cancels the "
      "leading term of the phase error of a wave of speed c along cells "
      "of size h (c tau / h = 1/2: 0.75, the default; 1/sqrt(2): 1, the "
      "consistent mass), and the error left shrinks like 1 - (c tau / "
      "h)^4, to none at c tau / h = 1. Above 1 (c tau / h above "
      "1/sqrt(2); linear elements only) the mass is beyond the consistent "
      "one: in 1D the same formula, in 2D and 3D its tensor product, by "
      "a two-point rule at 1/2 -+ sqrt(1 - 2 beta / 3) / 2 along each "
      "axis, and nearly singular near 1.5. Behind a moving velocity jump "
      "(an impact) the energy-norm error falls like h^0.4 with 0.75 "
      "instead of h^0.33 (lumped), and about as fast with c tau / h = 0.98, "
      "beta = 1.4604, with half the steps and a third of the CG iterations "
      "(doc/results.md); above 1 only on a fixed mesh with a fixed time "
      "step. c is the speed of the "
      "waves that matter, e.g. sqrt((lambda + 2 mu) / rho) for pressure "
      "waves. Not used by the other Mass matrix choices.");
    prm.declare_entry(
      "Numerical dissipation",
      "0",
      Patterns::Double(0., 0.5),
      "theta (dimensionless, 0 to 0.5): the displacement step of every "
      "dynamic scheme applies the stiffness A to (1/2 + theta) u^{n+1} + "
      "(1/2 - theta) u^n instead of the mean of the two, i.e. S = M + "
      "(1/4 + theta/2) tau^2 A + tau/2 B. Each step then dissipates "
      "theta (du)^T A (du) (column dissipation_numerical, in J), the most "
      "in the highest frequencies: a mode of angular frequency omega is "
      "damped with the ratio theta omega tau / 2 where omega tau << 1. "
      "Theorem 3.2 and the contact stabilisation hold as for theta = 0 "
      "(doc/algorithms.md); the scheme is of first order in tau for "
      "theta > 0. 0: the paper's schemes. Must be 0 with the static "
      "scheme, which has no time steps to dissipate in.");
    prm.declare_entry("End time",
                      "2.5",
                      Patterns::Double(0.),
                      "Final time T, in s (>= 0). If T is not a multiple of "
                      "tau, the last step ends after T. The static scheme "
                      "has no time (its solution is at t = 1, the load "
                      "factor) but takes loads, prescribed displacements and "
                      "obstacle motions that are functions of t at T.");
    prm.declare_entry("Time step",
                      "0.0125",
                      Patterns::Double(0.),
                      "Time step tau, in s (> 0).");
    prm.declare_entry("Time step adaptation",
                      "false",
                      Patterns::Bool(),
                      "If a step's active-set iteration fails, retry it with "
                      "half the time step (and keep that), down to Time step "
                      "/ 1024; otherwise the run stops with a message.");
    prm.declare_entry(
      "Time step control",
      "fixed",
      Patterns::Selection("fixed|adaptive"),
      "fixed: every step takes Time step. adaptive: tau moves between the "
      "levels Time step * 2^k inside [Minimum time step, Maximum time "
      "step]: a step whose error estimate (see doc/running.md) exceeds "
      "Time step tolerance is repeated with tau/2, tau doubles after two "
      "steps below 1/8 of it; a step that would bring a contact row into "
      "contact (or release one) is shortened to end at the predicted "
      "moment of that event; steps also end at the output and reference "
      "times (see Output/Output interval) and at End time. Not used "
      "by the static scheme.");
    prm.declare_entry(
      "Event location",
      "onset and separation",
      Patterns::Selection("onset and separation|every row|none"),
      "Adaptive control: which contact events end a step at their "
      "predicted moment. onset and separation: the first row to come into "
      "contact when none is active, and the release when no row stays "
      "active; every row: each row that comes into contact or is released "
      "(in a contact zone that grows node by node nearly every step is "
      "shortened, each with its own step matrix); none.");
    prm.declare_entry("Minimum time step",
                      "0",
                      Patterns::Double(0.),
                      "Smallest tau of the adaptive control, in s (> 0 and "
                      "<= Time step; 0 means Time step / 64).");
    prm.declare_entry("Maximum time step",
                      "0",
                      Patterns::Double(0.),
                      "Largest tau of the adaptive control, in s (>= Time "
                      "step; 0 means Time step).");
    prm.declare_entry("Time step tolerance",
                      "0.01",
                      Patterns::Double(0.),
                      "Adaptive control: the largest error estimate of a "
                      "step that is accepted, relative to the velocity "
                      "scale sqrt(2 E) (dimensionless, > 0).");
    prm.leave_subsection();
  }



  void
  TimeIntegrationParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Time integration");
    scheme       = prm.get("Scheme");
    lumped_mass  = (prm.get("Mass matrix") == "lumped");
    blended_mass = (prm.get("Mass matrix") == "blended");
    consistent_mass_fraction =
      blended_mass ? prm.get_double("Consistent mass fraction") : 1.;
    AssertThrow(consistent_mass_fraction < 1.5,
                ExcMessage("Time integration/Consistent mass fraction = 1.5 "
                           "makes the mass matrix singular; the range is 0 "
                           "to 1, and below 1.5 for Polynomial degree = 1."));
    numerical_dissipation = prm.get_double("Numerical dissipation");
    end_time              = prm.get_double("End time");
    time_step             = prm.get_double("Time step");
    time_step_adaptation  = prm.get_bool("Time step adaptation");
    adaptive              = (prm.get("Time step control") == "adaptive");
    event_location        = prm.get("Event location");
    minimum_time_step     = prm.get_double("Minimum time step");
    maximum_time_step     = prm.get_double("Maximum time step");
    tolerance             = prm.get_double("Time step tolerance");
    prm.leave_subsection();
  }



  void
  TimeIntegrationParameters::check_mass_fraction(const unsigned int degree,
                                                 const bool mesh_adapts) const
  {
    if (consistent_mass_fraction <= 1.)
      return;
    AssertThrow(degree == 1,
                ExcMessage("Time integration/Consistent mass fraction above "
                           "1 (a mass beyond the consistent one, by a "
                           "two-point rule per axis) is for Polynomial "
                           "degree = 1 only; the range is 0 to 1 for "
                           "Polynomial degree = " +
                           std::to_string(degree) + "."));
    // beta = 1/2 + (c tau/h)^2 holds for one tau and one h: the two-point
    // rule under-integrates |v|^2, so that a refinement adds kinetic
    // energy, and a shorter step sees a mass far from its formula
    AssertThrow(!mesh_adapts && !adaptive,
                ExcMessage("Time integration/Consistent mass fraction above "
                           "1 (a mass beyond the consistent one) is for a "
                           "fixed mesh and a fixed time step: its fraction "
                           "1/2 + (c tau/h)^2 holds for one tau and one h, "
                           "and a refinement adds kinetic energy. Take "
                           "Mesh refinement/Refinement interval = 0 and Time "
                           "step control = fixed, or a fraction of at most "
                           "1."));
  }
} // namespace dyncontact
