#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <dyncontact/base/global_parameters.h>
#include <dyncontact/contact/contact_setup.h>
#include <dyncontact/core/parameter_file.h>
#include <dyncontact/mesh_refinement/mesh_adaptor.h>
#include <dyncontact/output/checkpoint.h>
#include <dyncontact/output/output_parameters.h>
#include <dyncontact/output/reference_states.h>
#include <dyncontact/postprocess/interface.h>
#include <dyncontact/scenes/interface.h>
#include <dyncontact/time_stepping/time_integration_parameters.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <utility>
#include <vector>

namespace dyncontact
{
  namespace
  {
    std::string
    expand_includes(const std::string        &text,
                    const std::string        &source,
                    const std::string        &includer,
                    std::vector<std::string> &chain,
                    std::vector<std::string> &chain_lines,
                    std::vector<std::string> &origins)
    {
      // an included file closes the subsections it opens, as deal.II's own
      // 'include' demands (pasted into the including text, an unclosed one
      // would be reported there, without the included file's name)
      const bool        is_included = !includer.empty();
      const std::string as_included =
        is_included ? "'" + source + "' (included at line " +
                        chain_lines.back() + " of '" + includer + "')" :
                      "";
      std::vector<std::pair<std::string, unsigned int>> open;
      std::string                                       body = text;
      if (body.rfind("\xEF\xBB\xBF", 0) == 0)
        body.erase(0, 3);
      std::istringstream in(body);
      std::ostringstream out;
      unsigned int       line_number = 0;
      for (std::string line; std::getline(in, line);)
        {
          ++line_number;
          const auto first = line.find_first_not_of(" \t");
          // (deal.II's parser also takes INCLUDE)
          if (first == std::string::npos ||
              (line.compare(first, 8, "include ") != 0 &&
               line.compare(first, 8, "INCLUDE ") != 0))
            {
              out << line << "\n";
              origins.push_back("Line " + std::to_string(line_number) +
                                " of '" + source + "'");
              if (!is_included || first == std::string::npos)
                continue;
              std::string entry = line.substr(first, line.find('#') - first);
              entry.erase(entry.find_last_not_of(" \t\r") + 1);
              if (entry.rfind("subsection ", 0) == 0 ||
                  entry.rfind("SUBSECTION ", 0) == 0)
                open.emplace_back(entry.substr(11), line_number);
              else if (entry == "end" || entry == "END")
                {
                  AssertThrow(!open.empty(),
                              ExcMessage(
                                as_included + ": the 'end' at its line " +
                                std::to_string(line_number) +
                                " closes a subsection that the file did not "
                                "open; an included file must close exactly "
                                "the subsections it opens."));
                  open.pop_back();
                }
              continue;
            }
          std::string name = line.substr(first + 8);
          name.erase(0, name.find_first_not_of(" \t"));
          name.erase(name.find_last_not_of(" \t\r") + 1);
          const std::string where =
            "line " + std::to_string(line_number) + " of '" + source + "'";
          AssertThrow(!name.empty(),
                      ExcMessage(where + ": 'include' needs a file name."));
          // relative names: the including file's folder, else the working
          // directory
          std::filesystem::path path(name);
          if (path.is_relative())
            {
              const auto beside =
                std::filesystem::path(source).parent_path() / path;
              if (std::filesystem::exists(beside))
                path = beside;
            }
          std::error_code   error;
          const std::string canonical =
            std::filesystem::weakly_canonical(path, error).string();
          AssertThrow(std::filesystem::is_regular_file(path),
                      ExcMessage(where + ": the included file '" + name +
                                 "' does not exist or is not a regular "
                                 "file."));
          const auto cycle = std::find(chain.begin(), chain.end(), canonical);
          if (cycle != chain.end())
            {
              std::string message =
                "the parameter file '" + canonical + "' includes itself:";
              for (auto c = cycle; c + 1 != chain.end(); ++c)
                message += " '" + *c + "' includes '" + *(c + 1) +
                           "' at line " + chain_lines[c - chain.begin()] + ";";
              message += " '" + chain.back() + "' includes '" + canonical +
                         "' at line " + std::to_string(line_number) + ".";
              AssertThrow(false, ExcMessage(message));
            }
          AssertThrow(chain.size() < 32,
                      ExcMessage(where + ": more than 32 nested 'include' "
                                         "levels."));
          std::ifstream file(path);
          AssertThrow(file.good(),
                      ExcMessage(where + ": cannot read the included file '" +
                                 name + "'."));
          std::stringstream included;
          included << file.rdbuf();
          chain_lines.push_back(std::to_string(line_number));
          chain.push_back(canonical);
          out << expand_includes(
            included.str(), path.string(), source, chain, chain_lines, origins);
          chain.pop_back();
          chain_lines.pop_back();
        }
      AssertThrow(open.empty(),
                  ExcMessage(
                    as_included + ": 'subsection " +
                    (open.empty() ? "" : open.back().first) + "' at its line " +
                    std::to_string(open.empty() ? 0 : open.back().second) +
                    " has no 'end' before the file ends; an "
                    "included file must close the subsections it "
                    "opens."));
      return out.str();
    }
  } // namespace



