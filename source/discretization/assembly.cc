#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>
#include <deal.II/fe/fe_values.h>

#include <dyncontact/discretization/cell_assembly.h>
#include <dyncontact/discretization/element_matrix_adder.h>
#include <dyncontact/discretization/semi_discrete_system.h>

#include <algorithm>
#include <limits>
#include <sstream>
#include <tuple>

// The assembly of the semi-discrete system: M (or its diagonal), f and the
// boundary weights w (SemiDiscreteSystem::assemble()); the matrices of the
// step are in stiffness_assembly.cc.

namespace dyncontact
{
  using namespace CellAssembly;

  namespace
  {
    /**
     * The element mass matrix (only its diagonal if lumped), load and
     * boundary weights of one cell. Every shape function of FE_Q<dim>^dim
     * is a scalar shape function of FE_Q times a unit vector, so the
     * integrals are those of the scalar element.
     */
    template <int dim>
    class CellTerms
    {
    public:
      CellTerms(const Mapping<dim>  &mapping,
                const FESystem<dim> &fe,
                const FE_Q<dim>     &scalar_fe,
                const bool           lumped_mass,
                const double         consistent_fraction)
        : lumped_mass(lumped_mass)
        , consistent_fraction(lumped_mass ? 0. : consistent_fraction)
        , lumped_fraction(lumped_mass ? 1. : 1. - consistent_fraction)
        , quadrature(fe.degree + 1)
        , face_quadrature(fe.degree + 1)
        , lumped_face_quadrature(fe.degree + 1)
        , fe_values(mapping,
                    scalar_fe,
                    quadrature,
                    update_values | update_JxW_values)
        , face_values(mapping,
                      scalar_fe,
                      face_quadrature,
                      update_values | update_JxW_values)
        , lumped_face_values(mapping,
                             scalar_fe,
                             lumped_face_quadrature,
                             update_values | update_JxW_values)
        // the lumped mass matrix: nodal (Gauss-Lobatto) quadrature makes
        // the element mass matrix of FE_Q diagonal
        , nodal_values(mapping,
                       scalar_fe,
                       QGaussLobatto<dim>(fe.degree + 1),
                       update_values | update_JxW_values)
        , beyond_consistent_values(mapping,
                                   scalar_fe,
                                   two_point_rule(consistent_fraction),
                                   update_values | update_JxW_values)
        , dofs_per_cell(fe.n_dofs_per_cell())
        , n_nodes(scalar_fe.n_dofs_per_cell())
        , scalar_mass(lumped_mass ? 0 : n_nodes * n_nodes)
        , scalar_lumped(n_nodes)
        , scalar_load(n_nodes)
      {
        if (lumped_fraction > 0.)
          mass_diagonal.reinit(dofs_per_cell);
        if (!lumped_mass)
          mass.reinit(dofs_per_cell, dofs_per_cell);
        load.reinit(dofs_per_cell);
        boundary_weights.reinit(dofs_per_cell);
        std::tie(component, node) = components_and_nodes(fe);
      }

      /// The terms of @p cell, of density @p rho and body force
      /// @p body_force, with the tractions @p tractions and the contact
      /// boundaries @p contact_ids; false if the Jacobian is not positive
      /// at every quadrature point (an inverted or twisted cell, which
      /// deal.II does not reject on reading).
      bool
      compute(const typename Triangulation<dim>::cell_iterator &cell,
              const double                                      rho,
              const Tensor<1, dim>                             &body_force,
              const std::vector<std::pair<types::boundary_id, Tensor<1, dim>>>
                                                    &tractions,
              const std::vector<types::boundary_id> &contact_ids)
      {
        boundary_weights = 0.;
        fe_values.reinit(cell);
        if (lumped_fraction > 0.)
          nodal_values.reinit(cell);
        if (consistent_fraction > 1.)
          beyond_consistent_values.reinit(cell);
        const auto positive_at = [](const FEValues<dim> &values) {
          for (unsigned int q = 0; q < values.n_quadrature_points; ++q)
            if (!(values.JxW(q) > 0.))
              return false;
          return true;
        };
        const bool positive =
          positive_at(fe_values) &&
          (consistent_fraction <= 1. || positive_at(beyond_consistent_values));
        // a translation of the cell before has its values and JxW
        // (FEValues keeps them), hence with the same density its scalar
        // mass and load, and the same element mass matrix
        const bool same_volume_terms =
          have_volume_terms && rho == volume_rho &&
          fe_values.get_cell_similarity() == CellSimilarity::translation &&
          (lumped_fraction <= 0. ||
           nodal_values.get_cell_similarity() == CellSimilarity::translation) &&
          (consistent_fraction <= 1. ||
           beyond_consistent_values.get_cell_similarity() ==
             CellSimilarity::translation);
        if (!same_volume_terms)
          volume_terms(rho);
        have_volume_terms = true;
        volume_rho        = rho;
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
          load(i) = scalar_load[node[i]] * body_force[component[i]];
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            face_terms(cell, f, tractions, contact_ids);
        return positive;
      }

