#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <dyncontact/base/collective_errors.h>
#include <dyncontact/discretization/cell_assembly.h>
#include <dyncontact/discretization/semi_discrete_system.h>

#include <cmath>
#include <sstream>
#include <utility>
#include <vector>

// The loads a scene gives as functions of x and t (FunctionLoads): their
// assembly at a time, and the load of a step when they change in time
// (doc/algorithms.md, "Loads that change in time").

namespace dyncontact
{
  template <int dim>
  void
  SemiDiscreteSystem<dim>::assemble_function_loads(const double t,
                                                   const bool   of_time,
                                                   VectorType  &f) const
  {
    // (those of this part only)
    const auto in_part = [&](const Function<dim> *function) {
      return function != nullptr &&
             function_loads.of_time.count(function) == (of_time ? 1 : 0);
    };
    for (Function<dim> *function : function_loads.body_forces)
      if (in_part(function))
        function->set_time(t);
    for (const auto &load_of_tag :
         {&function_loads.tractions, &function_loads.pressures})
      for (const auto &[id, function] : *load_of_tag)
        if (in_part(function))
          function->set_time(t);

    const QGauss<dim>     quadrature(fe.degree + 1);
    const QGauss<dim - 1> face_quadrature(fe.degree + 1);
    FEValues<dim>         values(mapping,
                         scalar_fe,
                         quadrature,
                         update_values | update_JxW_values |
                           update_quadrature_points);
    FEFaceValues<dim>     face_values(mapping,
                                  scalar_fe,
                                  face_quadrature,
                                  update_values | update_JxW_values |
                                    update_quadrature_points |
                                    update_normal_vectors);
    const auto [component, node] = CellAssembly::components_and_nodes(fe);
    const unsigned int                   dofs_per_cell = fe.n_dofs_per_cell();
    std::vector<types::global_dof_index> dof_indices(dofs_per_cell);
    Vector<double>                       cell_load(dofs_per_cell);
    std::vector<Vector<double>>          body_force(quadrature.size(),
                                           Vector<double>(dim));
    std::vector<Vector<double>>          traction(face_quadrature.size(),
                                         Vector<double>(dim));
    std::vector<double>                  pressure(face_quadrature.size());

    // the first value on this rank that is not finite or beyond 1e15
    std::string problem;
    // (@p what and @p number name the load, only when it fails)
    const auto check = [&](const double       value,
                           const Point<dim>  &x,
                           const char        *what,
                           const unsigned int number) {
      if (problem.empty() && !(std::abs(value) <= 1e15))
        {
          std::ostringstream text;
          text << "A load given as a function is " << value << " (not "
               << "finite, or beyond 1e15 in magnitude) at t = " << t
               << " s: " << what << number << " at (" << x[0];
          for (unsigned int d = 1; d < dim; ++d)
            text << ", " << x[d];
          text << "). Check its expression (Scene/Gmsh/Body force, "
                  "Pressures or Neumann tractions).";
          problem = text.str();
        }
    };
    VectorType function_part;
    reinit_vector(function_part);
    {
      CellAssembly::OwnedAdder adder(function_part, locally_owned);
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            cell_load          = 0.;
            bool           any = false;
            Function<dim> *force =
              cell->material_id() < function_loads.body_forces.size() ?
                function_loads.body_forces[cell->material_id()] :
                nullptr;
            if (in_part(force))
              {
                values.reinit(cell);
                force->vector_value_list(values.get_quadrature_points(),
                                         body_force);
                for (unsigned int q = 0; q < quadrature.size(); ++q)
                  for (unsigned int d = 0; d < dim; ++d)
                    check(body_force[q][d],
                          values.quadrature_point(q),
                          "the body force of body ",
                          cell->material_id() + 1);
                for (unsigned int q = 0; q < quadrature.size(); ++q)
                  for (unsigned int i = 0; i < dofs_per_cell; ++i)
                    cell_load(i) += values.shape_value(node[i], q) *
                                    body_force[q][component[i]] * values.JxW(q);
                any = true;
              }
            for (const unsigned int face : cell->face_indices())
              if (cell->face(face)->at_boundary())
                {
                  const auto id = cell->face(face)->boundary_id();
                  for (const auto *loads :
                       {&function_loads.tractions, &function_loads.pressures})
                    for (const auto &[load_id, function] : *loads)
                      if (load_id == id && in_part(function))
                        {
                          // a traction, or a pressure's traction -p n
                          const bool is_pressure =
                            loads == &function_loads.pressures;
                          face_values.reinit(cell, face);
                          const auto &points =
                            face_values.get_quadrature_points();
                          if (is_pressure)
                            function->value_list(points, pressure);
                          else
                            function->vector_value_list(points, traction);
                          for (unsigned int q = 0; q < points.size(); ++q)
                            {
                              if (is_pressure)
                                {
                                  check(pressure[q],
                                        points[q],
                                        "the pressure of tag ",
                                        id);
                                  for (unsigned int d = 0; d < dim; ++d)
                                    traction[q][d] =
                                      -pressure[q] *
                                      face_values.normal_vector(q)[d];
                                }
                              else
                                for (unsigned int d = 0; d < dim; ++d)
                                  check(traction[q][d],
                                        points[q],
                                        "the traction of tag ",
                                        id);
                              for (unsigned int i = 0; i < dofs_per_cell; ++i)
                                cell_load(i) +=
                                  face_values.shape_value(node[i], q) *
                                  traction[q][component[i]] *
                                  face_values.JxW(q);
                            }
                          any = true;
                        }
                }
            if (any)
              {
                cell->get_dof_indices(dof_indices);
                adder.add(dof_indices, cell_load);
              }
          }
    }
    function_part.compress(VectorOperation::add);
    stop_with_any_message(problem, comm);
    if (of_time)
      {
        f = constant_load;
        f += function_part;
      }
    else
      f = function_part;
  }



  template <int dim>
  void
  SemiDiscreteSystem<dim>::set_load_time(const double t)
  {
    if (function_loads.time_dependent && t != load_time)
      assemble_function_loads(t, true, load);
    load_time = t;
  }



  template <int dim>
  void
  SemiDiscreteSystem<dim>::begin_step_load(const double t_end)
  {
    end_load_time = t_end;
    if (prescribed)
      prescribed_values(t_end, prescribed->at_end);
    if (!function_loads.time_dependent)
      return;
    assemble_function_loads(t_end, true, end_load);
    // the paper's F((u^n + u^{n+1})/2) with the trapezoidal mean of f
    step_load = load;
    step_load += end_load;
    step_load *= 0.5;
  }



  template <int dim>
  void
  SemiDiscreteSystem<dim>::end_step_load()
  {
    if (!loads_change_in_time())
      return;
    previous_load_time = load_time;
    load_time          = end_load_time;
    if (!function_loads.time_dependent)
      return;
    // previous_load = f(t_n), load = f(t_end) (the vectors keep their
    // addresses, which matrices() hands out)
    previous_load.swap(load);
    load.swap(end_load);
  }



  template <int dim>
  void
  SemiDiscreteSystem<dim>::undo_step_load()
  {
    if (!loads_change_in_time())
      return;
    load_time = previous_load_time;
    if (!function_loads.time_dependent)
      return;
    load.swap(end_load);
    previous_load.swap(load);
  }



#define DYNCONTACT_INSTANTIATE(dim)                                            \
  template void SemiDiscreteSystem<dim>::assemble_function_loads(const double, \
                                                                 const bool,   \
                                                                 VectorType &) \
    const;                                                                     \
  template void SemiDiscreteSystem<dim>::set_load_time(const double);          \
  template void SemiDiscreteSystem<dim>::begin_step_load(const double);        \
  template void SemiDiscreteSystem<dim>::end_step_load();                      \
  template void SemiDiscreteSystem<dim>::undo_step_load();
  DYNCONTACT_INSTANTIATE(2)
  DYNCONTACT_INSTANTIATE(3)
#undef DYNCONTACT_INSTANTIATE
} // namespace dyncontact
