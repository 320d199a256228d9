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
  } // namespace



  OutputDirectory::OutputDirectory(const std::string &directory,
                                   const MPI_Comm     comm)
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