  std::string
  expand_includes(const std::string        &text,
                  const std::string        &source,
                  std::vector<std::string> &origins)
  {
    std::error_code          error;
    std::vector<std::string> chain = {
      std::filesystem::weakly_canonical(source, error).string()};
    std::vector<std::string> chain_lines;
    origins.clear();
    return expand_includes(text, source, "", chain, chain_lines, origins);
  }



  std::string
  with_origin(const std::string              &message,
              const std::string              &source,
              const std::vector<std::string> &origins)
  {
    // deal.II's parser: "Line <N> of file <source>" (one of its messages
    // lacks the last '>')
    const std::string head = "Line <", tail = "> of file <" + source;
    const auto        begin = message.find(head);
    if (begin == std::string::npos)
      return message;
    const auto end = message.find(tail, begin);
    if (end == std::string::npos)
      return message;
    // (the source's whole name, not the start of another file's)
    const std::string next = message.substr(end + tail.size(), 1);
    if (next != ">" && next != ":")
      return message;
    const std::size_t after = end + tail.size() + (next == ">" ? 1 : 0);
    const std::string number =
      message.substr(begin + head.size(), end - begin - head.size());
    if (number.empty() ||
        number.find_first_not_of("0123456789") != std::string::npos)
      return message;
    const unsigned long n = std::stoul(number);
    if (n == 0 || n > origins.size())
      return message;
    return message.substr(0, begin) + origins[n - 1] + message.substr(after);
  }



  const std::vector<ParameterOwner> &
  parameter_owners()
  {
    // the declarations do not depend on the dimension
    constexpr int                            dim    = 2;
    static const std::vector<ParameterOwner> owners = {
      {"GlobalParameters", &GlobalParameters::declare_parameters},
      {"TimeIntegrationParameters",
       &TimeIntegrationParameters::declare_parameters},
      {"Material",
       [](ParameterHandler &prm) {
         Material::declare_parameters(prm, "Material", true);
         Material::declare_parameters(prm, "Material of body 2");
       }},
      {"ActiveSetSolver", &ActiveSetSolver::Parameters::declare_parameters},
      {"ContactSetup", &ContactSetup<dim>::Parameters::declare_parameters},
      {"MeshAdaptor", &MeshAdaptor<dim>::declare_parameters},
      {"OutputParameters", &OutputParameters::declare_parameters},
      {"Checkpoints", &Checkpoints::declare_parameters},
      {"ReferenceStates", &ReferenceStates<dim>::declare_parameters},
      {"Postprocess::Manager", &Postprocess::Manager<dim>::declare_parameters},
      {"Scene", &declare_scene_parameters}};
    return owners;
  }



  void
  declare_all_parameters(ParameterHandler &prm)
  {
    for (const ParameterOwner &owner : parameter_owners())
      owner.declare_parameters(prm);
  }



