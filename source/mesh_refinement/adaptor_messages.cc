// What the mesh adaptor tells the user: the entries of subsection Mesh
// refinement that a run does not read, and what to reduce when a
// refinement does not fit into the memory.

#include <dyncontact/mesh_refinement/mesh_adaptor.h>

#include <algorithm>
#include <sstream>

namespace dyncontact
{
  template <int dim>
  std::vector<std::pair<std::string, std::string>>
  MeshAdaptor<dim>::unread_entries(const bool is_static) const
  {
    const bool        adapts = interval > 0 && !is_static;
    const std::string why =
      interval > 0 ? "the static problem takes no time steps (one solve), so "
                     "the mesh does not adapt during the run" :
                     "the mesh does not adapt during the run (Mesh "
                     "refinement/Refinement interval = 0)";
    std::vector<std::pair<std::string, std::string>> unread;
    if (adapts)
      {
        const bool zone_criterion =
          std::find(criterion_names.begin(),
                    criterion_names.end(),
                    "contact zone") != criterion_names.end();
        // (Refinement interval without contact reads the zone's Distance)
        const bool skips = interval_without_contact > interval;
        if (initial_refinements == 0 && !zone_criterion && !skips)
          unread.emplace_back("Mesh refinement/Contact zone",
                              "no criterion of Mesh refinement/Criteria is "
                              "the contact zone, and Initial contact "
                              "refinements = 0");
        else if (!zone_criterion)
          unread.emplace_back("Mesh refinement/Contact zone/Keep distance",
                              "it acts at the adaptations during the run, "
                              "and no criterion of Mesh refinement/Criteria "
                              "is the contact zone (Initial contact "
                              "refinements and Refinement interval without "
                              "contact use its Distance only)");
        if (interval_without_contact > 0 && !skips)
          unread.emplace_back(
            "Mesh refinement/Refinement interval without contact",
            "it equals Refinement interval, so that no adaptation is "
            "skipped");
        if (error_tolerance > 0.)
          {
            for (const std::string entry :
                 {"Refine fraction", "Coarsen fraction"})
              unread.emplace_back("Mesh refinement/" + entry,
                                  "the cells are marked by Mesh "
                                  "refinement/Error tolerance");
            std::string indicators;
            for (const auto &name : criterion_names)
              if (name != "contact zone" && name != "curved boundary")
                indicators += (indicators.empty() ? "" : ", ") + name;
            if (!indicators.empty())
              unread.emplace_back(
                "Mesh refinement/Criteria",
                "the indicators of " + indicators +
                  " are not used: the cells are marked by Mesh "
                  "refinement/Error tolerance (its estimate is the "
                  "criterion energy error's); only the flags of contact "
                  "zone and curved boundary are");
          }
        else
          unread.emplace_back("Mesh refinement/Error tolerance split",
                              "the cells are marked by the fractions (Mesh "
                              "refinement/Error tolerance = 0)");
        return unread;
      }
    // (curved boundary refines before t = 0 with Initial contact
    // refinements)
    const bool curved = curved_boundary() != nullptr;
    for (const std::string entry : {"Refinement interval",
                                    "Refinement interval without contact",
                                    "Refine fraction",
                                    "Coarsen fraction",
                                    "Coarsening tolerance",
                                    "Position tolerance",
                                    "Keep body motion",
                                    "Error tolerance",
                                    "Error tolerance split",
                                    "Minimum level",
                                    "Front widening",
                                    "Criteria"})
      if ((entry != std::string("Refinement interval") || interval > 0) &&
          (entry != std::string("Criteria") || !curved))
        unread.emplace_back("Mesh refinement/" + entry, why);
    if (initial_refinements == 0)
      for (const std::string entry : {"Maximum level", "Contact zone"})
        unread.emplace_back("Mesh refinement/" + std::string(entry),
                            why + ", and Initial contact refinements = 0");
    else
      unread.emplace_back("Mesh refinement/Contact zone/Keep distance", why);
    return unread;
  }



  template <int dim>
  std::string
  MeshAdaptor<dim>::memory_remedy(const bool initial) const
  {
    std::ostringstream text; // 6 digits
    if (initial)
      {
        text << "Mesh refinement/Initial contact refinements (now "
             << initial_refinements << ") or Maximum level (now " << max_level
             << ")";
        return text.str();
      }
    // (the caller writes "Reduce " before it)
    text << "Mesh refinement/Maximum level (now " << max_level << ")";
    if (error_tolerance == 0.)
      text << ", Refine fraction (now " << refine_fraction << ")";
    if (front_widening > 0.)
      text << ", Front widening (now " << front_widening << ")";
    if (error_tolerance > 0.)
      text << ", or raise Error tolerance (now " << error_tolerance << ")";
    else
      text << ", or raise Refinement interval (now " << interval << ")";
    return text.str();
  }



  // (the class is instantiated in mesh_adaptor.cc)
  template std::vector<std::pair<std::string, std::string>>
  MeshAdaptor<2>::unread_entries(const bool) const;
  template std::vector<std::pair<std::string, std::string>>
  MeshAdaptor<3>::unread_entries(const bool) const;
  template std::string
  MeshAdaptor<2>::memory_remedy(const bool) const;
  template std::string
  MeshAdaptor<3>::memory_remedy(const bool) const;
} // namespace dyncontact
