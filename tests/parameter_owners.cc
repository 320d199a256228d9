// One owner per subsection (doc/architecture.md, "Parameters"): every
// subsection of the prm that holds entries is declared by exactly one of
// parameter_owners(), and every plugin (scene, refinement criterion,
// statistic) declares its entries only in <Component>/<Plugin>, the
// plugin's name with a capital first letter (as ASPECT nests its plugins'
// parameters). The table of subsections and owners is the output.

#include <deal.II/base/parameter_handler.h>

#include <dyncontact/core/parameter_file.h>
#include <dyncontact/mesh_refinement/interface.h>
#include <dyncontact/postprocess/interface.h>
#include <dyncontact/scenes/interface.h>

#include <cctype>
#include <fstream>
#include <map>
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
}
