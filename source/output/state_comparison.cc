#include <deal.II/base/array_view.h>
#include <deal.II/base/mpi_remote_point_evaluation.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/solution_transfer.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>

#include <dyncontact/base/checksum.h>
#include <dyncontact/base/collective_errors.h>
#include <dyncontact/base/triangulation.h>
#include <dyncontact/discretization/energy_density.h>
#include <dyncontact/discretization/semi_discrete_system.h>
#include <dyncontact/discretization/serial_transfer.h>
#include <dyncontact/output/state_comparison.h>
#include <dyncontact/scenes/interface.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>

namespace dyncontact
{
  /// A state (u, udot) on its own triangulation and DoFs.
  template <int dim>
  struct ComparedState
  {
    using VectorType = TrilinosWrappers::MPI::Vector;

    std::unique_ptr<Triangulation<dim>> triangulation;
    std::unique_ptr<FESystem<dim>>      fe;
    std::unique_ptr<DoFHandler<dim>>    dofs;
    VectorType                          u, udot;
    /// A state read from files: the values of u, then of udot, on each
    /// active cell this rank owns (by its active cell index).
    std::vector<double> cell_values;
    /// The bytes of the last file read.
    std::string buffer;

    ComparedState(const Triangulation<dim> &source, const unsigned int degree)
      : triangulation(make_triangulation<dim>(as_distributed(source) == nullptr,
                                              source.get_communicator()))
      , fe(std::make_unique<FESystem<dim>>(FE_Q<dim>(degree), dim))
    {
      triangulation->copy_triangulation(source);
    }

    void
    distribute()
    {
      if (!dofs)
        dofs = std::make_unique<DoFHandler<dim>>(*triangulation);
      dofs->distribute_dofs(*fe);
      u.reinit(dofs->locally_owned_dofs(), triangulation->get_communicator());
      udot.reinit(u);
    }

    /// Ghosted copies of u and udot.
    std::pair<VectorType, VectorType>
    ghosted() const
    {
      IndexSet relevant;
      DoFTools::extract_locally_relevant_dofs(*dofs, relevant);
      VectorType a(dofs->locally_owned_dofs(),
                   relevant,
                   triangulation->get_communicator());
      VectorType b(a);
      a = u;
      b = udot;
      return {std::move(a), std::move(b)};
    }

    /// Refines the cells flagged, prolongating u and udot.
    void
    refine()
    {
      if (auto *distributed = as_distributed(*triangulation))
        {
          const auto [a, b] = ghosted();
          parallel::distributed::SolutionTransfer<dim, VectorType> transfer(
            *dofs);
          transfer.prepare_for_coarsening_and_refinement(
            std::vector<const VectorType *>{&a, &b});
          distributed->execute_coarsening_and_refinement();
          distribute();
          std::vector<VectorType *> out = {&u, &udot};
          transfer.interpolate(out);
        }
      else
        {
          SerialTransfer<dim> transfer;
          transfer.prepare(*dofs, {&u, &udot});
          triangulation->execute_coarsening_and_refinement();
          distribute();
          transfer.interpolate(*dofs, {&u, &udot});
        }
    }
  };



  namespace
  {
    using VectorType = TrilinosWrappers::MPI::Vector;

    /// The active cells this rank owns (of either triangulation).
    template <int dim>
    unsigned int
    n_owned_cells(const Triangulation<dim> &triangulation)
    {
      unsigned int n = 0;
      for (const auto &cell : triangulation.active_cell_iterators())
        n += cell->is_locally_owned() ? 1 : 0;
      return n;
    }

    /// The cell @p id of @p triangulation, or its end if this rank does
    /// not hold it; @p coarse_cells: the level-0 index of each coarse cell
    /// id.
    template <int dim>
    typename Triangulation<dim>::cell_iterator
    find_cell(const Triangulation<dim>                        &triangulation,
              const std::map<types::coarse_cell_id, unsigned> &coarse_cells,
              const CellId                                    &id)
    {
      const auto coarse = coarse_cells.find(id.get_coarse_cell_id());
      if (coarse == coarse_cells.end())
        return triangulation.end();
      typename Triangulation<dim>::cell_iterator cell(&triangulation,
                                                      0,
                                                      coarse->second);
      for (const auto child : id.get_child_indices())
        {
          if (!cell->has_children())
            return triangulation.end();
          cell = cell->child(child);
        }
      return cell;
    }