  std::set<std::string>
  declared_entries(const ParameterHandler &prm)
  {
    std::ostringstream text;
    prm.print_parameters(text, ParameterHandler::ShortPRM);
    std::istringstream       in(text.str());
    std::vector<std::string> path;
    std::set<std::string>    names;
    for (std::string line; std::getline(in, line);)
      {
        line = Utilities::trim(line);
        if (line.rfind("subsection ", 0) == 0)
          path.push_back(Utilities::trim(line.substr(11)));
        else if (line == "end" && !path.empty())
          path.pop_back();
        else if (line.rfind("set ", 0) == 0)
          {
            std::string name;
            for (const auto &p : path)
              name += p + "/";
            names.insert(name +
                         Utilities::trim(line.substr(4, line.find('=') - 4)));
          }
      }
    return names;
  }



  namespace
  {



    /// The entries that moved (full names before and now): each
    /// subsection has one owner, and a plugin's entries are in
    /// <Component>/<Plugin>.
    const std::vector<std::pair<std::string, std::string>> &
    moved_entries()
    {
      static const std::vector<std::pair<std::string, std::string>> moved = {
        {"Contact solver/Initial penetration", "Contact/Initial penetration"},
        {"Mesh refinement/Contact zone distance",
         "Mesh refinement/Contact zone/Distance"},
        {"Postprocess/Error norm interval",
         "Postprocess/Error energy norm/Interval"}};
      return moved;
    }



    /// Stops with a message naming the entry (subsection/.../@p entry),
    /// @p value and the values its pattern allows (for a number: its
    /// range) unless @p value matches the pattern declared in @p prm.
    void
    check_value(ParameterHandler               &prm,
                const std::vector<std::string> &path,
                const std::string              &entry,
                const std::string              &value,
                const std::string              &at)
    {
      std::string name;
      for (const auto &p : path)
        {
          prm.enter_subsection(p);
          name += p + "/";
        }
      std::string allowed;
      try
        {
          prm.set(entry, value);
        }
      catch (const ParameterHandler::ExcValueDoesNotMatchPattern &e)
        {
          // "... does not match the given pattern <[Double 0...1]>."
          std::ostringstream info;
          e.print_info(info);
          const std::string text  = info.str();
          const std::size_t begin = text.find("pattern <");
          const std::size_t end   = text.rfind('>');
          allowed = (begin == std::string::npos || end == std::string::npos ||
                     end < begin + 9) ?
                      text :
                      text.substr(begin + 9, end - begin - 9);
        }
      for (std::size_t k = 0; k < path.size(); ++k)
        prm.leave_subsection();
      AssertThrow(allowed.empty(),
                  ExcMessage(at + name + entry + " = '" + value +
                             "' is refused; the values allowed are " +
                             Utilities::trim(allowed) + "."));
    }



    /// Stops with a message if @p entry, set in subsection @p path where it
    /// is not declared, is declared elsewhere or has moved (@p at: the
    /// line); else leaves it to the parser, whose message names it.
    void
    refuse_misplaced(const std::set<std::string>    &declared,
                     const std::vector<std::string> &path,
                     const std::string              &entry,
                     const std::string              &at)
    {
      std::string where;
      for (const auto &p : path)
        where += p + "/";
      // an entry of an earlier layout
      for (const auto &[before, now] : moved_entries())
        AssertThrow(where + entry != before,
                    ExcMessage(at + "'" + before + "' has moved to '" + now +
                               "' (see doc/running.md)."));
      // the subsections that do declare an entry of this name
      const std::string name = (path.size() == 1 && path[0] == "Scene" &&
                                entry == "Contact search radius") ?
                                 "Search radius" :
                                 entry;
      std::string       candidates;
      for (const auto &full : declared)
        if (full.size() > name.size() &&
            full.compare(full.size() - name.size() - 1,
                         name.size() + 1,
                         "/" + name) == 0)
          candidates += (candidates.empty() ? "" : ", ") +
                        full.substr(0, full.size() - name.size() - 1);
      if (candidates.empty())
        return; // the parser's own message names the entry
      // (an entry of the flat layout of subsection Scene before each scene
      // had its own)
      const bool flat_scene =
        path.size() == 1 && path[0] == "Scene" &&
        (name == "Slave side" || name == "Search radius" ||
         candidates.find("Scene/") != std::string::npos);
      AssertThrow(!flat_scene,
                  ExcMessage(at + "'Scene/" + entry +
                             "' has moved: each scene reads its own "
                             "subsection now. Set '" +
                             name + "' in subsection " + candidates +
                             " (see doc/running.md)."));
      AssertThrow(false,
                  ExcMessage(
                    at + "subsection '" +
                    (path.empty() ? std::string("(top level)") :
                                    where.substr(0, where.size() - 1)) +
                    "' has no entry '" + entry +
                    "'; it is declared in subsection " + candidates + "."));
    }
  } // namespace



