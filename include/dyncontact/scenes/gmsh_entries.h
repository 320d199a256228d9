#ifndef dyncontact_scenes_gmsh_entries_h
#define dyncontact_scenes_gmsh_entries_h

#include <deal.II/base/tensor.h>

#include <array>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace dyncontact
{
  /**
   * The text forms of the entries of subsection Scene/Gmsh; each refuses a
   * malformed text with a message naming Scene/Gmsh/@p entry.
   */
  namespace GmshEntries
  {
    /// A list of tags "1, 2, 3" (each in [0, 65535)).
    std::set<unsigned int>
    parse_tags(const std::string &text, const std::string &entry);

    /// "Dirichlet tags": a list of tags, each with the displacement
    /// components it fixes ("10, 11: y, 12: xz"; a tag alone fixes all).
    template <int dim>
    std::map<unsigned int, std::array<bool, 3>>
    parse_dirichlet_tags(const std::string &text);

    /// A vector of dim components "1, 0" (in 2D also three, the last 0),
    /// each of magnitude at most @p max_component in @p unit.
    template <int dim>
    dealii::Tensor<1, dim>
    parse_vector(const std::string &text,
                 const std::string &entry,
                 const double       max_component,
                 const std::string &unit);

    /// The items of @p text between the @p separator, trimmed, empty ones
    /// kept (Utilities::split_string_list drops a last empty item); none
    /// for an empty text.
    std::vector<std::string>
    split_items(const std::string &text, const char separator);
  } // namespace GmshEntries
} // namespace dyncontact

#endif