      /// the element mass matrix, or (lumped) its diagonal; a blended
      /// mass's lumped part (1 - beta) M_K (Gauss-Lobatto) in mass_diagonal
      FullMatrix<double> mass;
      Vector<double>     mass_diagonal;
      Vector<double>     load;
      Vector<double>     boundary_weights;

    private:
      /**
       * For linear elements and 1 < @p beta < 3/2: the tensor product of
       * the two-point rule at 1/2 -+ a/2, a = sqrt(1 - 2 beta / 3), with
       * weights 1/2. In 1D its mass matrix is (1 - beta) times the lumped
       * plus beta times the consistent one (a = 1: Gauss-Lobatto, the
       * lumped mass; a = 1/sqrt(3): Gauss, the consistent mass), in 2D
       * and 3D the tensor product of those, positive definite for every
       * beta < 3/2 (the formula itself is indefinite above 9/8 in 2D).
       * Otherwise (unused) the one-point rule.
       */
      static Quadrature<dim>
      two_point_rule(const double beta)
      {
        if (!(beta > 1.))
          return QGauss<dim>(1);
        const double        a = std::sqrt(1. - 2. * beta / 3.);
        const Quadrature<1> rule({Point<1>(0.5 - a / 2.),
                                  Point<1>(0.5 + a / 2.)},
                                 {0.5, 0.5});
        return Quadrature<dim>(rule);
      }

      /// int phi_k (scalar_load) and the element mass matrix (lumped:
      /// its diagonal) of the present cell with density @p rho
      void
      volume_terms(const double rho)
      {
        std::fill(scalar_load.begin(), scalar_load.end(), 0.);
        for (unsigned int q = 0; q < quadrature.size(); ++q)
          for (unsigned int k = 0; k < n_nodes; ++k)
            scalar_load[k] += fe_values.shape_value(k, q) * fe_values.JxW(q);

        // the lumped part (1 - beta) M_K (Gauss-Lobatto), diagonal (a
        // lumped mass: all of it), also kept in mass_diagonal
        if (lumped_fraction > 0.)
          {
            std::fill(scalar_lumped.begin(), scalar_lumped.end(), 0.);
            for (unsigned int q = 0; q < nodal_values.n_quadrature_points; ++q)
              for (unsigned int k = 0; k < n_nodes; ++k)
                scalar_lumped[k] +=
                  lumped_fraction * rho * nodal_values.shape_value(k, q) *
                  nodal_values.shape_value(k, q) * nodal_values.JxW(q);
            for (unsigned int i = 0; i < dofs_per_cell; ++i)
              mass_diagonal(i) = scalar_lumped[node[i]];
          }
        if (lumped_mass)
          return;
        // the consistent part beta M_K (Gauss, the load's quadrature), or
        // beyond the consistent mass (beta > 1) all of M_K by the two-point
        // rule of two_point_rule()
        mass = 0.;
        std::fill(scalar_mass.begin(), scalar_mass.end(), 0.);
        const FEValues<dim> &values =
          consistent_fraction > 1. ? beyond_consistent_values : fe_values;
        for (unsigned int q = 0; q < values.n_quadrature_points; ++q)
          for (unsigned int k = 0; k < n_nodes; ++k)
            for (unsigned int l = 0; l < n_nodes; ++l)
              scalar_mass[k * n_nodes + l] += rho * values.shape_value(k, q) *
                                              values.shape_value(l, q) *
                                              values.JxW(q);
        if (lumped_fraction > 0.)
          {
            for (double &entry : scalar_mass)
              entry *= consistent_fraction;
            for (unsigned int k = 0; k < n_nodes; ++k)
              scalar_mass[k * n_nodes + k] += scalar_lumped[k];
          }
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
          for (unsigned int j = 0; j < dofs_per_cell; ++j)
            if (component[i] == component[j])
              mass(i, j) = scalar_mass[node[i] * n_nodes + node[j]];
      }

