#ifndef phasefield_core_statistics_h
#define phasefield_core_statistics_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

namespace PhaseField
{
  /**
   * A CSV table written row by row on rank 0 (flushed after every row, so
   * a long run can be watched with `tail -f`). Values are written with
   * 10 significant digits; NaN is written as `nan`. The constructor is
   * collective: if rank 0 cannot open the file, every rank throws an
   * InputError.
   */
  class StatisticsFile
  {
  public:
    /**
     * A new file @p filename with the header @p columns (an existing file
     * is overwritten). Collective: an error on rank 0 is thrown on every
     * rank.
     */
    StatisticsFile(const std::string              &filename,
                   const std::vector<std::string> &columns,
                   const MPI_Comm                  mpi_communicator);

    /**
     * Append mode (a resumed run): the existing file @p filename must have
     * the header @p columns, with the step in the first column. Its rows
     * up to the first row of step @p last_kept_step are kept, later ones
     * (written by a run that was killed after its last checkpoint) are
     * dropped, and add_row() appends. A later row of the same step (the
     * level-start row of a multilevel run, which repeats the last step of
     * the previous level) is dropped too: the resumed run writes it
     * again. Collective: an error on rank 0 is thrown on every rank.
     */
    StatisticsFile(const std::string              &filename,
                   const std::vector<std::string> &columns,
                   const MPI_Comm                  mpi_communicator,
                   const unsigned int              last_kept_step);

    /**
     * Append one row; must have as many entries as there are columns.
     * The row is flushed and the file's state checked: if the write
     * failed (disk full), every rank throws a WriteError naming the
     * file. Collective.
     */
    void
    add_row(const std::vector<double> &values);

  private:
    /** The header line of @p columns. */
    static std::string
    header(const std::vector<std::string> &columns);

    const std::size_t n_columns;
    const MPI_Comm    mpi_communicator;
    const std::string filename;
    /** The open file (rank 0 only). */
    std::ofstream file;
  };

  /**
   * Run @p function on rank 0 of @p mpi_communicator only (file system
   * work); if it throws there, every rank throws: InputError as
   * InputError, WriteError as WriteError, any other exception as
   * std::runtime_error with the same message (run_on_every_rank()). So
   * no rank waits for one that failed. Collective.
   */
  void
  run_on_root(const MPI_Comm               mpi_communicator,
              const std::function<void()> &function);

  /**
   * Create the output directory @p directory on rank 0 and lock it for
   * this process (lock_output_directory()); every rank returns once it
   * exists, or every rank throws an InputError naming <Output directory>
   * if it cannot be created or another run holds it. Collective.
   */
  void
  create_output_directory(const std::string &directory,
                          const MPI_Comm     mpi_communicator);

  /**
   * Return the free pages of this process's heap to the operating system
   * (glibc's malloc_trim; nothing elsewhere). A mesh transfer packs the
   * fields cell by cell into many small blocks; once freed, their pages
   * stay resident, because malloc only returns the top of the heap by
   * itself.
   */
  void
  return_free_heap_memory();

  /**
   * Print the peak resident memory (VmHWM) summed over all ranks, in MiB
   * (2^20 bytes) and in GB (10^9 bytes). Collective.
   */
  void
  print_peak_memory(const dealii::ConditionalOStream &pcout,
                    const MPI_Comm                    mpi_communicator);
} // namespace PhaseField

#endif
