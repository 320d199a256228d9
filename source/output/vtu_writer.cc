#include <deal.II/base/utilities.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <dyncontact/base/collective_errors.h>
#include <dyncontact/base/global_parameters.h>
#include <dyncontact/base/triangulation.h>
#include <dyncontact/contact/contact_setup.h>
#include <dyncontact/discretization/semi_discrete_system.h>
#include <dyncontact/output/vtu_writer.h>
#include <dyncontact/time_stepping/row_force.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <sstream>

namespace dyncontact
{
  namespace
  {
    /// Von Mises stress of the elastic stress 2 mu eps + lambda tr(eps) I.
    template <int dim>
    class VonMisesPostprocessor : public DataPostprocessorScalar<dim>
    {
    public:
      explicit VonMisesPostprocessor(const Scene<dim> &scene)
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



    /// The nodal contact fields on the scalar FE_Q, with ghost entries.
    struct NodalContactFields
    {
      TrilinosWrappers::MPI::Vector pressure, active, critical, gap;
    };



    /// The nodal contact fields of the @p contact rows after the step that
    /// @p report describes, with the displacement @p solution: pressure on
    /// both sides (the master side gets each row's force through the
    /// weights N_j of its image point), active and critical sets and the
    /// current gap g_p - (C u)_p on the slave side. Collective.
    template <int dim>
    NodalContactFields
    nodal_contact_fields(const SemiDiscreteSystem<dim> &system,
                         const ContactSetup<dim>       &contact,
                         const StepReport              &report,
                         const VectorType              &solution,
                         const MPI_Comm                 comm)
    {
      const ContactRows &rows                    = contact.get_rows();
      const auto        &scalar                  = system.scalar_dofs();
      const auto        &scalar_locally_owned    = scalar.locally_owned;
      const auto        &scalar_locally_relevant = scalar.locally_relevant;
      // the scalar DoF of each locally owned node by its component-0 DoF
      // (a row's slave node is owned here, its first entry that DoF)
      const IndexSet                      &owned = system.locally_owned_dofs();
      std::vector<types::global_dof_index> scalar_of(owned.n_elements());
      for (const auto &[dof0, scalar_dof] : scalar.owned_system0_to_scalar)
        scalar_of[owned.index_within_set(dof0)] = scalar_dof;

      VectorType master_force(system.locally_owned_dofs(), comm);
      const auto violation =
        contact.get_row_operator().constraint_values(solution);
      TrilinosWrappers::MPI::Vector pressure(scalar_locally_owned, comm),
        active(scalar_locally_owned, comm),
        critical(scalar_locally_owned, comm), gap(scalar_locally_owned, comm);
      for (unsigned int p = 0; p < rows.size(); ++p)
        {
          const double force = row_force(report, p);
          const auto   node =
            scalar_of[owned.index_within_set(rows.rows[p].entries[0].first)];
          pressure(node) = force / rows.rows[p].weight;
          active(node)   = report.active[p];
          critical(node) = report.critical[p];
          gap(node)      = -violation[p];
          for (const auto &[dof0, N] : rows.rows[p].master_nodes)
            master_force(dof0) += N * force;
        }
      master_force.compress(VectorOperation::add);
      for (const auto &[dof0, scalar_dof] : scalar.owned_system0_to_scalar)
        if (master_force(dof0) != 0.)
          pressure(scalar_dof) =
            master_force(dof0) / system.get_boundary_weights()(dof0);
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
      return {std::move(pressure_g),
              std::move(active_g),
              std::move(critical_g),
              std::move(gap_g)};
    }



    /// This rank's subdomain id on every active cell of @p triangulation
    /// (cell data).
    template <int dim>
    Vector<float>
    subdomains(const Triangulation<dim> &triangulation)
    {
      // (a serial triangulation has no subdomain of its own: 0)
      const auto   *distributed = as_distributed(triangulation);
      Vector<float> subdomain(triangulation.n_active_cells());
      subdomain = distributed ? distributed->locally_owned_subdomain() : 0;
      return subdomain;
    }



    /// The refinement level of every locally owned active cell of
    /// @p triangulation (cell data, 0 on the other cells).
    template <int dim>
    Vector<float>
    refinement_levels(const Triangulation<dim> &triangulation)
    {
      Vector<float> level(triangulation.n_active_cells());
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->is_locally_owned())
          level(cell->active_cell_index()) = cell->level();
      return level;
    }