      void
      face_terms(
        const typename Triangulation<dim>::cell_iterator &cell,
        const unsigned int                                f,
        const std::vector<std::pair<types::boundary_id, Tensor<1, dim>>>
                                              &tractions,
        const std::vector<types::boundary_id> &contact_ids)
      {
        const auto id = cell->face(f)->boundary_id();
        for (const auto &[traction_id, traction] : tractions)
          if (traction_id == id)
            {
              face_values.reinit(cell, f);
              for (unsigned int q = 0; q < face_quadrature.size(); ++q)
                for (unsigned int i = 0; i < dofs_per_cell; ++i)
                  load(i) += face_values.shape_value(node[i], q) *
                             traction[component[i]] * face_values.JxW(q);
            }
        if (std::find(contact_ids.begin(), contact_ids.end(), id) !=
            contact_ids.end())
          {
            // w_p = int psi_p ds, by nodal quadrature (positive)
            lumped_face_values.reinit(cell, f);
            for (unsigned int q = 0; q < lumped_face_quadrature.size(); ++q)
              for (unsigned int i = 0; i < dofs_per_cell; ++i)
                boundary_weights(i) +=
                  lumped_face_values.shape_value(node[i], q) *
                  lumped_face_values.JxW(q);
          }
      }

      const bool lumped_mass;
      /// the consistent part beta and the lumped part 1 - beta of the mass
      /// (lumped: 0 and 1; consistent: 1 and 0)
      const double                 consistent_fraction, lumped_fraction;
      const QGauss<dim>            quadrature;
      const QGauss<dim - 1>        face_quadrature;
      const QGaussLobatto<dim - 1> lumped_face_quadrature;
      FEValues<dim>                fe_values;
      FEFaceValues<dim>            face_values;
      FEFaceValues<dim>            lumped_face_values;
      FEValues<dim>                nodal_values;
      FEValues<dim>                beyond_consistent_values;
      const unsigned int           dofs_per_cell;
      const unsigned int           n_nodes;
      /// component and scalar shape function of each shape function
      std::vector<unsigned int> component, node;
      /// the scalar mass's consistent part, its lumped part (diagonal) and
      /// the load int phi_k
      std::vector<double> scalar_mass, scalar_lumped;
      std::vector<double> scalar_load;
      /// whether volume_terms() ran, and the density it had
      bool   have_volume_terms = false;
      double volume_rho        = 0.;
    };



    /// Stops with a message naming the inverted cell of some rank:
    /// @p bad_cell holds its centre and body + 1, or nothing (collective).
    template <int dim>
    void
    check_for_inverted_cells(const std::vector<double> &bad_cell,
                             const MPI_Comm             comm)
    {
      // (the gather, which serialises, only where some rank found one)
      if (Utilities::MPI::logical_or(!bad_cell.empty(), comm) == false)
        return;
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
    }



#ifdef DEBUG
    /// Whether the Jacobian of MappingQ1's map of @p cell (the one of the
    /// program) is above 1e-12 (diameter / sqrt(dim))^dim at the points of
    /// @p quadratures. deal.II's Debug build stops with an assertion in
    /// FEValues::reinit() where it is not; the Release build computes the
    /// cell's terms, and the assembly then names the cell. A Debug build
    /// tests the cells first, so that it names the cell as well.
    template <int dim>
    bool
    jacobians_positive(const typename Triangulation<dim>::cell_iterator &cell,
                       const std::vector<Quadrature<dim>> &quadratures)
    {
      const double bound = 1e-12 * Utilities::fixed_power<dim>(
                                     cell->diameter() / std::sqrt(double(dim)));
      for (const auto &quadrature : quadratures)
        for (const auto &point : quadrature.get_points())
          {
            Tensor<2, dim> jacobian;
            for (const unsigned int v : cell->vertex_indices())
              jacobian += outer_product(
                Tensor<1, dim>(cell->vertex(v)),
                GeometryInfo<dim>::d_linear_shape_function_gradient(point, v));
            if (!(determinant(jacobian) > bound))
              return false;
          }
      return true;
    }
#endif



  } // namespace



