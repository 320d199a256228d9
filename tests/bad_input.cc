// Bad input given to the dyncontact executable itself: every case must end
// with a non-zero exit status and a message that names the parameter and the
// allowed range (or the file), and no backtrace. Also: without an argument
// and with --help the program prints every parameter with its documentation
// and exits with status 0. The cases of bad entries run the executable's
// code in this process (testing::run_in_process(): run_command_line(), what
// main() runs once MPI has started), a start of the executable costing
// about a second each; a missing file, a directory, the valid input, no
// argument and --help start the executable itself.

#include <filesystem>

#include "tests.h"

namespace
{
  using testing::Outcome;
  using testing::run_in_process;
  using testing::run_program;

  const std::string valid = "set Dimension = 2\n"
                            "subsection Time integration\n"
                            "  set End time = 0.01\n"
                            "end\n"
                            "subsection Output\n"
                            "  set Write vtu = false\n"
                            "end\n";
} // namespace

int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);
  using namespace testing;

  const std::vector<std::pair<std::string, std::string>> cases = {
    {"unknown_key", "subsection Material\n  set Young modulus = 3\nend\n"},
    {"unknown_subsection", "subsection Materials\nend\n"},
    {"youngs_modulus_zero",
     "subsection Material\n  set Young's modulus = 0\nend\n"},
    {"youngs_modulus_negative",
     "subsection Material\n  set Young's modulus = -2\nend\n"},
    {"poisson_half", "subsection Material\n  set Poisson's ratio = 0.5\nend\n"},
    {"poisson_minus_one",
     "subsection Material\n  set Poisson's ratio = -1\nend\n"},
    {"density_zero", "subsection Material\n  set Density = 0\nend\n"},
    {"viscosity_negative",
     "subsection Material\n  set Viscous shear modulus = -1\nend\n"},
    {"time_step_zero",
     "subsection Time integration\n  set Time step = 0\nend\n"},
    {"time_step_negative",
     "subsection Time integration\n  set Time step = -0.1\nend\n"},
    {"time_step_not_a_number",
     "subsection Time integration\n  set Time step = abc\nend\n"},
    {"end_time_negative",
     "subsection Time integration\n  set End time = -1\nend\n"},
    {"unknown_scheme",
     "subsection Time integration\n  set Scheme = RK4\nend\n"},
    {"unknown_mass_matrix",
     "subsection Time integration\n  set Mass matrix = diagonal\nend\n"},
    {"unknown_scene", "subsection Scene\n  set Name = pendulum\nend\n"},
    {"dimension_four", "set Dimension = 4\n"},
    {"bar_length_zero",
     testing::scene_entries("Bar impact", "    set Length = 0\n")},
    {"syntax_error", "subsection Material\n  Young's modulus 3\nend\n"},
    {"unclosed_subsection", "subsection Material\n"},
    {"output_directory_unwritable", "set Output directory = a_file/sub\n"},
    {"youngs_modulus_nan",
     "subsection Material\n  set Young's modulus = nan\nend\n"},
    {"time_step_inf",
     "subsection Time integration\n  set Time step = inf\nend\n"},
    {"initial_gap_nan",
     testing::scene_entries("Bar impact", "    set Initial gap = nan\n")},
    {"output_interval_negative",
     "subsection Output\n  set Output interval = -1\nend\n"},
    {"degree_zero", "set Polynomial degree = 0\n"},
    {"refinement_levels_inverted",
     "subsection Mesh refinement\n  set Minimum level = 3\n"
     "  set Maximum level = 1\nend\n"},
    // (two bad entries: the message names the one read first, as it did
    // before the components' parameters were read in another order)
    {"time_step_zero_and_levels_inverted",
     "subsection Time integration\n  set Time step = 0\nend\n"
     "subsection Mesh refinement\n  set Minimum level = 3\n"
     "  set Maximum level = 1\nend\n"},
    {"reference_states_missing_adaptive_mesh",
     "subsection Mesh refinement\n  set Refinement interval = 2\nend\n"
     "subsection Time integration\n  set End time = 0.0125\nend\n"
     "subsection Reference solution\n  set Compare with states = true\n"
     "  set Interval = 0.0125\nend\n"},
    {"reference_interval_beyond_end_time",
     "subsection Reference solution\n  set Write states = true\nend\n"},
    {"resume_without_checkpoint",
     "set Output directory = never-run\n"
     "subsection Checkpointing\n  set Resume = true\nend\n"},
    {"solver_tolerance_one",
     "subsection Contact solver\n  set Linear solver tolerance = 1\nend\n"},
    {"step_solver_tolerance_zero",
     "subsection Contact solver\n  set Step solver tolerance = 0\nend\n"},
    {"matrix_free_step_with_amg",
     "subsection Contact solver\n  set Step matrix = matrix-free\n"
     "  set Preconditioner = AMG\nend\n"},
    {"multigrid_with_assembled_step",
     "subsection Contact solver\n  set Preconditioner = multigrid\nend\n"},
    {"multigrid_linear_elements",
     "subsection Contact solver\n  set Step matrix = matrix-free\n"
     "  set Preconditioner = multigrid\nend\n"},
    {"front_widening_without_adaptation",
     "subsection Mesh refinement\n  set Front widening = 1\nend\n"},
    {"numerical_dissipation_above_half",
     "subsection Time integration\n  set Numerical dissipation = 0.6\nend\n"},
    {"consistent_mass_fraction_above_range",
     "subsection Time integration\n  set Mass matrix = blended\n"
     "  set Consistent mass fraction = 2\nend\n"},
    {"consistent_mass_fraction_singular",
     "subsection Time integration\n  set Mass matrix = blended\n"
     "  set Consistent mass fraction = 1.5\nend\n"},
    {"consistent_mass_fraction_above_one_adaptive_mesh",
     "subsection Time integration\n  set Mass matrix = blended\n"
     "  set Consistent mass fraction = 1.2\nend\n"
     "subsection Mesh refinement\n  set Refinement interval = 4\nend\n"},
    {"consistent_mass_fraction_above_one_adaptive_tau",
     "subsection Time integration\n  set Mass matrix = blended\n"
     "  set Consistent mass fraction = 1.2\n"
     "  set Time step control = adaptive\nend\n"},
    {"consistent_mass_fraction_above_one_quadratic",
     "set Polynomial degree = 2\n"
     "subsection Time integration\n  set Mass matrix = blended\n"
     "  set Consistent mass fraction = 1.2\nend\n"},
    {"numerical_dissipation_static",
     "subsection Time integration\n  set Scheme = static\n"
     "  set Numerical dissipation = 0.1\nend\n"},
    {"matrix_free_step_static",
     "subsection Contact solver\n  set Step matrix = matrix-free\nend\n"
     "subsection Time integration\n  set Scheme = static\nend\n"},
    {"hertz_in_3d",
     "set Dimension = 3\nsubsection Scene\n  set Name = hertz\nend\n"},
    {"negative_load", testing::scene_prm("hertz", "    set Load = -1\n")},
    {"old_flat_scene_entry", "subsection Scene\n  set Length = 2\nend\n"},
    {"old_flat_slave_side",
     "subsection Scene\n  set Name = two bars\n  set Slave side = 2\nend\n"},
    {"moved_error_norm_interval",
     "subsection Postprocess\n  set Error norm interval = every step\nend\n"},
    {"moved_initial_penetration",
     "subsection Contact solver\n  set Initial penetration = project\nend\n"},
    {"slash_in_subsection",
     "subsection Mesh refinement/Contact zone\n  set Distance = 1\nend\n"},
    {"entry_of_another_scene",
     "subsection Scene\n  subsection Bar impact\n    set Radius = 2\n"
     "  end\nend\n"},
    {"gmsh_without_search_radius",
     testing::scene_prm("gmsh",
                        "    set Mesh file = " +
                          std::string(DYNCONTACT_PRM_DIR) +
                          "/meshes/two_blocks.msh\n"
                          "    set Body 2 tags = 2\n"
                          "    set Contact tags of body 1 = 11\n"
                          "    set Contact tags of body 2 = 12\n")},
  };
  std::ofstream("a_file") << "not a directory\n";

  for (const auto &[name, text] : cases)
    {
      const std::string file = name + ".prm";
      std::ofstream(file) << valid << text;
      const Outcome outcome = run_in_process(file);
      const bool clean = error_names(outcome, "") && without_backtrace(outcome);
      log() << name << ": exit status non-zero: " << check(outcome.status != 0)
            << ", clean message: " << check(clean) << "\n"
            << outcome.text.substr(outcome.text.find("dyncontact: error:"))
            << "\n";
    }

  // a missing file and a directory instead of a file
  std::filesystem::create_directories("a_directory.prm");
  for (const std::string file : {"missing.prm", "a_directory.prm"})
    {
      const Outcome outcome = run_program(file);
      log() << file << ": exit status non-zero: " << check(outcome.status != 0)
            << "\n"
            << outcome.text << "\n";
    }

  // the valid base input runs
  std::ofstream("valid.prm") << valid;
  log() << "valid input: exit status zero: "
        << check(run_program("valid.prm").status == 0) << "\n";

  // no argument, and --help: every parameter with documentation and units
  for (const std::string arguments : {"", "--help"})
    {
      const Outcome outcome = run_program(arguments);
      bool          all     = outcome.status == 0;
      for (const std::string entry : {"set Dimension",
                                      "set Output directory",
                                      "set Polynomial degree",
                                      "subsection Scene",
                                      "set Name",
                                      "set Initial gap",
                                      "set Scheme",
                                      "set Time step",
                                      "set End time",
                                      "set Mass matrix",
                                      "set Young's modulus",
                                      "set Poisson's ratio",
                                      "set Density",
                                      "set Viscous shear modulus",
                                      "in Pa",
                                      "in kg/m^3",
                                      "in s (> 0)"})
        all = all && outcome.text.find(entry) != std::string::npos;
      log() << "'dyncontact " << arguments
            << "' lists every parameter with units: " << check(all) << "\n";
    }
}
