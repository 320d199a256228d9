#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>

#include <dyncontact/base/input_checks.h>
#include <dyncontact/scenes/material.h>

#include <cmath>
#include <sstream>

namespace dyncontact
{
  using namespace dealii;

  double
  Material::bar_wave_speed() const
  {
    return std::sqrt(youngs_modulus / density);
  }



  double
  Material::p_wave_speed() const
  {
    return std::sqrt((lambda() + 2. * mu()) / density);
  }


  void
  Material::declare_parameters(ParameterHandler  &prm,
                               const std::string &subsection)
  {
    prm.enter_subsection(subsection);
    prm.declare_entry("Young's modulus",
                      "1",
                      Patterns::Double(1e-12, 1e15),
                      "Young's modulus E of the body, in Pa, 1e-12 to 1e15.");
    prm.declare_entry("Poisson's ratio",
                      "0",
                      Patterns::Double(-1., 0.5),
                      "Poisson's ratio nu of the body, dimensionless, in "
                      "(-1, 0.5).");
    prm.declare_entry("Density",
                      "1",
                      Patterns::Double(1e-9, 1e6),
                      "Mass density rho, in kg/m^3, 1e-9 to 1e6.");
    prm.declare_entry(
      "Viscous shear modulus",
      "0",
      Patterns::Double(0., 1e18),
      "Kelvin-Voigt viscous shear modulus mu_v, in Pa s, 0 to 1e18. Together "
      "with the viscous Lame parameter it defines the viscous form b(u,v) = "
      "int 2 mu_v eps(u):eps(v) + lambda_v div u div v. Both zero: an "
      "elastic body, and no viscous matrix is assembled.");
    prm.declare_entry("Viscous Lame parameter",
                      "0",
                      Patterns::Double(-1e18, 1e18),
                      "Kelvin-Voigt viscous Lame parameter lambda_v, in Pa s, "
                      "-1e18 to 1e18 with lambda_v + 2/3 mu_v >= 0.");
    prm.leave_subsection();
  }

  void
  Material::parse_parameters(ParameterHandler  &prm,
                             const std::string &subsection)
  {
    prm.enter_subsection(subsection);
    youngs_modulus        = prm.get_double("Young's modulus");
    poissons_ratio        = prm.get_double("Poisson's ratio");
    density               = prm.get_double("Density");
    viscous_shear_modulus = prm.get_double("Viscous shear modulus");
    viscous_lambda        = prm.get_double("Viscous Lame parameter");
    prm.leave_subsection();

    check_in_range(
      youngs_modulus, 1e-12, 1e15, subsection + "/Young's modulus", "Pa");
    AssertThrow(std::isfinite(poissons_ratio) && poissons_ratio > -1. &&
                  poissons_ratio < 0.5,
                ExcMessage(subsection +
                           "/Poisson's ratio must lie in the open "
                           "interval (-1, 0.5); got " +
                           format_number(poissons_ratio) + "."));
    check_in_range(density, 1e-9, 1e6, subsection + "/Density", "kg/m^3");
    check_in_range(viscous_shear_modulus,
                   0.,
                   1e18,
                   subsection + "/Viscous shear modulus",
                   "Pa s");
    AssertThrow(std::abs(viscous_lambda) <= 1e18,
                ExcMessage(subsection +
                           "/Viscous Lame parameter must lie in [-1e18, "
                           "1e18] (Pa s); got " +
                           format_number(viscous_lambda) + "."));
    AssertThrow(std::isfinite(viscous_lambda) &&
                  viscous_lambda + 2. * viscous_shear_modulus / 3. >= 0.,
                ExcMessage(subsection +
                           "/Viscous Lame parameter must be finite "
                           "with lambda_v + 2/3 mu_v >= 0 (Pa s); got " +
                           format_number(viscous_lambda) + "."));
  }
} // namespace dyncontact
