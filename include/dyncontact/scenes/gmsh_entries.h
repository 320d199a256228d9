#ifndef dyncontact_scenes_gmsh_entries_h
#define dyncontact_scenes_gmsh_entries_h

#include <deal.II/base/tensor.h>

#include <array>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace dealii
{
  template <int dim>
  class FunctionParser;
}

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

    /// The items of @p text between the @p separator outside parentheses
    /// (so that 'min(t, 1), 0' is two items), trimmed; none for an empty
    /// text.
    std::vector<std::string>
    split_top_level(const std::string &text, const char separator);

    /// Function constants: 'name = value', comma-separated (names of
    /// letters, digits and '_', not x, y, z, t or body).
    std::map<std::string, double>
    parse_constants(const std::string &text);

    /// Whether one of @p expressions uses the variable t.
    bool
    mentions_time(const std::vector<std::string> &expressions);

    /// A function parser of @p expressions (one per component) in x, y (,
    /// z) and, if @p of_time, t, with @p constants; an expression that does
    /// not parse is refused naming Scene/Gmsh/@p entry, the component and
    /// muparser's message (with the position).
    template <int dim>
    std::shared_ptr<dealii::FunctionParser<dim>>
    make_function(const std::string                   &entry,
                  const std::vector<std::string>      &expressions,
                  const std::map<std::string, double> &constants,
                  const bool                           of_time);
  } // namespace GmshEntries
} // namespace dyncontact

#endif
