#ifndef phasefield_core_statistics_h
#define phasefield_core_statistics_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <fstream>
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
    StatisticsFile(const std::string              &filename,
                   const std::vector<std::string> &columns,
                   const MPI_Comm                  mpi_communicator);

    /** Append one row; must have as many entries as there are columns. */
    void
    add_row(const std::vector<double> &values);

  private:
    const std::size_t n_columns;
    const bool        is_root;
    std::ofstream     file;
  };

  /**
   * Create the output directory @p directory on rank 0; every rank
   * returns once it exists, or every rank throws an InputError naming
   * <Output directory> if it cannot be created. Collective.
   */
  void
  create_output_directory(const std::string &directory,
                          const MPI_Comm     mpi_communicator);

  /** Print the peak resident memory summed over all ranks. Collective. */
  void
  print_peak_memory(const dealii::ConditionalOStream &pcout,
                    const MPI_Comm                    mpi_communicator);
} // namespace PhaseField

#endif
