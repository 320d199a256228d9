#ifndef dyncontact_discretization_semi_discrete_system_h
#define dyncontact_discretization_semi_discrete_system_h

#include <deal.II/base/index_set.h>
#include <deal.II/distributed/solution_transfer.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <dyncontact/discretization/elastic_operator.h>
#include <dyncontact/discretization/serial_transfer.h>
#include <dyncontact/scenes/interface.h>

#include <array>
#include <functional>
#include <map>
#include <memory>
#include <utility>
#include <vector>

class Epetra_CrsGraph;

namespace dyncontact
{
  using VectorType = TrilinosWrappers::MPI::Vector;
  using MatrixType = TrilinosWrappers::SparseMatrix;

  /// y = L x for a linear operator L.
  using Product = std::function<void(VectorType &y, const VectorType &x)>;

  /**
   * y = A x for an operator A, remembered for the last x: the elastic
   * energy after a step and the right-hand side of the next step need the
   * same product. A hit is decided on the bits of x on every rank at once
   * (one scalar reduction), so that the ranks take part in the same
   * operator applications.
   */
  class CachedProduct
  {
  public:
    /// Forgets the last product; @p product from now on.
    void
    reinit(const Product &product);

    /// A x (the reference stays valid until the next call or reinit()).
    const VectorType &
    vmult(const VectorType &x) const;

  private:
    Product            product;
    mutable bool       valid = false;
    mutable VectorType x_last;
    mutable VectorType y_last;
  };

  /**
   * Dirichlet DoFs whose displacement is prescribed and moves
   * (Scene::prescribed_displacements()): a step solves for v - G with the
   * homogeneous constraints and adds G, the prescribed values
   * (doc/algorithms.md, "Prescribed displacements").
   */
  struct PrescribedMotion
  {
    /// The locally owned prescribed DoFs, sorted.
    std::vector<types::global_dof_index> dofs;
    /// The locally owned hanging DoFs whose parents include prescribed DoFs
    /// (of any rank): the weights of those parents; their values follow.
    std::vector<
      std::pair<types::global_dof_index,
                std::vector<std::pair<types::global_dof_index, double>>>>
      children;
    /// G at the end of the present trial step (the prescribed DoFs and
    /// their children; zero elsewhere).
    VectorType at_end;
    /// W = w on the prescribed DoFs and their children, zero elsewhere
    /// (collective).
    std::function<void(const VectorType &w, VectorType &W)> part_of;
    /// R += the force r on the prescribed DoFs, with a hanging child's
    /// force passed to its parents by its weights (collective).
    std::function<void(const VectorType &r, VectorType &R)> reaction_of;
  };

  /**
   * The operators and the load of the semi-discrete problem that a time
   * integrator needs. The mass is either a consistent matrix M or, lumped,
   * its diagonal M_lumped (no sparse matrix is kept for it). The elastic
   * and viscous stiffness A and B are applied without a matrix
   * (ElasticOperator); a matrix a A + b B, such as the time step's, is
   * assembled on demand. B_vmult is empty for an elastic body.
   */
  struct SystemMatrices
  {
    /// (M_lower: a diagonal D <= M: the lumped M, a blended M's lumped part)
    const MatrixType    *M         = nullptr;
    const VectorType    *M_lumped  = nullptr;
    const VectorType    *M_lower   = nullptr;
    const CachedProduct *A_product = nullptr;
    Product              B_vmult;
    /// matrix = a A + b B + m M, on the unconstrained operator's pattern.
    std::function<void(MatrixType &matrix, double a, double b, double m)>
      assemble_stiffness;
    /// y = (a A + b B) x in one pass over the cells, without a matrix.
    std::function<void(VectorType &y, const VectorType &x, double a, double b)>
      stiffness_combination_vmult;
    /// d = the diagonal of a A + b B (the assembled matrix's), matrix-free.
    std::function<void(VectorType &d, double a, double b)>
      stiffness_combination_diagonal;
    /// The preconditioner of a step matrix S = M + a A + b B applied by
    /// the product given, with the diagonal given; empty: Jacobi.
    std::function<Product(double            a,
                          double            b,
                          const Product    &S_vmult,
                          const VectorType &S_diagonal)>
      step_preconditioner;
    /// The load of the step: f, or with loads that change in time
    /// (f(t_n) + f(t_{n+1})) / 2 (SemiDiscreteSystem::begin_step_load()).
    const VectorType *f = nullptr;
    /// The load at the step's end, f(t_{n+1}) (the static problem's).
    const VectorType *f_end = nullptr;
    /// Dirichlet data that move, or nullptr.
    const PrescribedMotion *prescribed = nullptr;