  template <int dim>
  std::vector<std::pair<types::boundary_id, Tensor<1, dim>>>
  SemiDiscreteSystem<dim>::boundary_tractions(const Scene<dim> &scene) const
  {
    auto tractions = scene.neumann_tractions();
    // loads given as total forces: spread over the boundary as the mesh
    // represents it, so that they sum to the force exactly
    const auto forces = scene.neumann_forces();
    if (forces.empty())
      return tractions;
    const QGauss<dim - 1> face_quadrature(fe.degree + 1);
    FEFaceValues<dim>     area_values(mapping,
                                  fe,
                                  face_quadrature,
                                  update_JxW_values);
    std::vector<double>   areas(forces.size(), 0.);
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
        tractions.emplace_back(forces[k].first, forces[k].second / areas[k]);
      }
    return tractions;
  }



  template <int dim>
  void
  SemiDiscreteSystem<dim>::assemble(const Scene<dim> &scene)
  {
    // (the multigrid's linear level needs neither the load nor w)
    const auto tractions =
      parameters.multigrid_level ?
        std::vector<std::pair<types::boundary_id, Tensor<1, dim>>>() :
        boundary_tractions(scene);
    const auto          contact_ids = parameters.multigrid_level ?
                                        std::vector<types::boundary_id>() :
                                        scene.all_contact_boundary_ids();
    CellTerms<dim>      terms(mapping,
                         fe,
                         scalar_fe,
                         parameters.lumped_mass,
                         parameters.consistent_mass_fraction);
    std::vector<double> bad_cell; // centre and body of an inverted cell
    const auto          note_bad_cell = [&bad_cell](const auto &cell) {
      if (!bad_cell.empty())
        return;
      for (unsigned int d = 0; d < dim; ++d)
        bad_cell.push_back(cell->center()[d]);
      bad_cell.push_back(cell->material_id() + 1);
    };
    std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
    std::unique_ptr<OwnedAdder> lumped_mass_adder, load_adder, weight_adder;
    // (setup() sized lumped_mass_diagonal for a lumped mass, or a blended
    // mass's lumped part)
    if (lumped_mass_diagonal.size() > 0)
      lumped_mass_adder =
        std::make_unique<OwnedAdder>(lumped_mass_diagonal, locally_owned);
    if (!parameters.multigrid_level)
      {
        load_adder = std::make_unique<OwnedAdder>(load, locally_owned);
        weight_adder =
          std::make_unique<OwnedAdder>(boundary_weights, locally_owned);
      }

#ifdef DEBUG
    {
      // the points of CellTerms' FEValues (see jacobians_positive())
      const std::vector<Quadrature<dim>> points = {
        QGauss<dim>(fe.degree + 1), QGaussLobatto<dim>(fe.degree + 1)};
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned() && bad_cell.empty() &&
            !jacobians_positive<dim>(cell, points))
          note_bad_cell(cell);
      check_for_inverted_cells<dim>(bad_cell, comm);
    }
#endif
    materials.clear();
    std::unique_ptr<ElementMatrixAdder> mass_adder;
    if (!parameters.lumped_mass)
      mass_adder = std::make_unique<ElementMatrixAdder>(mass_matrix);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const Material &material =
            materials
              .emplace(cell->material_id(), scene.material(cell->material_id()))
              .first->second;
          const bool positive =
            terms.compute(typename Triangulation<dim>::cell_iterator(cell),
                          material.density,
                          scene.body_force(cell->material_id()),
                          tractions,
                          contact_ids);
          if (!positive)
            note_bad_cell(cell);
          cell->get_dof_indices(dof_indices);
          if (lumped_mass_adder)
            lumped_mass_adder->add(dof_indices, terms.mass_diagonal);
          if (mass_adder)
            mass_adder->add(dof_indices, terms.mass);
          if (!parameters.multigrid_level)
            {
              load_adder->add(dof_indices, terms.load);
              weight_adder->add(dof_indices, terms.boundary_weights);
            }
        }

    if (lumped_mass_adder)
      lumped_mass_diagonal.compress(VectorOperation::add);
    if (mass_adder)
      mass_matrix.compress(VectorOperation::add);
    check_for_inverted_cells<dim>(bad_cell, comm);
    if (parameters.multigrid_level)
      return;
    load.compress(VectorOperation::add);
    boundary_weights.compress(VectorOperation::add);
    // the loads given as functions, at the present time
    function_loads = scene.function_loads();
    if (!function_loads.empty())
      {
        // the constant loads with the functions of x alone, once per mesh,
        // and the functions of t at the present time
        constant_load = load;
        VectorType of_x;
        assemble_function_loads(load_time, false, of_x);
        constant_load += of_x;
        if (function_loads.time_dependent)
          assemble_function_loads(load_time, true, load);
        else
          load = constant_load;
        if (function_loads.time_dependent)
          for (VectorType *v : {&previous_load, &end_load, &step_load})
            reinit_vector(*v);
      }
    elastic_operator.reinit(mapping, dof_handler, materials);
    stiffness_product.reinit(
      [this](VectorType &y, const VectorType &x) { stiffness_vmult(y, x); });
  }



#define DYNCONTACT_INSTANTIATE(dim)                                      \
  template std::vector<std::pair<types::boundary_id, Tensor<1, dim>>>    \
  SemiDiscreteSystem<dim>::boundary_tractions(const Scene<dim> &) const; \
  template void SemiDiscreteSystem<dim>::assemble(const Scene<dim> &);
  DYNCONTACT_INSTANTIATE(2)
  DYNCONTACT_INSTANTIATE(3)
#undef DYNCONTACT_INSTANTIATE
} // namespace dyncontact