    /**
     * The fields of one output, computed once and added to the DataOut of
     * each of its pieces: displacement, velocity, von Mises stress, the
     * nodal contact fields (nodal_contact_fields()), subdomain and
     * refinement level.
     */
    template <int dim>
    class OutputFields
    {
    public:
      /// The fields of the state that @p access sees. Collective.
      explicit OutputFields(const SimulatorAccess<dim> &access)
        : system(access.get_system())
        , scene(access.get_scene())
        , u_ghosted(system.ghosted(access.get_solution()))
        , v_ghosted(system.ghosted(access.get_velocity()))
        , contact(nodal_contact_fields(system,
                                       access.get_contact(),
                                       access.get_step_report(),
                                       access.get_solution(),
                                       access.get_mpi_communicator()))
        , subdomain(subdomains(access.get_triangulation()))
        , level(refinement_levels(access.get_triangulation()))
        , von_mises(scene)
        , vector_field(dim,
                       DataComponentInterpretation::component_is_part_of_vector)
      {}

      /// Adds the fields to @p data_out (collective: the ghost entries of
      /// the distributed vectors are exchanged).
      void
      add_to(DataOut<dim> &data_out) const
      {
        data_out.add_data_vector(system.get_dof_handler(),
                                 u_ghosted,
                                 std::vector<std::string>(dim, "displacement"),
                                 vector_field);
        data_out.add_data_vector(system.get_dof_handler(),
                                 v_ghosted,
                                 std::vector<std::string>(dim, "velocity"),
                                 vector_field);
        data_out.add_data_vector(system.get_dof_handler(),
                                 u_ghosted,
                                 von_mises);
        const DoFHandler<dim> &scalar = system.scalar_dofs().dof_handler;
        data_out.add_data_vector(scalar, contact.pressure, "contact_pressure");
        data_out.add_data_vector(scalar, contact.active, "active_set");
        data_out.add_data_vector(scalar, contact.critical, "critical_set");
        if (!scene.contact_pairs().empty())
          data_out.add_data_vector(scalar, contact.gap, "gap");
        data_out.add_data_vector(subdomain, "subdomain");
        data_out.add_data_vector(level, "refinement_level");
      }

    private:
      const SemiDiscreteSystem<dim> &system;
      const Scene<dim>              &scene;
      /// Displacement and velocity with ghost entries.
      const VectorType         u_ghosted, v_ghosted;
      const NodalContactFields contact;
      /// Cell data: subdomains() and refinement_levels().
      const Vector<float>              subdomain, level;
      const VonMisesPostprocessor<dim> von_mises;
      const std::vector<
        DataComponentInterpretation::DataComponentInterpretation>
        vector_field;
    };



    /**
     * The rank's cells are written in pieces of at most 'Cells per piece'
     * cells, each from its own patches: the memory a write needs beyond the
     * run's is that of one piece (0.4 GB for the 338 000 cells of a 3D mesh
     * with 1e6 DoFs in one piece).
     */
    template <int dim>
    struct Pieces
    {
      /// Piece k of the rank's cells starts at the cell first_cell[k] and
      /// ends before the active cell index end_index[k].
      std::vector<typename Triangulation<dim>::active_cell_iterator> first_cell;
      std::vector<unsigned int>                                      end_index;
      /// The pieces are numbered over all ranks, rank by rank: with one
      /// piece per rank, piece number = rank (the names deal.II's
      /// write_vtu_with_pvtu_record() gives). The number of this rank's
      /// first piece and the number of pieces over all ranks.
      unsigned int my_first_piece = 0, n_global_pieces = 0;
      /// Adding a distributed vector to a DataOut is collective (its ghost
      /// entries are exchanged): every rank takes part in as many rounds as
      /// the rank with the most pieces, with no cells selected once its own
      /// pieces are written.
      unsigned int n_rounds = 0;

      /// Whether this rank has a piece @p k.
      bool
      has_piece(const unsigned int k) const
      {
        return k < first_cell.size();
      }
    };



    /// The locally owned cells of @p triangulation in pieces of at most
    /// @p cells_per_piece cells, numbered over all ranks. Collective.
    template <int dim>
    Pieces<dim>
    split_into_pieces(const Triangulation<dim> &triangulation,
                      const unsigned int        cells_per_piece,
                      const MPI_Comm            comm)
    {
      Pieces<dim>  pieces;
      unsigned int n_owned = 0;
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->is_locally_owned() && n_owned++ % cells_per_piece == 0)
          {
            if (!pieces.first_cell.empty())
              pieces.end_index.push_back(cell->active_cell_index());
            pieces.first_cell.push_back(cell);
          }
      pieces.end_index.push_back(triangulation.n_active_cells());
      // (a rank without cells writes no piece: ParaView complains about a
      // piece without points)
      const unsigned int              n_pieces = pieces.first_cell.size();
      const std::vector<unsigned int> pieces_of_rank =
        Utilities::MPI::all_gather(comm, n_pieces);
      const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
      for (unsigned int r = 0; r < pieces_of_rank.size(); ++r)
        {
          if (r == rank)
            pieces.my_first_piece = pieces.n_global_pieces;
          pieces.n_global_pieces += pieces_of_rank[r];
        }
      pieces.n_rounds =
        *std::max_element(pieces_of_rank.begin(), pieces_of_rank.end());
      return pieces;
    }