    /// Whether there is a viscous form B.
    bool
    viscous() const
    {
      return static_cast<bool>(B_vmult);
    }

    /// Whether the mass is lumped (given by M_lumped, M is nullptr).
    bool
    lumped_mass() const
    {
      return M == nullptr;
    }

    /// y = M x.
    void
    mass_vmult(VectorType &y, const VectorType &x) const;

    /// A x, remembered for the last x (CachedProduct).
    const VectorType &
    stiffness_vmult(const VectorType &x) const
    {
      return A_product->vmult(x);
    }

    /// ||M||_infty.
    double
    mass_linfty_norm() const;

    /// matrix += factor * M (on M's sparsity pattern, which @p matrix
    /// contains).
    void
    add_mass(MatrixType &matrix, const double factor) const;
  };

  /**
   * The space discretisation of the scene on the current mesh: vector-valued
   * FE_Q(p)^dim with its DoFs, the hanging-node and homogeneous Dirichlet
   * constraints, the mass matrix M (consistent or lumped), the elastic and
   * viscous stiffness matrices A and B (B only for a viscous scene), the
   * load f, the boundary weights w_p of the contact boundaries, and the
   * transfer of a state (u, udot) to a new mesh or to a checkpoint. Rebuilt
   * (setup(), assemble()) whenever the mesh changes.
   */
  template <int dim>
  class SemiDiscreteSystem
  {
  public:
    struct Parameters
    {
      /// Polynomial degree (GlobalParameters).
      unsigned int degree = 1;
      /// Time integration/Mass matrix = lumped (TimeIntegrationParameters).
      bool lumped_mass = true;
      /// beta of a mass not lumped: beta M_K(Gauss) + (1-beta) M_K(nodal).
      double consistent_mass_fraction = 1.;
      /// Whether matrices a A + b B + m M are assembled (Contact solver/Step
      /// matrix = assembled, or a static problem); else a lumped mass needs
      /// no sparsity pattern, and none is built.
      bool assembled_step_matrix = true;
      /// The linear level of the p-multigrid (Contact solver/Preconditioner
      /// = multigrid): M and the assembled a A + b B + m M only; no load, no
      /// boundary weights and no matrix-free A and B are built.
      bool multigrid_level = false;
    };

    SemiDiscreteSystem(const Parameters   &parameters,
                       const Mapping<dim> &mapping,
                       const MPI_Comm      comm);
    ~SemiDiscreteSystem();

    /// DoFs, constraints, sparsity patterns and vectors on the current mesh
    /// (the first call attaches the DoF handlers to @p triangulation).
    void
    setup(const Triangulation<dim> &triangulation, const Scene<dim> &scene);

    /// M (the diagonal only if lumped), the matrix-free A and B, f and the
    /// boundary weights w (only M on Parameters::multigrid_level); checks
    /// that no cell is inverted.
    void
    assemble(const Scene<dim> &scene);

    /// The scene's initial displacement and velocity, nodal interpolation
    /// body by body; hanging nodes follow their parents, Dirichlet nodes are
    /// fixed. Returns the largest values of u and udot that the Dirichlet
    /// constraints set to zero (0 where they are round-off of the largest
    /// value).
    std::array<double, 2>
    interpolate_initial_values(const Scene<dim> &scene,
                               VectorType       &u,
                               VectorType       &udot) const;

    /// An owned vector of this system.
    void
    reinit_vector(VectorType &v) const;

    /// A copy of @p v (an owned vector of this system) with the ghost
    /// entries of the locally relevant DoFs, for reading it on cells.
    VectorType
    ghosted(const VectorType &v) const;

    /// E_kin = 1/2 udot^T M udot and E_el = 1/2 u^T A u - f^T u;
    /// @p M_udot receives M udot.
    std::pair<double, double>
    energies(const VectorType &u,
             const VectorType &udot,
             VectorType       &M_udot) const;

    /// E_kin + E_el.
    double
    total_energy(const VectorType &u, const VectorType &udot) const;

