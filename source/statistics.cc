#include <deal.II/base/exceptions.h>

#include <phasefield/statistics.h>

#include <cmath>
#include <iomanip>

namespace PhaseField
{
  StatisticsFile::StatisticsFile(const std::string &             filename,
                                 const std::vector<std::string> &columns,
                                 const MPI_Comm mpi_communicator)
    : n_columns(columns.size())
    , is_root(dealii::Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
  {
    if (!is_root)
      return;
    file.open(filename);
    AssertThrow(file, dealii::ExcMessage("Cannot write <" + filename + ">."));
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
} // namespace PhaseField
