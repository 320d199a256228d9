#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_postprocessor.h>
#include <deal.II/numerics/vector_tools.h>

#include <boost/serialization/array.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>

#include <dyncontact/contact_mapping.h>
#include <dyncontact/simulator.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <set>

namespace dyncontact
{
  namespace
  {
    /// Von Mises stress of the elastic stress 2 mu eps + lambda tr(eps) I.
    template <int dim>
    class VonMisesPostprocessor : public DataPostprocessorScalar<dim>
    {
    public:
      VonMisesPostprocessor(const Scene<dim> &scene)
        : DataPostprocessorScalar<dim>("von_mises_stress", update_gradients)
        , scene(scene)
      {}

      void
      evaluate_vector_field(
        const DataPostprocessorInputs::Vector<dim> &inputs,
        std::vector<Vector<double>> &computed_quantities) const override
      {
        const auto      cell     = inputs.template get_cell<dim>();
        const Material &material = scene.material(cell->material_id());
        const double    mu = material.mu(), lambda = material.lambda();
        for (unsigned int q = 0; q < inputs.solution_gradients.size(); ++q)
          {
            Tensor<2, dim> grad;
            for (unsigned int d = 0; d < dim; ++d)
              grad[d] = inputs.solution_gradients[q][d];
            const SymmetricTensor<2, dim> eps = symmetrize(grad);
            SymmetricTensor<2, 3>         sigma;
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int j = 0; j < dim; ++j)
                sigma[i][j] = 2. * mu * eps[i][j];
            for (unsigned int i = 0; i < 3; ++i)
              sigma[i][i] += lambda * trace(eps);
            const SymmetricTensor<2, 3> s = deviator(sigma);
            computed_quantities[q](0)     = std::sqrt(1.5 * (s * s));
          }
      }

