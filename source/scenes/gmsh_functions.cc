#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <dyncontact/base/collective_errors.h>
#include <dyncontact/scenes/gmsh_entries.h>
#include <dyncontact/scenes/gmsh_scene.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <iostream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>


// GmshScene's initial displacement and velocity as functions of x.

namespace dyncontact
{
  namespace GmshEntries
  {
    /// Function constants: 'name = value', comma-separated.
    std::map<std::string, double>
    parse_constants(const std::string &text)
    {
      std::map<std::string, double> constants;
      for (const std::string &item : Utilities::split_string_list(text, ','))
        {
          const std::size_t equal = item.find('=');
          char             *end   = nullptr;
          const std::string name =
            Utilities::trim(item.substr(0, std::min(equal, item.size())));
          const std::string value  = equal == std::string::npos ?
                                       "" :
                                       Utilities::trim(item.substr(equal + 1));
          const double      number = std::strtod(value.c_str(), &end);
          const bool        identifier =
            !name.empty() && (std::isalpha(name[0]) || name[0] == '_') &&
            std::all_of(name.begin(), name.end(), [](const char c) {
              return std::isalnum(c) || c == '_';
            });
          AssertThrow(identifier && !value.empty() && *end == '\0' &&
                        std::isfinite(number) &&
                        value.find_first_of("xX") == std::string::npos,
                      ExcMessage("Scene/Gmsh/Function constants: '" + item +
                                 "' is no 'name = value' with a name of "
                                 "letters, digits and '_' and a finite "
                                 "decimal value."));
          AssertThrow(name != "pi",
                      ExcMessage("Scene/Gmsh/Function constants: '" + item +
                                 "' names a constant 'pi', which is "
                                 "predefined (3.14159...)."));
          for (const std::string reserved : {"x", "y", "z", "t", "body"})
            AssertThrow(name != reserved,
                        ExcMessage("Scene/Gmsh/Function constants: '" + item +
                                   "' names a constant '" + name +
                                   "', which is a variable of the functions "
                                   "(x, y, z, t) or the body's number "
                                   "('body')."));
          AssertThrow(constants.count(name) == 0,
                      ExcMessage("Scene/Gmsh/Function constants gives '" +
                                 name + "' twice."));
          constants[name] = number;
        }
      return constants;
    }



    std::vector<std::string>
    split_top_level(const std::string &text, const char separator)
    {
      std::vector<std::string> items;
      std::string              item;
      int                      depth = 0;
      for (const char c : text)
        {
          depth += (c == '(') - (c == ')');
          if (c == separator && depth == 0)
            {
              items.push_back(Utilities::trim(item));
              item.clear();
            }
          else
            item += c;
        }
      if (!text.empty())
        items.push_back(Utilities::trim(item));
      return items;
    }



    bool
    mentions_time(const std::vector<std::string> &expressions)
    {
      const auto identifier = [](const char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
      };
      for (const std::string &e : expressions)
        for (std::size_t k = 0; k < e.size(); ++k)
          if (e[k] == 't' && (k == 0 || !identifier(e[k - 1])) &&
              (k + 1 == e.size() || !identifier(e[k + 1])))
            return true;
      return false;
    }



