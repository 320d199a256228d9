#include <dyncontact/output/summary.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace dyncontact
{
  std::string
  summary_text(const Statistics   &s,
               const SummaryInput &input,
               const std::string  &statistics_lines)
  {
    std::ostringstream out;
    out << std::setprecision(6);
    if (s.rows.empty())
      return "steps: 0\n";
    const auto         time = s.column("time");
    const auto         step = s.column("step");
    const unsigned int last = s.rows.size() - 1;
    if (input.is_static)
      out << "static problem: one constrained solve (no time)\n";
    else
      out << "steps: " << step[last] << "\n"
          << "time: " << time[0] << " to " << time[last] << " s\n";
    if (input.adaptive_time_steps && s.has_column("time_step") && last > 0)
      {
        const auto tau = s.column("time_step");
        out << "time steps: adaptive, tau from "
            << *std::min_element(tau.begin() + 1, tau.end()) << " to "
            << *std::max_element(tau.begin() + 1, tau.end()) << " s, "
            << input.located_events << " steps shortened to a contact event, "
            << input.repeated_steps
            << " steps repeated for the error estimate, "
            << (input.passed_output_times > 0 ?
                  std::to_string(input.passed_output_times) +
                    " output times passed for a contact event, " :
                  std::string())
            << input.step_matrices << " step matrices S built\n";
      }

    out << statistics_lines;
    out << "preconditioner: " << input.preconditioner
        << (input.matrix_free ? " on the matrix-free step operator" : "");
    if (input.matrix_free)
      out << " (largest S_ii/M_ii " << std::setprecision(3)
          << input.inertia_ratio << std::setprecision(6) << ")";
    else if (std::isfinite(input.condition_bound))
      out << " (condition number of S scaled by its diagonal at most "
          << std::setprecision(3) << input.condition_bound
          << std::setprecision(6) << ")";
    out << (input.adaptive_time_steps ? " for the last step matrix" : "")
        << "\n";

    if (!input.ranks_and_mesh.empty())
      out << "parallel: " << input.ranks_and_mesh << "\n";
    out << std::setprecision(3) << "wall time: " << input.wall_time
        << " s, of which the time loop " << input.loop_wall_time << " s\n";
    std::size_t width = 0;
    for (const auto &section : input.section_wall_times)
      width = std::max(width, section.first.size());
    for (const auto &[section, wall] : input.section_wall_times)
      out << "  " << std::left << std::setw(width) << section << std::right
          << std::setw(10) << wall << " s " << std::setw(8)
          << static_cast<unsigned long>(input.section_calls.at(section))
          << " calls  " << std::setw(5) << std::fixed << std::setprecision(1)
          << 100. * wall / std::max(input.wall_time, 1e-300) << "%\n"
          << std::defaultfloat << std::setprecision(3);
    return out.str();
  }
} // namespace dyncontact
