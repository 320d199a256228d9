#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <dyncontact/base/checksum.h>
#include <dyncontact/base/collective_errors.h>
#include <dyncontact/output/checkpoint.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <vector>

namespace dyncontact
{
  namespace
  {
    /// @p text with every run of white space one space, and none beside
    /// the separators , ; : = or at the ends of a line.
    std::string
    canonical_form(const std::string &text)
    {
      std::string out;
      bool        space     = false;
      const auto  separator = [](const char c) {
        return c == ',' || c == ';' || c == ':' || c == '=' || c == '\n';
      };
      for (const char c : text)
        {
          if (c == ' ' || c == '\t' || c == '\r')
            {
              space = true;
              continue;
            }
          if (space && !out.empty() && !separator(out.back()) && !separator(c))
            out += ' ';
          space = false;
          out += c;
        }
      return out;
    }



    /// What a resumed run may change (the entries parse_parameters() leaves
    /// out of the critical parameters).
    const std::string changeable_on_resume =
      "End time, Time step adaptation, the Contact solver's Maximum "
      "active-set iterations and Maximum linear iterations, Output directory, "
      "subsection Output and subsection Checkpointing";

    /// The folder name in the file 'last' of the checkpoints in @p root,
    /// without leading and trailing blanks and carriage returns (a file
    /// written by hand may carry them); nullopt if there is no such file.
    /// Throws if 'last' is there but no regular file (a folder, or a FIFO,
    /// whose opening would block).
    std::optional<std::string>
    last_name(const std::string &root)
    {
      std::error_code error;
      const auto      status = std::filesystem::status(root + "/last", error);
      if (error || !std::filesystem::exists(status))
        return std::nullopt;
      AssertThrow(std::filesystem::is_regular_file(status),
                  ExcMessage("'" + root +
                             "/last' is not a regular file: it must be a "
                             "text file that names the last good "
                             "checkpoint's folder. Remove it."));
      std::ifstream last(root + "/last");
      if (!last.good())
        return std::nullopt;
      std::string name;
      std::getline(last, name);
      const auto first = name.find_first_not_of(" \t\r");
      if (first == std::string::npos)
        return "";
      return name.substr(first, name.find_last_not_of(" \t\r") + 1 - first);
    }
  } // namespace



