// Checkpoint and restart: the triangulation with u and udot attached (p4est's
// save/load, so a run may resume on another number of ranks), and a state
// file with everything else a resumed run needs to continue exactly as the
// uninterrupted one would (time, tau, accumulators, warm-start active sets,
// output history, the statistics so far, the critical parameters).
// A checkpoint is written to a new folder and only then marked as the last
// good one (an atomic rename of checkpoints/last), so a crash while writing
// leaves the previous checkpoint usable.

#include <deal.II/base/utilities.h>
#include <deal.II/distributed/solution_transfer.h>

#include <dyncontact/simulator.h>

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace dyncontact
{
  namespace
  {
    std::string
    flags(const std::vector<char> &active)
    {
      std::string text(active.size(), '0');
      for (unsigned int p = 0; p < active.size(); ++p)
        text[p] = active[p] ? '1' : '0';
      return text.empty() ? "-" : text;
    }

    std::vector<char>
    unflag(const std::string &text)
    {
      std::vector<char> active;
      if (text != "-")
        for (const char c : text)
          active.push_back(c == '1');
      return active;
    }
  } // namespace



  template <int dim>
  std::string
  Simulator<dim>::checkpoint_root() const
  {
    return parameters.output_directory + "/checkpoints";
  }



  template <int dim>
  std::string
  Simulator<dim>::write_checkpoint(const unsigned int step,
                                   const double       time,
                                   const double       next_output)
  {
    TimerOutput::Scope t(*timer, "checkpoint");
    const bool         root = Utilities::MPI::this_mpi_process(comm) == 0;
    const std::string  name = "step_" + Utilities::int_to_string(step, 7);
    const std::string  dir  = checkpoint_root() + "/" + name;
    if (root)
      {
        std::filesystem::remove_all(dir);
        std::filesystem::create_directories(dir);
      }
    MPI_Barrier(comm);

    VectorType u_ghosted(locally_owned, locally_relevant, comm);
    VectorType v_ghosted(locally_owned, locally_relevant, comm);
    u_ghosted = u;
    v_ghosted = udot;
    parallel::distributed::SolutionTransfer<dim, VectorType> transfer(
      dof_handler);
    transfer.prepare_for_serialization(
      std::vector<const VectorType *>{&u_ghosted, &v_ghosted});
    triangulation.save(dir + "/mesh");

    if (root)
      {
        std::ofstream out(dir + "/state.txt");
        out << std::setprecision(17);
        const auto [displacement_active, projection_active] =
          integrator->active_sets();
        out << "step " << step << "\ntime " << time << "\ntau "
            << integrator->time_step() << "\nnext_output " << next_output
            << "\nviscous_dissipation " << viscous_dissipation
            << "\ncritical_measure_sum " << critical_measure_sum
            << "\nenergy_transfer " << energy_transfer
            << "\ntransfer_penetration " << transfer_penetration
            << "\noutput_counter " << output_counter << "\ndisplacement_active "
            << flags(displacement_active) << "\nprojection_active "
            << flags(projection_active) << "\npvd " << pvd_records.size()
            << "\n";
        for (const auto &[t, file] : pvd_records)
          out << t << " " << file << "\n";
        out << "critical_parameters\n"
            << parameters.critical_parameters << "end_critical_parameters\n";
        out << "statistics " << statistics.rows.size() << "\n";
        for (const auto &row : statistics.rows)
          {
            for (unsigned int c = 0; c < row.size(); ++c)
              out << (c ? " " : "") << row[c];
            out << "\n";
          }
        out.close();
        AssertThrow(out.good(),
                    ExcMessage("Cannot write the checkpoint '" + dir + "'."));
        // mark it as the last good checkpoint (atomically), then remove all
        // but the previous one
        std::string previous;
        if (std::ifstream last(checkpoint_root() + "/last"); last.good())
          std::getline(last, previous);
        std::ofstream(checkpoint_root() + "/last.tmp") << name << "\n";
        std::filesystem::rename(checkpoint_root() + "/last.tmp",
                                checkpoint_root() + "/last");
        for (const auto &entry :
             std::filesystem::directory_iterator(checkpoint_root()))
          if (entry.is_directory() && entry.path().filename() != name &&
              entry.path().filename() != previous)
            std::filesystem::remove_all(entry.path());
      }
    MPI_Barrier(comm);
    return dir;
  }



  template <int dim>
  void
  Simulator<dim>::resume_from_checkpoint(unsigned int &step,
                                         double       &time,
                                         double       &next_output)
  {
    std::string name;
    {
      std::ifstream last(checkpoint_root() + "/last");
      AssertThrow(last.good(),
                  ExcMessage(
                    "Checkpointing/Resume: there is no checkpoint in '" +
                    checkpoint_root() +
                    "' (the file 'last' that marks the last good "
                    "one is missing)."));
      std::getline(last, name);
    }
    const std::string dir = checkpoint_root() + "/" + name;
    std::ifstream     in(dir + "/state.txt");
    AssertThrow(in.good(),
                ExcMessage("Checkpointing/Resume: the checkpoint '" + dir +
                           "' has no readable state.txt."));

    std::string key;
    double      tau = 0.;
    std::string displacement_active, projection_active;
    std::size_t n_pvd = 0;
    in >> key >> step >> key >> time >> key >> tau >> key >> next_output >>
      key >> viscous_dissipation >> key >> critical_measure_sum >> key >>
      energy_transfer >> key >> transfer_penetration >> key >> output_counter >>
      key >> displacement_active >> key >> projection_active >> key >> n_pvd;
    pvd_records.resize(n_pvd);
    for (auto &[t, file] : pvd_records)
      in >> t >> file;
    in >> key;
    AssertThrow(in.good() && key == "critical_parameters",
                ExcMessage("Checkpointing/Resume: the checkpoint '" + dir +
                           "' is damaged."));
    in.ignore();
    std::string saved, line;
    while (std::getline(in, line) && line != "end_critical_parameters")
      saved += line + "\n";

    // refuse a prm whose critical parameters differ
    if (saved != parameters.critical_parameters)
      {
        std::istringstream a(saved), b(parameters.critical_parameters);
        std::string        la, lb;
        while (std::getline(a, la) && std::getline(b, lb) && la == lb)
          ;
        AssertThrow(false,
                    ExcMessage("Checkpointing/Resume: this input differs from "
                               "the checkpoint's in a parameter that must not "
                               "change (everything but End time, Output and "
                               "Checkpointing may not): the checkpoint has '" +
                               la + "', this input '" + lb + "'."));
      }

    std::size_t n_rows = 0;
    in >> key >> n_rows;
    statistics.rows.assign(n_rows,
                           std::vector<double>(statistics.columns.size()));
    for (auto &row : statistics.rows)
      for (double &value : row)
        in >> value;
    AssertThrow(!in.fail(),
                ExcMessage("Checkpointing/Resume: the checkpoint '" + dir +
                           "' is damaged."));

    // the mesh and the state
    triangulation.load(dir + "/mesh");
    setup_system();
    parallel::distributed::SolutionTransfer<dim, VectorType> transfer(
      dof_handler);
    std::vector<VectorType *> out = {&u, &udot};
    transfer.deserialize(out);
    assemble_system();
    make_contact_rows();
    current_tau = tau;
    make_integrator();
    integrator->warm_start(unflag(displacement_active),
                           unflag(projection_active));

    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        statistics_file.open(parameters.output_directory + "/statistics.tsv");
        statistics.write_header(statistics_file);
        for (const auto &row : statistics.rows)
          statistics.write_row(statistics_file, row);
        statistics_file.flush();
      }
    pcout << "   resumed from " << dir << " at step " << step
          << ", t = " << time << " s" << std::endl;
  }

  template std::string
  Simulator<2>::checkpoint_root() const;
  template std::string
  Simulator<3>::checkpoint_root() const;
  template std::string
  Simulator<2>::write_checkpoint(const unsigned int,
                                 const double,
                                 const double);
  template std::string
  Simulator<3>::write_checkpoint(const unsigned int,
                                 const double,
                                 const double);
  template void
  Simulator<2>::resume_from_checkpoint(unsigned int &, double &, double &);
  template void
  Simulator<3>::resume_from_checkpoint(unsigned int &, double &, double &);
} // namespace dyncontact
