#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <dyncontact/base/input_checks.h>
#include <dyncontact/scenes/material.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <memory>
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


  bool
  Material::operator==(const Material &other) const
  {
    return youngs_modulus == other.youngs_modulus &&
           poissons_ratio == other.poissons_ratio && density == other.density &&
           viscous_shear_modulus == other.viscous_shear_modulus &&
           viscous_lambda == other.viscous_lambda;
  }



  namespace
  {
    /// The entries of a material: name, default, bounds of the pattern,
    /// documentation (the ranges are checked again by Material::check()).
    struct Entry
    {
      const char *name;
      const char *default_value;
      double      lower, upper;
      const char *documentation;
      double Material::*value;
    };

    const Entry entries[] = {
      {"Young's modulus",
       "1",
       1e-12,
       1e15,
       "Young's modulus E of the body, in Pa, 1e-12 to 1e15.",
       &Material::youngs_modulus},
      {"Poisson's ratio",
       "0",
       -1.,
       0.5,
       "Poisson's ratio nu of the body, dimensionless, in (-1, 0.5).",
       &Material::poissons_ratio},
      {"Density",
       "1",
       1e-9,
       1e6,
       "Mass density rho, in kg/m^3, 1e-9 to 1e6.",
       &Material::density},
      {"Viscous shear modulus",
       "0",
       0.,
       1e18,
       "Kelvin-Voigt viscous shear modulus mu_v, in Pa s, 0 to 1e18. "
       "Together with the viscous Lame parameter it defines the viscous "
       "form b(u,v) = int 2 mu_v eps(u):eps(v) + lambda_v div u div v. Both "
       "zero: an elastic body, and no viscous matrix is assembled.",
       &Material::viscous_shear_modulus},
      {"Viscous Lame parameter",
       "0",
       -1e18,
       1e18,
       "Kelvin-Voigt viscous Lame parameter lambda_v, in Pa s, -1e18 to "
       "1e18 with lambda_v + 2/3 mu_v >= 0.",
       &Material::viscous_lambda}};

    /// One number in [lower, upper], or a comma-separated list of them (the
    /// lengths are checked when read, against the number of bodies).
    class NumberList : public Patterns::PatternBase
    {
    public:
      NumberList(const double lower, const double upper)
        : lower(lower)
        , upper(upper)
      {}

      bool
      match(const std::string &text) const override
      {
        // (split_string_list() drops a last empty item: '1, 2,' would be
        // a list of two)
        const std::string trimmed = Utilities::trim(text);
        const auto        items   = Utilities::split_string_list(text);
        return !items.empty() && !trimmed.empty() && trimmed.back() != ',' &&
               std::all_of(
                 items.begin(), items.end(), [this](const std::string &item) {
                   char        *end   = nullptr;
                   const double value = std::strtod(item.c_str(), &end);
                   return !item.empty() && *end == '\0' &&
                          item.find_first_of("xX") == std::string::npos &&
                          std::isfinite(value) && value >= lower &&
                          value <= upper;
                 });
      }

      std::string
      description(const OutputStyle = Machine) const override
      {
        std::ostringstream text;
        text << "[a number in [" << lower << ", " << upper
             << "], or a comma-separated list of one per body]";
        return text.str();
      }

      std::unique_ptr<Patterns::PatternBase>
      clone() const override
      {
        return std::make_unique<NumberList>(lower, upper);
      }

    private:
      double lower, upper;
    };
  } // namespace



  void
  Material::declare_parameters(ParameterHandler  &prm,
                               const std::string &subsection,
                               const bool         lists)
  {
    prm.enter_subsection(subsection);
    for (const Entry &entry : entries)
      {
        const Patterns::Double value(entry.lower, entry.upper);
        if (lists)
          prm.declare_entry(entry.name,
                            entry.default_value,
                            NumberList(entry.lower, entry.upper),
                            std::string(entry.documentation) +
                              " One value for every body, or a "
                              "comma-separated list of one value per body "
                              "(in the order of the bodies).");
        else
          prm.declare_entry(entry.name,
                            entry.default_value,
                            value,
                            entry.documentation);
      }
    prm.leave_subsection();
  }



  void
  Material::parse_parameters(ParameterHandler  &prm,
                             const std::string &subsection)
  {
    prm.enter_subsection(subsection);
    for (const Entry &entry : entries)
      this->*entry.value = prm.get_double(entry.name);
    prm.leave_subsection();
    check(subsection);
  }



  std::vector<Material>
  Material::parse_per_body(ParameterHandler  &prm,
                           const unsigned int n_bodies,
                           const std::string &subsection)
  {
    std::vector<Material> materials(n_bodies);
    bool                  per_body = false;
    prm.enter_subsection(subsection);
    for (const Entry &entry : entries)
      {
        const std::string name  = subsection + "/" + entry.name;
        const std::string text  = prm.get(entry.name);
        const auto        items = Utilities::split_string_list(text);
        AssertThrow(items.size() == 1 || items.size() == n_bodies,
                    ExcMessage(name + " has " + std::to_string(items.size()) +
                               " values ('" + text +
                               "'): give one value (for every body) or one "
                               "per body (" +
                               std::to_string(n_bodies) + " bod" +
                               (n_bodies == 1 ? "y" : "ies") +
                               " in this scene)."));
        per_body = per_body || items.size() > 1;
        std::vector<double> values;
        for (const std::string &item : items)
          {
            char *end = nullptr;
            values.push_back(std::strtod(item.c_str(), &end));
            AssertThrow(!item.empty() && *end == '\0' &&
                          std::isfinite(values.back()),
                        ExcMessage(name + " must be a finite number" +
                                   (items.size() > 1 ?
                                      std::string(" for every body") :
                                      std::string()) +
                                   "; got '" + text + "'."));
          }
        for (unsigned int b = 0; b < n_bodies; ++b)
          materials[b].*entry.value = values[values.size() == 1 ? 0 : b];
      }
    prm.leave_subsection();
    for (unsigned int b = 0; b < n_bodies; ++b)
      materials[b].check(subsection,
                         per_body ? " of body " + std::to_string(b + 1) : "");
    if (!per_body)
      return {};
    return materials;
  }



  void
  Material::check(const std::string &subsection,
                  const std::string &of_body) const
  {
    check_in_range(youngs_modulus,
                   1e-12,
                   1e15,
                   subsection + "/Young's modulus" + of_body,
                   "Pa");
    AssertThrow(std::isfinite(poissons_ratio) && poissons_ratio > -1. &&
                  poissons_ratio < 0.5,
                ExcMessage(subsection + "/Poisson's ratio" + of_body +
                           " must lie in the open "
                           "interval (-1, 0.5); got " +
                           format_number(poissons_ratio) + "."));
    check_in_range(
      density, 1e-9, 1e6, subsection + "/Density" + of_body, "kg/m^3");
    check_in_range(viscous_shear_modulus,
                   0.,
                   1e18,
                   subsection + "/Viscous shear modulus" + of_body,
                   "Pa s");
    AssertThrow(std::abs(viscous_lambda) <= 1e18,
                ExcMessage(subsection + "/Viscous Lame parameter" + of_body +
                           " must lie in [-1e18, "
                           "1e18] (Pa s); got " +
                           format_number(viscous_lambda) + "."));
    AssertThrow(std::isfinite(viscous_lambda) &&
                  viscous_lambda + 2. * viscous_shear_modulus / 3. >= 0.,
                ExcMessage(subsection + "/Viscous Lame parameter" + of_body +
                           " must be finite "
                           "with lambda_v + 2/3 mu_v >= 0 (Pa s); got " +
                           format_number(viscous_lambda) + "."));
  }
} // namespace dyncontact
