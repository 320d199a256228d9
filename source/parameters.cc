#include <deal.II/base/parameter_handler.h>

#include <dyncontact/parameters.h>
#include <dyncontact/scene.h>

#include <cmath>
#include <sstream>

namespace dyncontact
{
  void
  RunParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Dimension",
                      "2",
                      Patterns::Integer(2, 3),
                      "Space dimension of the simulation: 2 or 3.");
    prm.declare_entry("Output directory",
                      "results",
                      Patterns::Anything(),
                      "Folder for the VTU/PVTU/PVD files and statistics.tsv; "
                      "created if missing, relative to the working directory.");
    prm.declare_entry(
      "Polynomial degree",
      "1",
      Patterns::Integer(1, 4),
      "Degree p of the displacement space FE_Q(p)^dim, 1 to 4.");

    prm.enter_subsection("Time integration");
    prm.declare_entry("Scheme",
                      "N-CS++",
                      Patterns::Selection("N-CI|N-CS|N-CS++|static"),
                      "Time integrator: N-CI (contact-implicit Newmark, Kane "
                      "et al.), N-CS (contact-stabilized Newmark, Deuflhard, "
                      "Krause and Ertel), N-CS++ (the improved "
                      "contact-stabilized Newmark method, eq. (12)), or "
                      "static (the quasi-static limit: min 1/2 v^T A v - "
                      "f^T v on K_h, solved once).");
    prm.declare_entry("Time step",
                      "0.0125",
                      Patterns::Double(),
                      "Time step tau, in s (> 0).");
    prm.declare_entry("End time",
                      "2.5",
                      Patterns::Double(),
                      "Final time T, in s (>= 0). If T is not a multiple of "
                      "tau, the last step ends after T.");
    prm.declare_entry("Time step adaptation",
                      "false",
                      Patterns::Bool(),
                      "If a step's active-set iteration fails, retry it with "
                      "half the time step (and keep that), down to Time step "
                      "/ 1024; otherwise the run stops with a message.");
    prm.declare_entry("Mass matrix",
                      "lumped",
                      Patterns::Selection("lumped|consistent"),
                      "lumped: diagonal, by Gauss-Lobatto (nodal) quadrature; "
                      "consistent: by Gauss quadrature.");
    prm.leave_subsection();

    prm.enter_subsection("Mesh");
    prm.declare_entry("Initial global refinements",
                      "0",
                      Patterns::Integer(0, 12),
                      "Number of global refinements of the scene's coarse "
                      "mesh, 0 to 12.");
    prm.leave_subsection();

    prm.enter_subsection("Output");
    prm.declare_entry("Output interval",
                      "0.05",
                      Patterns::Double(),
                      "Time between two VTU outputs, in s (>= 0; 0 writes "
                      "every step). statistics.tsv gets every step.");
    prm.declare_entry("Write vtu",
                      "true",
                      Patterns::Bool(),
                      "Whether to write VTU/PVTU files and solution.pvd.");
    prm.leave_subsection();

    prm.enter_subsection("Checkpointing");
    prm.declare_entry("Interval in steps",
                      "0",
                      Patterns::Integer(0),
                      "Write a checkpoint every this many steps (0: not by "
                      "steps). Checkpoints go to <Output directory>/"
                      "checkpoints; each is written to a new folder and only "
                      "then marked as the last good one.");
    prm.declare_entry("Interval in minutes",
                      "0",
                      Patterns::Double(0.),
                      "Write a checkpoint when this much wall-clock time (in "
                      "minutes) has passed since the last one (0: not by "
                      "time).");
    prm.declare_entry("Resume",
                      "false",
                      Patterns::Bool(),
                      "Continue from the last good checkpoint in <Output "
                      "directory>/checkpoints. The prm must agree with the "
                      "checkpoint's in everything but End time, subsection "
                      "Output and subsection Checkpointing.");
    prm.leave_subsection();

    prm.enter_subsection("Reference solution");
    prm.declare_entry("Write states",
                      "false",
                      Patterns::Bool(),
                      "Write u and udot every 'Interval' to 'Directory', as "
                      "the reference for other runs on the same mesh.");
    prm.declare_entry("Compare with states",
                      "false",
                      Patterns::Bool(),
                      "Read the states of a reference run (same mesh, same "
                      "number of MPI ranks) from 'Directory' every "
                      "'Interval' and report the error in the physical "
                      "energy norm against them (column error_reference).");
    prm.declare_entry("Directory",
                      "reference",
                      Patterns::Anything(),
                      "Folder of the reference states.");
    prm.declare_entry("Interval",
                      "0.1",
                      Patterns::Double(0.),
                      "Time between two reference states, in s (> 0; a "
                      "multiple of the time steps of both runs).");
    prm.leave_subsection();

    Material::declare_parameters(prm, "Material");
    Material::declare_parameters(prm, "Material of body 2");
    ActiveSetSolver::Parameters::declare_parameters(prm);
    MeshRefinementParameters::declare_parameters(prm);
    declare_scene_parameters(prm);
  }



  namespace
  {
    std::string
    number(const double x)
    {
      std::ostringstream s;
      s << x;
      return s.str();
    }
  } // namespace



  void
  RunParameters::parse_parameters(ParameterHandler &prm)
  {
    dimension        = prm.get_integer("Dimension");
    output_directory = prm.get("Output directory");
    degree           = prm.get_integer("Polynomial degree");
    AssertThrow(!output_directory.empty(),
                ExcMessage("Output directory must not be empty."));

    prm.enter_subsection("Time integration");
    scheme               = scheme_from_string(prm.get("Scheme"));
    time_step            = prm.get_double("Time step");
    end_time             = prm.get_double("End time");
    lumped_mass          = (prm.get("Mass matrix") == "lumped");
    time_step_adaptation = prm.get_bool("Time step adaptation");
    prm.leave_subsection();
    AssertThrow(std::isfinite(time_step) && time_step > 0.,
                ExcMessage("Time integration/Time step must be a finite "
                           "number > 0 (s); got " +
                           number(time_step) + "."));
    AssertThrow(std::isfinite(end_time) && end_time >= 0.,
                ExcMessage("Time integration/End time must be a finite "
                           "number >= 0 (s); got " +
                           number(end_time) + "."));
    AssertThrow(end_time / time_step < 1e8,
                ExcMessage("Time integration: End time / Time step = " +
                           number(end_time / time_step) +
                           " steps; at most 1e8 steps are allowed."));

    prm.enter_subsection("Mesh");
    initial_refinements = prm.get_integer("Initial global refinements");
    prm.leave_subsection();

    prm.enter_subsection("Output");
    output_interval = prm.get_double("Output interval");
    write_vtu       = prm.get_bool("Write vtu");
    prm.leave_subsection();
    AssertThrow(std::isfinite(output_interval) && output_interval >= 0.,
                ExcMessage("Output/Output interval must be a finite number "
                           ">= 0 (s); got " +
                           number(output_interval) + "."));

    prm.enter_subsection("Checkpointing");
    checkpoint_steps   = prm.get_integer("Interval in steps");
    checkpoint_minutes = prm.get_double("Interval in minutes");
    resume             = prm.get_bool("Resume");
    prm.leave_subsection();

    // the critical parameters: the whole input in a canonical form, less
    // what a resumed run may change
    {
      std::ostringstream all;
      prm.print_parameters(all, ParameterHandler::ShortPRM);
      std::istringstream       in(all.str());
      std::vector<std::string> path;
      for (std::string line; std::getline(in, line);)
        {
          const auto first = line.find_first_not_of(' ');
          if (first == std::string::npos)
            continue;
          line = line.substr(first);
          if (line.rfind("subsection ", 0) == 0)
            path.push_back(line.substr(11));
          else if (line == "end")
            path.pop_back();
          else if (line.rfind("set ", 0) == 0)
            {
              const std::string entry = line.substr(4, line.find('=') - 4);
              // a resumed run may change the end time, the output, the
              // checkpointing, and the solver's limits (to get past a step
              // that failed)
              auto is = [&](const std::string &section,
                            const std::string &name) {
                return path.size() == 1 && path[0] == section &&
                       entry.rfind(name, 0) == 0;
              };
              const bool skip =
                (!path.empty() &&
                 (path[0] == "Output" || path[0] == "Checkpointing")) ||
                (path.empty() && entry.rfind("Output directory", 0) == 0) ||
                is("Time integration", "End time") ||
                is("Time integration", "Time step adaptation") ||
                is("Contact solver", "Maximum active-set iterations") ||
                is("Contact solver", "Maximum linear iterations");
              if (!skip)
                {
                  std::string name;
                  for (const auto &p : path)
                    name += p + "/";
                  critical_parameters += name + line.substr(4) + "\n";
                }
            }
        }
    }

    prm.enter_subsection("Reference solution");
    write_reference     = prm.get_bool("Write states");
    compare_reference   = prm.get_bool("Compare with states");
    reference_directory = prm.get("Directory");
    reference_interval  = prm.get_double("Interval");
    prm.leave_subsection();
    AssertThrow(!(write_reference && compare_reference),
                ExcMessage("Reference solution: a run either writes states "
                           "or compares with them, not both."));
    AssertThrow(reference_interval > 0.,
                ExcMessage("Reference solution/Interval must be > 0 (s)."));

    materials.resize(2);
    materials[0].parse_parameters(prm, "Material");
    materials[1].parse_parameters(prm, "Material of body 2");
    solver.parse_parameters(prm);
    refinement.parse_parameters(prm);
  }
} // namespace dyncontact
