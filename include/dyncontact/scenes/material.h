#ifndef dyncontact_scenes_material_h
#define dyncontact_scenes_material_h

#include <string>
#include <vector>

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


    bool
    operator==(const Material &other) const;

    /// Declares the subsection (by default "Material") with its entries;
    /// with @p lists each entry takes one value or a comma-separated list
    /// of one value per body (as ASPECT's lists per compositional field).
    static void
    declare_parameters(dealii::ParameterHandler &prm,
                       const std::string        &subsection = "Material",
                       const bool                lists      = false);

    /// Reads the subsection (each entry one value) and checks every value's
    /// range.
    void
    parse_parameters(dealii::ParameterHandler &prm,
                     const std::string        &subsection = "Material");

    /// The materials of @p n_bodies bodies from the lists of @p subsection
    /// (declared with lists): an entry of one value holds for every body, an
    /// entry of @p n_bodies values gives body k its k-th; another length, a
    /// value that is not a number or out of its range stops with a message
    /// naming the entry (and the body). Empty if every entry has one value
    /// (the scene then says which subsection each body reads).
    static std::vector<Material>
    parse_per_body(dealii::ParameterHandler &prm,
                   const unsigned int        n_bodies,
                   const std::string        &subsection = "Material");

  private:
    /// Stops with a message naming the entry of @p subsection (and @p
    /// of_body, e.g. " of body 3") if a value is out of its range.
    void
    check(const std::string &subsection, const std::string &of_body = "") const;
  };
} // namespace dyncontact

#endif
