#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/numerics/vector_tools.h>

#include <dyncontact/discretization/semi_discrete_system.h>

#include <Epetra_CrsGraph.h>
#include <Epetra_CrsMatrix.h>
#include <Epetra_Map.h>
#include <Epetra_Vector.h>

#include <algorithm>
#include <cstring>
#include <limits>
#include <sstream>

namespace dyncontact
{
  namespace
  {
    /// The displacement component and the scalar FE_Q shape function of
    /// each shape function of FE_Q<dim>^dim.
    template <int dim>
    std::pair<std::vector<unsigned int>, std::vector<unsigned int>>
    components_and_nodes(const FESystem<dim> &fe)
    {
      std::vector<unsigned int> component(fe.n_dofs_per_cell()),
        node(fe.n_dofs_per_cell());
      for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
        {
          component[i] = fe.system_to_component_index(i).first;
          node[i]      = fe.system_to_component_index(i).second;
        }
      return {component, node};
    }



    /**
     * Adds element matrices into a Trilinos matrix whose sparsity pattern
     * holds them. A locally owned row goes straight into Epetra's row (its
     * column indices are local, and sorted once the pattern is complete:
     * one merge with the element's sorted columns finds every entry),
     * instead of deal.II's add(), which has Epetra look up every entry's
     * global column (3D bar at 1e6 DoFs: 1.5 s of the step matrix's
     * assembly). Other rows, an entry the merge does not find, and a
     * matrix whose pattern is not complete go through deal.II's add().
     */
    class ElementMatrixAdder
    {
    public:
      explicit ElementMatrixAdder(MatrixType &matrix)
        : matrix(matrix)
        , epetra(const_cast<Epetra_CrsMatrix &>(matrix.trilinos_matrix()))
        , direct(epetra.Filled() && epetra.IndicesAreLocal())
      {}

      void
      add(const std::vector<types::global_dof_index> &dofs,
          const FullMatrix<double>                   &element_matrix)
      {
        const unsigned int n = dofs.size();
        if (!direct)
          {
            matrix.add(dofs, element_matrix);
            return;
          }
        rows.resize(n);
        columns.resize(n);
        order.resize(n);
        positions.assign(n, std::numeric_limits<int>::max());
        for (unsigned int j = 0; j < n; ++j)
          {
            const auto gid =
              static_cast<TrilinosWrappers::types::int_type>(dofs[j]);
            rows[j]    = epetra.RowMap().LID(gid);
            columns[j] = epetra.ColMap().LID(gid);
            order[j]   = j;
          }
        std::sort(order.begin(),
                  order.end(),
                  [this](const unsigned int a, const unsigned int b) {
                    return columns[a] < columns[b];
                  });
        for (unsigned int i = 0; i < n; ++i)
          {
            if (rows[i] < 0)
              {
                // not owned here: Epetra keeps it for the owner until
                // compress()
                matrix.add(dofs[i], n, dofs.data(), &element_matrix(i, 0));
                continue;
              }
            int     length  = 0;
            double *values  = nullptr;
            int    *indices = nullptr;
            epetra.ExtractMyRowView(rows[i], length, values, indices);
            // Each entry is first looked for where the row before had it:
            // the rows of one node's components have the same columns. Else
            // a binary search from the entry before finds it (the
            // element's columns come in runs of neighbours in the row).
            const int *q = indices, *const end = indices + length;
            for (const unsigned int j : order)
              {
                const int p = positions[j];
                if (p < length && indices[p] == columns[j])
                  {
                    values[p] += element_matrix(i, j);
                    q = indices + p + 1;
                    continue;
                  }
                if (q == end || *q != columns[j])
                  q = std::lower_bound(q, end, columns[j]);
                if (q != end && *q == columns[j])
                  {
                    positions[j] = q - indices;
                    values[q++ - indices] += element_matrix(i, j);
                  }
                else
                  matrix.add(dofs[i], dofs[j], element_matrix(i, j));
              }
          }
      }