    /// Reads the values of @p file into @p state's cell_values on the
    /// cells this rank owns; returns how many cells it set. The file is
    /// read once: its checksum is that of the bytes read.
    template <int dim>
    unsigned int
    read_values(const std::string  &file,
                const std::string  &checksum,
                ComparedState<dim> &state)
    {
      std::ifstream in(file, std::ios::binary);
      AssertThrow(in.good(),
                  ExcMessage("Reference solution: there is no reference "
                             "state '" +
                             file + "'."));
      // read at once into a buffer kept between the states (no new pages)
      in.seekg(0, std::ios::end);
      const std::streamoff size = in.tellg();
      in.seekg(0);
      std::string &bytes = state.buffer;
      bytes.resize(std::max<std::streamoff>(size, 0));
      in.read(bytes.data(), bytes.size());
      AssertThrow(in.good() && checksum_of_text(bytes) == checksum,
                  ExcMessage("Reference solution: the reference state '" +
                             file +
                             "' is damaged (its checksum differs from the "
                             "one in its header): run the reference again."));
      std::uint64_t count = 0;
      std::uint32_t n     = 0;
      std::size_t   at    = 0;
      const auto    take  = [&](void *to, const std::size_t size) {
        AssertThrow(at + size <= bytes.size(),
                    ExcMessage("Reference solution: the state '" + file +
                               "' ends early."));
        std::memcpy(to, bytes.data() + at, size);
        at += size;
      };
      take(&count, sizeof(count));
      take(&n, sizeof(n));
      AssertThrow(n == state.fe->n_dofs_per_cell(),
                  ExcMessage("Reference solution: the state '" + file +
                             "' does not fit its header (damaged?)."));
      state.cell_values.resize(state.triangulation->n_active_cells() * 2 * n);
      CellId::binary_type                       id;
      unsigned int                              set = 0;
      std::map<types::coarse_cell_id, unsigned> coarse_cells;
      for (const auto &cell : state.triangulation->cell_iterators_on_level(0))
        coarse_cells[cell->id().get_coarse_cell_id()] = cell->index();
      for (std::uint64_t k = 0; k < count; ++k)
        {
          take(id.data(), sizeof(id));
          const std::size_t values = at;
          AssertThrow(at + 2 * n * sizeof(double) <= bytes.size(),
                      ExcMessage("Reference solution: the state '" + file +
                                 "' ends early."));
          at += 2 * n * sizeof(double);
          const auto cell =
            find_cell(*state.triangulation, coarse_cells, CellId(id));
          if (cell == state.triangulation->end() || !cell->is_active() ||
              !cell->is_locally_owned())
            continue;
          std::memcpy(state.cell_values.data() +
                        std::size_t(cell->active_cell_index()) * 2 * n,
                      bytes.data() + values,
                      2 * n * sizeof(double));
          ++set;
        }
      return set;
    }
  } // namespace



