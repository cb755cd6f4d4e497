#ifndef phasefield_core_file_io_h
#define phasefield_core_file_io_h

#include <cstdint>
#include <deal.II/base/mpi.h>
#include <functional>
#include <ostream>
#include <stdexcept>
#include <string>

namespace PhaseField
{
  /**
   * Thrown when an output file (statistics.csv, VTU/PVTU/PVD, pictures,
   * checkpoint files) cannot be written completely. run_program() prints
   * its message and exits with status 1; the message names the file.
   */
  class WriteError : public std::runtime_error
  {
  public:
    explicit WriteError(const std::string &message)
      : std::runtime_error(message)
    {}
  };

  /**
   * The message of a failed write of @p filename with the system error
   * @p error_number (errno; 0: none known): one paragraph that names the
   * file and says what of the run's output is intact.
   */
  std::string
  write_failure_message(const std::string &filename, const int error_number);

  /**
   * Write @p filename by @p writer and check that every byte reached the
   * file (the stream is flushed and closed, and its state checked
   * after each); throws WriteError naming the file otherwise, after
   * removing a partly written regular file. Not collective.
   */
  void
  write_checked(const std::string                         &filename,
                const std::function<void(std::ostream &)> &writer);

  /**
   * Run @p function on every rank of @p mpi_communicator; if it throws on
   * any rank, every rank throws the exception of the lowest failing rank
   * (an InputError as InputError, a WriteError as WriteError, anything
   * else as std::runtime_error), so that no rank waits in a later
   * collective operation for one that failed. @p function itself must
   * not be collective. Collective.
   */
  void
  run_on_every_rank(const MPI_Comm               mpi_communicator,
                    const std::function<void()> &function);

  /**
   * The 64-bit FNV-1a hash of the contents of the file @p filename, as 16
   * hexadecimal digits. Throws std::runtime_error if it cannot be read.
   */
  std::string
  file_checksum(const std::string &filename);

  /** The 64-bit FNV-1a hash of @p data as file_checksum() writes it. */
  std::string
  data_checksum(const std::string &data);

  /**
   * Write @p text into @p filename as write_checked() does, then read the
   * file back: its size and checksum must be those of @p text (a file
   * that a file size limit or a full disk cut short without an error is
   * found here). Throws WriteError naming the file otherwise, after
   * removing it. Not collective.
   */
  void
  write_verified(const std::string &filename, const std::string &text);

  /**
   * Lock the output directory @p directory for this process: rank 0
   * creates the file `phasefield.lock` there (atomically, O_CREAT |
   * O_EXCL) with its pid and host name. If another running process holds
   * the lock, every rank throws an InputError naming it; a lock of a
   * process that no longer runs on this host (a killed run) is reported
   * and replaced. Locking a directory this process holds already does
   * nothing. The lock file is removed when the process exits normally or
   * by an error that run_program() reports (release_output_locks()).
   * Collective.
   */
  void
  lock_output_directory(const std::string &directory,
                        const MPI_Comm     mpi_communicator);

  /** Remove the lock files this process created. Not collective. */
  void
  release_output_locks();
} // namespace PhaseField

#endif