    /// Before the triangulation is refined: remember (u, udot).
    void
    prepare_for_refinement(const VectorType &u, const VectorType &udot);
    /// After refinement and setup(): (u, udot) on the new mesh.
    void
    interpolate_after_refinement(VectorType &u, VectorType &udot);
    /// Checkpoint: the mesh and @p vectors (u, udot, a nodal vector of the
    /// warm-start active sets, and what else the run needs to resume) into
    /// @p file: p4est's files (attached to the triangulation's save()), or
    /// on a serial triangulation SerialMeshFile.
    void
    save(const std::string                     &file,
         const std::vector<const VectorType *> &vectors);
    /// Resume: @p triangulation, which holds the coarse mesh, refined to the
    /// mesh of @p file (before setup()).
    static void
    load_mesh(const std::string &file, Triangulation<dim> &triangulation);
    /// Resume, after load_mesh() and setup(): the vectors of @p file, in the
    /// order and number they were saved.
    void
    load_vectors(const std::string               &file,
                 const std::vector<VectorType *> &vectors);

    SystemMatrices
    matrices() const;
    /// Mass matrix: lumped, consistent or blended (the banner's words).
    std::string
    mass_description() const;

    const FESystem<dim> &
    get_fe() const
    {
      return fe;
    }
    const FE_Q<dim> &
    get_scalar_fe() const
    {
      return scalar_fe;
    }
    /// For each node (support point of the scalar element) the index
    /// within the vector element of its shape function of each component:
    /// get_fe().component_to_system_index(c, node), which searches the
    /// element's table, looked up once.
    const std::vector<std::array<unsigned int, dim>> &
    get_node_system_indices() const
    {
      return node_system_indices;
    }
    const DoFHandler<dim> &
    get_dof_handler() const
    {
      return dof_handler;
    }
    /// The scalar FE_Q(p) on the same mesh, for the nodal contact fields of
    /// the output and the sparsity pattern: its DoFs, the locally owned and
    /// relevant ones, and (component-0 system DoF, scalar DoF) of each node
    /// owned here, in the order of the cells.
    struct ScalarDoFs
    {
      explicit ScalarDoFs(const Triangulation<dim> &triangulation)
        : dof_handler(triangulation)
      {}
      DoFHandler<dim> dof_handler;
      IndexSet        locally_owned;
      IndexSet        locally_relevant;
      std::vector<std::pair<types::global_dof_index, types::global_dof_index>>
        owned_system0_to_scalar;
    };
    /// The scalar DoFs of the current mesh, numbered at the first call
    /// after each setup() (collective then): a mesh adaptation that no
    /// output and no sparsity pattern follows does not number them.
    const ScalarDoFs &
    scalar_dofs() const;
    const IndexSet &
    locally_owned_dofs() const
    {
      return locally_owned;
    }
    const IndexSet &
    locally_relevant_dofs() const
    {
      return locally_relevant;
    }
    /// Hanging nodes and homogeneous Dirichlet data.
    const AffineConstraints<double> &
    get_constraints() const
    {
      return constraints;
    }
    /// Whether setup() made a sparsity pattern (for an assembled S or a
    /// consistent M).
    bool
    has_sparsity_pattern() const
    {
      return graph != nullptr;
    }
    /// Whether the scene has a viscous body (a viscous form B).
    bool
    is_viscous() const
    {
      return viscous;
    }
    /// y = A x (elastic form, without a matrix).
    void
    stiffness_vmult(VectorType &y, const VectorType &x) const
    {
      elastic_operator.vmult(y, x, ElasticOperator<dim>::Form::elastic);
    }
    /// y = B x (viscous form, without a matrix).
    void
    viscous_vmult(VectorType &y, const VectorType &x) const
    {
      elastic_operator.vmult(y, x, ElasticOperator<dim>::Form::viscous);
    }
    /// Zienkiewicz and Zhu's indicator of @p field on the locally owned
    /// cells (ElasticOperator::recovery_indicators()).
    void
    recovery_indicators(const VectorType &field,
                        Vector<float>    &indicators) const
    {
      elastic_operator.recovery_indicators(field, indicators);
    }
    /// @p diagonal = the diagonal of a A + b B, as the assembled matrix
    /// has it (cell by cell from the shape gradients, without a matrix).
    void
    stiffness_diagonal(VectorType &diagonal, double a, double b) const;

