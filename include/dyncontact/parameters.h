#ifndef dyncontact_parameters_h
#define dyncontact_parameters_h

#include <dyncontact/active_set_solver.h>
#include <dyncontact/material.h>
#include <dyncontact/mesh_refinement.h>
#include <dyncontact/time_integrator.h>

#include <string>
#include <vector>

namespace dyncontact
{
  /**
   * The parameters of a run that are not a scene's own. Each group is
   * declared by the class that uses it (Material, ActiveSetSolver, the
   * scenes); this struct collects them.
   */
  struct RunParameters
  {
    unsigned int dimension        = 2;
    std::string  output_directory = "results";
    unsigned int degree           = 1;
    /// Folder of the prm file (relative file names in it refer to it).
    std::string input_directory;

    // subsection Time integration
    Scheme scheme      = Scheme::improved_contact_stabilized;
    double time_step   = 0.0125;
    double end_time    = 2.5;
    bool   lumped_mass = true;

    // subsection Mesh
    unsigned int initial_refinements = 0;

    // subsection Output
    double output_interval = 0.05;
    bool   write_vtu       = true;

    // subsection Checkpointing
    unsigned int checkpoint_steps   = 0;
    double       checkpoint_minutes = 0.;
    bool         resume             = false;
    /// The parameters a resumed run must share with its checkpoint (all but
    /// End time, Output, Checkpointing), as text.
    std::string critical_parameters;

    // subsection Time integration: retry a failed step with tau/2
    bool time_step_adaptation = false;

    // subsection Reference solution
    bool        write_reference   = false;
    bool        compare_reference = false;
    std::string reference_directory;
    double      reference_interval = 0.1;

    /// Body 1 ("Material") and body 2 ("Material of body 2").
    std::vector<Material>       materials;
    ActiveSetSolver::Parameters solver;
    MeshRefinementParameters    refinement;

    /// Declares every parameter of the program (the scenes' included).
    static void
    declare_parameters(ParameterHandler &prm);

    /// Reads and checks them; throws with a message naming the parameter
    /// and its allowed range.
    void
    parse_parameters(ParameterHandler &prm);
  };
} // namespace dyncontact

#endif