    private:
      const Scene<dim> &scene;
    };
  } // namespace



  template <int dim>
  Simulator<dim>::Simulator(const RunParameters &parameters,
                            ParameterHandler    &prm,
                            const MPI_Comm       comm)
    : parameters(parameters)
    , comm(comm)
    , pcout(std::cout, Utilities::MPI::this_mpi_process(comm) == 0)
    , timer(std::make_unique<TimerOutput>(comm,
                                          pcout,
                                          TimerOutput::never,
                                          TimerOutput::wall_times))
    , scene(create_scene<dim>(prm,
                              parameters.materials,
                              parameters.input_directory))
    , triangulation(comm)
    , fe(FE_Q<dim>(parameters.degree), dim)
    , dof_handler(triangulation)
    , scalar_fe(parameters.degree)
    , scalar_dof_handler(triangulation)
    , current_tau(parameters.time_step)
  {}



  template <int dim>
  void
  Simulator<dim>::setup_system()
  {
    TimerOutput::Scope t(*timer, "setup");

    dof_handler.distribute_dofs(fe);
    scalar_dof_handler.distribute_dofs(scalar_fe);
    locally_owned = dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dof_handler, locally_relevant);
    scalar_locally_owned = scalar_dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(scalar_dof_handler,
                                            scalar_locally_relevant);

    // hanging nodes and homogeneous Dirichlet data
    mesh_constraints.clear();
    mesh_constraints.reinit(locally_relevant);
    DoFTools::make_hanging_node_constraints(dof_handler, mesh_constraints);
    for (const auto &boundary : scene->dirichlet_boundaries())
      {
        std::vector<bool> components(dim);
        for (unsigned int d = 0; d < dim; ++d)
          components[d] = boundary.components[d];
        VectorTools::interpolate_boundary_values(mapping,
                                                 dof_handler,
                                                 boundary.id,
                                                 Functions::ZeroFunction<dim>(
                                                   dim),
                                                 mesh_constraints,
                                                 ComponentMask(components));
      }
    mesh_constraints.close();
    DoFTools::extract_constant_modes(dof_handler,
                                     ComponentMask(dim, true),
                                     constant_modes);

    // M, A, B share the sparsity pattern of the unconstrained operator;
    // constraints are applied by the active-set solver, not by assembly
    DynamicSparsityPattern dsp(locally_relevant);
    DoFTools::make_sparsity_pattern(dof_handler, dsp);
    SparsityTools::distribute_sparsity_pattern(dsp,
                                               locally_owned,
                                               comm,
                                               locally_relevant);
    mass_matrix.reinit(locally_owned, locally_owned, dsp, comm);
    stiffness_matrix.reinit(locally_owned, locally_owned, dsp, comm);
    bool viscous = false;
    for (unsigned int b = 0; b < scene->n_bodies(); ++b)
      viscous = viscous || scene->material(b).is_viscous();
    if (viscous)
      viscous_matrix.reinit(locally_owned, locally_owned, dsp, comm);
    else
      viscous_matrix.clear();

    load.reinit(locally_owned, comm);
    boundary_mass.reinit(locally_owned, comm);
    u.reinit(locally_owned, comm);
    udot.reinit(locally_owned, comm);
    u_old.reinit(locally_owned, comm);
    // component-0 system DoF -> scalar DoF of the locally owned nodes
    owned_system0_to_scalar.clear();
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
              for (unsigned int node = 0; node < scalar_dofs.size(); ++node)
                {
                  const auto dof0 = dofs[fe.component_to_system_index(0, node)];
                  if (locally_owned.is_element(dof0))
                    owned_system0_to_scalar[dof0] = scalar_dofs[node];
                }
            }
          ++scalar_cell;
        }
    }

    // locally owned DoFs of each body and component (for the momentum)
    body_component_dofs.assign(
      scene->n_bodies(),
      std::vector<IndexSet>(dim, IndexSet(dof_handler.n_dofs())));
    {
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            cell->get_dof_indices(dofs);
            for (unsigned int i = 0; i < dofs.size(); ++i)
              if (locally_owned.is_element(dofs[i]))
                body_component_dofs[cell->material_id()]
                                   [fe.system_to_component_index(i).first]
                                     .add_index(dofs[i]);
          }
      for (auto &body : body_component_dofs)
        for (auto &set : body)
          set.compress();
    }

    pcout << "   cells: " << triangulation.n_global_active_cells()
          << ", DoFs: " << dof_handler.n_dofs() << std::endl;
  }



  template <int dim>
  void
  Simulator<dim>::assemble_system()
  {
    TimerOutput::Scope t(*timer, "assembly");

    bool viscous = false;
    for (unsigned int b = 0; b < scene->n_bodies(); ++b)
      viscous = viscous || scene->material(b).is_viscous();
    const auto tractions   = scene->neumann_tractions();
    const auto contact_ids = all_contact_boundary_ids();

    const QGauss<dim> quadrature(fe.degree + 1);
    // the lumped mass matrix: nodal (Gauss-Lobatto) quadrature makes the
    // element mass matrix of FE_Q diagonal
    const Quadrature<dim> mass_quadrature =
      parameters.lumped_mass ?
        Quadrature<dim>(QGaussLobatto<dim>(fe.degree + 1)) :
        Quadrature<dim>(QGauss<dim>(fe.degree + 1));
    const QGauss<dim - 1>        face_quadrature(fe.degree + 1);
    const QGaussLobatto<dim - 1> lumped_face_quadrature(fe.degree + 1);

    FEValues<dim>     fe_values(mapping,
                            fe,
                            quadrature,
                            update_values | update_gradients |
                              update_JxW_values);
    FEValues<dim>     mass_values(mapping,
                              fe,
                              mass_quadrature,
                              update_values | update_JxW_values);
    FEFaceValues<dim> face_values(mapping,
                                  fe,
                                  face_quadrature,
                                  update_values | update_JxW_values);
    FEFaceValues<dim> lumped_face_values(mapping,
                                         fe,
                                         lumped_face_quadrature,
                                         update_values | update_JxW_values);

    const unsigned int  dofs_per_cell = fe.n_dofs_per_cell();
    std::vector<double> bad_cell; // centre and body of an inverted cell
    FullMatrix<double>  cell_mass(dofs_per_cell, dofs_per_cell);
    FullMatrix<double>  cell_stiffness(dofs_per_cell, dofs_per_cell);
    FullMatrix<double>  cell_viscous(dofs_per_cell, dofs_per_cell);
    Vector<double>      cell_load(dofs_per_cell);
    Vector<double>      cell_boundary_mass(dofs_per_cell);
    std::vector<types::global_dof_index> dof_indices(dofs_per_cell);

    const FEValuesExtractors::Vector     displacement(0);
    std::vector<SymmetricTensor<2, dim>> eps(dofs_per_cell);
    std::vector<double>                  div(dofs_per_cell);

    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell_mass                  = 0.;
          cell_stiffness             = 0.;
          cell_viscous               = 0.;
          cell_load                  = 0.;
          cell_boundary_mass         = 0.;
          const Material &material   = scene->material(cell->material_id());
          const double    mu         = material.mu();
          const double    lambda     = material.lambda();
          const double    rho        = material.density;
          const auto      body_force = scene->body_force(cell->material_id());
          fe_values.reinit(cell);
          mass_values.reinit(cell);
          // an inverted or twisted cell (which deal.II does not reject on
          // reading) has a non-positive Jacobian somewhere
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            if (!(fe_values.JxW(q) > 0.) && bad_cell.empty())
              {
                for (unsigned int d = 0; d < dim; ++d)
                  bad_cell.push_back(cell->center()[d]);
                bad_cell.push_back(cell->material_id() + 1);
              }

          for (unsigned int q = 0; q < quadrature.size(); ++q)
            {
              const double JxW = fe_values.JxW(q);
              for (unsigned int i = 0; i < dofs_per_cell; ++i)
                {
                  eps[i] = fe_values[displacement].symmetric_gradient(i, q);
                  div[i] = fe_values[displacement].divergence(i, q);
                }
              for (unsigned int i = 0; i < dofs_per_cell; ++i)
                {
                  for (unsigned int j = 0; j < dofs_per_cell; ++j)
                    {
                      const double ee = eps[i] * eps[j];
                      const double dd = div[i] * div[j];
                      cell_stiffness(i, j) +=
                        (2. * mu * ee + lambda * dd) * JxW;
                      if (material.is_viscous())
                        cell_viscous(i, j) +=
                          (2. * material.viscous_shear_modulus * ee +
                           material.viscous_lambda * dd) *
                          JxW;
                    }
                  cell_load(i) +=
                    fe_values[displacement].value(i, q) * body_force * JxW;
                }
            }
          for (unsigned int q = 0; q < mass_quadrature.size(); ++q)
            for (unsigned int i = 0; i < dofs_per_cell; ++i)
              for (unsigned int j = 0; j < dofs_per_cell; ++j)
                cell_mass(i, j) += rho *
                                   (mass_values[displacement].value(i, q) *
                                    mass_values[displacement].value(j, q)) *
                                   mass_values.JxW(q);

          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary())
              {
                const auto id = cell->face(f)->boundary_id();
                for (const auto &[traction_id, traction] : tractions)
                  if (traction_id == id)
                    {
                      face_values.reinit(cell, f);
                      for (unsigned int q = 0; q < face_quadrature.size(); ++q)
                        for (unsigned int i = 0; i < dofs_per_cell; ++i)
                          cell_load(i) +=
                            face_values[displacement].value(i, q) * traction *
                            face_values.JxW(q);
                    }
                if (std::find(contact_ids.begin(), contact_ids.end(), id) !=
                    contact_ids.end())
                  {
                    // w_p = int psi_p ds, by nodal quadrature (positive)
                    lumped_face_values.reinit(cell, f);
                    for (unsigned int q = 0; q < lumped_face_quadrature.size();
                         ++q)
                      for (unsigned int i = 0; i < dofs_per_cell; ++i)
                        {
                          const unsigned int c =
                            fe.system_to_component_index(i).first;
                          cell_boundary_mass(i) +=
                            lumped_face_values.shape_value_component(i, q, c) *
                            lumped_face_values.JxW(q);
                        }
                  }
              }

          cell->get_dof_indices(dof_indices);
          mass_matrix.add(dof_indices, cell_mass);
          stiffness_matrix.add(dof_indices, cell_stiffness);
          if (viscous)
            viscous_matrix.add(dof_indices, cell_viscous);
          load.add(dof_indices, cell_load);
          boundary_mass.add(dof_indices, cell_boundary_mass);
        }

    mass_matrix.compress(VectorOperation::add);
    stiffness_matrix.compress(VectorOperation::add);
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
    if (viscous)
      viscous_matrix.compress(VectorOperation::add);
    load.compress(VectorOperation::add);
    boundary_mass.compress(VectorOperation::add);
  }



  template <int dim>
  std::vector<types::boundary_id>
  Simulator<dim>::all_contact_boundary_ids() const
  {
    std::vector<types::boundary_id> ids = scene->contact_boundary_ids();
    for (const auto &pair : scene->contact_pairs())
      {
        ids.insert(ids.end(), pair.first_side.begin(), pair.first_side.end());
        ids.insert(ids.end(), pair.second_side.begin(), pair.second_side.end());
      }
    return ids;
  }



  template <int dim>
  void
  Simulator<dim>::make_contact_rows()
  {
    TimerOutput::Scope t(*timer, "contact rows");

    rows.rows.clear();
    row_scalar_dofs.clear();
    const unsigned int my_rank = Utilities::MPI::this_mpi_process(comm);

    VectorType w_ghosted(locally_owned, locally_relevant, comm);
    w_ghosted = boundary_mass;

    auto contains = [](const std::vector<types::boundary_id> &ids,
                       const types::boundary_id               id) {
      return std::find(ids.begin(), ids.end(), id) != ids.end();
    };

    // Calls f(x, dofs, scalar dof) once for every locally owned, non-hanging
    // node on the boundary parts @p ids.
    auto for_each_boundary_node =
      [&](const std::vector<types::boundary_id> &ids, const auto &f) {
        std::set<types::global_dof_index>    seen;
        std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
        std::vector<types::global_dof_index> scalar_dofs(
          scalar_fe.n_dofs_per_cell());
        const auto &unit_points = scalar_fe.get_unit_support_points();
        auto        scalar_cell = scalar_dof_handler.begin_active();
        for (const auto &cell : dof_handler.active_cell_iterators())
          {
            if (cell->is_locally_owned())
              for (const unsigned int face : cell->face_indices())
                if (cell->face(face)->at_boundary() &&
                    contains(ids, cell->face(face)->boundary_id()))
                  {
                    cell->get_dof_indices(dofs);
                    scalar_cell->get_dof_indices(scalar_dofs);
                    for (unsigned int node = 0;
                         node < scalar_fe.n_dofs_per_cell();
                         ++node)
                      {
                        if (!scalar_fe.has_support_on_face(node, face))
                          continue;
                        std::array<types::global_dof_index, dim> node_dofs;
                        for (unsigned int d = 0; d < dim; ++d)
                          node_dofs[d] =
                            dofs[fe.component_to_system_index(d, node)];
                        if (!locally_owned.is_element(node_dofs[0]) ||
                            seen.count(node_dofs[0]))
                          continue;
                        seen.insert(node_dofs[0]);
                        f(mapping.transform_unit_to_real_cell(
                            cell, unit_points[node]),
                          node_dofs,
                          scalar_dofs[node]);
                      }
                  }
            ++scalar_cell;
          }
      };

    // completes a row: weight, owner, eliminated component (the free one
    // with the largest |nu_i|); false for a node without a free component
    // (a hanging node, or a node fixed by Dirichlet data)
    auto finish_row = [&](ContactRow &row) {
      row.owner  = my_rank;
      row.weight = w_ghosted(row.entries[0].first);
      int best   = -1;
      for (unsigned int d = 0; d < dim; ++d)
        if (!mesh_constraints.is_constrained(row.entries[d].first) &&
            std::abs(row.normal[d]) > 1e-12 &&
            (best < 0 || std::abs(row.normal[d]) > std::abs(row.normal[best])))
          best = d;
      row.eliminated = std::max(best, 0);
      return best >= 0;
    };

    std::vector<std::pair<ContactRow, types::global_dof_index>> local_rows;

    // a rigid obstacle: nu = -n, g = (x - x0) . n, no master entries
    if (const auto obstacle = scene->obstacle())
      for_each_boundary_node(
        scene->contact_boundary_ids(),
        [&](const Point<dim> &x, const auto &dofs, const auto scalar_dof) {
          ContactRow row;
          row.n_components = dim;
          for (unsigned int d = 0; d < dim; ++d)
            {
              row.entries.emplace_back(dofs[d], -obstacle->normal[d]);
              row.normal[d]   = -obstacle->normal[d];
              row.position[d] = x[d];
            }
          row.gap = (x - obstacle->point) * obstacle->normal;
          AssertThrow(std::isfinite(row.gap),
                      ExcMessage("The gap of the node at (" +
                                 Utilities::to_string(x[0]) + ", " +
                                 Utilities::to_string(x[1]) +
                                 ", ...) to the obstacle is not finite."));
          AssertThrow(parameters.solver.project_initial_penetration ||
                        row.gap >= -1e-12 * (std::abs(row.gap) + 1.),
                      ExcMessage("The initial configuration penetrates the "
                                 "obstacle: the node at (" +
                                 Utilities::to_string(x[0]) + ", " +
                                 Utilities::to_string(x[1]) + ", ...) lies " +
                                 Utilities::to_string(-row.gap) +
                                 " m inside it. Correct the scene, or set "
                                 "'Contact solver/Initial penetration = "
                                 "project'."));
          if (finish_row(row))
            local_rows.emplace_back(row, scalar_dof);
        });

    // two-body pairs: the mortar-like mapping phi_h onto the gathered master
    // surface
    for (const ContactPair &pair : scene->contact_pairs())
      {
        const std::array<std::vector<MasterFace<dim>>, 2> sides = {
          {gather_faces(pair.first_side), gather_faces(pair.second_side)}};
        int slave = pair.slave_side;
        if (slave < 0)
          {
            // the finer side is the slave: compare the mean size of the
            // faces that face the other side (their centre has an image on
            // it), so that a coarse far field does not count
            std::array<double, 2> size{{0., 0.}};
            for (unsigned int s = 0; s < 2; ++s)
              {
                const ContactMapping<dim> other(sides[1 - s],
                                                pair.search_radius);
                unsigned int              n = 0;
                for (const auto &face : sides[s])
                  {
                    Point<dim> centre;
                    for (const auto &v : face.vertices)
                      centre += v / double(face.vertices.size());
                    if (other.find_image(centre))
                      {
                        size[s] +=
                          face.vertices[0].distance(face.vertices.back());
                        ++n;
                      }
                  }
                size[s] = (n > 0) ? size[s] / n : 1e300;
              }
            slave = (size[1] < size[0]) ? 1 : 0;
          }
        const ContactMapping<dim> phi(sides[1 - slave], pair.search_radius);
        for_each_boundary_node(
          slave == 0 ? pair.first_side : pair.second_side,
          [&](const Point<dim> &x, const auto &dofs, const auto scalar_dof) {
            const auto image = phi.find_image(x);
            if (!image)
              return;
            auto       projection = *image;
            const bool inside     = (x - image->point) * image->master_normal <
                                -1e-10 * pair.search_radius;
            AssertThrow(
              parameters.solver.project_initial_penetration || !inside,
              ExcMessage("The initial configuration penetrates: the slave "
                         "node at (" +
                         Utilities::to_string(x[0]) + ", " +
                         Utilities::to_string(x[1]) +
                         ", ...) lies inside the master body by " +
                         Utilities::to_string(image->gap) +
                         " m. Correct the mesh, or set 'Contact "
                         "solver/Initial penetration = project'."));
            if (inside)
              {
                // a negative gap along the master's normal: the row asks
                // for the node to be moved out
                projection.normal = -image->master_normal;
                projection.gap    = -image->gap;
              }
            ContactRow row = make_two_body_row<dim>(
              x, dofs, projection, phi.faces()[image->face], fe.degree);
            if (finish_row(row))
              local_rows.emplace_back(row, scalar_dof);
          });
        pcout << "   contact pair: slave is side " << slave + 1 << " ("
              << sides[slave].size() << " faces), master side " << 2 - slave
              << " (" << sides[1 - slave].size() << " faces)" << std::endl;
      }

    // every rank gets all rows, in rank order
    const auto all = Utilities::MPI::all_gather(comm, local_rows);
    for (const auto &rank_rows : all)
      for (const auto &r : rank_rows)
        {
          rows.rows.push_back(r.first);
          row_scalar_dofs.push_back(r.second);
        }

    row_evaluator = std::make_unique<ActiveSetSolver>(parameters.solver, comm);
    row_evaluator->reinit(locally_owned,
                          locally_relevant,
                          mesh_constraints,
                          rows);

    double measure = 0.;
    for (const auto &row : rows.rows)
      measure += row.weight;
    pcout << "   contact rows: " << rows.size()
          << ", measure of the slave contact boundary: " << measure
          << std::endl;
  }



  template <int dim>
  std::vector<MasterFace<dim>>
  Simulator<dim>::gather_faces(const std::vector<types::boundary_id> &ids) const
  {
    std::vector<MasterFace<dim>>         local;
    std::vector<types::global_dof_index> face_dofs(fe.n_dofs_per_face());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              std::find(ids.begin(), ids.end(), cell->face(f)->boundary_id()) !=
                ids.end())
            {
              const auto      face = cell->face(f);
              MasterFace<dim> master;
              for (const unsigned int v : face->vertex_indices())
                master.vertices.push_back(face->vertex(v));
              master.cell_center         = cell->center();
              const unsigned int n_nodes = fe.n_dofs_per_face() / dim;
              master.node_dofs.resize(n_nodes);
              master.node_dof0.assign(n_nodes, numbers::invalid_dof_index);
              face->get_dof_indices(face_dofs);
              for (unsigned int i = 0; i < face_dofs.size(); ++i)
                {
                  const auto [c, node] = fe.face_system_to_component_index(i);
                  const auto dof       = face_dofs[i];
                  auto      &entries   = master.node_dofs[node][c];
                  if (mesh_constraints.is_constrained(dof))
                    {
                      // hanging: its parents; Dirichlet: nothing (fixed)
                      for (const auto &entry :
                           *mesh_constraints.get_constraint_entries(dof))
                        entries.push_back(entry);
                    }
                  else
                    {
                      entries.emplace_back(dof, 1.);
                      if (c == 0)
                        master.node_dof0[node] = dof;
                    }
                }
              local.push_back(master);
            }
    std::vector<MasterFace<dim>> all;
    for (const auto &rank_faces : Utilities::MPI::all_gather(comm, local))
      all.insert(all.end(), rank_faces.begin(), rank_faces.end());
    return all;
  }



  template <int dim>
  void
  Simulator<dim>::make_integrator()
  {
    TimerOutput::Scope       t(*timer, "setup");
    const SemiDiscreteSystem system{&mass_matrix,
                                    &stiffness_matrix,
                                    viscous_matrix.m() > 0 ? &viscous_matrix :
                                                             nullptr,
                                    &load,
                                    parameters.lumped_mass};
    integrator = std::make_unique<TimeIntegrator>(parameters.scheme,
                                                  current_tau,
                                                  system,
                                                  parameters.solver,
                                                  locally_owned,
                                                  locally_relevant,
                                                  mesh_constraints,
                                                  rows,
                                                  constant_modes,
                                                  comm);
  }



  template <int dim>
  std::pair<double, double>
  Simulator<dim>::energies(VectorType &M_udot) const
  {
    mass_matrix.vmult(M_udot, udot);
    const double kinetic = 0.5 * (M_udot * udot);
    VectorType   Au(u);
    stiffness_matrix.vmult(Au, u);
    return {kinetic, 0.5 * (Au * u) - load * u};
  }



  template <int dim>
  double
  Simulator<dim>::total_energy() const
  {
    VectorType M_udot(udot);
    const auto [kinetic, elastic] = energies(M_udot);
    return kinetic + elastic;
  }



  template <int dim>
  void
  Simulator<dim>::set_initial_values()
  {
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
                scene->initial_displacement(x, cell->material_id());
              const Tensor<1, dim> v0 =
                scene->initial_velocity(x, cell->material_id());
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
    mesh_constraints.distribute(u);
    mesh_constraints.distribute(udot);
  }



  template <int dim>
  double
  Simulator<dim>::compute_energy_error(const double time) const
  {
    // ||(e, edot)||_E^2 = 1/2 ||edot||^2_{L2(rho)} + 1/2 a(e, e) (eq. 22-24)
    const Material &material = scene->material(0);
    // the exact solution has kinks and jumps inside cells: an iterated
    // Gauss rule (no point at cell or sub-cell midpoints) integrates them
    // robustly
    const QIterated<dim> quadrature(QGauss<1>(fe.degree + 1), 2);
    FEValues<dim>        fe_values(mapping,
                            fe,
                            quadrature,
                            update_values | update_gradients |
                              update_quadrature_points | update_JxW_values);
    VectorType           u_ghosted(locally_owned, locally_relevant, comm);
    VectorType           v_ghosted(locally_owned, locally_relevant, comm);
    u_ghosted = u;
    v_ghosted = udot;

    const FEValuesExtractors::Vector displacement(0);
    std::vector<Tensor<1, dim>>      vh(quadrature.size());
    std::vector<Tensor<2, dim>>      grad_uh(quadrature.size());
    double                           local = 0.;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          fe_values[displacement].get_function_values(v_ghosted, vh);
          fe_values[displacement].get_function_gradients(u_ghosted, grad_uh);
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            {
              const ExactValues<dim> exact =
                scene->exact_solution(fe_values.quadrature_point(q), time);
              const Tensor<1, dim>          edot = exact.velocity - vh[q];
              const SymmetricTensor<2, dim> eps =
                symmetrize(exact.displacement_gradient - grad_uh[q]);
              local += (0.5 * material.density * (edot * edot) +
                        0.5 * (2. * material.mu() * (eps * eps) +
                               material.lambda() * trace(eps) * trace(eps))) *
                       fe_values.JxW(q);
            }
        }
    return std::sqrt(Utilities::MPI::sum(local, comm));
  }



  template <int dim>
  void
  Simulator<dim>::record_step(const unsigned int step,
                              const double       time,
                              const StepReport  &report,
                              const double       wall_time)
  {
    TimerOutput::Scope t(*timer, "diagnostics");
    const double       tau          = integrator->time_step();
    const double       force_factor = integrator->force_factor();

    VectorType tmp(u);
    const auto [kinetic, elastic] = energies(tmp);
    // momentum: sum of M udot over the DoFs of each body and component
    // (Theorem 3.1); body_momentum[3 b + d]
    std::vector<double> body_momentum(3 * scene->n_bodies(), 0.);
    for (unsigned int b = 0; b < scene->n_bodies(); ++b)
      for (unsigned int d = 0; d < dim; ++d)
        for (const auto i : body_component_dofs[b][d])
          body_momentum[3 * b + d] += tmp(i);
    sum_over_ranks(body_momentum, comm);
    std::vector<double> momentum(3, 0.);
    for (unsigned int b = 0; b < scene->n_bodies(); ++b)
      for (unsigned int d = 0; d < 3; ++d)
        momentum[d] += body_momentum[3 * b + d];
    if (step > 0 && viscous_matrix.m() > 0)
      {
        VectorType du(u);
        du -= u_old;
        viscous_matrix.vmult(tmp, du);
        viscous_dissipation += (tmp * du) / tau;
      }

    // contact: force 2/tau^2 mu_p, pressure per boundary weight
    double n_active = 0., active_measure = 0., critical_measure = 0.;
    double force = 0., max_pressure = 0.;
    for (unsigned int p = 0; p < rows.size(); ++p)
      {
        if (report.active[p])
          {
            n_active += 1.;
            active_measure += rows.rows[p].weight;
            const double f_p = force_factor * report.multipliers[p];
            force += f_p;
            max_pressure = std::max(max_pressure, f_p / rows.rows[p].weight);
          }
        if (report.critical[p])
          critical_measure += rows.rows[p].weight;
      }
    critical_measure_sum += critical_measure;

    double max_penetration = 0., max_normal_velocity = 0.;
    if (!rows.empty())
      {
        const auto violation       = row_evaluator->constraint_values(u);
        const auto normal_velocity = row_evaluator->apply_rows(udot);
        for (unsigned int p = 0; p < rows.size(); ++p)
          {
            max_penetration = std::max(max_penetration, violation[p]);
            if (report.active[p])
              max_normal_velocity =
                std::max(max_normal_velocity, std::abs(normal_velocity[p]));
          }
      }

    std::vector<double> row = {double(step),
                               time,
                               kinetic,
                               elastic,
                               viscous_dissipation,
                               kinetic + elastic,
                               momentum[0],
                               momentum[1],
                               momentum[2],
                               n_active,
                               active_measure,
                               critical_measure,
                               critical_measure_sum,
                               force,
                               max_pressure,
                               max_penetration,
                               max_normal_velocity,
                               report.velocity_correction,
                               double(report.displacement_solve.iterations),
                               double(report.projection_solve.iterations),
                               double(
                                 report.displacement_solve.linear_iterations +
                                 report.projection_solve.linear_iterations),
                               double(triangulation.n_global_active_cells()),
                               double(dof_handler.n_dofs()),
                               wall_time};
    if (scene->n_bodies() == 2)
      for (unsigned int d = 0; d < 3; ++d)
        row.push_back(body_momentum[3 + d]);
    if (parameters.compare_reference)
      row.push_back(process_reference_state(time));
    else if (parameters.write_reference)
      process_reference_state(time);
    if (parameters.refinement.adaptive())
      {
        row.push_back(energy_transfer);
        row.push_back(transfer_penetration);
        energy_transfer      = 0.;
        transfer_penetration = 0.;
      }
    if (scene->has_exact_solution())
      row.push_back(compute_energy_error(time));

    statistics.rows.push_back(row);
    if (statistics_file.is_open())
      {
        statistics.write_row(statistics_file, row);
        statistics_file.flush();
      }
  }



  template <int dim>
  void
  Simulator<dim>::output_results(const double time, const StepReport &report)
  {
    TimerOutput::Scope t(*timer, "output");

    VectorType u_ghosted(locally_owned, locally_relevant, comm);
    VectorType v_ghosted(locally_owned, locally_relevant, comm);
    u_ghosted = u;
    v_ghosted = udot;

    // nodal contact fields on the scalar FE_Q: pressure on both sides (the
    // master side gets each row's force through the weights N_j of its
    // image point), active and critical sets and the current gap
    // g_p - (C u)_p on the slave side
    const double factor = integrator->force_factor();
    VectorType   master_force(locally_owned, comm);
    const auto   violation = row_evaluator->constraint_values(u);
    TrilinosWrappers::MPI::Vector pressure(scalar_locally_owned, comm),
      active(scalar_locally_owned, comm), critical(scalar_locally_owned, comm),
      gap(scalar_locally_owned, comm);
    const unsigned int my_rank = Utilities::MPI::this_mpi_process(comm);
    for (unsigned int p = 0; p < rows.size(); ++p)
      if (rows.rows[p].owner == my_rank)
        {
          const double force =
            report.active[p] ? factor * report.multipliers[p] : 0.;
          pressure(row_scalar_dofs[p]) = force / rows.rows[p].weight;
          active(row_scalar_dofs[p])   = report.active[p];
          critical(row_scalar_dofs[p]) = report.critical[p];
          gap(row_scalar_dofs[p])      = -violation[p];
          for (const auto &[dof0, N] : rows.rows[p].master_nodes)
            master_force(dof0) += N * force;
        }
    master_force.compress(VectorOperation::add);
    for (const auto &[dof0, scalar_dof] : owned_system0_to_scalar)
      if (master_force(dof0) != 0.)
        pressure(scalar_dof) = master_force(dof0) / boundary_mass(dof0);
    pressure.compress(VectorOperation::insert);
    active.compress(VectorOperation::insert);
    critical.compress(VectorOperation::insert);
    gap.compress(VectorOperation::insert);
    TrilinosWrappers::MPI::Vector pressure_g(scalar_locally_owned,
                                             scalar_locally_relevant,
                                             comm),
      active_g(pressure_g), critical_g(pressure_g), gap_g(pressure_g);
    pressure_g = pressure;
    active_g   = active;
    critical_g = critical;
    gap_g      = gap;

    DataOut<dim> data_out;
    data_out.attach_triangulation(triangulation);
    const std::vector<DataComponentInterpretation::DataComponentInterpretation>
      vector_field(dim,
                   DataComponentInterpretation::component_is_part_of_vector);
    data_out.add_data_vector(dof_handler,
                             u_ghosted,
                             std::vector<std::string>(dim, "displacement"),
                             vector_field);
    data_out.add_data_vector(dof_handler,
                             v_ghosted,
                             std::vector<std::string>(dim, "velocity"),
                             vector_field);
    const VonMisesPostprocessor<dim> von_mises(*scene);
    data_out.add_data_vector(dof_handler, u_ghosted, von_mises);
    data_out.add_data_vector(scalar_dof_handler,
                             pressure_g,
                             "contact_pressure");
    data_out.add_data_vector(scalar_dof_handler, active_g, "active_set");
    data_out.add_data_vector(scalar_dof_handler, critical_g, "critical_set");
    if (!scene->contact_pairs().empty())
      data_out.add_data_vector(scalar_dof_handler, gap_g, "gap");
    Vector<float> subdomain(triangulation.n_active_cells());
    for (auto &s : subdomain)
      s = triangulation.locally_owned_subdomain();
    data_out.add_data_vector(subdomain, "subdomain");
    Vector<float> level(triangulation.n_active_cells());
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        level(cell->active_cell_index()) = cell->level();
    data_out.add_data_vector(level, "refinement_level");
    data_out.build_patches(mapping, fe.degree);

    const std::string pvtu = data_out.write_vtu_with_pvtu_record(
      parameters.output_directory + "/", "solution", output_counter, comm, 5);
    ++output_counter;
    pvd_records.emplace_back(time, pvtu);
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        std::ofstream pvd(parameters.output_directory + "/solution.pvd");
        DataOutBase::write_pvd_record(pvd, pvd_records);
      }
  }



  template <int dim>
  Statistics
  Simulator<dim>::run()
  {
    try
      {
        return run_simulation();
      }
    catch (...)
      {
        // TimerOutput would otherwise print an MPI warning while the
        // exception unwinds; the user gets the exception's message instead
        timer.reset();
        throw;
      }
  }



  template <int dim>
  Statistics
  Simulator<dim>::run_simulation()
  {
    pcout << "dyncontact: scene '" << scene->name() << "', " << dim
          << "D, scheme " << to_string(parameters.scheme) << ", "
          << Utilities::MPI::n_mpi_processes(comm) << " MPI rank(s)"
          << std::endl;

    // the output directory must be writable; nothing in it is touched
    // before the setup has succeeded
    bool writable = true;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        std::error_code error;
        std::filesystem::create_directories(parameters.output_directory, error);
        const std::string probe =
          parameters.output_directory + "/.dyncontact-write-test";
        writable = std::ofstream(probe).good();
        std::filesystem::remove(probe, error);
      }
    writable = Utilities::MPI::broadcast(comm, writable, 0);
    AssertThrow(writable,
                ExcMessage("Output directory '" + parameters.output_directory +
                           "' cannot be created or written."));

    {
      TimerOutput::Scope t(*timer, "setup");
      scene->create_coarse_mesh(triangulation);
      if (!parameters.resume)
        {
          triangulation.refine_global(parameters.initial_refinements);
          scene->refine_initial_mesh(triangulation);
        }
      for (const auto &cell : triangulation.active_cell_iterators())
        AssertThrow(cell->material_id() < scene->n_bodies(),
                    ExcMessage("A cell of the mesh has material id " +
                               std::to_string(cell->material_id()) +
                               ", but the scene has " +
                               std::to_string(scene->n_bodies()) +
                               " bodies (ids 0 to n-1)."));
    }
    if (!parameters.resume)
      {
        setup_system();
        assemble_system();
        make_contact_rows();
        initial_refinement();
        set_initial_values();
        make_integrator();
      }

    statistics.columns = {"step",
                          "time",
                          "energy_kinetic",
                          "energy_elastic",
                          "dissipation_viscous",
                          "energy_total",
                          "momentum_x",
                          "momentum_y",
                          "momentum_z",
                          "active_nodes",
                          "active_measure",
                          "critical_measure",
                          "critical_measure_sum",
                          "contact_force",
                          "max_contact_pressure",
                          "max_penetration",
                          "max_active_normal_velocity",
                          "velocity_correction",
                          "active_set_iterations",
                          "projection_iterations",
                          "linear_iterations",
                          "cells",
                          "dofs",
                          "step_wall_time"};
    if (scene->n_bodies() == 2)
      for (const std::string column :
           {"momentum_x_body2", "momentum_y_body2", "momentum_z_body2"})
        statistics.columns.push_back(column);
    AssertThrow(!(parameters.refinement.interval > 0 &&
                  (parameters.write_reference || parameters.compare_reference)),
                ExcMessage(
                  "Reference solutions need the same mesh in both "
                  "runs: they cannot be combined with adaptive "
                  "meshes (Mesh refinement/Refinement interval > 0)."));
    if (parameters.compare_reference)
      statistics.columns.push_back("error_reference");
    if (parameters.refinement.adaptive())
      {
        statistics.columns.push_back("energy_transfer");
        statistics.columns.push_back("transfer_penetration");
      }
    if (scene->has_exact_solution())
      statistics.columns.push_back("error_energy_norm");
    unsigned int step        = 0;
    double       time        = 0.;
    double       next_output = parameters.output_interval;
    StepReport   report;
    if (parameters.resume)
      resume_from_checkpoint(step, time, next_output);
    else
      {
        if (Utilities::MPI::this_mpi_process(comm) == 0)
          {
            statistics_file.open(parameters.output_directory +
                                 "/statistics.tsv");
            statistics.write_header(statistics_file);
          }

        // an initially penetrating configuration (allowed only with
        // 'Initial penetration = project'): the M-projection onto K_h
        const auto violation = row_evaluator->constraint_values(u);
        double     largest   = 0.;
        for (const double v : violation)
          largest = std::max(largest, v);
        if (largest > 1e-12)
          {
            integrator->project_onto_constraints(u);
            pcout << "   warning: the initial configuration penetrated by up "
                     "to "
                  << largest
                  << " m; the initial displacement was projected onto K_h."
                  << std::endl;
          }

        {
          TimerOutput::Scope t(*timer, "time step");
          report = integrator->initialize(u, udot);
        }
        record_step(0, 0., report, 0.);
        if (parameters.write_vtu)
          output_results(0., report);
      }

    // the static problem is solved once, at t = End time
    const bool is_static = parameters.scheme == Scheme::quasi_static;
    auto       more      = [&]() {
      return is_static ? step < 1 :
                                    time < parameters.end_time - 1e-9 * current_tau;
    };
    // t = t_base + n tau, so that times do not accumulate round-off
    double       time_base   = time;
    unsigned int steps_since = 0;
    Timer        since_checkpoint;
    while (more())
      {
        Timer step_timer;
        u_old    = u;
        udot_old = udot;
        {
          TimerOutput::Scope t(*timer, "time step");
          report = integrator->step(u, udot);
        }
        const bool good = report.displacement_solve.converged &&
                          report.projection_solve.converged &&
                          std::isfinite(u.l2_norm()) &&
                          std::isfinite(udot.l2_norm());
        if (!good)
          {
            // back to the last good state
            u    = u_old;
            udot = udot_old;
            if (parameters.time_step_adaptation && !is_static &&
                current_tau > parameters.time_step / 1024. * (1. + 1e-12))
              {
                current_tau /= 2.;
                time_base   = time;
                steps_since = 0;
                pcout << "   warning: step " << step + 1 << " (t = " << time
                      << " s) failed; retrying with tau = " << current_tau
                      << " s" << std::endl;
                const auto active = integrator->active_sets();
                make_integrator();
                integrator->warm_start(active.first, active.second);
                continue;
              }
            const std::string dir = write_checkpoint(step, time, next_output);
            const double residual = std::max(report.displacement_solve.residual,
                                             report.projection_solve.residual);
            std::ostringstream message;
            message << std::setprecision(6) << "step " << step + 1
                    << " (from t = " << time << " s, tau = " << current_tau
                    << " s) failed: ";
            if (std::isfinite(u.l2_norm()))
              message << "the active-set iteration did not converge within "
                         "'Contact solver/Maximum active-set iterations' "
                         "(complementarity residual "
                      << std::setprecision(3) << residual << " m)";
            else
              message << "the solution is not finite";
            message << ". The last good state (step " << step
                    << ") is the checkpoint '" << dir
                    << "' (resume with 'Checkpointing/Resume = true'), or "
                       "set 'Time integration/Time step adaptation = true'.";
            AssertThrow(false, ExcMessage(message.str()));
          }
        ++step;
        ++steps_since;
        time = is_static ? parameters.end_time :
                           time_base + steps_since * current_tau;
        step_timer.stop();
        record_step(step, time, report, step_timer.wall_time());
        if (parameters.write_vtu &&
            (time >= next_output - 1e-9 * current_tau || !more()))
          {
            output_results(time, report);
            next_output += parameters.output_interval;
          }
        if (parameters.refinement.interval > 0 && more() &&
            step % parameters.refinement.interval == 0)
          adapt_mesh();

        bool checkpoint = parameters.checkpoint_steps > 0 &&
                          step % parameters.checkpoint_steps == 0;
        if (parameters.checkpoint_minutes > 0.)
          checkpoint =
            checkpoint ||
            Utilities::MPI::broadcast(comm,
                                      since_checkpoint.wall_time() >
                                        60. * parameters.checkpoint_minutes,
                                      0);
        if (checkpoint)
          {
            write_checkpoint(step, time, next_output);
            since_checkpoint.restart();
          }
      }

    timer->print_summary();
    return statistics;
  }

  template class Simulator<2>;
  template class Simulator<3>;
} // namespace dyncontact