  void
  Checkpoints::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Checkpointing");
    prm.declare_entry("Resume",
                      "false",
                      Patterns::Bool(),
                      "Continue from the last good checkpoint in <Output "
                      "directory>/checkpoints (the folder named in its file "
                      "'last'). The prm must agree with the checkpoint's in "
                      "everything but " +
                        changeable_on_resume + ".");
    prm.declare_entry("Interval in steps",
                      "0",
                      Patterns::Integer(0),
                      "Write a checkpoint every this many steps (0: not by "
                      "steps). Checkpoints go to <Output directory>/"
                      "checkpoints; each is written to a new folder and only "
                      "then marked as the last good one.");
    prm.declare_entry("Interval in minutes",
                      "0",
                      Patterns::Double(0.),
                      "Write a checkpoint when this much wall-clock time (in "
                      "minutes) has passed since the last one (0: not by "
                      "time).");
    prm.leave_subsection();
  }



  Checkpoints::Checkpoints(const MPI_Comm comm)
    : comm(comm)
  {}



  void
  Checkpoints::set_output_directory(const std::string &output_directory)
  {
    root = output_directory + "/checkpoints";
  }



  void
  Checkpoints::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Checkpointing");
    resume_run       = prm.get_bool("Resume");
    interval_steps   = prm.get_integer("Interval in steps");
    interval_minutes = prm.get_double("Interval in minutes");
    prm.leave_subsection();

    // the critical parameters: the whole input in a canonical form, less
    // what a resumed run may change
    critical_parameters.clear();
    std::ostringstream all;
    prm.print_parameters(all, ParameterHandler::ShortPRM);
    std::istringstream       in(all.str());
    std::vector<std::string> path;
    for (std::string line; std::getline(in, line);)
      {
        const auto first = line.find_first_not_of(' ');
        if (first == std::string::npos)
          continue;
        line = line.substr(first);
        if (line.rfind("subsection ", 0) == 0)
          path.push_back(line.substr(11));
        else if (line == "end")
          path.pop_back();
        else if (line.rfind("set ", 0) == 0)
          {
            const std::string entry = line.substr(4, line.find('=') - 4);
            // a resumed run may change the end time, the output, the
            // checkpointing, and the solver's limits (to get past a step
            // that failed)
            auto is = [&](const std::string &section, const std::string &name) {
              return path.size() == 1 && path[0] == section &&
                     entry.rfind(name, 0) == 0;
            };
            const bool skip =
              (!path.empty() &&
               (path[0] == "Output" || path[0] == "Checkpointing")) ||
              (path.empty() && entry.rfind("Output directory", 0) == 0) ||
              is("Time integration", "End time") ||
              is("Time integration", "Time step adaptation") ||
              is("Contact solver", "Maximum active-set iterations") ||
              is("Contact solver", "Maximum linear iterations");
            if (!skip)
              {
                std::string name;
                for (const auto &p : path)
                  name += p + "/";
                critical_parameters += name + line.substr(4) + "\n";
              }
          }
      }
  }



  std::string
  Checkpoints::begin(const unsigned int step) const
  {
    const std::string dir = root + "/step_" + Utilities::int_to_string(step, 7);
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        std::filesystem::remove_all(dir);
        std::filesystem::create_directories(dir);
      }
    MPI_Barrier(comm);
    return dir;
  }



  void
  Checkpoints::finish(const std::string                        &dir,
                      const std::map<std::string, std::string> &state) const
  {
    // rank 0 writes the state: what fails there stops every rank
    std::string failure;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      try
        {
          // key, length, value: values may hold anything (lines, spaces);
          // then the size and checksum of every other file, and the checksum
          // of all of this
          std::ostringstream text;
          text << "dyncontact-checkpoint 3\n";
          for (const auto &[key, value] : state)
            text << key << " " << value.size() << "\n" << value << "\n";
          text << "critical_parameters " << critical_parameters.size() << "\n"
               << critical_parameters << "\n";
          std::ostringstream files;
          for (const auto &entry : std::filesystem::directory_iterator(dir))
            if (entry.path().filename() != "state.txt")
              files << entry.path().filename().string() << " "
                    << entry.file_size() << " "
                    << checksum_of_file(entry.path().string()) << "\n";
          text << "files " << files.str().size() << "\n" << files.str() << "\n";
          std::ofstream out(dir + "/state.txt");
          out << text.str() << "checksum " << checksum_of_text(text.str())
              << "\n";
          out.close();
          AssertThrow(out.good(),
                      ExcMessage("Cannot write the checkpoint '" + dir + "'."));
          // mark it as the last good checkpoint (atomically), then remove all
          // but the previous one
          const std::string name     = std::filesystem::path(dir).filename();
          const std::string previous = last_name(root).value_or("");
          // (a link or FIFO left there is replaced, not written through)
          std::error_code ignored;
          if (!std::filesystem::is_directory(
                std::filesystem::symlink_status(root + "/last.tmp", ignored)))
            std::filesystem::remove(root + "/last.tmp", ignored);
          std::ofstream last(root + "/last.tmp");
          last << name << "\n";
          last.close();
          AssertThrow(last.good(),
                      ExcMessage("Cannot write the checkpoint '" + dir +
                                 "' (its mark " + root + "/last.tmp)."));
          std::filesystem::rename(root + "/last.tmp", root + "/last");
          for (const auto &entry : std::filesystem::directory_iterator(root))
            if (entry.is_directory() && entry.path().filename() != name &&
                entry.path().filename() != previous)
              std::filesystem::remove_all(entry.path());
        }
      catch (const std::exception &e)
        {
          failure = message_of(e);
        }
    stop_with_message_of_rank_0(failure, comm);
  }



  std::string
  Checkpoints::last_directory() const
  {
    // rank 0 reads 'last' and, without it, looks for what to advise; every
    // rank stops with its message
    std::string name, failure;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      try
        {
          const std::optional<std::string> last = last_name(root);
          if (last.has_value() && !last->empty())
            name = *last;
          else
            {
              // (a 'last' lost while checkpoints that pass the checks are
              // there: the newest of them is named, not taken without
              // being asked)
              std::string advice = ".";
              try
                {
                  advice = advice_beside("");
                }
              catch (const std::exception &)
                {}
              failure = "Checkpointing/Resume: the file '" + root +
                        "/last', which names the checkpoint to resume from, "
                        "is " +
                        (last.has_value() ? "empty" : "missing") + advice;
            }
        }
      catch (const std::exception &e)
        {
          failure = "Checkpointing/Resume: " + message_of(e);
        }
    stop_with_message_of_rank_0(failure, comm);
    return root + "/" + Utilities::MPI::broadcast(comm, name, 0);
  }



  std::map<std::string, std::string>
  Checkpoints::read_state(const std::string &dir) const
  {
    // rank 0 verifies every file of the checkpoint before anything is read
    // (what throws there becomes the message, which every rank then stops
    // with, instead of rank 0 alone)
    std::string problem;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      try
        {
          problem = verify(dir);
          if (!problem.empty())
            problem += advice_beside(dir);
        }
      catch (const std::exception &e)
        {
          problem = message_of(e);
        }
    stop_with_message_of_rank_0(problem.empty() ?
                                  problem :
                                  "Checkpointing/Resume: the checkpoint '" +
                                    dir + "' cannot be used: " + problem,
                                comm);

    std::ifstream in(dir + "/state.txt");
    const auto  damaged = ExcMessage("Checkpointing/Resume: the checkpoint '" +
                                    dir + "' is damaged.");
    std::string header;
    std::getline(in, header);
    std::map<std::string, std::string> state;
    std::string                        key;
    std::size_t                        length = 0;
    while (in >> key >> length)
      {
        if (key == "checksum")
          break;
        AssertThrow(length < (std::size_t(1) << 32), damaged);
        in.get();
        std::string value(length, '\0');
        in.read(value.data(), length);
        AssertThrow(in.good() && in.get() == '\n', damaged);
        state[key] = value;
      }
    AssertThrow(state.count("critical_parameters"), damaged);

    // refuse a prm whose critical parameters differ (in more than white
    // space: '1e6, 2e6' and '1e6 ,2e6' are one list)
    const std::string &saved = state["critical_parameters"];
    if (canonical_form(saved) != canonical_form(critical_parameters))
      {
        std::istringstream a(saved), b(critical_parameters);
        std::string        la, lb;
        while (std::getline(a, la) && std::getline(b, lb) &&
               canonical_form(la) == canonical_form(lb))
          ;
        AssertThrow(false,
                    ExcMessage("Checkpointing/Resume: this input differs from "
                               "the checkpoint's in a parameter that must not "
                               "change (only " +
                               changeable_on_resume +
                               " may): the checkpoint has '" + la +
                               "', this input '" + lb + "'."));
      }
    return state;
  }


  void
  Checkpoints::add_critical_parameter(const std::string &name,
                                      const std::string &value)
  {
    critical_parameters += name + " = " + value + "\n";
  }



  std::string
  Checkpoints::advice_beside(const std::string &dir) const
  {
    // the newest other checkpoint that passes the checks (a crash while
    // writing may have left a newer, incomplete folder): how to resume from
    // it. The refused one is not removed behind the user's back, nor
    // silently replaced by an older state.
    std::map<unsigned long, std::string> others; // by step, newest last
    // (an empty dir has an empty name: no folder is left out)
    const std::string refused = std::filesystem::path(dir).filename();
    std::error_code   error; // an unreadable folder: no advice
    for (auto entry = std::filesystem::directory_iterator(root, error);
         !error && entry != std::filesystem::directory_iterator();
         entry.increment(error))
      {
        const std::string name = entry->path().filename();
        if (name != refused && name.rfind("step_", 0) == 0 && name.size() > 5 &&
            name.find_first_not_of("0123456789", 5) == std::string::npos &&
            name.size() < 5 + 19)
          {
            std::error_code not_a_directory;
            if (entry->is_directory(not_a_directory))
              others[std::stoul(name.substr(5))] = name;
          }
      }
    const auto passes = [&](const std::string &name) {
      try
        {
          return verify(root + "/" + name).empty();
        }
      catch (const std::exception &)
        {
          return false;
        }
    };
    for (auto other = others.rbegin(); other != others.rend(); ++other)
      if (passes(other->second))
        return (dir.empty() ?
                  ". The newest checkpoint there that passes the checks is '" +
                    other->second + "': to resume from it, write its " :
                  ". The newest other checkpoint that passes the checks, '" +
                    other->second +
                    "', is kept beside it: to resume from that one, write "
                    "its ") +
               "name into '" + root + "/last'" +
               // a command to paste, where quoting the path is simple
               (root.find('\'') == std::string::npos ?
                  " (echo " + other->second + " > '" + root + "/last')" :
                  std::string()) +
               "; or start afresh (Checkpointing/Resume = false), whose "
               "checkpoints replace those there: give it another Output "
               "directory to keep them.";
    if (!dir.empty())
      return ". There is no other checkpoint beside it that passes the "
             "checks: start afresh (Checkpointing/Resume = false).";
    return std::string(others.empty() ?
                         ". There is no checkpoint folder there" :
                         ". No checkpoint folder there passes the checks") +
           ": start afresh (Checkpointing/Resume = false).";
  }



  std::string
  Checkpoints::verify(const std::string &dir)
  {
    const std::string state_file = dir + "/state.txt";
    if (!std::filesystem::is_directory(dir))
      return "the folder does not exist (its name is in the file 'last' of "
             "the checkpoints)";
    if (!std::filesystem::is_regular_file(state_file))
      return "its file state.txt is missing";
    std::ifstream     in(state_file, std::ios::binary);
    std::stringstream buffer;
    buffer << in.rdbuf();
    const std::string text = buffer.str();
    if (text.rfind("dyncontact-checkpoint 3\n", 0) != 0)
      return "state.txt is not a checkpoint state of this program's version";
    // the last line: "checksum <crc of everything before it>"
    const auto last =
      text.rfind("checksum ", text.size() < 2 ? 0 : text.size() - 2);
    if (last == std::string::npos || text.back() != '\n' ||
        (last > 0 && text[last - 1] != '\n'))
      return "state.txt is truncated (its checksum line is missing)";
    if (text.substr(last) !=
        "checksum " + checksum_of_text(text.substr(0, last)) + "\n")
      return "state.txt is damaged (its checksum does not match)";

    // the listed files: present, of their size and checksum
    const auto files_at = text.rfind("\nfiles ", last);
    if (files_at == std::string::npos)
      return "state.txt lists no files";
    std::istringstream files(text.substr(files_at + 7, last - files_at - 7));
    std::size_t        length = 0;
    files >> length;
    std::string name, checksum;
    std::size_t size = 0;
    while (files >> name >> size >> checksum)
      {
        const std::string file = dir + "/" + name;
        if (!std::filesystem::is_regular_file(file))
          return "its file '" + name + "' is missing";
        if (std::filesystem::file_size(file) != size)
          return "its file '" + name + "' has " +
                 std::to_string(std::filesystem::file_size(file)) +
                 " bytes instead of " + std::to_string(size) +
                 " (truncated or changed)";
        if (checksum_of_file(file) != checksum)
          return "its file '" + name +
                 "' is damaged (its checksum does not "
                 "match)";
      }
    return "";
  }
} // namespace dyncontact