    /// @p matrix = a A + b B + m M, assembled cell by cell on the sparsity
    /// pattern of the unconstrained operator (a lumped M on the diagonal in
    /// the cell loop, a consistent M added afterwards).
    void
    assemble_stiffness_matrix(MatrixType  &matrix,
                              const double a,
                              const double b,
                              const double m) const;
    /// The load f at the present time (get_load_time()).
    const VectorType &
    get_load() const
    {
      return load;
    }
    /// Whether the scene's loads change in time (FunctionLoads) or its
    /// Dirichlet data move: then every step evaluates them at its end.
    bool
    loads_change_in_time() const
    {
      return function_loads.time_dependent || prescribed != nullptr;
    }
    /// Whether Dirichlet data move (Scene::prescribed_displacements()).
    bool
    has_prescribed_motion() const
    {
      return prescribed != nullptr;
    }
    /// Sets @p u (and @p udot unless nullptr) on the prescribed DoFs and
    /// their children to the prescribed displacement at @p t (its time
    /// derivative by central differences, with the step @p delta_t
    /// remembered for later calls with delta_t = 0). Collective.
    void
    set_prescribed_state(const double t,
                         const double delta_t,
                         VectorType  &u,
                         VectorType  *udot);
    /// Whether the DoF @p dof (locally relevant) is prescribed and moves.
    bool
    is_prescribed(const types::global_dof_index dof) const;
    /// The time of get_load() (s).
    double
    get_load_time() const
    {
      return load_time;
    }
    /// f at time @p t (collective; only loads that change in time are
    /// evaluated again).
    void
    set_load_time(const double t);
    /// Before a trial step to @p t_end: f(t_end) (matrices().f_end) and the
    /// step's load (f(t_n) + f(t_end)) / 2 (matrices().f).
    void
    begin_step_load(const double t_end);
    /// After the trial: get_load() is f(t_end), get_previous_load() f(t_n).
    void
    end_step_load();
    /// Back to the start of the step: get_load() is f(t_n) again.
    void
    undo_step_load();
    /// With loads that change in time, after end_step_load(): f(t_n) of the
    /// step's start.
    const VectorType &
    get_previous_load() const
    {
      return previous_load;
    }
    /// w_p = int_{Gamma_C} psi_p ds at every DoF of the contact boundaries.
    const VectorType &
    get_boundary_weights() const
    {
      return boundary_weights;
    }
    /// The number of locally owned DoFs of each body.
    const std::vector<types::global_dof_index> &
    n_locally_owned_body_dofs() const
    {
      return n_owned_body_dofs;
    }
    /// For each locally owned DoF, in the order of the vectors' local
    /// entries: body * dim + component.
    const std::vector<unsigned char> &
    get_owned_dof_slots() const
    {
      return owned_dof_slots;
    }
    /// Rigid translations, the near-null-space for AMG.
    const std::vector<std::vector<bool>> &
    get_constant_modes() const
    {
      return constant_modes;
    }
    /// The infinitesimal rigid rotations about the origin (1 in 2D, 3 in
    /// 3D: e_k x x at each DoF's support point), for AMG's near-null space;
    /// computed on each call.
    std::vector<VectorType>
    rotation_modes() const;

  private:
    const Parameters    parameters;
    const Mapping<dim> &mapping;
    const MPI_Comm      comm;
    bool                attached = false;
    bool                viscous  = false;

    FESystem<dim>   fe;
    DoFHandler<dim> dof_handler;
    FE_Q<dim>       scalar_fe;
    /// (see get_node_system_indices())
    std::vector<std::array<unsigned int, dim>> node_system_indices;
    /// (null until scalar_dofs() numbers them on the current mesh)
    mutable std::unique_ptr<ScalarDoFs> scalar;

    IndexSet                             locally_owned;
    IndexSet                             locally_relevant;
    AffineConstraints<double>            constraints;
    std::vector<types::global_dof_index> n_owned_body_dofs;
    std::vector<unsigned char>           owned_dof_slots;
    std::vector<std::vector<bool>>       constant_modes;

