#ifndef dyncontact_core_input_checks_h
#define dyncontact_core_input_checks_h

#include <deal.II/base/exceptions.h>

#include <cmath>
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
} // namespace dyncontact

#endif