  std::string
  unread_entry_warnings(
    const std::vector<std::pair<std::string, std::string>> &set_entries,
    const std::string                                      &scene_name,
    const std::string                                      &scene_subsection,
    const std::vector<std::pair<std::string, std::string>> &unread)
  {
    std::ostringstream    text;
    std::set<std::string> warned;
    // (an entry set more than once: the line whose value the run takes,
    // the last)
    std::map<std::string, std::string> last_origin;
    for (const auto &[name, origin] : set_entries)
      last_origin[name] = origin;
    for (const auto &set_entry : set_entries)
      {
        const std::string &name = set_entry.first;
        std::string        reason;
        if (name.rfind("Scene/", 0) == 0 && name != "Scene/Name" &&
            name.rfind(scene_subsection + "/", 0) != 0)
          reason = "the scene is '" + scene_name + "', which reads " +
                   scene_subsection + " only";
        for (const auto &[prefix, why] : unread)
          if (reason.empty() &&
              (name == prefix || name.rfind(prefix + "/", 0) == 0))
            reason = why;
        if (!reason.empty() && warned.insert(name).second)
          text << "   warning: " << last_origin[name] << ": " << name
               << " is set, but this run does not read it: " << reason << ".\n";
      }
    return text.str();
  }



  std::vector<std::pair<std::string, std::string>>
  check_for_misplaced_entries(const std::string              &text,
                              const std::vector<std::string> &origins)
  {
    std::vector<std::pair<std::string, std::string>> set_entries;
    ParameterHandler                                 prm;
    declare_all_parameters(prm);
    const std::set<std::string> declared = declared_entries(prm);

    std::istringstream       in(text);
    std::vector<std::string> path;
    unsigned int             line_number = 0;
    for (std::string line; std::getline(in, line);)
      {
        ++line_number;
        // where the line came from (an included file's own line)
        AssertThrow(line_number <= origins.size(), ExcInternalError());
        const std::string &origin = origins[line_number - 1];
        const auto         hash   = line.find('#');
        if (hash != std::string::npos)
          line.erase(hash);
        line = Utilities::trim(line);
        if (line.rfind("subsection ", 0) == 0)
          {
            path.push_back(Utilities::trim(line.substr(11)));
            AssertThrow(path.back().find('/') == std::string::npos,
                        ExcMessage(origin + ": 'subsection " + path.back() +
                                   "': a subsection name has no '/'; nest "
                                   "one subsection in the other."));
          }
        else if (line == "end" && !path.empty())
          path.pop_back();
        else if (line.rfind("set ", 0) == 0 &&
                 line.find('=') != std::string::npos)
          {
            const std::string entry =
              Utilities::trim(line.substr(4, line.find('=') - 4));
            std::string where;
            for (const auto &p : path)
              where += p + "/";
            const std::string at = origin + ": ";
            if (declared.count(where + entry))
              {
                // a value continued on the next line is left to the parser
                if (line.back() != '\\')
                  check_value(prm,
                              path,
                              entry,
                              Utilities::trim(line.substr(line.find('=') + 1)),
                              at);
                set_entries.emplace_back(where + entry, origin);
                continue;
              }
            refuse_misplaced(declared, path, entry, at);
          }
      }
    return set_entries;
  }
} // namespace dyncontact
