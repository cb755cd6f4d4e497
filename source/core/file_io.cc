#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <phasefield/core/file_io.h>
#include <phasefield/core/parameters.h>
#include <sstream>
#include <sys/types.h>
#include <unistd.h>
#include <vector>

namespace PhaseField
{
  namespace
  {
    /** The name of the lock file in an output directory. */
    const std::string lock_filename = "phasefield.lock";

    /** The lock files this process created; removed at exit. */
    struct LockRegistry
    {
      std::vector<std::string> paths;

      ~LockRegistry()
      {
        release();
      }

      void
      release()
      {
        for (const std::string &path : paths)
          ::unlink(path.c_str());
        paths.clear();
      }
    };

    LockRegistry &
    lock_registry()
    {
      static LockRegistry registry;
      return registry;
    }

    /** This machine's host name. */
    std::string
    host_name()
    {
      char name[256] = {};
      if (::gethostname(name, sizeof(name) - 1) != 0)
        return "unknown";
      return name;
    }

    /** The holder of a lock file: pid and host (pid 0: unreadable). */
    struct LockHolder
    {
      long        pid = 0;
      std::string host;
    };

    LockHolder
    read_lock(const std::string &path)
    {
      std::ifstream in(path);
      LockHolder    holder;
      std::string   pid_key, host_key;
      in >> pid_key >> holder.pid >> host_key >> holder.host;
      if (!in || pid_key != "pid" || host_key != "host")
        return LockHolder();
      return holder;
    }

    /**
     * Create the lock file @p path with O_CREAT | O_EXCL; false if it
     * exists. Throws WriteError if it cannot be created or written.
     */
    bool
    create_lock(const std::string &path)
    {
      const int fd = ::open(path.c_str(), O_CREAT | O_EXCL | O_WRONLY, 0644);
      if (fd < 0 && errno == EEXIST)
        return false;
      if (fd < 0)
        throw WriteError(write_failure_message(path, errno));
      const std::string text =
        "pid " + std::to_string(::getpid()) + "\nhost " + host_name() + "\n";
      const ssize_t written = ::write(fd, text.data(), text.size());
      const int     error   = errno;
      if (::close(fd) != 0 || written != static_cast<ssize_t>(text.size()))
        {
          ::unlink(path.c_str());
          throw WriteError(write_failure_message(path, error));
        }
      lock_registry().paths.push_back(path);
      return true;
    }

    /** Does the process @p pid run on this host? */
    bool
    process_alive(const long pid)
    {
      return ::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH;
    }

    /** The lock of rank 0 (see lock_output_directory()). */
    void
    lock_on_root(const std::string &directory)
    {
      const std::string path = directory + "/" + lock_filename;
      for (unsigned int attempt = 0; attempt < 2; ++attempt)
        {
          if (create_lock(path))
            return;
          const LockHolder holder = read_lock(path);
          const bool       here   = holder.host == host_name();
          if (here && holder.pid == ::getpid())
            return;
          if (holder.pid <= 0 || !here || process_alive(holder.pid))
            throw InputError(
              "The output directory <" + directory + "> is in use by " +
              (holder.pid > 0 ? "process " + std::to_string(holder.pid) +
                                  " on host <" + holder.host + ">" :
                                std::string("another run")) +
              " (lock file <" + path +
              ">): two runs in one output directory would overwrite each "
              "other's files. Choose another <Output directory> or wait "
              "for that run to end; if it no longer runs, delete the lock "
              "file.");
          std::cout << "Warning: the output directory <" << directory
                    << "> was locked by process " << holder.pid
                    << " on this host, which no longer runs (a killed "
                       "run?): the stale lock file <"
                    << path << "> is replaced." << std::endl;
          ::unlink(path.c_str());
        }
      throw InputError("The lock file <" + path +
                       "> in <Output directory> could not be replaced.");
    }
  } // namespace



  std::string
  write_failure_message(const std::string &filename, const int error_number)
  {
    return "Cannot write the file <" + filename + ">" +
           (error_number != 0 ?
              " (" + std::string(std::strerror(error_number)) + ")" :
              std::string()) +
           ". The run stops here: is the disk full, or is the path not "
           "writable? statistics.csv and the output are complete up to the "
           "previous step, and the last complete checkpoint (if any) is "
           "intact.";
  }