    template <int dim>
    std::shared_ptr<FunctionParser<dim>>
    make_function(const std::string                   &entry,
                  const std::vector<std::string>      &expressions,
                  const std::map<std::string, double> &constants,
                  const bool                           of_time)
    {
      // (pi as in deal.II's ParsedFunction; Function constants may not
      // name it)
      std::map<std::string, double> with_pi = constants;
      with_pi.emplace("pi", numbers::PI);
      std::string variables = FunctionParser<dim>::default_variable_names();
      if (of_time)
        variables += ",t";
      // (muparser reads the expressions at the first evaluation and throws
      // its own type)
      const auto problem_of = [&](FunctionParser<dim>            &parser,
                                  const std::vector<std::string> &e) {
        // (deal.II prints muparser's report on std::cerr before it throws;
        // the message below has it)
        std::ostringstream quiet;
        struct Restore
        {
          std::streambuf *buffer;
          ~Restore()
          {
            std::cerr.rdbuf(buffer);
          }
        } restore{std::cerr.rdbuf(quiet.rdbuf())};
        try
          {
            parser.initialize(variables, e, with_pi, of_time);
            for (unsigned int d = 0; d < e.size(); ++d)
              (void)parser.value(Point<dim>(), d);
          }
        catch (const std::exception &error)
          {
            // (deal.II's column counts in the whole list of expressions
            // that it hands muparser, not in this one: muparser's own
            // position, which follows, is the one to read)
            return std::regex_replace(message_of(error),
                                      std::regex("Parsing Error at Column "
                                                 "[0-9]+\\. "),
                                      "");
          }
        catch (...)
          {
            return std::string("the parser refused it");
          }
        return std::string();
      };
      auto function = std::make_shared<FunctionParser<dim>>(expressions.size());
      // (muparser's rand() differs between evaluations and ranks)
      for (const std::string &expression : expressions)
        AssertThrow(!std::regex_search(expression,
                                       std::regex("(^|[^A-Za-z0-9_])rand"
                                                  "[ ]*\\(")),
                    ExcMessage("Scene/Gmsh/" + entry + ": '" + expression +
                               "' uses rand(), whose values differ from one "
                               "evaluation and one MPI rank to the next; "
                               "give a function of x, y, z and t."));
      std::string problem = problem_of(*function, expressions);
      if (!problem.empty() && expressions.size() == 1)
        problem = "'" + expressions[0] + "': " + problem;
      // name the component that fails
      for (unsigned int d = 0;
           !problem.empty() && d < expressions.size() && expressions.size() > 1;
           ++d)
        {
          FunctionParser<dim> one(1);
          const std::string   own = problem_of(one, {expressions[d]});
          if (!own.empty())
            {
              problem = "component " + std::to_string(d + 1) + " ('" +
                        expressions[d] + "'): " + own;
              break;
            }
        }
      AssertThrow(problem.empty(),
                  ExcMessage("Scene/Gmsh/" + entry +
                             " cannot be read (variables x, y" +
                             (dim == 3 ? ", z" : "") + (of_time ? ", t" : "") +
                             ", the constant 'body' where it is per body, and "
                             "those of Function constants): " +
                             problem));
      return function;
    }

    template std::shared_ptr<FunctionParser<2>>
    make_function<2>(const std::string &,
                     const std::vector<std::string> &,
                     const std::map<std::string, double> &,
                     const bool);
    template std::shared_ptr<FunctionParser<3>>
    make_function<3>(const std::string &,
                     const std::vector<std::string> &,
                     const std::map<std::string, double> &,
                     const bool);
  } // namespace GmshEntries



  template <int dim>
  void
  GmshScene<dim>::parse_initial_functions(ParameterHandler &prm)
  {
    const auto constants =
      GmshEntries::parse_constants(prm.get("Function constants"));
    displacement_functions.clear();
    velocity_functions.clear();
    for (const auto &[entry, functions] :
         {std::make_pair(std::string("Initial displacement"),
                         &displacement_functions),
          std::make_pair(std::string("Initial velocity"), &velocity_functions)})
      {
        const std::string text = prm.get(entry);
        if (text.empty())
          continue;
        const auto expressions = Utilities::split_string_list(text, ';');
        AssertThrow(expressions.size() == dim,
                    ExcMessage("Scene/Gmsh/" + entry + " = '" + text +
                               "' has " + std::to_string(expressions.size()) +
                               " components separated by ';'; a " +
                               std::to_string(dim) + "D mesh needs " +
                               std::to_string(dim) + "."));
        for (unsigned int b = 0; b < body_tags.size(); ++b)
          {
            auto with_body    = constants;
            with_body["body"] = b + 1;
            functions->push_back(GmshEntries::make_function<dim>(
              entry + " = '" + text + "'", expressions, with_body, false));
          }
      }
    if (!velocity_functions.empty())
      for (const std::string entry : {"Initial velocities",
                                      "Initial velocity of body 1",
                                      "Initial velocity of body 2"})
        AssertThrow(prm.get(entry).empty() || prm.get(entry) == "0, 0, 0",
                    ExcMessage("Scene/Gmsh/Initial velocity (a function) "
                               "replaces Scene/Gmsh/" +
                               entry + ": leave that out."));
  }



  // (the class is instantiated where it is registered, in gmsh_scene.cc)
  template void
  GmshScene<2>::parse_initial_functions(ParameterHandler &);
  template void
  GmshScene<3>::parse_initial_functions(ParameterHandler &);
} // namespace dyncontact
