#ifndef dyncontact_time_stepping_row_force_h
#define dyncontact_time_stepping_row_force_h

#include <dyncontact/time_stepping/step_operators.h>

namespace dyncontact
{
  /// The normal contact force of row @p p in the step of @p report (N; per
  /// unit thickness in 2D): the row's multiplier times the step's force
  /// factor if the row is active, 0 if not.
  inline double
  row_force(const StepReport &report, const unsigned int p)
  {
    return report.active[p] ? report.force_factor * report.multipliers[p] : 0.;
  }
} // namespace dyncontact

#endif
