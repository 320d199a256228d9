#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <dyncontact/scenes/gmsh_entries.h>
#include <dyncontact/scenes/gmsh_scene.h>

#include <cmath>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>


// GmshScene's loads: a traction per tag (numbers, or functions of x and t),
// a normal pressure per tag, and a body force per body; and the prescribed
// displacements of Dirichlet tags that move.

namespace dyncontact
{
  using namespace GmshEntries;

  namespace
  {
    /// Whether every item of @p items is a plain finite number.
    bool
    all_numbers(const std::vector<std::string> &items)
    {
      for (const std::string &item : items)
        {
          char        *end   = nullptr;
          const double value = std::strtod(item.c_str(), &end);
          if (item.empty() || *end != '\0' || !std::isfinite(value))
            return false;
        }
      return true;
    }

    /// The items 'tag: components' of Scene/Gmsh/@p entry (@p text): each
    /// tag with its components (split at commas outside parentheses).
    std::vector<std::pair<unsigned int, std::vector<std::string>>>
    tag_items(const std::string &entry, const std::string &text)
    {
      std::vector<std::pair<unsigned int, std::vector<std::string>>> items;
      for (const std::string &item : split_items(text, ';'))
        {
          if (item.empty())
            continue;
          const std::size_t colon = item.find(':');
          AssertThrow(colon != std::string::npos,
                      ExcMessage("Scene/Gmsh/" + entry + ": '" + item +
                                 "' is no 'tag: components'."));
          const auto tags = parse_tags(Utilities::trim(item.substr(0, colon)),
                                       entry + " ('" + item + "')");
          AssertThrow(tags.size() == 1,
                      ExcMessage("Scene/Gmsh/" + entry + ": '" + item +
                                 "' is no 'tag: components'."));
          items.emplace_back(*tags.begin(),
                             split_top_level(item.substr(colon + 1), ','));
        }
      return items;
    }
  } // namespace



