#ifndef dyncontact_core_parameter_file_h
#define dyncontact_core_parameter_file_h

#include <functional>
#include <set>
#include <string>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace dyncontact
{
  /**
   * A class that owns subsections of the prm: it declares every entry of
   * them (a plugin manager also has its plugins declare theirs, each in
   * <Component>/<Plugin>), reads them, and hands the values to the
   * components that use them. No subsection has two owners (tested by
   * tests/parameter_owners).
   */
  struct ParameterOwner
  {
    std::string                                     name;
    std::function<void(dealii::ParameterHandler &)> declare_parameters;
  };

  /// Every owner of parameters, in the order of declaration.
  const std::vector<ParameterOwner> &
  parameter_owners();

  /// Declares every parameter of the program (all owners, with plugins).
  void
  declare_all_parameters(dealii::ParameterHandler &prm);

  /// The full names (subsection/.../entry) of every entry declared in
  /// @p prm.
  std::set<std::string>
  declared_entries(const dealii::ParameterHandler &prm);

  /**
   * Stops with a clear message if the prm text @p text sets an entry in a
   * subsection that does not declare it but another one does: an entry of
   * the old flat layout (e.g. "Length" directly in subsection Scene, which
   * moved to Scene/Bar impact, or "Slave side", which moved to Contact), or
   * an entry of another scene. The message names the line and the
   * subsections that declare the entry. Also stops if a value does not match
   * its entry's pattern (for a number: its range), naming the line, the
   * entry with its subsections, the value and the values allowed, where
   * @p origins (from expand_includes()) says the line came from. Called
   * before the text is parsed. Returns the entries the text sets, as
   * (full name "Subsection/.../Entry", where its line came from), in the
   * order of the text.
   */
  std::vector<std::pair<std::string, std::string>>
  check_for_misplaced_entries(const std::string              &text,
                              const std::vector<std::string> &origins);

  /**
   * The warnings (lines of text) for the entries of @p set_entries (full
   * name, where it was set: check_for_misplaced_entries()) that a run does
   * not read: those of subsection Scene outside @p scene_subsection (the
   * scene @p scene_name reads its own only), and those that @p unread
   * names (an entry or a whole subsection, and why), each once, at the
   * last line that sets it (whose value the run would take).
   */
  std::string
  unread_entry_warnings(
    const std::vector<std::pair<std::string, std::string>> &set_entries,
    const std::string                                      &scene_name,
    const std::string                                      &scene_subsection,
    const std::vector<std::pair<std::string, std::string>> &unread);

  /**
   * The prm text @p text (read from @p source) with a leading UTF-8 byte
   * order mark removed and every line "include <file>" replaced by the
   * text of that file (recursively; a relative name refers to the folder of
   * the including file, else to the working directory, as deal.II's
   * ParameterHandler reads it). A file that includes itself, directly or
   * through others, a missing include file, or more than 32 nested levels
   * stop with a message naming the files and lines. @p origins gets, for
   * each line of the result, where it came from ("Line 3 of 'inc.prm'"),
   * for the messages about it.
   */
  std::string
  expand_includes(const std::string        &text,
                  const std::string        &source,
                  std::vector<std::string> &origins);

  /**
   * @p message of deal.II's parser about line N of the expanded text of
   * @p source ("Line <N> of file <source>") with the line's origin in its
   * place (an included file's own line); other messages unchanged.
   */
  std::string
  with_origin(const std::string              &message,
              const std::string              &source,
              const std::vector<std::string> &origins);
} // namespace dyncontact

#endif
