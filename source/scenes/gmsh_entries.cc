#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <dyncontact/base/input_checks.h>
#include <dyncontact/scenes/gmsh_entries.h>

#include <cmath>
#include <cstdlib>
#include <sstream>

namespace dyncontact
{
  namespace GmshEntries
  {
    using namespace dealii;

    std::set<unsigned int>
    parse_tags(const std::string &text, const std::string &entry)
    {
      std::set<unsigned int> tags;
      for (const auto &item : Utilities::split_string_list(text, ','))
        {
          char      *end = nullptr;
          const long tag = std::strtol(item.c_str(), &end, 10);
          AssertThrow(!item.empty() && *end == '\0' && tag >= 0 && tag < 65535,
                      ExcMessage("Scene/Gmsh/" + entry +
                                 " must be a comma-separated list of "
                                 "physical tags (integers 0 to 65534); got '" +
                                 text + "'."));
          tags.insert(tag);
        }
      return tags;
    }

    template <int dim>
    std::map<unsigned int, std::array<bool, 3>>
    parse_dirichlet_tags(const std::string &text)
    {
      std::map<unsigned int, std::array<bool, 3>> fixed;
      const std::string letters = dim == 2 ? "xy" : "xyz";
      for (const auto &item : Utilities::split_string_list(text, ','))
        {
          AssertThrow(!item.empty(),
                      ExcMessage("Scene/Gmsh/Dirichlet tags has an empty "
                                 "item (two commas in a row, or one alone) "
                                 "in '" +
                                 text + "'."));
          const auto        colon = item.find(':');
          const std::string components =
            colon == std::string::npos ? letters : item.substr(colon + 1);
          // (the tag alone, as parse_tags reads it: one integer)
          const std::string tag_text = Utilities::trim(item.substr(0, colon));
          AssertThrow(!tag_text.empty(),
                      ExcMessage("Scene/Gmsh/Dirichlet tags: '" + item +
                                 "' has no tag before ':'."));
          const unsigned int tag =
            *parse_tags(tag_text, "Dirichlet tags").begin();
          // (a tag given twice fixes what either item names)
          auto &fixed_here =
            fixed.try_emplace(tag, std::array<bool, 3>{}).first->second;
          unsigned int n = 0;
          for (const char c : components)
            if (c != ' ')
              {
                const auto d = letters.find(c);
                AssertThrow(d != std::string::npos,
                            ExcMessage(
                              "Scene/Gmsh/Dirichlet tags: '" + item +
                              "' names the component '" + std::string(1, c) +
                              "'; the components of a tag (after ':') are "
                              "letters of '" +
                              letters +
                              "' (e.g. '11: y' fixes u_y on tag 11)."));
                fixed_here[d] = true;
                ++n;
              }
          AssertThrow(n > 0,
                      ExcMessage(
                        "Scene/Gmsh/Dirichlet tags: '" + item +
                        "' names no component after ':' (letters of '" +
                        letters + "', or the tag alone for all)."));
        }
      return fixed;
    }

    template <int dim>
    Tensor<1, dim>
    parse_vector(const std::string &text,
                 const std::string &entry,
                 const double       max_component,
                 const std::string &unit)
    {
      const auto items = Utilities::split_string_list(text, ',');
      AssertThrow(
        items.size() == dim || (dim == 2 && items.size() == 3),
        ExcMessage("Scene/Gmsh/" + entry + " must have " + std::to_string(dim) +
                   " comma-separated components; got '" + text + "'."));
      Tensor<1, dim + 1> v;
      for (unsigned int d = 0; d < items.size(); ++d)
        {
          char *end = nullptr;
          v[d]      = std::strtod(items[d].c_str(), &end);
          AssertThrow(!items[d].empty() && *end == '\0' && std::isfinite(v[d]),
                      ExcMessage("Scene/Gmsh/" + entry +
                                 " must have finite components; got '" + text +
                                 "'."));
          AssertThrow(std::abs(v[d]) <= max_component,
                      ExcMessage("Scene/Gmsh/" + entry +
                                 ": each component must lie in [-" +
                                 format_number(max_component) + ", " +
                                 format_number(max_component) + "] " + unit +
                                 "; got '" + text + "'."));
        }
      // the default has three components; in 2D the third must be zero
      AssertThrow(items.size() == dim || v[dim] == 0.,
                  ExcMessage("Scene/Gmsh/" + entry +
                             " has a third component in 2D (Dimension = 2): "
                             "it must be 0 or left out; got '" +
                             text + "'."));
      Tensor<1, dim> result;
      for (unsigned int d = 0; d < dim; ++d)
        result[d] = v[d];
      return result;
    }

    std::vector<std::string>
    split_items(const std::string &text, const char separator)
    {
      std::vector<std::string> items;
      std::string              item;
      for (std::istringstream in(text); std::getline(in, item, separator);)
        items.push_back(Utilities::trim(item));
      if (!text.empty() && text.back() == separator)
        items.emplace_back();
      return items;
    }



    template std::map<unsigned int, std::array<bool, 3>>
    parse_dirichlet_tags<2>(const std::string &);
    template std::map<unsigned int, std::array<bool, 3>>
    parse_dirichlet_tags<3>(const std::string &);
    template Tensor<1, 2>
    parse_vector<2>(const std::string &,
                    const std::string &,
                    const double,
                    const std::string &);
    template Tensor<1, 3>
    parse_vector<3>(const std::string &,
                    const std::string &,
                    const double,
                    const std::string &);
  } // namespace GmshEntries
} // namespace dyncontact