    private:
      MatrixType               &matrix;
      Epetra_CrsMatrix         &epetra;
      const bool                direct;
      std::vector<int>          rows, columns;
      std::vector<unsigned int> order;
      /// where each column of the element was found in the row before
      std::vector<int> positions;
    };
  } // namespace


  template <int dim>
  void
  SemiDiscreteSystem<dim>::Parameters::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry(
      "Polynomial degree",
      "1",
      Patterns::Integer(1, 4),
      "Degree p of the displacement space FE_Q(p)^dim, 1 to 4.");
    prm.enter_subsection("Time integration");
    prm.declare_entry("Mass matrix",
                      "lumped",
                      Patterns::Selection("lumped|consistent"),
                      "lumped: diagonal, by Gauss-Lobatto (nodal) quadrature; "
                      "consistent: by Gauss quadrature.");
    prm.leave_subsection();
  }



  template <int dim>
  void
  SemiDiscreteSystem<dim>::Parameters::parse_parameters(ParameterHandler &prm)
  {
    degree = prm.get_integer("Polynomial degree");
    prm.enter_subsection("Time integration");
    lumped_mass = (prm.get("Mass matrix") == "lumped");
    prm.leave_subsection();
  }



  template <int dim>
  SemiDiscreteSystem<dim>::SemiDiscreteSystem(const Parameters   &parameters,
                                              const Mapping<dim> &mapping,
                                              const MPI_Comm      comm)
    : parameters(parameters)
    , mapping(mapping)
    , comm(comm)
    , fe(FE_Q<dim>(parameters.degree), dim)
    , scalar_fe(parameters.degree)
  {}



  template <int dim>
  SemiDiscreteSystem<dim>::~SemiDiscreteSystem() = default;



  template <int dim>
  void
  SemiDiscreteSystem<dim>::setup(
    const parallel::distributed::Triangulation<dim> &triangulation,
    const Scene<dim>                                &scene)
  {
    if (!attached)
      {
        // attached only now, after the scene has built and refined its
        // mesh: a DoF handler without DoFs must not take part in a
        // refinement of the triangulation
        dof_handler.reinit(triangulation);
        scalar_dof_handler.reinit(triangulation);
        attached = true;
      }
    dof_handler.distribute_dofs(fe);
    scalar_dof_handler.distribute_dofs(scalar_fe);
    locally_owned = dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dof_handler, locally_relevant);
    scalar_locally_owned = scalar_dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(scalar_dof_handler,
                                            scalar_locally_relevant);

    // hanging nodes and homogeneous Dirichlet data
    constraints.clear();
    constraints.reinit(locally_relevant);
    DoFTools::make_hanging_node_constraints(dof_handler, constraints);
    for (const auto &boundary : scene.dirichlet_boundaries())
      {
        std::vector<bool> components(dim);
        for (unsigned int d = 0; d < dim; ++d)
          components[d] = boundary.components[d];
        VectorTools::interpolate_boundary_values(mapping,
                                                 dof_handler,
                                                 boundary.id,
                                                 Functions::ZeroFunction<dim>(
                                                   dim),
                                                 constraints,
                                                 ComponentMask(components));
      }
    constraints.close();
    // M, A, B share the sparsity pattern of the unconstrained operator;
    // constraints are applied by the active-set solver, not by assembly
    make_sparsity_graph();
    // a lumped mass is kept as its diagonal only
    if (parameters.lumped_mass)
      {
        mass_matrix.clear();
        lumped_mass_diagonal.reinit(locally_owned, comm);
      }
    else
      {
        reinit_matrix(mass_matrix);
        lumped_mass_diagonal.clear();
      }
    stiffness_product.reinit(nullptr);
    viscous = scene.is_viscous();

    load.reinit(locally_owned, comm);
    boundary_weights.reinit(locally_owned, comm);
    // one pass over the locally owned cells: for each locally owned node its
    // component-0 DoF and scalar DoF, and for each locally owned DoF its
    // slot body * dim + component (the momentum's sums)
    owned_system0_to_scalar.clear();
    constexpr unsigned char unset = std::numeric_limits<unsigned char>::max();
    owned_dof_slots.assign(locally_owned.n_elements(), unset);
    n_owned_body_dofs.assign(scene.n_bodies(), 0);
    {
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      std::vector<types::global_dof_index> scalar_dofs(
        scalar_fe.n_dofs_per_cell());
      auto scalar_cell = scalar_dof_handler.begin_active();
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          if (cell->is_locally_owned())
            {
              cell->get_dof_indices(dofs);
              scalar_cell->get_dof_indices(scalar_dofs);
              const types::material_id body = cell->material_id();
              for (unsigned int node = 0; node < scalar_dofs.size(); ++node)
                {
                  const auto dof0 = dofs[fe.component_to_system_index(0, node)];
                  if (!locally_owned.is_element(dof0))
                    continue;
                  // (a node's DoFs are owned together)
                  const auto k0 = locally_owned.index_within_set(dof0);
                  if (owned_dof_slots[k0] != unset)
                    continue;
                  owned_system0_to_scalar.emplace_back(dof0, scalar_dofs[node]);
                  for (unsigned int c = 0; c < dim; ++c)
                    owned_dof_slots[locally_owned.index_within_set(
                      dofs[fe.component_to_system_index(c, node)])] =
                      body * dim + c;
                  n_owned_body_dofs[body] += dim;
                }
            }
          ++scalar_cell;
        }
    }

    // AMG's near-null space: the rigid translations, one per component,
    // as DoFTools::extract_constant_modes() gives them (whether each
    // locally owned DoF belongs to the component)
    constant_modes.assign(dim, std::vector<bool>(owned_dof_slots.size()));
    for (std::size_t k = 0; k < owned_dof_slots.size(); ++k)
      constant_modes[owned_dof_slots[k] % dim][k] = true;
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
    bool expanded = expand(scalar_locally_owned) == locally_owned &&
                    expand(scalar_locally_relevant) == locally_relevant;
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    std::vector<types::global_dof_index> scalar_dofs(
      scalar_fe.n_dofs_per_cell());
    auto scalar_cell = scalar_dof_handler.begin_active();
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        if (expanded && !cell->is_artificial())
          {
            cell->get_dof_indices(dofs);
            scalar_cell->get_dof_indices(scalar_dofs);
            for (unsigned int i = 0; i < dofs.size(); ++i)
              expanded =
                expanded &&
                (dofs[i] ==
                 dim * scalar_dofs[fe.system_to_component_index(i).second] +
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
    const bool      expanded = vector_dofs_expand_scalar_dofs();
    const IndexSet &rows     = expanded ? scalar_locally_owned : locally_owned;
    const IndexSet &columns =
      expanded ? scalar_locally_relevant : locally_relevant;
    const unsigned int     block = expanded ? dim : 1;
    DynamicSparsityPattern dsp(columns);
    DoFTools::make_sparsity_pattern(expanded ? scalar_dof_handler : dof_handler,
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
        for (auto entry = dsp.begin(row); entry != dsp.end(row); ++entry)
          {
            const int column = local_column(entry->column());
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
    const Epetra_CrsMatrix carrier(View, *graph);
    matrix.reinit(carrier, false);
  }



  template <int dim>
  void
  SemiDiscreteSystem<dim>::assemble(const Scene<dim> &scene)
  {
    auto       tractions   = scene.neumann_tractions();
    const auto contact_ids = scene.all_contact_boundary_ids();

    const QGauss<dim> quadrature(fe.degree + 1);
    // the lumped mass matrix: nodal (Gauss-Lobatto) quadrature makes the
    // element mass matrix of FE_Q diagonal
    const Quadrature<dim> mass_quadrature =
      parameters.lumped_mass ?
        Quadrature<dim>(QGaussLobatto<dim>(fe.degree + 1)) :
        Quadrature<dim>(QGauss<dim>(fe.degree + 1));
    const QGauss<dim - 1>        face_quadrature(fe.degree + 1);
    const QGaussLobatto<dim - 1> lumped_face_quadrature(fe.degree + 1);

    // loads given as total forces: spread over the boundary as the mesh
    // represents it, so that they sum to the force exactly
    if (const auto forces = scene.neumann_forces(); !forces.empty())
      {
        FEFaceValues<dim>   area_values(mapping,
                                      fe,
                                      face_quadrature,
                                      update_JxW_values);
        std::vector<double> areas(forces.size(), 0.);
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            for (const unsigned int f : cell->face_indices())
              if (cell->face(f)->at_boundary())
                for (unsigned int k = 0; k < forces.size(); ++k)
                  if (cell->face(f)->boundary_id() == forces[k].first)
                    {
                      area_values.reinit(cell, f);
                      for (unsigned int q = 0; q < face_quadrature.size(); ++q)
                        areas[k] += area_values.JxW(q);
                    }
        Utilities::MPI::sum(areas, comm, areas);
        for (unsigned int k = 0; k < forces.size(); ++k)
          {
            AssertThrow(areas[k] > 0.,
                        ExcMessage("The scene loads boundary id " +
                                   std::to_string(forces[k].first) +
                                   " with a force, but no boundary face of "
                                   "the mesh has that id."));
            tractions.emplace_back(forces[k].first,
                                   forces[k].second / areas[k]);
          }
      }

    FEValues<dim>     fe_values(mapping,
                            scalar_fe,
                            quadrature,
                            update_values | update_JxW_values);
    FEValues<dim>     mass_values(mapping,
                              scalar_fe,
                              mass_quadrature,
                              update_values | update_JxW_values);
    FEFaceValues<dim> face_values(mapping,
                                  scalar_fe,
                                  face_quadrature,
                                  update_values | update_JxW_values);
    FEFaceValues<dim> lumped_face_values(mapping,
                                         scalar_fe,
                                         lumped_face_quadrature,
                                         update_values | update_JxW_values);

    const unsigned int  dofs_per_cell = fe.n_dofs_per_cell();
    const unsigned int  n_nodes       = scalar_fe.n_dofs_per_cell();
    std::vector<double> bad_cell; // centre and body of an inverted cell
    FullMatrix<double>  cell_mass(dofs_per_cell, dofs_per_cell);
    Vector<double>      cell_lumped_mass(dofs_per_cell);
    Vector<double>      cell_load(dofs_per_cell);
    Vector<double>      cell_boundary_weights(dofs_per_cell);
    std::vector<types::global_dof_index> dof_indices(dofs_per_cell);

    // component and scalar shape function of each shape function
    const auto [component, node] = components_and_nodes(fe);
    // the scalar mass int phi_k phi_l and load int phi_k
    std::vector<double> scalar_mass(n_nodes * n_nodes);
    std::vector<double> scalar_load(n_nodes);

    materials.clear();
    std::unique_ptr<ElementMatrixAdder> mass_adder;
    if (!parameters.lumped_mass)
      mass_adder = std::make_unique<ElementMatrixAdder>(mass_matrix);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell_mass             = 0.;
          cell_load             = 0.;
          cell_boundary_weights = 0.;
          const Material &material =
            materials
              .emplace(cell->material_id(), scene.material(cell->material_id()))
              .first->second;
          const double rho        = material.density;
          const auto   body_force = scene.body_force(cell->material_id());
          const typename Triangulation<dim>::cell_iterator tria_cell(cell);
          fe_values.reinit(tria_cell);
          mass_values.reinit(tria_cell);
          // an inverted or twisted cell (which deal.II does not reject on
          // reading) has a non-positive Jacobian somewhere
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            if (!(fe_values.JxW(q) > 0.) && bad_cell.empty())
              {
                for (unsigned int d = 0; d < dim; ++d)
                  bad_cell.push_back(cell->center()[d]);
                bad_cell.push_back(cell->material_id() + 1);
              }

          std::fill(scalar_load.begin(), scalar_load.end(), 0.);
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            for (unsigned int k = 0; k < n_nodes; ++k)
              scalar_load[k] += fe_values.shape_value(k, q) * fe_values.JxW(q);
          for (unsigned int i = 0; i < dofs_per_cell; ++i)
            cell_load(i) = scalar_load[node[i]] * body_force[component[i]];

          // (lumped: the element matrix is diagonal, only its diagonal is
          // computed)
          std::fill(scalar_mass.begin(), scalar_mass.end(), 0.);
          for (unsigned int q = 0; q < mass_quadrature.size(); ++q)
            for (unsigned int k = 0; k < n_nodes; ++k)
              for (unsigned int l = (parameters.lumped_mass ? k : 0);
                   l < (parameters.lumped_mass ? k + 1 : n_nodes);
                   ++l)
                scalar_mass[k * n_nodes + l] +=
                  rho * mass_values.shape_value(k, q) *
                  mass_values.shape_value(l, q) * mass_values.JxW(q);
          for (unsigned int i = 0; i < dofs_per_cell; ++i)
            for (unsigned int j = (parameters.lumped_mass ? i : 0);
                 j < (parameters.lumped_mass ? i + 1 : dofs_per_cell);
                 ++j)
              if (component[i] == component[j])
                cell_mass(i, j) = scalar_mass[node[i] * n_nodes + node[j]];

          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary())
              {
                const auto id = cell->face(f)->boundary_id();
                for (const auto &[traction_id, traction] : tractions)
                  if (traction_id == id)
                    {
                      face_values.reinit(tria_cell, f);
                      for (unsigned int q = 0; q < face_quadrature.size(); ++q)
                        for (unsigned int i = 0; i < dofs_per_cell; ++i)
                          cell_load(i) += face_values.shape_value(node[i], q) *
                                          traction[component[i]] *
                                          face_values.JxW(q);
                    }
                if (std::find(contact_ids.begin(), contact_ids.end(), id) !=
                    contact_ids.end())
                  {
                    // w_p = int psi_p ds, by nodal quadrature (positive)
                    lumped_face_values.reinit(tria_cell, f);
                    for (unsigned int q = 0; q < lumped_face_quadrature.size();
                         ++q)
                      for (unsigned int i = 0; i < dofs_per_cell; ++i)
                        cell_boundary_weights(i) +=
                          lumped_face_values.shape_value(node[i], q) *
                          lumped_face_values.JxW(q);
                  }
              }

          cell->get_dof_indices(dof_indices);
          if (parameters.lumped_mass)
            {
              for (unsigned int i = 0; i < dofs_per_cell; ++i)
                cell_lumped_mass(i) = cell_mass(i, i);
              lumped_mass_diagonal.add(dof_indices, cell_lumped_mass);
            }
          else
            mass_adder->add(dof_indices, cell_mass);
          load.add(dof_indices, cell_load);
          boundary_weights.add(dof_indices, cell_boundary_weights);
        }

    if (parameters.lumped_mass)
      lumped_mass_diagonal.compress(VectorOperation::add);
    else
      mass_matrix.compress(VectorOperation::add);
    for (const auto &rank_bad : Utilities::MPI::all_gather(comm, bad_cell))
      if (!rank_bad.empty())
        {
          std::ostringstream where;
          where << "(" << rank_bad[0];
          for (unsigned int d = 1; d < dim; ++d)
            where << ", " << rank_bad[d];
          where << ")";
          AssertThrow(false,
                      ExcMessage("The mesh has an inverted or twisted cell "
                                 "(non-positive Jacobian) at " +
                                 where.str() + " in body " +
                                 std::to_string(int(rank_bad[dim])) +
                                 "; check the mesh (file) and the order of "
                                 "the cell's vertices."));
        }
    load.compress(VectorOperation::add);
    boundary_weights.compress(VectorOperation::add);

    elastic_operator.reinit(mapping, dof_handler, materials);
    stiffness_product.reinit(
      [this](VectorType &y, const VectorType &x) { stiffness_vmult(y, x); });
  }



  template <int dim>
  void
  SemiDiscreteSystem<dim>::assemble_stiffness_matrix(MatrixType  &matrix,
                                                     const double a,
                                                     const double b,
                                                     const double m) const
  {
    reinit_matrix(matrix);
    // a lumped m M goes onto the diagonal in the first cell of each owned
    // row (a locally owned DoF lies on a locally owned cell)
    const bool lumped_mass_in_cells = (m != 0. && parameters.lumped_mass);
    std::vector<bool> mass_added(
      lumped_mass_in_cells ? locally_owned.n_elements() : 0, false);
    // Every shape function of FE_Q<dim>^dim is a scalar shape function
    // phi_k of FE_Q times a unit vector e_c, so the element matrices follow
    // from the scalar gradients (a third of the work of the vector
    // element's FEValues): with H^ab_kl = int d_a phi_k d_b phi_l,
    //   2 mu eps(phi_k e_c) : eps(phi_l e_d) = mu (delta_cd sum_a H^aa_kl
    //                                              + H^dc_kl),
    //   div(phi_k e_c) div(phi_l e_d)        = H^cd_kl.
    const QGauss<dim>  quadrature(fe.degree + 1);
    FEValues<dim>      fe_values(mapping,
                            scalar_fe,
                            quadrature,
                            update_gradients | update_JxW_values);
    const unsigned int dofs_per_cell = fe.n_dofs_per_cell();
    const unsigned int n_nodes       = scalar_fe.n_dofs_per_cell();
    FullMatrix<double> cell_matrix(dofs_per_cell, dofs_per_cell);
    std::vector<types::global_dof_index> dof_indices(dofs_per_cell);
    const auto [component, node] = components_and_nodes(fe);
    // H^ab_kl at [(a * dim + b) * n_nodes * n_nodes + k * n_nodes + l]
    std::vector<double> gradient_products(dim * dim * n_nodes * n_nodes);
    std::vector<double> laplace(n_nodes * n_nodes);
    std::vector<Tensor<1, dim>> gradients(n_nodes);

    // H and the scalar Laplacian sum_c H^cc_kl of the cell in fe_values
    const auto compute_products = [&]() {
      std::fill(gradient_products.begin(), gradient_products.end(), 0.);
      for (unsigned int q = 0; q < quadrature.size(); ++q)
        {
          const double JxW = fe_values.JxW(q);
          for (unsigned int k = 0; k < n_nodes; ++k)
            gradients[k] = fe_values.shape_grad(k, q);
          for (unsigned int c = 0; c < dim; ++c)
            for (unsigned int d = 0; d < dim; ++d)
              {
                double *H =
                  &gradient_products[(c * dim + d) * n_nodes * n_nodes];
                for (unsigned int k = 0; k < n_nodes; ++k)
                  {
                    const double left = gradients[k][c] * JxW;
                    for (unsigned int l = 0; l < n_nodes; ++l)
                      H[k * n_nodes + l] += left * gradients[l][d];
                  }
              }
        }
      std::fill(laplace.begin(), laplace.end(), 0.);
      for (unsigned int c = 0; c < dim; ++c)
        for (unsigned int kl = 0; kl < n_nodes * n_nodes; ++kl)
          laplace[kl] +=
            gradient_products[(c * dim + c) * n_nodes * n_nodes + kl];
    };
    bool have_products = false;
    // the element matrix a A + b B of the cell before, and its moduli
    FullMatrix<double> element_matrix(dofs_per_cell, dofs_per_cell);
    double             element_mu = 0., element_lambda = 0.;
    ElementMatrixAdder adder(matrix);

    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const Material &material = materials.at(cell->material_id());
          // the moduli of a A + b B
          const double mu = a * material.mu() +
                            (b != 0. ? b * material.viscous_shear_modulus : 0.);
          const double lambda = a * material.lambda() +
                                (b != 0. ? b * material.viscous_lambda : 0.);
          fe_values.reinit(typename Triangulation<dim>::cell_iterator(cell));

          // a translation of the cell before has the same H (deal.II's
          // FEValues recognises it on a mapping of degree 1), and with the
          // same moduli the same element matrix
          const bool same_products =
            have_products &&
            fe_values.get_cell_similarity() == CellSimilarity::translation;
          if (!same_products)
            compute_products();
          if (!same_products || mu != element_mu || lambda != element_lambda)
            {
              const auto H = [&](const unsigned int c,
                                 const unsigned int d,
                                 const unsigned int k,
                                 const unsigned int l) {
                return gradient_products[(c * dim + d) * n_nodes * n_nodes +
                                         k * n_nodes + l];
              };
              for (unsigned int i = 0; i < dofs_per_cell; ++i)
                {
                  const unsigned int c = component[i], k = node[i];
                  for (unsigned int j = 0; j < dofs_per_cell; ++j)
                    {
                      const unsigned int d = component[j], l = node[j];
                      const double       shear =
                        (c == d ? laplace[k * n_nodes + l] : 0.) +
                        H(d, c, k, l);
                      element_matrix(i, j) =
                        mu * shear + lambda * H(c, d, k, l);
                    }
                }
              element_mu     = mu;
              element_lambda = lambda;
            }
          have_products = true;
          cell_matrix   = element_matrix;
          cell->get_dof_indices(dof_indices);
          if (lumped_mass_in_cells)
            for (unsigned int i = 0; i < dofs_per_cell; ++i)
              if (locally_owned.is_element(dof_indices[i]))
                {
                  const auto row =
                    locally_owned.index_within_set(dof_indices[i]);
                  if (!mass_added[row])
                    {
                      cell_matrix(i, i) +=
                        m * lumped_mass_diagonal(dof_indices[i]);
                      mass_added[row] = true;
                    }
                }
          adder.add(dof_indices, cell_matrix);
        }
    matrix.compress(VectorOperation::add);
    if (m != 0. && !parameters.lumped_mass)
      matrix.add(m, mass_matrix);
  }



  template <int dim>
  void
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
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(dofs);
          for (unsigned int node = 0; node < unit_points.size(); ++node)
            {
              const Point<dim> x =
                mapping.transform_unit_to_real_cell(cell, unit_points[node]);
              const Tensor<1, dim> u0 =
                scene.initial_displacement(x, cell->material_id());
              const Tensor<1, dim> v0 =
                scene.initial_velocity(x, cell->material_id());
              for (unsigned int d = 0; d < dim; ++d)
                {
                  const auto dof = dofs[fe.component_to_system_index(d, node)];
                  if (locally_owned.is_element(dof))
                    {
                      u(dof)    = u0[d];
                      udot(dof) = v0[d];
                    }
                }
            }
        }
    u.compress(VectorOperation::insert);
    udot.compress(VectorOperation::insert);
    // hanging nodes follow their parents, Dirichlet nodes are fixed
    constraints.distribute(u);
    constraints.distribute(udot);
  }



  template <int dim>
  void
  SemiDiscreteSystem<dim>::reinit_vector(VectorType &v) const
  {
    v.reinit(locally_owned, comm);
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
  std::vector<const VectorType *>
  SemiDiscreteSystem<dim>::start_transfer(
    const std::vector<const VectorType *> &vectors)
  {
    transferred.assign(vectors.size(),
                       VectorType(locally_owned, locally_relevant, comm));
    std::vector<const VectorType *> ghosted;
    for (unsigned int i = 0; i < vectors.size(); ++i)
      {
        transferred[i] = *vectors[i];
        ghosted.push_back(&transferred[i]);
      }
    transfer = std::make_unique<
      parallel::distributed::SolutionTransfer<dim, VectorType>>(dof_handler);
    return ghosted;
  }



  template <int dim>
  void
  SemiDiscreteSystem<dim>::prepare_for_refinement(const VectorType &u,
                                                  const VectorType &udot)
  {
    const auto vectors = start_transfer({&u, &udot});
    transfer->prepare_for_coarsening_and_refinement(vectors);
  }



  template <int dim>
  void
  SemiDiscreteSystem<dim>::interpolate_after_refinement(VectorType &u,
                                                        VectorType &udot)
  {
    reinit_vector(u);
    reinit_vector(udot);
    std::vector<VectorType *> out = {&u, &udot};
    transfer->interpolate(out);
    transfer.reset();
    transferred.clear();
    constraints.distribute(u);
    constraints.distribute(udot);
  }



  template <int dim>
  void
  SemiDiscreteSystem<dim>::prepare_for_serialization(
    const std::vector<const VectorType *> &vectors)
  {
    const auto ghosted = start_transfer(vectors);
    transfer->prepare_for_serialization(ghosted);
  }



  template <int dim>
  void
  SemiDiscreteSystem<dim>::deserialize(const std::vector<VectorType *> &vectors)
  {
    for (VectorType *v : vectors)
      reinit_vector(*v);
    parallel::distributed::SolutionTransfer<dim, VectorType> loader(
      dof_handler);
    std::vector<VectorType *> out = vectors;
    loader.deserialize(out);
  }



  template <int dim>
  SystemMatrices
  SemiDiscreteSystem<dim>::matrices() const
  {
    SystemMatrices system;
    system.M         = parameters.lumped_mass ? nullptr : &mass_matrix;
    system.M_lumped  = parameters.lumped_mass ? &lumped_mass_diagonal : nullptr;
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
    system.f = &load;
    return system;
  }



  void
  CachedProduct::reinit(const Product &product)
  {
    this->product = product;
    valid         = false;
  }



  const VectorType &
  CachedProduct::vmult(const VectorType &x) const
  {
    Assert(product, ExcInternalError());
    bool hit = valid &&
               x_last.locally_owned_elements() == x.locally_owned_elements() &&
               std::memcmp(x_last.begin(),
                           x.begin(),
                           x.locally_owned_size() * sizeof(double)) == 0;
    hit = (Utilities::MPI::min(hit ? 1 : 0, x.get_mpi_communicator()) == 1);
    if (!hit)
      {
        x_last = x;
        y_last.reinit(x, true);
        product(y_last, x);
        valid = true;
      }
    return y_last;
  }



  void
  SystemMatrices::mass_vmult(VectorType &y, const VectorType &x) const
  {
    if (M != nullptr)
      {
        y.reinit(x, true);
        M->vmult(y, x);
      }
    else
      {
        y = x;
        y.scale(*M_lumped);
      }
  }



  double
  SystemMatrices::mass_linfty_norm() const
  {
    return M != nullptr ? M->linfty_norm() : M_lumped->linfty_norm();
  }



  void
  SystemMatrices::add_mass(MatrixType &matrix, const double factor) const
  {
    if (M != nullptr)
      {
        matrix.add(factor, *M);
        return;
      }
    // the diagonal of the Epetra matrix, changed in place (deal.II's wrapper
    // gives only a const view of the matrix it owns)
    auto &epetra = const_cast<Epetra_CrsMatrix &>(matrix.trilinos_matrix());
    Epetra_Vector diagonal(epetra.RowMap());
    int           error = epetra.ExtractDiagonalCopy(diagonal);
    if (error == 0)
      error = diagonal.Update(factor, M_lumped->trilinos_vector(), 1.);
    if (error == 0)
      error = epetra.ReplaceDiagonalValues(diagonal);
    AssertThrow(error == 0,
                ExcMessage("adding the lumped mass to a matrix's diagonal "
                           "failed (Epetra error " +
                           std::to_string(error) + ")"));
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
                const Point<dim>  &x = values.quadrature_point(i);
                auto               coordinate = [&](const unsigned int j) {
                  return j < dim ? x[j] : 0.;
                };
                // e_axis x x = x_a e_b - x_b e_a, (axis, a, b) cyclic; the
                // axis is z in 2D, and x, y, z in 3D
                for (unsigned int k = 0; k < modes.size(); ++k)
                  {
                    const unsigned int axis = (dim == 2) ? 2 : k;
                    const unsigned int a = (axis + 1) % 3, b = (axis + 2) % 3;
                    const double       value = (c == b) ? coordinate(a) :
                                               (c == a) ? -coordinate(b) :
                                                          0.;
                    modes[k](dofs[i])        = value;
                  }
              }
        }
    for (auto &mode : modes)
      mode.compress(VectorOperation::insert);
    return modes;
  }



  template class SemiDiscreteSystem<2>;
  template class SemiDiscreteSystem<3>;
} // namespace dyncontact