  void
  write_checked(const std::string                         &filename,
                const std::function<void(std::ostream &)> &writer)
  {
    errno = 0;
    std::ofstream out(filename, std::ios::binary);
    if (!out)
      throw WriteError(write_failure_message(filename, errno));
    // a partly written regular file is removed: no truncated output
    const auto fail = [&](const int error) {
      out.close();
      std::error_code ignored;
      if (std::filesystem::is_regular_file(
            std::filesystem::symlink_status(filename, ignored)))
        std::filesystem::remove(filename, ignored);
      throw WriteError(write_failure_message(filename, error));
    };
    try
      {
        writer(out);
      }
    catch (...)
      {
        // deal.II's writers check the stream themselves (ExcIO)
        fail(errno);
      }
    out.flush();
    if (!out)
      fail(errno);
    out.close();
    if (out.fail())
      fail(errno);
  }



  void
  run_on_every_rank(const MPI_Comm               mpi_communicator,
                    const std::function<void()> &function)
  {
    // what happened here: 0 success, 1 InputError, 2 WriteError, 3 other
    std::pair<int, std::string> outcome(0, "");
    try
      {
        function();
      }
    catch (const InputError &error)
      {
        outcome = {1, error.what()};
      }
    catch (const WriteError &error)
      {
        outcome = {2, error.what()};
      }
    catch (const dealii::ExceptionBase &error)
      {
        std::ostringstream info;
        error.print_info(info);
        outcome = {3, info.str()};
      }
    catch (const std::exception &error)
      {
        outcome = {3, error.what()};
      }
    const unsigned int n_ranks =
      dealii::Utilities::MPI::n_mpi_processes(mpi_communicator);
    const unsigned int first_failed =
      dealii::Utilities::MPI::min(outcome.first != 0 ?
                                    dealii::Utilities::MPI::this_mpi_process(
                                      mpi_communicator) :
                                    n_ranks,
                                  mpi_communicator);
    if (first_failed == n_ranks)
      return;
    outcome = dealii::Utilities::MPI::broadcast(mpi_communicator,
                                                outcome,
                                                first_failed);
    if (outcome.first == 1)
      throw InputError(outcome.second);
    if (outcome.first == 2)
      throw WriteError(outcome.second);
    throw std::runtime_error(outcome.second);
  }



  namespace
  {
    /** 64-bit FNV-1a, fed piece by piece. */
    struct Fnv1a
    {
      std::uint64_t hash = 14695981039346656037ull;

      void
      add(const char *data, const std::size_t n)
      {
        constexpr std::uint64_t prime = 1099511628211ull;
        for (std::size_t i = 0; i < n; ++i)
          {
            hash ^= static_cast<unsigned char>(data[i]);
            hash *= prime;
          }
      }

      std::string
      text() const
      {
        std::ostringstream out;
        out << std::hex;
        out.width(16);
        out.fill('0');
        out << hash;
        return out.str();
      }
    };
  } // namespace



  std::string
  file_checksum(const std::string &filename)
  {
    std::ifstream in(filename, std::ios::binary);
    if (!in)
      throw std::runtime_error("Cannot read the file <" + filename + ">.");
    Fnv1a             hash;
    std::vector<char> buffer(1 << 20);
    while (in)
      {
        in.read(buffer.data(), buffer.size());
        hash.add(buffer.data(), in.gcount());
      }
    if (in.bad())
      throw std::runtime_error("Cannot read the file <" + filename + ">.");
    return hash.text();
  }



  std::string
  data_checksum(const std::string &data)
  {
    Fnv1a hash;
    hash.add(data.data(), data.size());
    return hash.text();
  }



  void
  write_verified(const std::string &filename, const std::string &text)
  {
    write_checked(filename, [&](std::ostream &out) { out << text; });
    std::error_code      error;
    const std::uintmax_t size = std::filesystem::file_size(filename, error);
    std::string          problem;
    if (error)
      problem = "is missing";
    else if (size != text.size())
      problem = "has " + std::to_string(size) + " bytes instead of " +
                std::to_string(text.size());
    else if (file_checksum(filename) != data_checksum(text))
      problem = "does not hold what was written";
    if (problem.empty())
      return;
    std::filesystem::remove(filename, error);
    throw WriteError("The file <" + filename + "> " + problem +
                     " when it is read back after writing. " +
                     write_failure_message(filename, 0));
  }



  void
  lock_output_directory(const std::string &directory,
                        const MPI_Comm     mpi_communicator)
  {
    run_on_every_rank(mpi_communicator, [&]() {
      if (dealii::Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
        lock_on_root(directory);
    });
  }



  void
  release_output_locks()
  {
    lock_registry().release();
  }
} // namespace PhaseField
