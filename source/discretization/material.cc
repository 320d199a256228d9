#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>

#include <dyncontact/discretization/material.h>

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


  void
  Material::declare_parameters(ParameterHandler  &prm,
                               const std::string &subsection)
  {
    prm.enter_subsection(subsection);
    prm.declare_entry("Young's modulus",
                      "1",
                      Patterns::Double(),
                      "Young's modulus E of the body, in Pa. Must be > 0.");
    prm.declare_entry("Poisson's ratio",
                      "0",
                      Patterns::Double(),
                      "Poisson's ratio nu of the body, dimensionless, in "
                      "(-1, 0.5).");
    prm.declare_entry("Density",
                      "1",
                      Patterns::Double(),
                      "Mass density rho, in kg/m^3. Must be > 0.");
    prm.declare_entry(
      "Viscous shear modulus",
      "0",
      Patterns::Double(),
      "Kelvin-Voigt viscous shear modulus mu_v, in Pa s (>= 0). Together "
      "with the viscous Lame parameter it defines the viscous form b(u,v) = "
      "int 2 mu_v eps(u):eps(v) + lambda_v div u div v. Both zero: an "
      "elastic body, and no viscous matrix is assembled.");
    prm.declare_entry("Viscous Lame parameter",
                      "0",
                      Patterns::Double(),
                      "Kelvin-Voigt viscous Lame parameter lambda_v, in Pa s "
                      "(>= 0).");
    prm.leave_subsection();
  }

  namespace
  {
    std::string
    number(const double x)
    {
      std::ostringstream s;
      s << x;
      return s.str();
    }
  } // namespace

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

    AssertThrow(std::isfinite(youngs_modulus) && youngs_modulus > 0.,
                ExcMessage(subsection +
                           "/Young's modulus must be a finite number > 0 "
                           "(Pa); got " +
                           number(youngs_modulus) + "."));
    AssertThrow(std::isfinite(poissons_ratio) && poissons_ratio > -1. &&
                  poissons_ratio < 0.5,
                ExcMessage(subsection +
                           "/Poisson's ratio must lie in the open "
                           "interval (-1, 0.5); got " +
                           number(poissons_ratio) + "."));
    AssertThrow(std::isfinite(density) && density > 0.,
                ExcMessage(subsection +
                           "/Density must be a finite number > 0 "
                           "(kg/m^3); got " +
                           number(density) + "."));
    AssertThrow(std::isfinite(viscous_shear_modulus) &&
                  viscous_shear_modulus >= 0.,
                ExcMessage(subsection +
                           "/Viscous shear modulus must be a finite "
                           "number >= 0 (Pa s); got " +
                           number(viscous_shear_modulus) + "."));
    AssertThrow(std::isfinite(viscous_lambda) &&
                  viscous_lambda + 2. * viscous_shear_modulus / 3. >= 0.,
                ExcMessage(subsection +
                           "/Viscous Lame parameter must be finite "
                           "with lambda_v + 2/3 mu_v >= 0 (Pa s); got " +
                           number(viscous_lambda) + "."));
  }
} // namespace dyncontact