    /// Selects for @p data_out the cells of piece @p k of @p pieces: the
    /// locally owned active cells of @p triangulation from first_cell[k] on,
    /// with an active cell index below end_index[k] (none if this rank has
    /// no piece @p k).
    template <int dim>
    void
    select_piece(DataOut<dim>             &data_out,
                 const Triangulation<dim> &triangulation,
                 const Pieces<dim>        &pieces,
                 const unsigned int        k)
    {
      using active_cell_iterator =
        typename Triangulation<dim>::active_cell_iterator;
      using cell_iterator     = typename Triangulation<dim>::cell_iterator;
      const bool         mine = pieces.has_piece(k);
      const unsigned int end  = mine ? pieces.end_index[k] : 0;
      const auto         next_owned = [end](const Triangulation<dim> &tria,
                                    active_cell_iterator      cell) {
        for (; cell != tria.end() && cell->active_cell_index() < end; ++cell)
          if (cell->is_locally_owned())
            return cell_iterator(cell);
        return cell_iterator(tria.end());
      };
      const active_cell_iterator first =
        mine ? pieces.first_cell[k] : active_cell_iterator(triangulation.end());
      data_out.set_cell_selection(
        [first, next_owned](const Triangulation<dim> &tria) {
          return next_owned(tria, first);
        },
        [next_owned](const Triangulation<dim> &tria,
                     const cell_iterator      &cell) {
          active_cell_iterator next(cell);
          return next_owned(tria, ++next);
        });
    }