    /// The sparsity pattern of the unconstrained operator (locally owned
    /// rows, columns of the locally relevant DoFs), shared by the matrices
    /// built on it.
    std::unique_ptr<Epetra_CrsGraph> graph;
    /// Hanging nodes and the scene's homogeneous Dirichlet data, and the
    /// prescribed DoFs of the boundaries that move (in dirichlet_data.cc).
    void
    make_constraints(const Scene<dim> &scene);
    /// @p G = the prescribed values at @p t on the prescribed DoFs and
    /// their children, zero elsewhere (collective); a value that is not
    /// finite or beyond 1e15 stops the run if @p finite.
    void
    prescribed_values(const double t,
                      VectorType  &G,
                      const bool   finite = true) const;
    /// Sets the children of the prescribed DoFs in @p G from their parents
    /// (collective).
    void
    set_children(VectorType &G) const;
    /// For each locally owned DoF its body and component, the DoFs of each
    /// body and the rigid translations.
    void
    index_owned_nodes(const unsigned int n_bodies);
    /// Makes the graph (in setup()).
    void
    make_sparsity_graph();
    /// Whether every vector DoF is dim * (its node's scalar DoF) +
    /// component, on every cell this rank sees and in the owned and
    /// relevant sets (collective).
    bool
    vector_dofs_expand_scalar_dofs() const;
    /// The scene's tractions, with its loads given as total forces spread
    /// over the boundary as the mesh represents it (in assembly.cc).
    std::vector<std::pair<types::boundary_id, Tensor<1, dim>>>
    boundary_tractions(const Scene<dim> &scene) const;
    /// @p f = the constant load plus the function loads that depend on t,
    /// at time @p t (@p of_time; in function_loads.cc), or (not @p of_time)
    /// the function loads that do not depend on t.
    void
    assemble_function_loads(const double t,
                            const bool   of_time,
                            VectorType  &f) const;
    /// A zero matrix on the graph.
    void
    reinit_matrix(MatrixType &matrix) const;
    /// the moduli of each material id of the mesh
    std::map<types::material_id, Material> materials;
    /// M if not lumped; the lumped M's diagonal, or a blended M's lumped part
    MatrixType           mass_matrix;
    VectorType           lumped_mass_diagonal;
    ElasticOperator<dim> elastic_operator;
    CachedProduct        stiffness_product;
    /// f at load_time (the constant loads plus the function loads)
    VectorType load;
    double     load_time = 0.;
    /// the scene's loads given as functions, and the constant part of f
    /// (the scene's constant loads and its function loads that do not
    /// depend on t)
    FunctionLoads<dim> function_loads;
    VectorType         constant_load;
    /// with loads that change in time: f at the start and the end of the
    /// step, and the step's load (their mean)
    VectorType previous_load;
    VectorType end_load;
    VectorType step_load;
    double     previous_load_time = 0.;
    double     end_load_time      = 0.;
    /// Dirichlet data that move: each boundary with its function and the
    /// components it fixes, the prescribed DoFs among the locally relevant
    /// ones (sorted), and the time step of the central differences.
    struct MovingBoundary
    {
      types::boundary_id id;
      Function<dim>     *function;
      std::vector<bool>  components;
    };
    std::vector<MovingBoundary>          moving_boundaries;
    std::vector<types::global_dof_index> relevant_prescribed;
    std::unique_ptr<PrescribedMotion>    prescribed;
    double                               prescribed_delta = 0.;
    VectorType                           boundary_weights;

    /// A state in transfer to a refined mesh and its ghosted copy for
    /// p4est's transfer, or the transfer on a serial triangulation.
    std::unique_ptr<parallel::distributed::SolutionTransfer<dim, VectorType>>
                                         transfer;
    std::vector<VectorType>              transferred;
    std::unique_ptr<SerialTransfer<dim>> serial_transfer;
    /// Whether the DoFs are on deal.II's serial triangulation.
    bool
    is_serial() const;
  };



  /// A state's mesh and @p ghosted vectors (none: the mesh alone) into @p
  /// file, as a checkpoint writes them (p4est's files, or SerialMeshFile on
  /// deal.II's serial triangulation): readable on any number of ranks into
  /// a triangulation that holds the same coarse mesh.
  template <int dim>
  void
  write_state_file(const std::string                     &file,
                   const DoFHandler<dim>                 &dof_handler,
                   const std::vector<const VectorType *> &ghosted);

  /// After SemiDiscreteSystem::load_mesh(@p file) and the DoFs of @p
  /// dof_handler: the vectors of @p file (sized, without ghosts).
  template <int dim>
  void
  read_state_vectors(const std::string               &file,
                     const DoFHandler<dim>           &dof_handler,
                     const std::vector<VectorType *> &vectors);
} // namespace dyncontact

#endif
