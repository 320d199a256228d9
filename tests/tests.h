// Helpers shared by the tests: build parameter texts, run the program's
// library, summarise statistics, and print a deal.II-style "output" file
// (rank 0 only) with few enough digits to be stable across machines.
#ifndef dyncontact_tests_h
#define dyncontact_tests_h

#include <dyncontact/base/statistics.h>
#include <dyncontact/core/run.h>

#include <mpi.h>
#include <sys/wait.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace testing
{
  using dyncontact::Statistics;

  /// This process's rank in MPI_COMM_WORLD. (tests.h includes none of
  /// deal.II, so that a test that includes only it compiles in a second.)
  inline unsigned int
  this_rank()
  {
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    return rank;
  }

  /// The number of ranks in MPI_COMM_WORLD.
  inline unsigned int
  n_ranks()
  {
    int n = 1;
    MPI_Comm_size(MPI_COMM_WORLD, &n);
    return n;
  }

  /// The whole content of @p file ("" if it cannot be read).
  inline std::string
  read(const std::string &file)
  {
    std::ifstream     in(file, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }

  /// The file "output" on rank 0, a null stream elsewhere.
  inline std::ostream &
  log()
  {
    static std::ofstream      file;
    static std::ostringstream sink;
    if (this_rank() != 0)
      {
        sink.str("");
        return sink;
      }
    if (!file.is_open())
      file.open("output");
    return file;
  }

  /// A number with @p digits significant digits.
  inline std::string
  fmt(const double x, const int digits = 3)
  {
    std::ostringstream s;
    s << std::setprecision(digits) << (std::abs(x) < 1e-300 ? 0. : x);
    return s.str();
  }

  /// "OK" or "FAILED", so that a failed check changes the output.
  inline std::string
  check(const bool ok)
  {
    return ok ? "OK" : "FAILED";
  }

  /// The bar impact of prm/bar_impact.prm (E = rho = v0 = L = 1, g0 = 0.1,
  /// H = 0.1) with the given scheme, cells along the length, time step and
  /// end time; @p extra is appended (later entries override earlier ones).
  /// The same geometry is also given to the scene "two bars", so that
  /// @p extra may switch to it (with scene_prm("two bars", ...)).
  inline std::string
  bar_prm(const unsigned int dim,
          const std::string &scheme,
          const unsigned int cells,
          const double       tau,
          const double       end_time,
          const std::string &extra = "")
  {
    std::ostringstream s;
    s << std::setprecision(17);
    s << "set Dimension = " << dim << "\n"
      << "set Output directory = output-" << scheme << "-" << cells << "\n"
      << "subsection Scene\n  set Name = bar impact\n";
    for (const std::string subsection : {"Bar impact", "Two bars"})
      s << "  subsection " << subsection << "\n    set Length = 1\n"
        << "    set Height = 0.1\n    set Impact velocity = 1\n"
        << "    set Initial gap = 0.1\n    set Cells along length = " << cells
        << "\n  end\n";
    s << "end\n"
      << "subsection Material\n  set Young's modulus = 1\n"
      << "  set Poisson's ratio = 0\n  set Density = 1\nend\n"
      << "subsection Time integration\n  set Scheme = " << scheme
      << "\n  set Time step = " << tau << "\n  set End time = " << end_time
      << "\n  set Mass matrix = lumped\nend\n"
      << "subsection Output\n  set Write vtu = false\nend\n"
      << "subsection Postprocess\n  subsection Error energy norm\n"
      << "    set Interval = every step\n  end\nend\n"
      << extra;
    return s.str();
  }

  /// "subsection Checkpointing": a checkpoint every @p steps steps, and
  /// whether the run resumes from the last one (the tests that split a run
  /// at a checkpoint).
  inline std::string
  checkpointing(const unsigned int steps, const bool resume)
  {
    return "subsection Checkpointing\n  set Interval in steps = " +
           std::to_string(steps) +
           "\n  set Resume = " + (resume ? "true" : "false") + "\nend\n";
  }

  /// Entries for the tests that compare two runs (another preconditioner,
  /// rank count, triangulation, a rotated or resumed run) or check a
  /// conservation law closer than the default Step solver tolerance (1e-7
  /// of each step's increment) keeps them: 1e-12.
  inline std::string
  tight_steps()
  {
    return "subsection Contact solver\n"
           "  set Step solver tolerance = 1e-12\nend\n";
  }

  /// "subsection Scene" choosing the scene @p name, with @p entries (lines
  /// "set ... = ...") in the scene's own subsection (its name with a
  /// capital first letter).
  inline std::string
  scene_prm(const std::string &name, const std::string &entries = "")
  {
    std::string subsection = name;
    subsection[0]          = std::toupper(subsection[0]);
    return "subsection Scene\n  set Name = " + name + "\n  subsection " +
           subsection + "\n" + entries + "  end\nend\n";
  }

  /// @p entries in subsection Scene/@p subsection, without choosing a scene.
  inline std::string
  scene_entries(const std::string &subsection, const std::string &entries)
  {
    return "subsection Scene\n  subsection " + subsection + "\n" + entries +
           "  end\nend\n";
  }

  inline Statistics
  run(const std::string &prm)
  {
    return dyncontact::run_simulation(prm, MPI_COMM_WORLD, "test input");
  }

  /// The message of the error the run of @p prm stops with (for deal.II's
  /// exceptions the additional information alone, without the place in the
  /// source; every run of white space is one space here), or "" if it
  /// does not stop; in this process, on every rank.
  inline std::string
  error_of(const std::string &prm)
  {
    std::string message;
    try
      {
        run(prm);
      }
    catch (const std::exception &e)
      {
        std::string       text = e.what();
        const std::size_t info = text.find("Additional information:");
        if (info != std::string::npos)
          text = text.substr(info + 23, text.find("Stacktrace:") - info - 23);
        std::istringstream words(text);
        for (std::string word; words >> word;)
          message += (message.empty() ? "" : " ") + word;
      }
    return message;
  }

  /// First and last time with active contact rows (-1 if none).
  inline std::pair<double, double>
  contact_interval(const Statistics &s)
  {
    const auto t = s.column("time"), a = s.column("active_nodes");
    double     begin = -1., end = -1.;
    for (unsigned int i = 0; i < t.size(); ++i)
      if (a[i] > 0)
        {
          if (begin < 0)
            begin = t[i];
          end = t[i];
        }
    return {begin, end};
  }

  inline double
  max_of(const std::vector<double> &v)
  {
    return *std::max_element(v.begin(), v.end());
  }

  inline double
  min_of(const std::vector<double> &v)
  {
    return *std::min_element(v.begin(), v.end());
  }

  inline double
  mean_of(const std::vector<double> &v)
  {
    double sum = 0.;
    for (const double x : v)
      sum += x;
    return sum / v.size();
  }

  /// Largest |c_p . udot| over the rows active in a step and the next one
  /// (persistent contact), and the number of such steps.
  inline std::pair<double, unsigned int>
  persistent_normal_velocity(const Statistics &s)
  {
    const auto   active = s.column("active_nodes");
    const auto   vn     = s.column("max_active_normal_velocity");
    double       vn_max = 0.;
    unsigned int n      = 0;
    for (unsigned int i = 0; i + 1 < active.size(); ++i)
      if (active[i] > 0 && active[i + 1] > 0)
        {
          vn_max = std::max(vn_max, vn[i]);
          ++n;
        }
    return {vn_max, n};
  }

  /// A statistics.tsv file as a table.
  inline Statistics
  read_statistics(const std::string &file)
  {
    Statistics    s;
    std::ifstream in(file);
    std::string   line;
    std::getline(in, line);
    std::stringstream header(line);
    for (std::string cell; std::getline(header, cell, '\t');)
      s.columns.push_back(cell);
    while (std::getline(in, line))
      {
        std::vector<double> row;
        std::stringstream   cells(line);
        for (std::string cell; std::getline(cells, cell, '\t');)
          row.push_back(std::stod(cell));
        s.rows.push_back(row);
      }
    return s;
  }

  /// The last row of a statistics.tsv file, as numbers.
  inline std::vector<double>
  last_row(const std::string &file)
  {
    std::ifstream in(file);
    std::string   line, last;
    while (std::getline(in, line))
      if (!line.empty())
        last = line;
    std::vector<double> values;
    std::stringstream   s(last);
    for (std::string cell; std::getline(s, cell, '\t');)
      values.push_back(std::stod(cell));
    return values;
  }

  /**
   * The largest difference between the statistics @p a and @p b and its
   * column: every column but the wall times, each relative to its largest
   * value but at least 1e-2 (the physical scale of the tests: columns that
   * are zero up to round-off, or small differences of large quantities,
   * are compared to it). A column sampled in other rows (nan in one table,
   * a value in the other) differs by 1e300, except in row @p sampled_row
   * where only @p b has a value (the last step of a run that stopped
   * there); so do tables of other shapes.
   */
  inline std::pair<double, std::string>
  statistics_difference(
    const Statistics  &a,
    const Statistics  &b,
    const unsigned int sampled_row = static_cast<unsigned int>(-1))
  {
    if (a.rows.size() != b.rows.size() || a.columns != b.columns)
      return {1e300, "the shape"};
    std::pair<double, std::string> largest = {0., ""};
    for (unsigned int k = 0; k < a.columns.size(); ++k)
      if (a.columns[k] != "step_wall_time")
        {
          double scale = 1e-2, d = 0.;
          for (unsigned int i = 0; i < a.rows.size(); ++i)
            {
              const double x = a.rows[i][k], y = b.rows[i][k];
              scale = std::max(scale, std::abs(x));
              if (std::isnan(x) != std::isnan(y))
                {
                  if (!(i == sampled_row && std::isnan(x)))
                    d = 1e300;
                }
              else if (!std::isnan(x))
                d = std::max(d, std::abs(x - y));
            }
          if (d / scale > largest.first)
            largest = {d / scale, a.columns[k]};
        }
    return largest;
  }

  /// Two runs of one problem by different solvers: the largest
  /// difference of their statistics apart from the iteration counts
  /// (statistics_difference()), and the CG iterations of each in all.
  struct SolverComparison
  {
    std::pair<double, std::string> difference;
    double                         cg_a = 0., cg_b = 0.;
  };

  inline SolverComparison
  compare_solvers(const Statistics &a, const Statistics &b)
  {
    SolverComparison result;
    Statistics       a0 = a, b0 = b;
    for (Statistics *s : {&a0, &b0})
      for (const std::string column : {"active_set_iterations",
                                       "projection_iterations",
                                       "linear_iterations"})
        for (unsigned int k = 0; k < s->columns.size(); ++k)
          if (s->columns[k] == column)
            for (auto &row : s->rows)
              row[k] = 0.;
    result.difference = statistics_difference(a0, b0);
    const auto cg_a   = a.column("linear_iterations");
    const auto cg_b   = b.column("linear_iterations");
    for (unsigned int i = 0; i < cg_a.size() && i < cg_b.size(); ++i)
      if (!std::isnan(cg_a[i]))
        {
          result.cg_a += cg_a[i];
          result.cg_b += cg_b[i];
        }
    return result;
  }

  /// The calls of the TimerOutput section @p section in the summary file
  /// @p summary (0 if it is not there).
  inline unsigned int
  timer_calls(const std::string &summary, const std::string &section)
  {
    std::ifstream in(summary);
    for (std::string line; std::getline(in, line);)
      if (line.rfind("  " + section + " ", 0) == 0)
        {
          std::istringstream s(line.substr(section.size() + 2));
          double             seconds;
          std::string        unit;
          unsigned int       calls = 0;
          s >> seconds >> unit >> calls;
          return calls;
        }
    return 0;
  }

  /// Entries for bar_prm(): Q2, the mesh adapted every 4 steps up to two
  /// levels at the contact zone.
  inline std::string
  q2_contact_zone_prm()
  {
    return "set Polynomial degree = 2\n"
           "subsection Mesh refinement\n"
           "  set Refinement interval = 4\n"
           "  set Maximum level = 2\n"
           "  set Criteria = contact zone\n"
           "end\n";
  }

  /// Entries for bar_prm() of the adaptive resume tests: the two bars (1
  /// and 2 cells across) on a mesh adapted every 4 steps by the velocity's
  /// Kelly indicator and the contact zone.
  inline std::string
  adaptive_two_bars_prm()
  {
    return scene_prm("two bars",
                     "    set Cells across = 1\n"
                     "    set Cells across body 2 = 2\n") +
           "subsection Mesh refinement\n"
           "  set Refinement interval = 4\n"
           "  set Maximum level = 2\n"
           "  set Refine fraction = 0.3\n"
           "  set Coarsen fraction = 0.1\n"
           "  set Criteria = kelly velocity, contact zone\n"
           "end\n";
  }

  /// entries for bar_prm() (40 cells along, tau = 1/160 s): two bars of 4
  /// and 5 cells across the coarse mesh, adapted by the recovery indicator
  /// up to one level; the finer side of the interface changes at t = 0.63
  /// s, on 1 and 2 ranks.
  inline std::string
  recovery_two_bars_prm()
  {
    return scene_prm("two bars",
                     "    set Cells across = 4\n"
                     "    set Cells across body 2 = 5\n") +
           "subsection Mesh refinement\n"
           "  set Refinement interval = 2\n"
           "  set Maximum level = 1\n"
           "  set Initial contact refinements = 1\n"
           "  set Criteria = recovery velocity\n"
           "end\n";
  }

  struct Outcome
  {
    int         status;
    std::string text;
  };

  /// Whether @p outcome printed "dyncontact: error:" and, after it,
  /// @p fragment (an empty one: only the error line).
  inline bool
  error_names(const Outcome &outcome, const std::string &fragment)
  {
    const auto at = outcome.text.find("dyncontact: error:");
    return at != std::string::npos &&
           outcome.text.find(fragment, at) != std::string::npos;
  }

  /// Whether @p outcome printed no backtrace (neither deal.II's "An error
  /// occurred in" nor a stack trace).
  inline bool
  without_backtrace(const Outcome &outcome)
  {
    return outcome.text.find("Stacktrace") == std::string::npos &&
           outcome.text.find("An error occurred in") == std::string::npos;
  }

  /// Runs the dyncontact executable with @p arguments (after the shell
  /// text @p prefix, e.g. "ulimit -v 100000; "); exit status and all it
  /// printed.
  inline Outcome
  run_program(const std::string &arguments, const std::string &prefix = "")
  {
#ifdef DYNCONTACT_EXECUTABLE
    const std::string command =
      prefix + std::string(DYNCONTACT_EXECUTABLE) + " " + arguments + " 2>&1";
    FILE       *pipe = popen(command.c_str(), "r");
    std::string text;
    char        buffer[4096];
    while (fgets(buffer, sizeof(buffer), pipe) != nullptr)
      text += buffer;
    const int status = pclose(pipe);
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, text};
#else
    return {-1, arguments};
#endif
  }

  /// An axis-parallel block of nx x ny quadrilaterals with a physical cell
  /// tag and physical tags of its bottom, top and left edges (0: none).
  struct Block
  {
    double       x0, x1, y0, y1;
    unsigned int nx, ny, cell_tag, bottom_tag, top_tag, left_tag = 0,
                                                        right_tag = 0;
  };

  /// Writes a Gmsh 2.2 ASCII mesh of @p n_nodes lines of @p nodes ("k x y
  /// z") and @p n_elements lines of @p elements, on rank 0 (all ranks
  /// wait for it).
  inline void
  write_msh(const std::string &file,
            const unsigned int n_nodes,
            const std::string &nodes,
            const unsigned int n_elements,
            const std::string &elements)
  {
    if (this_rank() == 0)
      std::ofstream(file) << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n"
                          << n_nodes << "\n"
                          << nodes << "$EndNodes\n$Elements\n"
                          << n_elements << "\n"
                          << elements << "$EndElements\n";
    MPI_Barrier(MPI_COMM_WORLD);
  }

  /// Writes @p blocks as a Gmsh 2.2 ASCII mesh, no vertex shared.
  inline void
  write_block_msh(const std::string &file, const std::vector<Block> &blocks)
  {
    std::ostringstream nodes, elements;
    unsigned int       n_nodes = 0, n_elements = 0;
    nodes << std::setprecision(17);
    for (const Block &b : blocks)
      {
        const unsigned int first = n_nodes + 1;
        for (unsigned int j = 0; j <= b.ny; ++j)
          for (unsigned int i = 0; i <= b.nx; ++i)
            nodes << ++n_nodes << " " << b.x0 + (b.x1 - b.x0) * i / b.nx << " "
                  << b.y0 + (b.y1 - b.y0) * j / b.ny << " 0\n";
        const auto node = [&](const unsigned int i, const unsigned int j) {
          return first + j * (b.nx + 1) + i;
        };
        for (unsigned int j = 0; j < b.ny; ++j)
          for (unsigned int i = 0; i < b.nx; ++i)
            elements << ++n_elements << " 3 2 " << b.cell_tag << " "
                     << b.cell_tag << " " << node(i, j) << " " << node(i + 1, j)
                     << " " << node(i + 1, j + 1) << " " << node(i, j + 1)
                     << "\n";
        for (unsigned int i = 0; i < b.nx; ++i)
          {
            if (b.bottom_tag > 0)
              elements << ++n_elements << " 1 2 " << b.bottom_tag << " "
                       << b.bottom_tag << " " << node(i, 0) << " "
                       << node(i + 1, 0) << "\n";
            if (b.top_tag > 0)
              elements << ++n_elements << " 1 2 " << b.top_tag << " "
                       << b.top_tag << " " << node(i, b.ny) << " "
                       << node(i + 1, b.ny) << "\n";
          }
        for (unsigned int j = 0; j < b.ny && b.left_tag > 0; ++j)
          elements << ++n_elements << " 1 2 " << b.left_tag << " " << b.left_tag
                   << " " << node(0, j) << " " << node(0, j + 1) << "\n";
        for (unsigned int j = 0; j < b.ny && b.right_tag > 0; ++j)
          elements << ++n_elements << " 1 2 " << b.right_tag << " "
                   << b.right_tag << " " << node(b.nx, j) << " "
                   << node(b.nx, j + 1) << "\n";
      }
    write_msh(file, n_nodes, nodes.str(), n_elements, elements.str());
  }

  /// As run_program(@p file), in this process: the executable's own code
  /// after MPI starts (dyncontact::run_command_line()), its exit status and
  /// all it printed on std::cout and std::cerr; about a second faster than
  /// a start of the executable, for tests of many inputs. (A run of the
  /// executable removes the Open MPI session directory of this process,
  /// so that the checkpoints it reads or writes with MPI-IO must come
  /// before the first run_program() of a test.)
  inline Outcome
  run_in_process(const std::string &file)
  {
    std::ostringstream captured;
    // (the program's messages set their precision on std::cout)
    const std::ios_base::fmtflags flags     = std::cout.flags();
    const std::streamsize         precision = std::cout.precision();
    std::streambuf               *out       = std::cout.rdbuf(captured.rdbuf());
    std::streambuf               *err       = std::cerr.rdbuf(captured.rdbuf());
    std::string                   program = "dyncontact", argument = file;
    char *argv[] = {program.data(), argument.data(), nullptr};
    int   status = -1;
    try
      {
        status = dyncontact::run_command_line(2, argv);
      }
    catch (...)
      {
        // (run_command_line() lets nothing out; if it did, the executable
        // would end with a backtrace)
        captured << "An error occurred in run_command_line: an exception "
                    "escaped\n";
      }
    std::cout.rdbuf(out);
    std::cerr.rdbuf(err);
    std::cout.flags(flags);
    std::cout.precision(precision);
    return {status, captured.str()};
  }

  /// Runs a shell command in a clean environment (no MPI variables of this
  /// process, so that it may start mpirun or pvpython), returns what it
  /// printed, with a last line "command failed: ..." if it failed.
  inline std::string
  run_clean(const std::string &command)
  {
    const char       *path = std::getenv("PATH");
    const std::string full =
      std::string("env -i PATH='") + (path ? path : "/usr/bin:/bin") +
      "' HOME=/tmp OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 " +
      "OMPI_MCA_rmaps_base_oversubscribe=1 " + command + " 2>&1";
    FILE       *pipe = popen(full.c_str(), "r");
    std::string text;
    char        buffer[4096];
    while (fgets(buffer, sizeof(buffer), pipe) != nullptr)
      text += buffer;
    const int status = pclose(pipe);
    if (status != 0)
      text += "command failed: " + command + "\n";
    return text;
  }

  /// The dissipated energy W: the viscous one and, with Time
  /// integration/Numerical dissipation > 0, the scheme's own.
  inline std::vector<double>
  dissipated(const Statistics &s)
  {
    auto w = s.column("dissipation_viscous");
    if (s.has_column("dissipation_numerical"))
      {
        const auto w_num = s.column("dissipation_numerical");
        for (unsigned int i = 0; i < w.size(); ++i)
          w[i] += w_num[i];
      }
    return w;
  }

  /// The energy-norm error at the last row over sqrt(E(0)).
  inline double
  error_at_end(const Statistics &s)
  {
    return s.column("error_energy_norm").back() /
           std::sqrt(s.column("energy_total")[0]);
  }

  /// The largest |E^{n+1} - E^n| over the steps after the last active row.
  inline double
  change_after_release(const Statistics &s)
  {
    const auto e = s.column("energy_total"), active = s.column("active_nodes");
    unsigned int last = 0;
    for (unsigned int i = 0; i < e.size(); ++i)
      if (active[i] > 0)
        last = i;
    double change = 0.;
    for (unsigned int i = last + 2; i < e.size(); ++i)
      change = std::max(change, std::abs(e[i] - e[i - 1]));
    return change;
  }

  /// max_n (E^{n+1} + W^{n+1}) - (E^n + W^n): positive means energy growth.
  inline double
  max_energy_increase(const Statistics &s)
  {
    const auto e = s.column("energy_total"), w = dissipated(s);
    double     growth = -1e300;
    for (unsigned int i = 1; i < e.size(); ++i)
      growth = std::max(growth, (e[i] + w[i]) - (e[i - 1] + w[i - 1]));
    return growth;
  }
  /// On bar_prm()'s bar (v0 = c = 1, released at 2.1 s), @p s run with
  /// @p tau on @p cells cells along: E + W never increases, E is constant
  /// after the release, the normal velocity of persistently active nodes
  /// is zero (in more than @p min_steps steps), and the contact ends
  /// within 2 tau + h/c of 2.1 s; three lines of the log.
  inline void
  log_bar_release_checks(const Statistics  &s,
                         const double       tau,
                         const unsigned int cells,
                         const unsigned int min_steps)
  {
    const double e0 = s.column("energy_total")[0];
    log() << "  E + W non-increasing: "
          << check(max_energy_increase(s) <= 1e-10 * e0)
          << "; E constant after the release: "
          << check(change_after_release(s) <= 1e-10 * e0) << "\n";
    const auto [vn_max, n] = persistent_normal_velocity(s);
    log() << "  normal velocity at persistently active nodes zero: "
          << check(n > min_steps && vn_max < 1e-8) << "\n";
    const double end = contact_interval(s).second;
    log() << "  contact ends at " << fmt(end) << " (exact 2.1): "
          << check(std::abs(end - 2.1) <= 2. * tau + 1. / cells) << "\n";
  }

  /// The same on an adaptive mesh, less the energy changes of the mesh
  /// transfers (column energy_transfer), which Theorem 3.2 does not cover.
  inline double
  max_energy_increase_of_steps(const Statistics &s)
  {
    const auto e = s.column("energy_total"), w = dissipated(s),
               jump = s.column("energy_transfer");
    double growth   = -1e300;
    for (unsigned int i = 1; i < e.size(); ++i)
      growth =
        std::max(growth, (e[i] + w[i]) - (e[i - 1] + w[i - 1]) - jump[i]);
    return growth;
  }

  /// The largest energy change of the mesh transfers before one step.
  inline double
  largest_transfer(const Statistics &s)
  {
    double largest = 0.;
    for (const double jump : s.column("energy_transfer"))
      largest = std::max(largest, std::abs(jump));
    return largest;
  }
  /// A CSV file (separated by commas, no quoting) as rows of column ->
  /// text.
  inline std::vector<std::map<std::string, std::string>>
  read_csv(const std::string &file)
  {
    std::ifstream                                   in(file);
    std::vector<std::string>                        header;
    std::vector<std::map<std::string, std::string>> rows;
    for (std::string line; std::getline(in, line);)
      {
        std::vector<std::string> cells;
        std::stringstream        s(line);
        for (std::string cell; std::getline(s, cell, ',');)
          cells.push_back(cell);
        if (header.empty())
          header = cells;
        else
          {
            rows.emplace_back();
            for (unsigned int i = 0; i < cells.size() && i < header.size(); ++i)
              rows.back()[header[i]] = cells[i];
          }
      }
    return rows;
  }
} // namespace testing

#endif