    /// Writes the file @p name with @p write unless @p failure already
    /// holds the first file this rank could not write; if @p name cannot be
    /// opened, written (@p write throws) or closed, @p failure becomes
    /// write_failure() of it.
    void
    write_file(std::string                               &failure,
               const std::string                         &name,
               const std::function<void(std::ostream &)> &write)
    {
      if (!failure.empty())
        return;
      errno = 0;
      std::ofstream out(name);
      if (out)
        try
          {
            write(out);
          }
        catch (const ExceptionBase &)
          {
            out.setstate(std::ios::failbit);
          }
      out.close();
      if (!out.good())
        failure = write_failure(name);
    }
  } // namespace



  template <int dim>
  VtuWriter<dim>::VtuWriter(const OutputParameters &parameters)
  {
    write_vtu       = parameters.write_vtu;
    compression     = parameters.compression == "none" ?
                        DataOutBase::VtkFlags::no_compression :
                      parameters.compression == "fast" ?
                        DataOutBase::VtkFlags::best_speed :
                        DataOutBase::VtkFlags::best_compression;
    cells_per_piece = parameters.cells_per_piece;
  }



  template <int dim>
  void
  VtuWriter<dim>::write(const double time)
  {
    TimerOutput::Scope t(this->get_timer(), "output");
    const MPI_Comm     comm          = this->get_mpi_communicator();
    const auto        &triangulation = this->get_triangulation();

    const OutputFields<dim> fields(*this);
    DataOutBase::VtkFlags   flags;
    flags.compression_level =
      static_cast<DataOutBase::VtkFlags::ZlibCompressionLevel>(compression);

    const Pieces<dim> pieces =
      split_into_pieces(triangulation, cells_per_piece, comm);
    const std::string directory = this->get_parameters().output_directory;
    const std::string stem =
      "solution_" + Utilities::int_to_string(output_counter, 5);
    const std::string  base = stem + ".";
    const std::string  pvtu = stem + ".pvtu";
    const unsigned int n_digits =
      Utilities::needed_digits(std::max(0, int(pieces.n_global_pieces) - 1));
    const unsigned int rank = Utilities::MPI::this_mpi_process(comm);

    // the first file this rank could not write, and why
    std::string failure;
    for (unsigned int k = 0; k < pieces.n_rounds; ++k)
      {
        const bool   mine = pieces.has_piece(k);
        DataOut<dim> data_out;
        data_out.attach_triangulation(triangulation);
        select_piece(data_out, triangulation, pieces, k);
        fields.add_to(data_out);
        data_out.build_patches(this->get_mapping(),
                               this->get_system().get_fe().degree);
        data_out.set_flags(flags);
        if (mine)
          write_file(failure,
                     directory + "/" + base +
                       Utilities::int_to_string(pieces.my_first_piece + k,
                                                n_digits) +
                       ".vtu",
                     [&](std::ostream &out) { data_out.write_vtu(out); });
        if (rank == 0 && k == 0)
          {
            // the record of all pieces: any piece's DataOut knows the fields
            std::vector<std::string> piece_names;
            for (unsigned int i = 0; i < pieces.n_global_pieces; ++i)
              piece_names.push_back(
                base + Utilities::int_to_string(i, n_digits) + ".vtu");
            write_file(failure, directory + "/" + pvtu, [&](std::ostream &out) {
              data_out.write_pvtu_record(out, piece_names);
            });
          }
      }
    // (on every rank: a rank that stopped alone would leave the others
    // waiting in the next collective call)
    stop_with_any_message(failure, comm);
    ++output_counter;
    pvd_records.emplace_back(time, pvtu);
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      write_file(failure, directory + "/solution.pvd", [&](std::ostream &out) {
        DataOutBase::write_pvd_record(out, pvd_records);
      });
    stop_with_message_of_rank_0(failure, comm);
  }



  namespace
  {
    /// n of a file solution_<n>.pvtu or solution_<n>.<piece>.vtu (digits
    /// only), -1 for any other name.
    long long
    solution_file_number(const std::string &name)
    {
      const auto digits = [](const std::string &text) {
        return !text.empty() &&
               text.find_first_not_of("0123456789") == std::string::npos;
      };
      const std::size_t dot = name.find('.');
      if (name.rfind("solution_", 0) != 0 || dot == std::string::npos ||
          !digits(name.substr(9, dot - 9)) || dot - 9 > 18)
        return -1;
      const std::string rest   = name.substr(dot + 1);
      const std::size_t second = rest.find('.');
      if (rest == "pvtu" ||
          (second != std::string::npos && digits(rest.substr(0, second)) &&
           rest.substr(second) == ".vtu"))
        return std::stoll(name.substr(9, dot - 9));
      return -1;
    }
  } // namespace



  template <int dim>
  void
  VtuWriter<dim>::remove_later_files() const
  {
    namespace fs                = std::filesystem;
    const MPI_Comm    comm      = this->get_mpi_communicator();
    const std::string directory = this->get_parameters().output_directory;
    std::string       failure;
    unsigned int      n_removed = 0;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        std::vector<fs::path> later;
        std::error_code       error;
        for (fs::directory_iterator entry(directory, error), end;
             !error && entry != end;
             entry.increment(error))
          {
            const std::string name = entry->path().filename().string();
            const long long   n    = solution_file_number(name);
            if ((n >= 0 &&
                 static_cast<unsigned long long>(n) >= output_counter) ||
                (name == "solution.pvd" && !write_vtu))
              later.push_back(entry->path());
          }
        if (error)
          failure = "Cannot list the output directory '" + directory +
                    "': " + error.message() + ".";
        for (const fs::path &file : later)
          if (fs::remove(file, error))
            ++n_removed;
          else if (error && failure.empty())
            failure = "Cannot remove '" + file.string() +
                      "', a file of an earlier run: " + error.message() + ".";
      }
    stop_with_message_of_rank_0(failure, comm);
    if (n_removed > 0)
      this->get_pcout() << "   removed " << n_removed
                        << " solution files of an earlier run from '"
                        << directory << "'" << std::endl;
  }



  template <int dim>
  void
  VtuWriter<dim>::save(std::map<std::string, std::string> &state) const
  {
    std::ostringstream s;
    s << std::setprecision(17) << output_counter << " " << pvd_records.size()
      << "\n";
    for (const auto &[t, file] : pvd_records)
      s << t << " " << file << "\n";
    state["vtu_output"] = s.str();
  }



  template <int dim>
  void
  VtuWriter<dim>::load(const std::map<std::string, std::string> &state)
  {
    std::istringstream s(state.at("vtu_output"));
    std::size_t        n = 0;
    s >> output_counter >> n;
    AssertThrow(!s.fail() && n <= output_counter,
                ExcMessage("the output history in the checkpoint is damaged"));
    pvd_records.resize(n);
    for (auto &[t, file] : pvd_records)
      s >> t >> file;
    AssertThrow(!s.fail(),
                ExcMessage("the output history in the checkpoint is damaged"));
  }

  template class VtuWriter<2>;
  template class VtuWriter<3>;
} // namespace dyncontact
