#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <dyncontact/output/output_directory.h>

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

namespace dyncontact
{
  using namespace dealii;

  namespace
  {
    std::string
    host_name()
    {
      char name[256] = {};
      gethostname(name, sizeof(name) - 1);
      return name;
    }

    /// Whether process @p pid on this host lives (a zombie does not: in a
    /// container nobody may reap a killed run).
    bool
    lives(const long pid)
    {
      if (pid <= 0 || (::kill(pid, 0) != 0 && errno != EPERM))
        return false;
      std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
      std::string   text;
      std::getline(stat, text);
      const auto paren = text.rfind(')');
      return paren == std::string::npos || paren + 2 >= text.size() ||
             (text[paren + 2] != 'Z' && text[paren + 2] != 'X');
    }

    /// Creates @p file exclusively with "host pid"; false if it exists.
    bool
    create_lock(const std::string &file)
    {
      const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0644);
      if (fd < 0)
        return false;
      const std::string text =
        host_name() + " " + std::to_string(::getpid()) + "\n";
      const bool written =
        ::write(fd, text.data(), text.size()) == ssize_t(text.size());
      ::close(fd);
      return written;
    }

    /// What stands at @p path, if it is not a regular file ("" if it is one
    /// or nothing is there): the run neither writes through a symbolic link
    /// nor opens a FIFO or a device, which could block it for ever.
    std::string
    special_file_kind(const std::string &path)
    {
      namespace fs = std::filesystem;
      std::error_code error;
      switch (fs::symlink_status(path, error).type())
        {
          case fs::file_type::not_found:
          case fs::file_type::none:
            return "";
          case fs::file_type::regular:
            // (writing it would change the file of its other names)
            return fs::hard_link_count(path, error) > 1 && !error ?
                     "a file with other names (a hard link)" :
                     "";
          case fs::file_type::symlink:
            return "a symbolic link";
          case fs::file_type::fifo:
            return "a FIFO";
          case fs::file_type::directory:
            return "a directory";
          case fs::file_type::block:
          case fs::file_type::character:
            return "a device";
          case fs::file_type::socket:
            return "a socket";
          default:
            return "not a regular file";
        }
    }
  } // namespace



  OutputDirectory::OutputDirectory(const std::string              &directory,
                                   const std::vector<std::string> &files,
                                   const MPI_Comm                  comm)
    : lock_file(directory + "/.lock")
  {
    std::string problem;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        // a name too long to show whole is shown by its ends
        const std::string shown = directory.size() <= 200 ?
                                    directory :
                                    directory.substr(0, 100) + "...(" +
                                      std::to_string(directory.size()) +
                                      " characters)..." +
                                      directory.substr(directory.size() - 40);
        std::error_code   error;
        std::filesystem::create_directories(directory, error);
        if (!std::filesystem::is_directory(directory, error))
          problem = "Output directory '" + shown + "' cannot be created" +
                    (error ? ": " + error.message() : " (it is a file)") + ".";
        else
          {
            std::vector<std::string> names = files;
            names.push_back(".lock");
            for (const std::string &name : names)
              {
                // (a folder's name ends in '/')
                const std::string path =
                  directory + "/" + name.substr(0, name.find('/'));
                const std::string kind =
                  name.back() == '/' ?
                    (std::filesystem::exists(path, error) &&
                         !std::filesystem::is_directory(path, error) ?
                       "not a directory" :
                       "") :
                    special_file_kind(path);
                if (problem.empty() && !kind.empty())
                  problem = "'" + directory + "/" + name + "' is " + kind +
                            (name.back() == '/' ?
                               ": the run writes its checkpoints into this "
                               "folder." :
                               ", not a regular file: the run writes " + name +
                                 " itself and neither writes through nor "
                                 "opens such a file.") +
                            " Remove it, or choose another Output directory.";
              }
          }
        if (!problem.empty())
          owns_lock = false;
        else if (!create_lock(lock_file))
          {
            // someone else's lock: alive, or left by a killed run?
            std::string   host;
            long          pid = 0;
            std::ifstream in(lock_file);
            in >> host >> pid;
            const bool alive =
              !in.fail() && pid > 0 && (host != host_name() || lives(pid));
            if (in.fail() && !std::filesystem::exists(lock_file, error))
              problem =
                "Output directory '" + directory + "' cannot be written.";
            else if (alive)
              problem = "Output directory '" + directory +
                        "' is in use by another run (process " +
                        std::to_string(pid) + " on host " + host +
                        ", lock file '" + lock_file +
                        "'). Wait for it to finish, or choose another "
                        "Output directory.";
            else
              {
                std::filesystem::remove(lock_file, error);
                if (create_lock(lock_file))
                  std::cout << "   note: replaced the lock file of a run "
                               "that no longer lives ('"
                            << lock_file << "')" << std::endl;
                else
                  problem =
                    "Output directory '" + directory + "' cannot be written.";
              }
          }
        owns_lock = problem.empty();
      }
    problem = Utilities::MPI::broadcast(comm, problem, 0);
    AssertThrow(problem.empty(), ExcMessage(problem));
  }



  OutputDirectory::~OutputDirectory()
  {
    if (owns_lock)
      {
        std::error_code error;
        std::filesystem::remove(lock_file, error);
      }
  }
} // namespace dyncontact
