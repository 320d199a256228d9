#include <dyncontact/output/progress.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace dyncontact
{
  Progress::Progress(const double interval, const ConditionalOStream &pcout)
    : interval(interval)
    , pcout(pcout)
  {}



  void
  Progress::start()
  {
    clock.restart();
    last_line = 0.;
    started   = false;
  }



  namespace
  {
    /// A duration in s as "12 s", "3.4 min" or "1.2 h".
    std::string
    duration(const double seconds)
    {
      std::ostringstream s;
      if (seconds < 90.)
        s << std::fixed << std::setprecision(seconds < 10. ? 1 : 0) << seconds
          << " s";
      else if (seconds < 5400.)
        s << std::fixed << std::setprecision(1) << seconds / 60. << " min";
      else
        s << std::fixed << std::setprecision(1) << seconds / 3600. << " h";
      return s.str();
    }
  } // namespace



  void
  Progress::step(const unsigned int step,
                 const double       time,
                 const double       end_time,
                 const double       tau,
                 const double       steps_to_end,
                 const unsigned int active_rows,
                 const unsigned int rows,
                 const unsigned int active_set_iterations,
                 const unsigned int linear_iterations)
  {
    if (!started)
      {
        steps_at_start = step - 1;
        started        = true;
      }
    if (interval <= 0. || !pcout.is_active())
      return;
    const double wall = clock.wall_time();
    if (wall - last_line < interval)
      return;
    last_line                    = wall;
    const double       per_step  = wall / std::max(1u, step - steps_at_start);
    const double       remaining = steps_to_end * per_step;
    std::ostringstream line;
    line << std::setprecision(4) << "   step " << step << ", t = " << time
         << " / " << end_time << " s (" << std::fixed << std::setprecision(0)
         << 100. * time / std::max(end_time, 1e-300) << "%)"
         << std::defaultfloat << std::setprecision(3) << ", tau = " << tau
         << " s";
    if (rows > 0)
      line << ", active " << active_rows << "/" << rows << ", active-set it. "
           << active_set_iterations;
    line << ", CG it. " << linear_iterations << ", " << per_step
         << " s/step, about " << duration(remaining) << " to go" << std::endl;
    pcout << line.str();
  }
} // namespace dyncontact
