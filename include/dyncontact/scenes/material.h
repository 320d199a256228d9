#ifndef dyncontact_scenes_material_h
#define dyncontact_scenes_material_h

#include <string>

namespace dealii
{
  class ParameterHandler;
}

namespace dyncontact
{
  /**
   * A linear Kelvin-Voigt material: elastic Lame moduli (from Young's
   * modulus and Poisson's ratio), density, and viscous moduli (mu_v,
   * lambda_v) of the viscous form b(u,v) = int 2 mu_v eps(u):eps(v) +
   * lambda_v div u div v. Both viscous moduli zero means an elastic body:
   * then no viscous matrix is assembled.
   */
  struct Material
  {
    double youngs_modulus        = 1.0;
    double poissons_ratio        = 0.0;
    double density               = 1.0;
    double viscous_shear_modulus = 0.0;
    double viscous_lambda        = 0.0;

    double
    mu() const
    {
      return youngs_modulus / (2.0 * (1.0 + poissons_ratio));
    }

    double
    lambda() const
    {
      return youngs_modulus * poissons_ratio /
             ((1.0 + poissons_ratio) * (1.0 - 2.0 * poissons_ratio));
    }

    bool
    is_viscous() const
    {
      return viscous_shear_modulus != 0.0 || viscous_lambda != 0.0;
    }

    /// Speed of longitudinal waves in a thin bar, sqrt(E/rho), in m/s.
    double
    bar_wave_speed() const;

    /// Speed of pressure waves, sqrt((lambda + 2 mu)/rho), in m/s.
    double
    p_wave_speed() const;


    /// Declares the subsection (by default "Material") with its entries.
    static void
    declare_parameters(dealii::ParameterHandler &prm,
                       const std::string        &subsection = "Material");

    /// Reads the subsection and checks every value's range.
    void
    parse_parameters(dealii::ParameterHandler &prm,
                     const std::string        &subsection = "Material");
  };
} // namespace dyncontact

#endif