  template <int dim>
  void
  GmshScene<dim>::parse_loads(ParameterHandler &prm)
  {
    const auto constants = parse_constants(prm.get("Function constants"));
    tag_tractions.clear();
    traction_functions.clear();
    pressure_functions.clear();
    body_force_functions.clear();
    load_functions_of_time.clear();
    const auto loaded = [&](const unsigned int tag) {
      return neumann_tags.count(tag) || tag_tractions.count(tag) ||
             traction_functions.count(tag) || pressure_functions.count(tag);
    };
    // a tag's load items, each tag loaded once
    const auto load_items = [&](const std::string &entry) {
      const auto items = tag_items(entry, prm.get(entry));
      for (const auto &[tag, components] : items)
        {
          AssertThrow(!loaded(tag),
                      ExcMessage("Scene/Gmsh/" + entry + ": tag " +
                                 std::to_string(tag) +
                                 " has a traction already (listed twice, or "
                                 "in Neumann tags, Neumann tractions or "
                                 "Pressures)."));
          // (marks the tag as loaded for the next items)
          if (entry == "Pressures")
            pressure_functions[tag] = nullptr;
          else
            traction_functions[tag] = nullptr;
        }
      return items;
    };

    for (const auto &[tag, components] : load_items("Neumann tractions"))
      {
        const std::string entry =
          "Neumann tractions (tag " + std::to_string(tag) + ")";
        // numbers: a constant traction, as before functions existed
        if (all_numbers(components))
          {
            traction_functions.erase(tag);
            std::string text;
            for (const std::string &c : components)
              text += (text.empty() ? "" : ", ") + c;
            tag_tractions[tag] = parse_vector<dim>(text, entry, 1e15, "Pa");
            continue;
          }
        AssertThrow(components.size() == dim,
                    ExcMessage("Scene/Gmsh/" + entry + " has " +
                               std::to_string(components.size()) +
                               " components; a " + std::to_string(dim) +
                               "D mesh needs " + std::to_string(dim) + "."));
        const bool of_time = mentions_time(components);
        traction_functions[tag] =
          make_function<dim>(entry, components, constants, of_time);
        if (of_time)
          load_functions_of_time.insert(traction_functions[tag].get());
      }

    for (const auto &[tag, components] : load_items("Pressures"))
      {
        const std::string entry = "Pressures (tag " + std::to_string(tag) + ")";
        AssertThrow(components.size() == 1 && !components[0].empty(),
                    ExcMessage("Scene/Gmsh/" + entry +
                               " must be one expression: a pressure is a "
                               "scalar (Pa)."));
        const bool of_time = mentions_time(components);
        pressure_functions[tag] =
          make_function<dim>(entry, components, constants, of_time);
        if (of_time)
          load_functions_of_time.insert(pressure_functions[tag].get());
      }

    const std::string text = prm.get("Body force");
    if (!text.empty())
      {
        const auto expressions = split_items(text, ';');
        AssertThrow(expressions.size() == dim,
                    ExcMessage("Scene/Gmsh/Body force = '" + text + "' has " +
                               std::to_string(expressions.size()) +
                               " components separated by ';'; a " +
                               std::to_string(dim) + "D mesh needs " +
                               std::to_string(dim) + "."));
        const bool of_time = mentions_time(expressions);
        for (unsigned int b = 0; b < body_tags.size(); ++b)
          {
            auto with_body    = constants;
            with_body["body"] = b + 1;
            body_force_functions.push_back(make_function<dim>(
              "Body force = '" + text + "'", expressions, with_body, of_time));
            if (of_time)
              load_functions_of_time.insert(body_force_functions.back().get());
          }
      }

    // displacements that move: 'tag: components' of a Dirichlet tag
    prescribed_functions.clear();
    const std::string entry = "Prescribed displacements";
    for (const auto &[tag, components] : tag_items(entry, prm.get(entry)))
      {
        AssertThrow(dirichlet_components.count(tag) == 1,
                    ExcMessage("Scene/Gmsh/" + entry + ": tag " +
                               std::to_string(tag) +
                               " is not in Dirichlet tags, which say which "
                               "components it fixes."));
        AssertThrow(prescribed_functions.count(tag) == 0,
                    ExcMessage("Scene/Gmsh/" + entry + ": tag " +
                               std::to_string(tag) + " is listed twice."));
        const std::string where = entry + " (tag " + std::to_string(tag) + ")";
        AssertThrow(components.size() == dim,
                    ExcMessage("Scene/Gmsh/" + where + " has " +
                               std::to_string(components.size()) +
                               " components; a " + std::to_string(dim) +
                               "D mesh needs " + std::to_string(dim) + "."));
        for (unsigned int d = 0; d < dim; ++d)
          AssertThrow(dirichlet_components.at(tag)[d] || components[d] == "0",
                      ExcMessage("Scene/Gmsh/" + where + ": component " +
                                 std::to_string(d + 1) + " ('" + components[d] +
                                 "') is not fixed by Dirichlet tags, so it "
                                 "must be 0 (the boundary moves freely in "
                                 "it)."));
        prescribed_functions[tag] =
          make_function<dim>(where, components, constants, true);
      }

    // a tag in two roles: a support that is loaded (a clamped contact
    // surface is a master's, or refused by the contact set-up)
    for (const auto &[tag, components] : dirichlet_components)
      {
        (void)components;
        AssertThrow(!loaded(tag),
                    ExcMessage("Scene/Gmsh: boundary tag " +
                               std::to_string(tag) +
                               " is in Dirichlet tags and carries a load "
                               "(Neumann tags, Neumann tractions or "
                               "Pressures); give it one role."));
      }
  }



  template <int dim>
  FunctionLoads<dim>
  GmshScene<dim>::function_loads() const
  {
    FunctionLoads<dim> loads;
    for (const auto &f : body_force_functions)
      loads.body_forces.push_back(f.get());
    for (const auto &[tag, f] : traction_functions)
      loads.tractions.emplace_back(tag, f.get());
    for (const auto &[tag, f] : pressure_functions)
      loads.pressures.emplace_back(tag, f.get());
    loads.of_time        = load_functions_of_time;
    loads.time_dependent = !load_functions_of_time.empty();
    return loads;
  }



  template <int dim>
  std::vector<std::pair<types::boundary_id, Function<dim> *>>
  GmshScene<dim>::prescribed_displacements() const
  {
    std::vector<std::pair<types::boundary_id, Function<dim> *>> moving;
    for (const auto &[tag, f] : prescribed_functions)
      moving.emplace_back(tag, f.get());
    return moving;
  }



  // (the class is instantiated where it is registered, in gmsh_scene.cc)
  template void
  GmshScene<2>::parse_loads(ParameterHandler &);
  template void
  GmshScene<3>::parse_loads(ParameterHandler &);
  template FunctionLoads<2>
  GmshScene<2>::function_loads() const;
  template FunctionLoads<3>
  GmshScene<3>::function_loads() const;
  template std::vector<std::pair<types::boundary_id, Function<2> *>>
  GmshScene<2>::prescribed_displacements() const;
  template std::vector<std::pair<types::boundary_id, Function<3> *>>
  GmshScene<3>::prescribed_displacements() const;
} // namespace dyncontact
