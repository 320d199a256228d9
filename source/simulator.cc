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
      VonMisesPostprocessor(const Material &material)
        : DataPostprocessorScalar<dim>("von_mises_stress", update_gradients)
        , mu(material.mu())
        , lambda(material.lambda())
      {}

      void
      evaluate_vector_field(
        const DataPostprocessorInputs::Vector<dim> &inputs,
        std::vector<Vector<double>> &computed_quantities) const override
      {
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
      const double mu, lambda;
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
    , scene(create_scene<dim>(prm, parameters.material))
    , triangulation(comm)
    , fe(FE_Q<dim>(parameters.degree), dim)
    , dof_handler(triangulation)
    , scalar_fe(parameters.degree)
    , scalar_dof_handler(triangulation)
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
    for (const auto id : scene->dirichlet_boundary_ids())
      VectorTools::interpolate_boundary_values(
        mapping,
        dof_handler,
        id,
        Functions::ZeroFunction<dim>(dim),
        mesh_constraints);
    mesh_constraints.close();

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
    if (scene->material().is_viscous())
      viscous_matrix.reinit(locally_owned, locally_owned, dsp, comm);
    else
      viscous_matrix.clear();

    load.reinit(locally_owned, comm);
    boundary_mass.reinit(locally_owned, comm);
    u.reinit(locally_owned, comm);
    udot.reinit(locally_owned, comm);
    u_old.reinit(locally_owned, comm);
    for (unsigned int d = 0; d < dim; ++d)
      {
        ComponentMask mask(dim, false);
        mask.set(d, true);
        component_dofs[d] = DoFTools::extract_dofs(dof_handler, mask);
      }

    pcout << "   cells: " << triangulation.n_global_active_cells()
          << ", DoFs: " << dof_handler.n_dofs() << std::endl;
  }



  template <int dim>
  void
  Simulator<dim>::assemble_system()
  {
    TimerOutput::Scope t(*timer, "assembly");

    const Material &material    = scene->material();
    const bool      viscous     = material.is_viscous();
    const double    mu          = material.mu();
    const double    lambda      = material.lambda();
    const double    rho         = material.density;
    const auto      body_force  = scene->body_force();
    const auto      tractions   = scene->neumann_tractions();
    const auto      contact_ids = scene->contact_boundary_ids();

    const QGauss<dim> quadrature(fe.degree + 1);
    // the lumped mass matrix: nodal (Gauss-Lobatto) quadrature makes the
    // element mass matrix of FE_Q diagonal
    const Quadrature<dim> mass_quadrature =
      parameters.lumped_mass ? Quadrature<dim>(QGaussLobatto<dim>(fe.degree + 1)) :
                               Quadrature<dim>(QGauss<dim>(fe.degree + 1));
    const QGauss<dim - 1>        face_quadrature(fe.degree + 1);
    const QGaussLobatto<dim - 1> lumped_face_quadrature(fe.degree + 1);

    FEValues<dim> fe_values(mapping,
                            fe,
                            quadrature,
                            update_values | update_gradients |
                              update_JxW_values);
    FEValues<dim> mass_values(mapping,
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

    const unsigned int dofs_per_cell = fe.n_dofs_per_cell();
    FullMatrix<double> cell_mass(dofs_per_cell, dofs_per_cell);
    FullMatrix<double> cell_stiffness(dofs_per_cell, dofs_per_cell);
    FullMatrix<double> cell_viscous(dofs_per_cell, dofs_per_cell);
    Vector<double>     cell_load(dofs_per_cell);
    Vector<double>     cell_boundary_mass(dofs_per_cell);
    std::vector<types::global_dof_index> dof_indices(dofs_per_cell);

    const FEValuesExtractors::Vector displacement(0);
    std::vector<SymmetricTensor<2, dim>> eps(dofs_per_cell);
    std::vector<double>                  div(dofs_per_cell);

    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell_mass          = 0.;
          cell_stiffness     = 0.;
          cell_viscous       = 0.;
          cell_load          = 0.;
          cell_boundary_mass = 0.;
          fe_values.reinit(cell);
          mass_values.reinit(cell);

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
                      cell_stiffness(i, j) += (2. * mu * ee + lambda * dd) * JxW;
                      if (viscous)
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
    if (viscous)
      viscous_matrix.compress(VectorOperation::add);
    load.compress(VectorOperation::add);
    boundary_mass.compress(VectorOperation::add);
  }



  template <int dim>
  void
  Simulator<dim>::make_contact_rows()
  {
    TimerOutput::Scope t(*timer, "contact rows");

    rows.rows.clear();
    row_scalar_dofs.clear();
    const auto obstacle = scene->obstacle();
    if (!obstacle)
      return;

    const auto         contact_ids = scene->contact_boundary_ids();
    const unsigned int my_rank     = Utilities::MPI::this_mpi_process(comm);

    VectorType w_ghosted(locally_owned, locally_relevant, comm);
    w_ghosted = boundary_mass;

    // (row, scalar DoF of its node) for the nodes owned here
    std::vector<std::pair<ContactRow, types::global_dof_index>> local_rows;
    std::set<types::global_dof_index>     seen;
    std::vector<types::global_dof_index>  dofs(fe.n_dofs_per_cell());
    std::vector<types::global_dof_index>  scalar_dofs(scalar_fe.n_dofs_per_cell());
    const auto &unit_points = scalar_fe.get_unit_support_points();

    auto scalar_cell = scalar_dof_handler.begin_active();
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        if (cell->is_locally_owned())
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary() &&
                std::find(contact_ids.begin(),
                          contact_ids.end(),
                          cell->face(f)->boundary_id()) != contact_ids.end())
              {
                cell->get_dof_indices(dofs);
                scalar_cell->get_dof_indices(scalar_dofs);
                for (unsigned int node = 0; node < scalar_fe.n_dofs_per_cell();
                     ++node)
                  {
                    if (!scalar_fe.has_support_on_face(node, f))
                      continue;
                    const auto dof0 = dofs[fe.component_to_system_index(0, node)];
                    if (!locally_owned.is_element(dof0) || seen.count(dof0))
                      continue;
                    seen.insert(dof0);

                    ContactRow row;
                    row.n_components = dim;
                    row.owner        = my_rank;
                    const Point<dim> x =
                      mapping.transform_unit_to_real_cell(cell, unit_points[node]);
                    const Tensor<1, dim> nu = -obstacle->normal;
                    for (unsigned int d = 0; d < dim; ++d)
                      {
                        row.entries.emplace_back(
                          dofs[fe.component_to_system_index(d, node)], nu[d]);
                        row.normal[d]   = nu[d];
                        row.position[d] = x[d];
                      }
                    row.gap    = (x - obstacle->point) * obstacle->normal;
                    row.weight = w_ghosted(dof0);

                    // eliminate the free component with the largest |nu_i|;
                    // hanging nodes (all components constrained) get no row
                    int best = -1;
                    for (unsigned int d = 0; d < dim; ++d)
                      if (!mesh_constraints.is_constrained(row.entries[d].first) &&
                          std::abs(nu[d]) > 1e-12 &&
                          (best < 0 || std::abs(nu[d]) > std::abs(nu[best])))
                        best = d;
                    if (best < 0)
                      continue;
                    row.eliminated = best;

                    AssertThrow(row.gap >= -1e-12 * (std::abs(row.gap) + 1.),
                                ExcMessage(
                                  "The initial configuration penetrates the "
                                  "obstacle: the node at distance " +
                                  std::to_string(row.gap) +
                                  " m lies inside it. Check the scene's "
                                  "initial gap."));
                    local_rows.emplace_back(row, scalar_dofs[node]);
                  }
              }
        ++scalar_cell;
      }

    // every rank gets all rows, in rank order
    const auto all = Utilities::MPI::all_gather(comm, local_rows);
    for (const auto &rank_rows : all)
      for (const auto &r : rank_rows)
        {
          rows.rows.push_back(r.first);
          row_scalar_dofs.push_back(r.second);
        }

    double measure = 0.;
    for (const auto &row : rows.rows)
      measure += row.weight;
    pcout << "   contact rows: " << rows.size()
          << ", measure of Gamma_C: " << measure << std::endl;
  }



  template <int dim>
  void
  Simulator<dim>::set_initial_values()
  {
    struct Initial : public Function<dim>
    {
      Initial(const Scene<dim> &scene, const bool velocity)
        : Function<dim>(dim)
        , scene(scene)
        , velocity(velocity)
      {}
      void
      vector_value(const Point<dim> &p, Vector<double> &values) const override
      {
        const Tensor<1, dim> v = velocity ? scene.initial_velocity(p) :
                                            scene.initial_displacement(p);
        for (unsigned int d = 0; d < dim; ++d)
          values(d) = v[d];
      }
      const Scene<dim> &scene;
      const bool        velocity;
    };
    VectorTools::interpolate(mapping, dof_handler, Initial(*scene, false), u);
    VectorTools::interpolate(mapping, dof_handler, Initial(*scene, true), udot);
    mesh_constraints.set_zero(u);
    mesh_constraints.set_zero(udot);
  }



  template <int dim>
  double
  Simulator<dim>::compute_energy_error(const double time) const
  {
    // ||(e, edot)||_E^2 = 1/2 ||edot||^2_{L2(rho)} + 1/2 a(e, e) (eq. 22-24)
    const Material   &material = scene->material();
    // the exact solution has kinks and jumps inside cells: an iterated
    // Gauss rule (no point at cell or sub-cell midpoints) integrates them
    // robustly
    const QIterated<dim> quadrature(QGauss<1>(fe.degree + 1), 2);
    FEValues<dim>     fe_values(mapping,
                            fe,
                            quadrature,
                            update_values | update_gradients |
                              update_quadrature_points | update_JxW_values);
    VectorType u_ghosted(locally_owned, locally_relevant, comm);
    VectorType v_ghosted(locally_owned, locally_relevant, comm);
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
              const Tensor<1, dim> edot = exact.velocity - vh[q];
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
    const double       tau = parameters.time_step;

    VectorType tmp(u);
    // energies: E_kin = 1/2 udot^T M udot, E_el = 1/2 u^T A u - f^T u
    mass_matrix.vmult(tmp, udot);
    const double kinetic = 0.5 * (tmp * udot);
    // momentum: sum of M udot over the DoFs of each component (Thm. 3.1)
    std::vector<double> momentum(dim, 0.);
    for (unsigned int d = 0; d < dim; ++d)
      for (const auto i : component_dofs[d])
        momentum[d] += tmp(i);
    sum_over_ranks(momentum, comm);
    stiffness_matrix.vmult(tmp, u);
    const double elastic = 0.5 * (tmp * u) - load * u;
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
            const double f_p = 2. / (tau * tau) * report.multipliers[p];
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

    std::vector<double> row = {
      double(step),
      time,
      kinetic,
      elastic,
      viscous_dissipation,
      kinetic + elastic,
      momentum[0],
      momentum[1],
      dim == 3 ? momentum[dim - 1] : 0.,
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
      double(report.displacement_solve.linear_iterations +
             report.projection_solve.linear_iterations),
      double(triangulation.n_global_active_cells()),
      double(dof_handler.n_dofs()),
      wall_time};
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
  Simulator<dim>::output_results(const unsigned int step,
                                 const double       time,
                                 const StepReport  &report)
  {
    TimerOutput::Scope t(*timer, "output");

    VectorType u_ghosted(locally_owned, locally_relevant, comm);
    VectorType v_ghosted(locally_owned, locally_relevant, comm);
    u_ghosted = u;
    v_ghosted = udot;

    // nodal contact fields on the scalar FE_Q
    TrilinosWrappers::MPI::Vector pressure(scalar_locally_owned, comm),
      active(scalar_locally_owned, comm), critical(scalar_locally_owned, comm);
    const double tau = parameters.time_step;
    for (unsigned int p = 0; p < rows.size(); ++p)
      if (scalar_locally_owned.is_element(row_scalar_dofs[p]))
        {
          pressure(row_scalar_dofs[p]) =
            report.active[p] ?
              2. / (tau * tau) * report.multipliers[p] / rows.rows[p].weight :
              0.;
          active(row_scalar_dofs[p])   = report.active[p];
          critical(row_scalar_dofs[p]) = report.critical[p];
        }
    pressure.compress(VectorOperation::insert);
    active.compress(VectorOperation::insert);
    critical.compress(VectorOperation::insert);
    TrilinosWrappers::MPI::Vector pressure_g(scalar_locally_owned,
                                             scalar_locally_relevant,
                                             comm),
      active_g(pressure_g), critical_g(pressure_g);
    pressure_g = pressure;
    active_g   = active;
    critical_g = critical;

    DataOut<dim> data_out;
    data_out.attach_triangulation(triangulation);
    const std::vector<DataComponentInterpretation::DataComponentInterpretation>
      vector_field(dim, DataComponentInterpretation::component_is_part_of_vector);
    data_out.add_data_vector(dof_handler,
                             u_ghosted,
                             std::vector<std::string>(dim, "displacement"),
                             vector_field);
    data_out.add_data_vector(dof_handler,
                             v_ghosted,
                             std::vector<std::string>(dim, "velocity"),
                             vector_field);
    const VonMisesPostprocessor<dim> von_mises(scene->material());
    data_out.add_data_vector(dof_handler, u_ghosted, von_mises);
    data_out.add_data_vector(scalar_dof_handler, pressure_g, "contact_pressure");
    data_out.add_data_vector(scalar_dof_handler, active_g, "active_set");
    data_out.add_data_vector(scalar_dof_handler, critical_g, "critical_set");
    Vector<float> subdomain(triangulation.n_active_cells());
    for (auto &s : subdomain)
      s = triangulation.locally_owned_subdomain();
    data_out.add_data_vector(subdomain, "subdomain");
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
    (void)step;
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

    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        std::error_code error;
        std::filesystem::create_directories(parameters.output_directory, error);
        statistics_file.open(parameters.output_directory + "/statistics.tsv");
      }
    const bool writable = Utilities::MPI::broadcast(
      comm, Utilities::MPI::this_mpi_process(comm) != 0 || statistics_file.good(), 0);
    AssertThrow(writable,
                ExcMessage("Output directory '" + parameters.output_directory +
                           "' cannot be created or written."));

    {
      TimerOutput::Scope t(*timer, "setup");
      scene->create_coarse_mesh(triangulation);
      triangulation.refine_global(parameters.initial_refinements);
    }
    setup_system();
    assemble_system();
    make_contact_rows();
    row_evaluator = std::make_unique<ActiveSetSolver>(parameters.solver, comm);
    row_evaluator->reinit(locally_owned, locally_relevant, mesh_constraints, rows);
    set_initial_values();

    const SemiDiscreteSystem system{&mass_matrix,
                                    &stiffness_matrix,
                                    viscous_matrix.m() > 0 ? &viscous_matrix :
                                                             nullptr,
                                    &load,
                                    parameters.lumped_mass};
    {
      TimerOutput::Scope t(*timer, "setup");
      integrator = std::make_unique<TimeIntegrator>(parameters.scheme,
                                                    parameters.time_step,
                                                    system,
                                                    parameters.solver,
                                                    locally_owned,
                                                    locally_relevant,
                                                    mesh_constraints,
                                                    rows,
                                                    comm);
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
    if (scene->has_exact_solution())
      statistics.columns.push_back("error_energy_norm");
    if (statistics_file.is_open())
      statistics.write_header(statistics_file);

    StepReport report;
    {
      TimerOutput::Scope t(*timer, "time step");
      report = integrator->initialize(u, udot);
    }
    record_step(0, 0., report, 0.);
    if (parameters.write_vtu)
      output_results(0, 0., report);

    const double       tau     = parameters.time_step;
    const unsigned int n_steps = static_cast<unsigned int>(
      std::ceil(parameters.end_time / tau - 1e-9));
    double next_output = parameters.output_interval;
    for (unsigned int step = 1; step <= n_steps; ++step)
      {
        const double time = step * tau;
        Timer        step_timer;
        u_old = u;
        {
          TimerOutput::Scope t(*timer, "time step");
          report = integrator->step(u, udot);
        }
        AssertThrow(report.displacement_solve.converged &&
                      report.projection_solve.converged,
                    ExcMessage("The active-set iteration did not converge "
                               "within 'Contact solver/Maximum active-set "
                               "iterations' at step " +
                               std::to_string(step) + ", t = " +
                               std::to_string(time) + " s."));
        AssertThrow(std::isfinite(u.l2_norm()) && std::isfinite(udot.l2_norm()),
                    ExcMessage("The solution is not finite at step " +
                               std::to_string(step) + ", t = " +
                               std::to_string(time) + " s."));
        step_timer.stop();
        record_step(step, time, report, step_timer.wall_time());
        if (parameters.write_vtu &&
            (time >= next_output - 1e-9 * tau || step == n_steps))
          {
            output_results(step, time, report);
            next_output += parameters.output_interval;
          }
      }

    timer->print_summary();
    return statistics;
  }

  template class Simulator<2>;
  template class Simulator<3>;
} // namespace dyncontact
