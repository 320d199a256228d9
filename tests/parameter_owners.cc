// One owner per subsection (doc/architecture.md, "Parameters"): every
// subsection of the prm that holds entries is declared by exactly one of
// parameter_owners(), and every plugin (scene, refinement criterion,
// statistic) declares its entries only in <Component>/<Plugin>, the
// plugin's name with a capital first letter (as ASPECT nests its plugins'
// parameters). The table of subsections and owners is the output. And the
// owners alone read their entries: every top-level subsection is entered
// (prm.enter_subsection) by the files of one folder of source/, the owner's,
// and the top-level entries are read only by GlobalParameters
// (base/global_parameters.cc): another component is handed the value (as
// the scene is handed Polynomial degree and whether Contact solver/Step
// matrix stores S).

#include <deal.II/base/parameter_handler.h>

#include <dyncontact/core/parameter_file.h>
#include <dyncontact/mesh_refinement/interface.h>
#include <dyncontact/postprocess/interface.h>
#include <dyncontact/scenes/interface.h>

#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

using namespace dealii;
using namespace dyncontact;

std::ofstream out("output");

/// The full names (subsection/.../entry) of the entries @p declare declares.
std::set<std::string>
entries(const std::function<void(ParameterHandler &)> &declare)
{
  ParameterHandler prm;
  declare(prm);
  return declared_entries(prm);
}

std::string
subsection_of(const std::string &entry)
{
  const auto slash = entry.rfind('/');
  return slash == std::string::npos ? "(top level)" : entry.substr(0, slash);
}

/// Every entry of every plugin of @p Interface lies in
/// @p component/<Plugin>.
template <template <int> class Interface>
void
check_plugins(const std::string &component)
{
  unsigned int n = 0, misplaced = 0;
  for (const auto &info : PluginRegistry<Interface>::plugins())
    {
      std::string subsection = info.name;
      subsection[0]          = static_cast<char>(
        std::toupper(static_cast<unsigned char>(subsection[0])));
      const std::string prefix = component + "/" + subsection + "/";
      for (const auto &entry : entries(info.declare_parameters))
        {
          ++n;
          if (entry.rfind(prefix, 0) != 0)
            {
              ++misplaced;
              out << "FAILED: plugin '" << info.name << "' declares " << entry
                  << " outside " << prefix << "\n";
            }
        }
    }
  out << component << ": " << PluginRegistry<Interface>::plugins().size()
      << " plugins, " << n << " entries, "
      << (misplaced == 0 ? "each in its own subsection" : "FAILED") << "\n";
}

/// The subsections of @p owners' entries and who declares them; prints
/// them if @p print. Returns the number of subsections with several owners.
unsigned int
shared_subsections(const std::vector<ParameterOwner> &owners, const bool print)
{
  std::map<std::string, std::set<std::string>> owners_of;
  for (const ParameterOwner &owner : owners)
    for (const auto &entry : entries(owner.declare_parameters))
      owners_of[subsection_of(entry)].insert(owner.name);
  unsigned int shared = 0;
  for (const auto &[subsection, names] : owners_of)
    {
      if (print)
        {
          out << subsection << ":";
          for (const auto &name : names)
            out << " " << name;
          out << (names.size() > 1 ? "  FAILED: several owners" : "") << "\n";
        }
      shared += (names.size() > 1);
    }
  return shared;
}

int
main()
{
  const unsigned int shared = shared_subsections(parameter_owners(), true);
  out << "one owner per subsection: " << (shared == 0 ? "OK" : "FAILED")
      << "\n";
  std::size_t n_entries = 0;
  for (const ParameterOwner &owner : parameter_owners())
    n_entries += entries(owner.declare_parameters).size();
  out << "the owners declare every entry once: "
      << (n_entries == entries(&declare_all_parameters).size() ? "OK" :
                                                                 "FAILED")
      << "\n";

  // the check finds a second owner (the layout before the owners: the
  // progress line declared its own entry of subsection Output)
  const auto progress = [](ParameterHandler &prm) {
    prm.enter_subsection("Output");
    prm.declare_entry("Progress interval", "10");
    prm.leave_subsection();
  };
  const auto output = [](ParameterHandler &prm) {
    prm.enter_subsection("Output");
    prm.declare_entry("Output interval", "0.05");
    prm.leave_subsection();
  };
  out << "two owners of subsection Output are found: "
      << (shared_subsections({{"Progress", progress}, {"Output", output}},
                             false) == 1 ?
            "OK" :
            "FAILED")
      << "\n";

  check_plugins<Scene>("Scene");
  check_plugins<MeshRefinement::Interface>("Mesh refinement");
  check_plugins<Postprocess::Interface>("Postprocess");

  // who reads: the folders whose files enter each top-level subsection,
  // and the files that read a top-level entry by its name
  std::set<std::string> top_subsections, top_entries;
  for (const auto &entry : entries(&declare_all_parameters))
    {
      const auto slash = entry.find('/');
      if (slash == std::string::npos)
        top_entries.insert(entry);
      else
        top_subsections.insert(entry.substr(0, slash));
    }
  std::map<std::string, std::set<std::string>> readers;
  std::set<std::string>                        entry_readers;
  const std::regex            enter("enter_subsection\\(\"([^\"]+)\"\\)");
  const std::regex            get("\\.get[a-z_]*\\(\"([^\"]+)\"\\)");
  const std::filesystem::path root =
    std::filesystem::path(DYNCONTACT_SOURCE_DIR) / "source";
  for (const auto &file : std::filesystem::recursive_directory_iterator(root))
    {
      if (!file.is_regular_file())
        continue;
      const std::string name =
        std::filesystem::relative(file.path(), root).string();
      std::ifstream in(file.path());
      for (std::string line; std::getline(in, line);)
        {
          std::smatch match;
          if (std::regex_search(line, match, enter) &&
              top_subsections.count(match[1]))
            readers[match[1]].insert(name.substr(0, name.find('/')));
          if (std::regex_search(line, match, get) &&
              top_entries.count(match[1]))
            entry_readers.insert(name);
        }
    }
  unsigned int several = 0;
  for (const auto &[subsection, folders] : readers)
    {
      out << subsection << " is read in";
      for (const auto &folder : folders)
        out << " " << folder << "/";
      out << "\n";
      several += (folders.size() > 1);
    }
  out << "each top-level subsection is read in one folder: "
      << (several == 0 && readers.size() > 5 ? "OK" : "FAILED") << "\n";
  out << "the top-level entries are read only by GlobalParameters: "
      << (entry_readers == std::set<std::string>{"base/global_parameters.cc"} ?
            "OK" :
            "FAILED")
      << "\n";
}
