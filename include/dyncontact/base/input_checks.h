#ifndef dyncontact_base_input_checks_h
#define dyncontact_base_input_checks_h

#include <deal.II/base/exceptions.h>

#include <cmath>
#include <map>
#include <sstream>
#include <string>

namespace dyncontact
{
  /// @p x as a message prints it: six significant digits.
  inline std::string
  format_number(const double x)
  {
    std::ostringstream s;
    s << x;
    return s.str();
  }

  /**
   * Stops with a message naming the parameter @p entry (e.g.
   * "Material/Density"), the range [@p min, @p max] in @p unit and the value
   * given, unless @p value is a finite number in that range. The ranges of
   * physical data are wide (many orders of magnitude beyond any material or
   * body), but finite: values far outside them overflow or underflow the
   * matrices and would give NaN or garbage instead of a message.
   */
  inline void
  check_in_range(const double       value,
                 const double       min,
                 const double       max,
                 const std::string &entry,
                 const std::string &unit)
  {
    if (std::isfinite(value) && value >= min && value <= max)
      return;
    std::ostringstream message;
    message << entry << " must be a finite number in [" << min << ", " << max
            << "]" << (unit.empty() ? "" : " " + unit) << "; got " << value
            << ".";
    AssertThrow(false, dealii::ExcMessage(message.str()));
  }

  /**
   * Stops with a message naming @p where unless the sides @p a and @p b
   * (m) of a block's cells lie within a ratio of 1000 of each other
   * (thinner cells make the matrices too ill-conditioned to solve).
   */
  inline void
  check_cell_sides(const double a, const double b, const std::string &where)
  {
    AssertThrow(a <= 1e3 * b && b <= 1e3 * a,
                dealii::ExcMessage(
                  where + ": the cells would be degenerate (sides " +
                  format_number(a) + " and " + format_number(b) +
                  " m, a ratio beyond 1000): adjust Length, Height and the "
                  "cell counts."));
  }

  /**
   * The number stored under @p key in a checkpoint's @p state (its
   * state.txt), if it is a finite number in [@p min, @p max]; otherwise
   * stops with a message naming @p what (e.g. "time t (s)"), the key and the
   * text found. The checksums of state.txt guard against damage; this
   * guards against a checkpoint whose values were edited (or written by a
   * run whose state had gone wrong), which would otherwise be blamed on
   * some parameter of the input.
   */
  inline double
  checkpoint_number(const std::map<std::string, std::string> &state,
                    const std::string                        &key,
                    const std::string                        &what,
                    const double                              min,
                    const double                              max)
  {
    const auto entry = state.find(key);
    double     value = std::nan("");
    if (entry != state.end())
      try
        {
          std::size_t end = 0;
          value           = std::stod(entry->second, &end);
          if (end != entry->second.size())
            value = std::nan("");
        }
      catch (const std::exception &)
        {}
    if (std::isfinite(value) && value >= min && value <= max)
      return value;
    std::ostringstream message;
    message << "Checkpointing/Resume: the checkpoint's " << what << " ('" << key
            << "' = "
            << (entry == state.end() ? std::string("missing") :
                                       "'" + entry->second + "'")
            << ") is not a finite number in [" << min << ", " << max
            << "]: the checkpoint is damaged. Resume from another one, if "
               "one is kept beside it (write its folder's name into the file "
               "'last' of the checkpoints), or start afresh.";
    AssertThrow(false, dealii::ExcMessage(message.str()));
    return value;
  }
} // namespace dyncontact

#endif
