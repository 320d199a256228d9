#ifndef dyncontact_output_vtu_writer_h
#define dyncontact_output_vtu_writer_h

#include <dyncontact/core/simulator_access.h>
#include <dyncontact/output/output_parameters.h>

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace dyncontact
{
  /**
   * VTU output for ParaView: solution_NNNNN.pvtu (one .vtu per rank) with
   * displacement, velocity, von Mises stress, the nodal contact fields
   * (pressure on both sides, active and critical sets, gap), subdomain and
   * refinement level, and solution.pvd listing every output with its time.
   */
  template <int dim>
  class VtuWriter : public SimulatorAccess<dim>
  {
  public:
    /// The Output entries that a run without VTU files does not read.
    std::vector<std::pair<std::string, std::string>>
    unread_entries() const
    {
      if (write_vtu)
        return {};
      return {{"Output/Compression", "Output/Write vtu = false"},
              {"Output/Cells per piece", "Output/Write vtu = false"}};
    }

    /// Takes Output/Write vtu, Compression and Cells per piece (handed by
    /// their owner, OutputParameters).
    explicit VtuWriter(const OutputParameters &parameters);

    bool
    is_enabled() const
    {
      return write_vtu;
    }

    /// Writes the current state at @p time (collective).
    void
    write(const double time);

    /// Removes the files solution_<n>.pvtu and solution_<n>.<piece>.vtu with
    /// n from the first number this run writes on (an earlier run's, or
    /// the interrupted run's after the checkpoint a resumed run starts
    /// from), and, if this run writes no VTU, solution.pvd: so that the
    /// output directory holds this run's files only. Says how many it
    /// removed. Collective; stops the run if a file cannot be removed.
    void
    remove_later_files() const;

    /// The output counter and the .pvd history (checkpoints).
    void
    save(std::map<std::string, std::string> &state) const;
    void
    load(const std::map<std::string, std::string> &state);

  private:
    bool write_vtu = true;
    /// DataOutBase::VtkFlags::ZlibCompressionLevel
    int                                         compression     = 0;
    unsigned int                                cells_per_piece = 65536;
    unsigned int                                output_counter  = 0;
    std::vector<std::pair<double, std::string>> pvd_records;
  };
} // namespace dyncontact

#endif
