#ifndef dyncontact_simulator_h
#define dyncontact_simulator_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q1.h>

#include <dyncontact/contact_mapping.h>
#include <dyncontact/parameters.h>
#include <dyncontact/scene.h>
#include <dyncontact/statistics.h>

#include <array>
#include <fstream>
#include <map>
#include <memory>

namespace dyncontact
{
  /**
   * The application in the shape of deal.II's step-40/42: setup (DoFs,
   * constraints, matrices M, A, B and load f, assembled once per mesh),
   * contact rows, the time loop with one TimeIntegrator, diagnostics and
   * output.
   */
  template <int dim>
  class Simulator
  {
  public:
    Simulator(const RunParameters &parameters,
              ParameterHandler    &prm,
              const MPI_Comm       comm);

    /// Runs the whole simulation; returns the statistics (on all ranks).
    Statistics
    run();

  private:
    Statistics
    run_simulation();
    void
    setup_system();
    void
    assemble_system();
    void
    make_contact_rows();
    /// The contact faces with these boundary ids, from all ranks.
    std::vector<MasterFace<dim>>
    gather_faces(const std::vector<types::boundary_id> &ids) const;
    /// Boundary ids of every contact boundary (obstacle and pairs).
    std::vector<types::boundary_id>
    all_contact_boundary_ids() const;
    void
    set_initial_values();
    /// Appends one row to the statistics (and to statistics.tsv).
    void
    record_step(const unsigned int step,
                const double       time,
                const StepReport  &report,
                const double       wall_time);
    double
    compute_energy_error(const double time) const;
    /// Checkpoints (source/checkpoint.cc).
    std::string
    checkpoint_root() const;
    std::string
    write_checkpoint(const unsigned int step,
                     const double       time,
                     const double       next_output);
    void
    resume_from_checkpoint(unsigned int &step,
                           double       &time,
                           double       &next_output);
    /// Writes the state as a reference, or returns the energy-norm error
    /// against the reference state at this time (NaN when there is none;
    /// source/reference_solution.cc).
    double
    process_reference_state(const double time);
    /// E_kin = 1/2 udot^T M udot and E_el = 1/2 u^T A u - f^T u of the
    /// current state; @p M_udot receives M udot (for the momentum).
    std::pair<double, double>
    energies(VectorType &M_udot) const;
    /// E_kin + E_el of the current state.
    double
    total_energy() const;
    /// A new time integrator for the current matrices and rows.
    void
    make_integrator();
    /// Adaptive meshes (source/mesh_refinement.cc).
    void
    mark_contact_zone(const VectorType &displacement);
    void
    initial_refinement();
    void
    adapt_mesh();
    void
    output_results(const double time, const StepReport &report);

    const RunParameters          parameters;
    MPI_Comm                     comm;
    ConditionalOStream           pcout;
    std::unique_ptr<TimerOutput> timer;

    std::unique_ptr<Scene<dim>> scene;

    parallel::distributed::Triangulation<dim> triangulation;
    MappingQ1<dim>                            mapping;
    FESystem<dim>                             fe;
    DoFHandler<dim>                           dof_handler;
    /// Scalar FE_Q(p) on the same mesh for nodal contact fields.
    FE_Q<dim>       scalar_fe;
    DoFHandler<dim> scalar_dof_handler;

    IndexSet                  locally_owned;
    IndexSet                  locally_relevant;
    IndexSet                  scalar_locally_owned;
    IndexSet                  scalar_locally_relevant;
    AffineConstraints<double> mesh_constraints;
    /// Locally owned DoFs of each body and displacement component.
    std::vector<std::vector<IndexSet>> body_component_dofs;
    /// Rigid translations, the near-null-space for AMG.
    std::vector<std::vector<bool>> constant_modes;

    MatrixType mass_matrix;
    MatrixType stiffness_matrix;
    MatrixType viscous_matrix; // only for viscous materials
    VectorType load;
    VectorType boundary_mass; // w_p at every DoF of Gamma_C

    ContactRows rows;
    /// Component-0 system DoF -> scalar DoF, for the nodes owned here.
    std::map<types::global_dof_index, types::global_dof_index>
      owned_system0_to_scalar;
    /// For each row, the scalar DoF of its slave node (for output).
    std::vector<types::global_dof_index> row_scalar_dofs;

    std::unique_ptr<TimeIntegrator> integrator;
    /// Evaluates C v and C v - g for the diagnostics.
    std::unique_ptr<ActiveSetSolver> row_evaluator;
    VectorType                       u;
    VectorType                       udot;
    VectorType                       u_old;
    VectorType                       udot_old;
    /// The time step in use (Time step adaptation may halve it).
    double current_tau;

    Statistics    statistics;
    std::ofstream statistics_file;
    double        viscous_dissipation  = 0.;
    double        critical_measure_sum = 0.;
    /// Energy change and largest K_h violation from mesh transfers since
    /// the last statistics row.
    double                                      energy_transfer      = 0.;
    double                                      transfer_penetration = 0.;
    unsigned int                                output_counter       = 0;
    std::vector<std::pair<double, std::string>> pvd_records;
  };
} // namespace dyncontact

#endif
