#include <dyncontact/core/parameter_file.h>
#include <dyncontact/core/simulator.h>
#include <dyncontact/mesh_refinement/mesh_adaptor.h>
#include <dyncontact/output/reference_states.h>
#include <dyncontact/output/vtu_writer.h>
#include <dyncontact/scenes/interface.h>

// Simulator: the warnings of the entries the input sets and the run does
// not read.

namespace dyncontact
{
  template <int dim>
  void
  Simulator<dim>::warn_of_unread_entries(
    const std::vector<std::pair<std::string, std::string>> &set_entries) const
  {
    // (subsection or entry, why the run does not read it)
    std::vector<std::pair<std::string, std::string>> unread =
      scene->unread_entries();
    for (const auto &entry : mesh_adaptor->unread_entries(scheme->is_static))
      unread.push_back(entry);
    if (!scene->has_exact_solution() || scheme->is_static)
      unread.emplace_back("Postprocess/Error energy norm",
                          scheme->is_static ?
                            "the static problem has no exact solution in "
                            "time to compare with" :
                            "the '" + scene->name() +
                              "' scene has no exact solution");
    if (!time_integration.blended_mass)
      unread.emplace_back("Time integration/Consistent mass fraction",
                          "only Mass matrix = blended reads it");
    for (const auto &entry : vtu_writer->unread_entries())
      unread.push_back(entry);
    for (const auto &entry : reference_states->unread_entries())
      unread.push_back(entry);
    pcout << unread_entry_warnings(set_entries,
                                   scene->name(),
                                   scene->subsection(),
                                   unread);
  }



  // (the class is instantiated in simulator.cc)
  template void
  Simulator<2>::warn_of_unread_entries(
    const std::vector<std::pair<std::string, std::string>> &) const;
  template void
  Simulator<3>::warn_of_unread_entries(
    const std::vector<std::pair<std::string, std::string>> &) const;
} // namespace dyncontact