  template <int dim>
  void
  StateComparison<dim>::write_values(const std::string     &file,
                                     const DoFHandler<dim> &dof_handler,
                                     const VectorType      &u,
                                     const VectorType      &udot)
  {
    std::ofstream       out(file, std::ios::binary);
    const std::uint64_t count = n_owned_cells(dof_handler.get_triangulation());
    const std::uint32_t n     = dof_handler.get_fe().n_dofs_per_cell();
    out.write(reinterpret_cast<const char *>(&count), sizeof(count));
    out.write(reinterpret_cast<const char *>(&n), sizeof(n));
    Vector<double> a(n), b(n);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const CellId::binary_type id = cell->id().template to_binary<dim>();
          cell->get_dof_values(u, a);
          cell->get_dof_values(udot, b);
          out.write(reinterpret_cast<const char *>(id.data()), sizeof(id));
          out.write(reinterpret_cast<const char *>(a.data()),
                    n * sizeof(double));
          out.write(reinterpret_cast<const char *>(b.data()),
                    n * sizeof(double));
        }
    out.close();
    stop_with_any_message(out.good() ?
                            "" :
                            "Cannot write the reference state '" + file + "'.",
                          dof_handler.get_communicator());
  }



  template <int dim>
  StateComparison<dim>::StateComparison(
    const Scene<dim>                   &scene,
    const Mapping<dim>                 &mapping,
    std::unique_ptr<Triangulation<dim>> coarse)
    : scene(scene)
    , mapping(mapping)
    , coarse(std::move(coarse))
  {}



  template <int dim>
  StateComparison<dim>::~StateComparison() = default;



  template <int dim>
  double
  StateComparison<dim>::difference(
    const std::string              &mesh_file,
    const std::string              &values_file,
    const std::vector<std::string> &values_checksums,
    const unsigned int              reference_degree,
    const DoFHandler<dim>          &dof_handler,
    const VectorType               &u,
    const VectorType               &udot) const
  {
    const MPI_Comm comm = coarse->get_communicator();

    // the other run's mesh (loaded once for all its states), its state
    if (!reference || reference_mesh != mesh_file ||
        reference->fe->degree != reference_degree)
      {
        reference =
          std::make_unique<ComparedState<dim>>(*coarse, reference_degree);
        SemiDiscreteSystem<dim>::load_mesh(mesh_file,
                                           *reference->triangulation);
        reference->distribute();
        reference_mesh = mesh_file;
      }
    {
      const unsigned int reference_ranks = values_checksums.size();
      const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
      const unsigned int rank    = Utilities::MPI::this_mpi_process(comm);
      const unsigned int owned   = n_owned_cells(*reference->triangulation);
      // the same ranks hold the same cells (p4est keeps the partition of a
      // mesh loaded on as many ranks as saved it): the rank's own file;
      // otherwise every file, each rank keeping its cells
      unsigned int set = 0;
      if (n_ranks == reference_ranks)
        set = read_values(values_file + "." + std::to_string(rank),
                          values_checksums[rank],
                          *reference);
      if (Utilities::MPI::min(set == owned ? 1 : 0, comm) == 0)
        {
          set = 0;
          for (unsigned int r = 0; r < reference_ranks; ++r)
            set += read_values(values_file + "." + std::to_string(r),
                               values_checksums[r],
                               *reference);
        }
      stop_with_any_message(set == owned ?
                              "" :
                              "Reference solution: the states '" + values_file +
                                ".*' do not cover the mesh '" + mesh_file +
                                "'.",
                            comm);
    }
    const ComparedState<dim> &ref = *reference;

    // the difference is integrated on the reference's cells, where both
    // states are polynomials of degree at most this (exact for affine
    // cells)
    const unsigned int degree =
      std::max(reference_degree, dof_handler.get_fe().degree);
    const QGauss<dim>                quadrature(degree + 1);
    const FEValuesExtractors::Vector displacement(0);
    FEValues<dim>                    values_ref(mapping,
                             *ref.fe,
                             quadrature,
                             update_values | update_gradients |
                               update_JxW_values);
    const unsigned int               n_ref = ref.fe->n_dofs_per_cell();
    Vector<double>                   u_ref(n_ref), v_ref(n_ref);
    std::vector<Tensor<1, dim>>      v1(quadrature.size()), v2(v1);
    std::vector<Tensor<2, dim>>      g1(quadrature.size()), g2(g1);
    double                           local   = 0.;
    unsigned int                     missing = 0;
    // 1/2 rho |v1 - v2|^2 + 1/2 sigma(e) : eps(e) on the reference's cell
    const auto add = [&](const auto &cell) {
      const double *values = ref.cell_values.data() +
                             std::size_t(cell->active_cell_index()) * 2 * n_ref;
      std::copy(values, values + n_ref, u_ref.begin());
      std::copy(values + n_ref, values + 2 * n_ref, v_ref.begin());
      values_ref[displacement].get_function_values_from_local_dof_values(
        make_array_view(v_ref), v1);
      values_ref[displacement].get_function_gradients_from_local_dof_values(
        make_array_view(u_ref), g1);
      const Material &material = scene.material(cell->material_id());
      for (unsigned int q = 0; q < quadrature.size(); ++q)
        local += energy_density(material,
                                Tensor<1, dim>(v1[q] - v2[q]),
                                g1[q] - g2[q]) *
                 values_ref.JxW(q);
    };

    if (Utilities::MPI::n_mpi_processes(comm) == 1)
      {
        // on one rank every cell of both meshes is at hand: this run's
        // values on a reference cell are those of its ancestor in this
        // run's mesh, prolongated along the path of children
        const Triangulation<dim> &mesh = dof_handler.get_triangulation();
        const FiniteElement<dim> &fe   = dof_handler.get_fe();
        FEValues<dim>             values_own(mapping,
                                 fe,
                                 quadrature,
                                 update_values | update_gradients);
        const bool same_element = fe.get_name() == ref.fe->get_name();
        // plain copies: a Trilinos vector's entries are slow to look up
        const Vector<double>      u_here(u), udot_here(udot);
        Vector<double>            cu(fe.n_dofs_per_cell()), cv(cu), tmp(cu);
        std::vector<unsigned int> path;
        for (const auto &cell : ref.dofs->active_cell_iterators())
          {
            path.clear();
            typename Triangulation<dim>::cell_iterator c = cell;
            while (c->level() > 0)
              {
                path.push_back(c->parent()->child_iterator_to_index(c));
                c = c->parent();
              }
            typename Triangulation<dim>::cell_iterator here(&mesh,
                                                            0,
                                                            c->index());
            auto                                       step = path.rbegin();
            for (; step != path.rend() && here->has_children(); ++step)
              here = here->child(*step);
            if (here->has_children())
              {
                ++missing;
                continue;
              }
            const typename DoFHandler<dim>::active_cell_iterator source(
              &mesh, here->level(), here->index(), &dof_handler);
            source->get_dof_values(u_here, cu);
            source->get_dof_values(udot_here, cv);
            for (; step != path.rend(); ++step)
              {
                const auto &prolongation = fe.get_prolongation_matrix(
                  *step, RefinementCase<dim>::isotropic_refinement);
                prolongation.vmult(tmp, cu);
                cu = tmp;
                prolongation.vmult(tmp, cv);
                cv = tmp;
              }
            values_ref.reinit(cell);
            // this run's element on the reference's cell: the reference's
            // shape functions if the elements are the same
            FEValues<dim> &values = same_element ? values_ref : values_own;
            if (!same_element)
              values_own.reinit(
                typename Triangulation<dim>::cell_iterator(cell));
            values[displacement].get_function_values_from_local_dof_values(
              make_array_view(cv), v2);
            values[displacement].get_function_gradients_from_local_dof_values(
              make_array_view(cu), g2);
            add(cell);
          }
        AssertThrow(missing == 0,
                    ExcMessage("Reference solution: this run's mesh is finer "
                               "than the reference's (" +
                               mesh_file +
                               ") somewhere: the reference must be a "
                               "refinement of it."));
        return std::sqrt(local);
      }

    // on several ranks: this run's state on a copy of its mesh, refined to
    // the other's (p4est moves the cells between the ranks)
    ComparedState<dim> own(dof_handler.get_triangulation(),
                           dof_handler.get_fe().degree);
    own.distribute();
    {
      Vector<double>                       values(own.fe->n_dofs_per_cell());
      std::vector<types::global_dof_index> indices(own.fe->n_dofs_per_cell());
      for (const auto &cell : own.dofs->active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const auto here =
              dof_handler.get_triangulation().create_cell_iterator(cell->id());
            const typename DoFHandler<dim>::active_cell_iterator source(
              &dof_handler.get_triangulation(),
              here->level(),
              here->index(),
              &dof_handler);
            cell->get_dof_indices(indices);
            for (auto [in, out] :
                 {std::pair<const VectorType *, VectorType *>{&u, &own.u},
                  {&udot, &own.udot}})
              {
                source->get_dof_values(*in, values);
                for (unsigned int i = 0; i < indices.size(); ++i)
                  if (own.dofs->locally_owned_dofs().is_element(indices[i]))
                    (*out)(indices[i]) = values[i];
              }
          }
      own.u.compress(VectorOperation::insert);
      own.udot.compress(VectorOperation::insert);
    }

    // the cells refined in each cycle are the same as long as both meshes
    // are: a signature of this run's mesh (its cells' ids) and the other's
    // file
    double signature = 0.;
    for (const auto &cell :
         dof_handler.get_triangulation().active_cell_iterators())
      if (cell->is_locally_owned())
        signature += std::hash<std::string>()(cell->id().to_string()) % 1000003;
    const std::string cycles_key =
      mesh_file + "/" +
      std::to_string(dof_handler.get_triangulation().n_global_active_cells()) +
      "/" + std::to_string(Utilities::MPI::sum(signature, comm));
    const bool known = cycles_key == refinement_key;
    if (known)
      for (const auto &cycle : refinement_cycles)
        {
          for (const auto &id : cycle)
            own.triangulation->create_cell_iterator(id)->set_refine_flag();
          own.refine();
        }
    else
      {
        refinement_key = cycles_key;
        refinement_cycles.clear();
      }
    // refine where the other mesh is finer: its level at a point of each
    // cell that no refinement puts on a face (1/3 is no dyadic fraction)
    while (!known)
      {
        std::vector<Point<dim>>                                        points;
        std::vector<typename Triangulation<dim>::active_cell_iterator> cells;
        Point<dim>                                                     third;
        for (unsigned int d = 0; d < dim; ++d)
          third[d] = 1. / 3.;
        for (const auto &cell : own.triangulation->active_cell_iterators())
          if (cell->is_locally_owned())
            {
              points.push_back(
                mapping.transform_unit_to_real_cell(cell, third));
              cells.push_back(cell);
            }
        Utilities::MPI::RemotePointEvaluation<dim> evaluation;
        evaluation.reinit(points, *ref.triangulation, mapping);
        stop_with_any_message(
          evaluation.all_points_found() ?
            "" :
            "Reference solution: the reference state '" + mesh_file +
              "' does not cover this run's mesh (another coarse mesh?).",
          comm);
        std::vector<double>       levels, buffer;
        const Triangulation<dim> &other = *ref.triangulation;
        evaluation.template evaluate_and_process<double>(
          levels,
          buffer,
          [&](
            const ArrayView<double> &values,
            const typename Utilities::MPI::RemotePointEvaluation<dim>::CellData
              &data) {
            for (unsigned int c = 0; c < data.cells.size(); ++c)
              for (unsigned int q = data.reference_point_ptrs[c];
                   q < data.reference_point_ptrs[c + 1];
                   ++q)
                values[q] = typename Triangulation<dim>::cell_iterator(
                              &other, data.cells[c].first, data.cells[c].second)
                              ->level();
          });
        const auto &ptrs   = evaluation.get_point_ptrs();
        unsigned    marked = 0;
        std::string finer;
        for (unsigned int i = 0; i < cells.size(); ++i)
          {
            double level = 0;
            for (unsigned int j = ptrs[i]; j < ptrs[i + 1]; ++j)
              level = std::max(level, levels[j]);
            if (level > cells[i]->level())
              {
                cells[i]->set_refine_flag();
                ++marked;
              }
            else if (level < cells[i]->level() && finer.empty())
              finer =
                "Reference solution: this run's mesh is finer than the reference's (" +
                mesh_file + ") at level " + std::to_string(cells[i]->level()) +
                ": the reference must be a refinement of it.";
          }
        stop_with_any_message(finer, comm);
        if (Utilities::MPI::sum(marked, comm) == 0)
          break;
        refinement_cycles.emplace_back();
        for (const auto &cell : cells)
          if (cell->refine_flag_set())
            refinement_cycles.back().push_back(cell->id());
        own.refine();
      }

    FEValues<dim> values_own(mapping,
                             *own.fe,
                             quadrature,
                             update_values | update_gradients);
    const auto [u_own, v_own] = own.ghosted();
    for (const auto &cell : ref.dofs->active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const auto match =
            own.triangulation->create_cell_iterator(cell->id());
          if (!match->is_active() || !match->is_locally_owned())
            {
              ++missing;
              continue;
            }
          const typename DoFHandler<dim>::active_cell_iterator other(
            own.triangulation.get(),
            match->level(),
            match->index(),
            own.dofs.get());
          values_ref.reinit(cell);
          values_own.reinit(other);
          values_own[displacement].get_function_values(v_own, v2);
          values_own[displacement].get_function_gradients(u_own, g2);
          add(cell);
        }
    stop_with_any_message(
      missing == 0 ? "" :
                     "Reference solution: the reference state '" + mesh_file +
                       "' has cells that this run's refined mesh does not "
                       "hold on the same rank (a mesh of another coarse mesh, "
                       "or refined otherwise).",
      comm);
    return std::sqrt(Utilities::MPI::sum(local, comm));
  }

  template class StateComparison<2>;
  template class StateComparison<3>;
} // namespace dyncontact
