#include <dyncontact/output/summary.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace dyncontact
{
  namespace
  {
    /// The row of the largest value of a column (the first one; rows
    /// without a value, nan, are left out).
    unsigned int
    arg_max(const std::vector<double> &v)
    {
      unsigned int best = 0;
      for (unsigned int r = 0; r < v.size(); ++r)
        if (!std::isnan(v[r]) && (std::isnan(v[best]) || v[r] > v[best]))
          best = r;
      return best;
    }

    /// The row of the last value of a column that is not nan.
    unsigned int
    last_value(const std::vector<double> &v)
    {
      for (unsigned int r = v.size(); r > 0; --r)
        if (!std::isnan(v[r - 1]))
          return r - 1;
      return v.size() - 1;
    }
  } // namespace



  std::string
  summary_text(const Statistics &s, const SummaryInput &input)
  {
    std::ostringstream out;
    out << std::setprecision(6);
    if (s.rows.empty())
      return "steps: 0\n";
    const auto         time   = s.column("time");
    const auto         step   = s.column("step");
    const std::string  force  = input.dim == 2 ? "N/m" : "N";
    const std::string  energy = input.dim == 2 ? "J/m" : "J";
    const unsigned int last   = s.rows.size() - 1;
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
            << " steps repeated for the error estimate, " << input.step_matrices
            << " step matrices S built\n";
      }

    if (s.has_column("active_nodes") && input.is_static)
      {
        const std::string measure = input.dim == 2 ? "m" : "m^2";
        out << "active nodes: " << s.column("active_nodes")[last]
            << ", measure " << s.column("active_measure")[last] << " "
            << measure << "\n"
            << "contact force: " << s.column("contact_force")[last] << " "
            << force << "\n"
            << "peak contact pressure: "
            << s.column("max_contact_pressure")[last] << " Pa\n"
            << "largest penetration: " << s.column("max_penetration")[last]
            << " m\n";
      }
    else if (s.has_column("active_nodes"))
      {
        // an interval runs from the first to the last step of a run of
        // steps with active rows
        const auto               active = s.column("active_nodes");
        std::vector<std::string> intervals;
        for (unsigned int r = 0; r <= last; ++r)
          if (active[r] > 0 && (r == 0 || active[r - 1] == 0))
            {
              unsigned int e = r;
              while (e < last && active[e + 1] > 0)
                ++e;
              std::ostringstream interval;
              interval << std::setprecision(6) << "[" << time[r] << ", "
                       << time[e] << "]";
              intervals.push_back(interval.str());
            }
        out << "contact intervals: " << intervals.size();
        for (unsigned int i = 0;
             i < std::min<std::size_t>(intervals.size(), 20);
             ++i)
          out << (i == 0 ? ": " : ", ") << intervals[i];
        if (intervals.size() > 20)
          out << ", ...";
        out << (intervals.empty() ? "" : " s") << "\n";
        const auto contact_force = s.column("contact_force");
        const auto pressure      = s.column("max_contact_pressure");
        const auto penetration   = s.column("max_penetration");
        out << "peak contact force: " << contact_force[arg_max(contact_force)]
            << " " << force << " at t = " << time[arg_max(contact_force)]
            << " s\n"
            << "peak contact pressure: " << pressure[arg_max(pressure)]
            << " Pa at t = " << time[arg_max(pressure)] << " s\n"
            << "largest penetration: " << penetration[arg_max(penetration)]
            << " m at t = " << time[arg_max(penetration)] << " s\n";
      }

    if (s.has_column("energy_balance") && !input.is_static)
      {
        const auto kinetic     = s.column("energy_kinetic");
        const auto elastic     = s.column("energy_elastic");
        const auto dissipation = s.column("dissipation_viscous");
        const auto balance     = s.column("energy_balance");
        double     scale = 0., increase = 0.;
        unsigned   at = 0;
        for (unsigned int r = 0; r <= last; ++r)
          {
            scale =
              std::max(scale,
                       kinetic[r] + std::abs(elastic[r]) + dissipation[r]);
            if (r > 0 && balance[r] - balance[r - 1] > increase)
              {
                increase = balance[r] - balance[r - 1];
                at       = r;
              }
          }
        const double relative = increase / std::max(scale, 1e-300);
        out << "energy E + W_visc: " << kinetic[0] + elastic[0] + dissipation[0]
            << " " << energy << " at the start, "
            << kinetic[last] + elastic[last] + dissipation[last] << " "
            << energy << " at the end, energy_balance " << balance[last] << " "
            << energy << "\n"
            << "largest energy increase between steps: " << increase << " "
            << energy;
        if (increase > 0.)
          out << " at t = " << time[at] << " s";
        out << " (" << relative << " of the energy scale " << scale << " "
            << energy << "); Theorem 3.2 "
            << (relative <= input.energy_tolerance ? "held" : "did not hold")
            << " within the monitor's tolerance " << input.energy_tolerance
            << "\n";
      }

    if (s.has_column("critical_measure_sum") && !input.is_static)
      out << "sum of meas Gamma*: " << s.column("critical_measure_sum")[last]
          << " (eq. 40, summed over the steps)\n";

    for (const std::string name : {"error_energy_norm", "error_reference"})
      if (s.has_column(name))
        {
          const auto e = s.column(name);
          out << name << ": " << e[last_value(e)]
              << " at t = " << time[last_value(e)] << " s (the last value), "
              << e[arg_max(e)] << " at most (t = " << time[arg_max(e)]
              << " s)\n";
        }

    auto total = [&](const std::string &name) {
      double sum = 0.;
      if (s.has_column(name))
        for (const double v : s.column(name))
          sum += v;
      return sum;
    };
    if (s.has_column("active_set_iterations"))
      out << "iterations: active-set " << total("active_set_iterations")
          << ", projection " << total("projection_iterations") << ", CG "
          << total("linear_iterations") << "\n";
    out << "preconditioner: " << (input.uses_amg ? "AMG" : "Jacobi");
    if (std::isfinite(input.condition_bound))
      out << " (condition number of S scaled by its diagonal at most "
          << std::setprecision(3) << input.condition_bound
          << std::setprecision(6) << ")";
    out << (input.adaptive_time_steps ? " for the last step matrix" : "")
        << "\n";

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
