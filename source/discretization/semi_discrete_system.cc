#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>
#include <deal.II/distributed/p4est_wrappers.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/numerics/vector_tools.h>

#include <dyncontact/base/collective_errors.h>
#include <dyncontact/base/triangulation.h>
#include <dyncontact/discretization/rigid_motions.h>
#include <dyncontact/discretization/semi_discrete_system.h>
#include <dyncontact/discretization/serial_mesh_file.h>

#include <Epetra_CrsGraph.h>
#include <Epetra_CrsMatrix.h>
#include <Epetra_Map.h>
#include <Epetra_Vector.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <limits>
#include <sstream>

namespace dyncontact
{
  namespace
  {
    /// Calls @p f(cell, node, node_dofs) for each locally owned node (a
    /// support point of the scalar element whose component-0 DoF is
    /// locally owned) once, on the first locally owned cell that has it, in
    /// the order of the cells; node_dofs are the node's DoF of each
    /// component (a node's DoFs are owned together). @p system_index is
    /// SemiDiscreteSystem::get_node_system_indices().
    template <int dim, typename Function>
    void
    for_each_owned_node(
      const DoFHandler<dim> &dof_handler,
      const IndexSet        &locally_owned,
      const std::vector<std::array<unsigned int, std::size_t(dim)>>
                     &system_index,
      const Function &f)
    {
      const unsigned int                   n_nodes = system_index.size();
      std::vector<bool>                    seen(locally_owned.n_elements());
      std::vector<types::global_dof_index> dofs(
        dof_handler.get_fe().n_dofs_per_cell());
      std::array<types::global_dof_index, dim> node_dofs;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            cell->get_dof_indices(dofs);
            for (unsigned int node = 0; node < n_nodes; ++node)
              {
                const auto dof0 = dofs[system_index[node][0]];
                if (!locally_owned.is_element(dof0))
                  continue;
                const auto k0 = locally_owned.index_within_set(dof0);
                if (seen[k0])
                  continue;
                seen[k0] = true;
                for (unsigned int c = 0; c < dim; ++c)
                  node_dofs[c] = dofs[system_index[node][c]];
                f(cell, node, node_dofs);
              }
          }
    }
  } // namespace



  template <int dim>
  SemiDiscreteSystem<dim>::SemiDiscreteSystem(const Parameters   &parameters,
                                              const Mapping<dim> &mapping,
                                              const MPI_Comm      comm)
    : parameters(parameters)
    , mapping(mapping)
    , comm(comm)
    , fe(FE_Q<dim>(parameters.degree), dim)
    , scalar_fe(parameters.degree)
    , node_system_indices(scalar_fe.n_dofs_per_cell())
  {
    for (unsigned int node = 0; node < node_system_indices.size(); ++node)
      for (unsigned int c = 0; c < dim; ++c)
        node_system_indices[node][c] = fe.component_to_system_index(c, node);
  }



  template <int dim>
  SemiDiscreteSystem<dim>::~SemiDiscreteSystem() = default;



  template <int dim>
  void
  SemiDiscreteSystem<dim>::setup(const Triangulation<dim> &triangulation,
                                 const Scene<dim>         &scene)
  {
    // deal.II's cells must be p4est's leaves: where they are not (seen with
    // deal.II 9.4 on a coarse mesh with rotated faces: deal.II kept eight
    // children where p4est had coarsened them), every transfer of u, udot or
    // a checkpoint pairs data with the wrong cells. Stop instead.
    const auto *distributed = as_distributed(triangulation);
    AssertThrow(
      distributed == nullptr ||
        Utilities::MPI::logical_or(
          distributed->n_locally_owned_active_cells() !=
            static_cast<unsigned int>(
              distributed->get_p4est()->local_num_quadrants),
          comm) == false,
      ExcMessage(
        "the refined mesh is not the one p4est holds (deal.II and p4est "
        "disagree on the refinement, as deal.II 9.4 did on coarse meshes "
        "with rotated faces), so the solution cannot be transferred to it. "
        "Change 'Mesh refinement/Coarsen fraction' or 'Mesh "
        "refinement/Minimum level', or use a coarse mesh whose faces are in "
        "standard orientation."));
    if (!attached)
      {
        // attached only now, after the scene has built and refined its
        // mesh: a DoF handler without DoFs must not take part in a
        // refinement of the triangulation
        dof_handler.reinit(triangulation);
        attached = true;
      }
    // the scalar DoFs of the mesh before are released (they took part in
    // its refinement numbered, as a DoF handler must) and numbered again
    // where needed
    scalar.reset();
    dof_handler.distribute_dofs(fe);
    locally_owned = dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dof_handler, locally_relevant);

    make_constraints(scene);
    // M, A, B share the sparsity pattern of the unconstrained operator;
    // constraints are applied by the active-set solver, not by assembly.
    // Nothing needs it where the mass is lumped and the step matrix is
    // applied without a matrix.
    graph.reset();
    if (parameters.assembled_step_matrix || !parameters.lumped_mass)
      make_sparsity_graph();
    // a lumped mass is kept as its diagonal only; a blended mass as its
    // matrix and its lumped part (for the bound of Jacobi)
    if (parameters.lumped_mass)
      mass_matrix.clear();
    else
      reinit_matrix(mass_matrix);
    if (parameters.lumped_mass || parameters.consistent_mass_fraction < 1.)
      lumped_mass_diagonal.reinit(locally_owned, comm);
    else
      lumped_mass_diagonal.clear();
    stiffness_product.reinit(nullptr);
    viscous = scene.is_viscous();

    if (!parameters.multigrid_level)
      {
        load.reinit(locally_owned, comm);
        boundary_weights.reinit(locally_owned, comm);
      }
    index_owned_nodes(scene.n_bodies());
  }



  template <int dim>
  void
  SemiDiscreteSystem<dim>::index_owned_nodes(const unsigned int n_bodies)
  {
    // for each locally owned DoF its slot body * dim + component (the
    // momentum's sums)
    owned_dof_slots.assign(locally_owned.n_elements(),
                           std::numeric_limits<unsigned char>::max());
    n_owned_body_dofs.assign(n_bodies, 0);
    for_each_owned_node(
      dof_handler,
      locally_owned,
      node_system_indices,
      [&](const auto &cell, const unsigned int, const auto &node_dofs) {
        const types::material_id body = cell->material_id();
        for (unsigned int c = 0; c < dim; ++c)
          owned_dof_slots[locally_owned.index_within_set(node_dofs[c])] =
            body * dim + c;
        n_owned_body_dofs[body] += dim;
      });

    // AMG's near-null space: the rigid translations, one per component,
    // as DoFTools::extract_constant_modes() gives them (whether each
    // locally owned DoF belongs to the component)
    constant_modes.assign(dim, std::vector<bool>(owned_dof_slots.size()));
    for (std::size_t k = 0; k < owned_dof_slots.size(); ++k)
      constant_modes[owned_dof_slots[k] % dim][k] = true;
  }



  template <int dim>
  const typename SemiDiscreteSystem<dim>::ScalarDoFs &
  SemiDiscreteSystem<dim>::scalar_dofs() const
  {
    if (scalar)
      return *scalar;
    // (kept only once complete)
    auto numbered =
      std::make_unique<ScalarDoFs>(dof_handler.get_triangulation());
    numbered->dof_handler.distribute_dofs(scalar_fe);
    numbered->locally_owned = numbered->dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(numbered->dof_handler,
                                            numbered->locally_relevant);
    // each locally owned node once, in the order of the cells
    std::vector<types::global_dof_index> scalar_node_dofs(
      scalar_fe.n_dofs_per_cell());
    unsigned int read_on = numbers::invalid_unsigned_int;
    for_each_owned_node(
      dof_handler,
      locally_owned,
      node_system_indices,
      [&](const auto &cell, const unsigned int node, const auto &node_dofs) {
        // (the same cell in the scalar DoF handler, read once per cell)
        if (cell->active_cell_index() != read_on)
          {
            typename DoFHandler<dim>::active_cell_iterator(
              &cell->get_triangulation(),
              cell->level(),
              cell->index(),
              &numbered->dof_handler)
              ->get_dof_indices(scalar_node_dofs);
            read_on = cell->active_cell_index();
          }
        numbered->owned_system0_to_scalar.emplace_back(node_dofs[0],
                                                       scalar_node_dofs[node]);
      });
    scalar = std::move(numbered);
    return *scalar;
  }



  template <int dim>
  bool
  SemiDiscreteSystem<dim>::vector_dofs_expand_scalar_dofs() const
  {
    // the owned and relevant sets: each scalar interval [a, b) must give
    // the vector interval [dim a, dim b)
    const auto expand = [](const IndexSet &scalar) {
      IndexSet vector(dim * scalar.size());
      for (auto interval = scalar.begin_intervals();
           interval != scalar.end_intervals();
           ++interval)
        vector.add_range(dim * *interval->begin(),
                         dim * (interval->last() + 1));
      vector.compress();
      return vector;
    };
    const ScalarDoFs &numbered = scalar_dofs();
    bool expanded = expand(numbered.locally_owned) == locally_owned &&
                    expand(numbered.locally_relevant) == locally_relevant;
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    std::vector<types::global_dof_index> node_dofs(scalar_fe.n_dofs_per_cell());
    auto scalar_cell = numbered.dof_handler.begin_active();
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        if (expanded && !cell->is_artificial())
          {
            cell->get_dof_indices(dofs);
            scalar_cell->get_dof_indices(node_dofs);
            for (unsigned int i = 0; i < dofs.size(); ++i)
              expanded =
                expanded &&
                (dofs[i] ==
                 dim * node_dofs[fe.system_to_component_index(i).second] +
                   fe.system_to_component_index(i).first);
          }
        ++scalar_cell;
      }
    return Utilities::MPI::min(expanded ? 1 : 0, comm) == 1;
  }



  template <int dim>
  void
  SemiDiscreteSystem<dim>::make_sparsity_graph()
  {
    // The rows are the locally owned DoFs, the columns the locally relevant
    // ones (a DoF coupled to an owned one lies on an owned or a ghost
    // cell), given as local indices. Where every vector DoF is dim * (its
    // node's scalar DoF) + component (deal.II numbers both DoF handlers
    // cell by cell: so it is for degrees 1 and 2), the pattern is the
    // scalar element's with every entry a dim x dim block, 1/dim^2 of the
    // work of the vector element's (3D bar at 1e6 DoFs: 'setup: DoFs and
    // sparsity' 2.5 s with the vector element's pattern made into deal.II's
    // Trilinos sparsity pattern, 1.3 s so); otherwise the vector element's.
    const bool        expanded = vector_dofs_expand_scalar_dofs();
    const ScalarDoFs &numbered = scalar_dofs();
    const IndexSet   &rows = expanded ? numbered.locally_owned : locally_owned;
    const IndexSet   &columns =
      expanded ? numbered.locally_relevant : locally_relevant;
    const unsigned int     block = expanded ? dim : 1;
    DynamicSparsityPattern dsp(columns);
    DoFTools::make_sparsity_pattern(expanded ? numbered.dof_handler :
                                               dof_handler,
                                    dsp);
    SparsityTools::distribute_sparsity_pattern(dsp, rows, comm, columns);

    // the columns: the locally owned DoFs first, in their order, then the
    // ghosts in theirs, as Epetra orders a column map it makes itself
    // (Trilinos ML expects the column map to begin with the row map)
    IndexSet ghosts = columns;
    ghosts.subtract_set(rows);
    const auto local_column = [&](const types::global_dof_index column) {
      return static_cast<int>(rows.is_element(column) ?
                                rows.index_within_set(column) :
                                rows.n_elements() +
                                  ghosts.index_within_set(column));
    };
    IndexSet vector_ghosts = locally_relevant;
    vector_ghosts.subtract_set(locally_owned);
    std::vector<TrilinosWrappers::types::int_type> column_ids;
    column_ids.reserve(locally_relevant.n_elements());
    for (const IndexSet *set : {&locally_owned, &vector_ghosts})
      for (const auto i : *set)
        column_ids.push_back(i);
    const Epetra_Map row_map = locally_owned.make_trilinos_map(comm, false);
    const Epetra_Map column_map(TrilinosWrappers::types::int_type(-1),
                                static_cast<int>(column_ids.size()),
                                column_ids.data(),
                                0,
                                row_map.Comm());

    std::vector<int> lengths;
    lengths.reserve(locally_owned.n_elements());
    for (const auto row : rows)
      lengths.insert(lengths.end(), block, block * dsp.row_length(row));
    graph = std::make_unique<Epetra_CrsGraph>(
      Copy, row_map, column_map, lengths.data(), true);
    std::vector<int> indices;
    int              local_row = 0;
    int              error     = 0;
    for (const auto row : rows)
      {
        indices.clear();
        // (by position: deal.II 9.4's row iterators look for the next
        // non-empty row at every begin() and end())
        const unsigned int n_entries = dsp.row_length(row);
        for (unsigned int k = 0; k < n_entries; ++k)
          {
            const int column = local_column(dsp.column_number(row, k));
            for (unsigned int c = 0; c < block; ++c)
              indices.push_back(block * column + c);
          }
        for (unsigned int c = 0; c < block; ++c, ++local_row)
          if (const int e = graph->InsertMyIndices(local_row,
                                                   indices.size(),
                                                   indices.data());
              e < 0)
            error = e;
      }
    if (error >= 0)
      error = std::min(graph->FillComplete(row_map, row_map), 0);
    if (error >= 0)
      error = std::min(graph->OptimizeStorage(), 0);
    AssertThrow(error == 0,
                ExcMessage("building the sparsity pattern failed (Epetra "
                           "error " +
                           std::to_string(error) + ")"));
  }



  template <int dim>
  void
  SemiDiscreteSystem<dim>::reinit_matrix(MatrixType &matrix) const
  {
    // deal.II's matrix on the shared graph (Epetra counts its references),
    // handed over by an Epetra matrix that only views it
    Assert(graph != nullptr, ExcInternalError());
    const Epetra_CrsMatrix carrier(View, *graph);
    matrix.reinit(carrier, false);
  }



  template <int dim>
  std::array<double, 2>
  SemiDiscreteSystem<dim>::interpolate_initial_values(const Scene<dim> &scene,
                                                      VectorType       &u,
                                                      VectorType &udot) const
  {
    reinit_vector(u);
    reinit_vector(udot);
    // nodal interpolation, cell by cell, so that each body gets its own data
    // (bodies share no nodes)
    const auto &unit_points = scalar_fe.get_unit_support_points();
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    // (a scene's function may stop on one rank: every rank stops)
    std::string problem;
    try
      {
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              cell->get_dof_indices(dofs);
              for (unsigned int node = 0; node < unit_points.size(); ++node)
                {
                  const Point<dim> x =
                    mapping.transform_unit_to_real_cell(cell,
                                                        unit_points[node]);
                  const Tensor<1, dim> u0 =
                    scene.initial_displacement(x, cell->material_id());
                  const Tensor<1, dim> v0 =
                    scene.initial_velocity(x, cell->material_id());
                  for (unsigned int d = 0; d < dim; ++d)
                    {
                      const auto dof = dofs[node_system_indices[node][d]];
                      if (locally_owned.is_element(dof))
                        {
                          u(dof)    = u0[d];
                          udot(dof) = v0[d];
                        }
                    }
                }
            }
      }
    catch (const std::exception &e)
      {
        problem = message_of(e);
      }
    stop_with_any_message(problem, comm);
    u.compress(VectorOperation::insert);
    udot.compress(VectorOperation::insert);
    // values where Dirichlet boundaries hold the displacement at zero (a
    // constraint without entries), which they reset
    double fixed_u = 0., fixed_v = 0.;
    for (const auto dof : locally_owned)
      if (constraints.is_constrained(dof) &&
          constraints.get_constraint_entries(dof)->empty())
        {
          fixed_u = std::max(fixed_u, std::abs(u(dof)));
          fixed_v = std::max(fixed_v, std::abs(udot(dof)));
        }
    fixed_u                           = Utilities::MPI::max(fixed_u, comm);
    fixed_v                           = Utilities::MPI::max(fixed_v, comm);
    const std::array<double, 2> reset = {
      {fixed_u > 1e-9 * u.linfty_norm() ? fixed_u : 0.,
       fixed_v > 1e-9 * udot.linfty_norm() ? fixed_v : 0.}};
    // hanging nodes follow their parents, Dirichlet nodes are fixed
    constraints.distribute(u);
    constraints.distribute(udot);
    return reset;
  }



  template <int dim>
  void
  SemiDiscreteSystem<dim>::reinit_vector(VectorType &v) const
  {
    v.reinit(locally_owned, comm);
  }



  template <int dim>
  VectorType
  SemiDiscreteSystem<dim>::ghosted(const VectorType &v) const
  {
    VectorType result(locally_owned, locally_relevant, comm);
    result = v;
    return result;
  }



  template <int dim>
  std::pair<double, double>
  SemiDiscreteSystem<dim>::energies(const VectorType &u,
                                    const VectorType &udot,
                                    VectorType       &M_udot) const
  {
    const SystemMatrices system = matrices();
    system.mass_vmult(M_udot, udot);
    const double kinetic = 0.5 * (M_udot * udot);
    return {kinetic, 0.5 * (system.stiffness_vmult(u) * u) - load * u};
  }



  template <int dim>
  double
  SemiDiscreteSystem<dim>::total_energy(const VectorType &u,
                                        const VectorType &udot) const
  {
    VectorType M_udot(udot);
    const auto [kinetic, elastic] = energies(u, udot, M_udot);
    return kinetic + elastic;
  }



  template <int dim>
  std::string
  SemiDiscreteSystem<dim>::mass_description() const
  {
    if (parameters.lumped_mass)
      return "lumped";
    if (parameters.consistent_mass_fraction == 1.)
      return "consistent";
    std::ostringstream text;
    // (+ 0.: -0 printed as 0)
    text << "blended (" << parameters.consistent_mass_fraction + 0.
         << " consistent)";
    return text.str();
  }



  template <int dim>
  SystemMatrices
  SemiDiscreteSystem<dim>::matrices() const
  {
    SystemMatrices system;
    system.M        = parameters.lumped_mass ? nullptr : &mass_matrix;
    system.M_lumped = parameters.lumped_mass ? &lumped_mass_diagonal : nullptr;
    system.M_lower =
      lumped_mass_diagonal.size() > 0 ? &lumped_mass_diagonal : nullptr;
    system.A_product = &stiffness_product;
    if (viscous)
      system.B_vmult = [this](VectorType &y, const VectorType &x) {
        viscous_vmult(y, x);
      };
    system.assemble_stiffness = [this](MatrixType  &matrix,
                                       const double a,
                                       const double b,
                                       const double m) {
      assemble_stiffness_matrix(matrix, a, b, m);
    };
    system.stiffness_combination_vmult =
      [this](VectorType &y, const VectorType &x, double a, double b) {
        elastic_operator.vmult(y, x, a, b);
      };
    system.stiffness_combination_diagonal =
      [this](VectorType &d, double a, double b) {
        stiffness_diagonal(d, a, b);
      };
    system.f          = function_loads.time_dependent ? &step_load : &load;
    system.f_end      = function_loads.time_dependent ? &end_load : &load;
    system.prescribed = prescribed.get();
    return system;
  }



  template <int dim>
  std::vector<VectorType>
  SemiDiscreteSystem<dim>::rotation_modes() const
  {
    std::vector<VectorType> modes(dim == 2 ? 1 : 3,
                                  VectorType(locally_owned, comm));
    const Quadrature<dim> support_points(fe.get_unit_support_points());
    FEValues<dim> values(mapping, fe, support_points, update_quadrature_points);
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          values.reinit(cell);
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            if (locally_owned.is_element(dofs[i]))
              {
                const unsigned int c = fe.system_to_component_index(i).first;
                for (unsigned int k = 0; k < modes.size(); ++k)
                  modes[k](dofs[i]) =
                    rotation_component<dim>(k, c, values.quadrature_point(i));
              }
        }
    for (auto &mode : modes)
      mode.compress(VectorOperation::insert);
    return modes;
  }



  template class SemiDiscreteSystem<2>;
  template class SemiDiscreteSystem<3>;
} // namespace dyncontact
