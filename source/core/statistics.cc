#include <cmath>
#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>
#include <filesystem>
#include <iomanip>
#include <phasefield/core/parameters.h>
#include <phasefield/core/statistics.h>

namespace PhaseField
{
  StatisticsFile::StatisticsFile(const std::string              &filename,
                                 const std::vector<std::string> &columns,
                                 const MPI_Comm mpi_communicator)
    : n_columns(columns.size())
    , is_root(dealii::Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
  {
    if (is_root)
      file.open(filename);
    // every rank throws, or none does: no rank waits for a failed root
    const bool opened =
      dealii::Utilities::MPI::broadcast(mpi_communicator,
                                        is_root && static_cast<bool>(file),
                                        0);
    if (!opened)
      throw InputError("Cannot write <" + filename +
                       ">: check <Output directory>.");
    if (!is_root)
      return;
    for (std::size_t i = 0; i < columns.size(); ++i)
      file << (i ? "," : "") << columns[i];
    file << std::endl;
  }



  void
  StatisticsFile::add_row(const std::vector<double> &values)
  {
    AssertDimension(values.size(), n_columns);
    if (!is_root)
      return;
    file << std::setprecision(10);
    for (std::size_t i = 0; i < values.size(); ++i)
      {
        if (i)
          file << ',';
        if (std::isnan(values[i]))
          file << "nan";
        else
          file << values[i];
      }
    file << std::endl;
  }



  void
  create_output_directory(const std::string &directory,
                          const MPI_Comm     mpi_communicator)
  {
    bool created = false;
    if (dealii::Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      {
        std::error_code error;
        std::filesystem::create_directories(directory, error);
        created = std::filesystem::is_directory(directory, error);
      }
    // every rank throws, or none does: no rank waits for a failed root
    if (!dealii::Utilities::MPI::broadcast(mpi_communicator, created, 0))
      throw InputError("Cannot create the directory <" + directory +
                       "> given in <Output directory>.");
  }



  void
  print_peak_memory(const dealii::ConditionalOStream &pcout,
                    const MPI_Comm                    mpi_communicator)
  {
    dealii::Utilities::System::MemoryStats memory;
    dealii::Utilities::System::get_memory_stats(memory);
    const double peak_megabytes =
      dealii::Utilities::MPI::sum(memory.VmHWM / 1024., mpi_communicator);
    pcout << "Peak resident memory, summed over "
          << dealii::Utilities::MPI::n_mpi_processes(mpi_communicator)
          << " rank(s): " << std::fixed << std::setprecision(0)
          << peak_megabytes << " MB" << std::defaultfloat << std::endl;
  }
} // namespace PhaseField
