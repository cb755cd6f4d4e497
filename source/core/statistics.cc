#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <cmath>
#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>
#include <filesystem>
#include <iomanip>
#ifdef __GLIBC__
#  include <malloc.h>
#endif
#include <phasefield/core/parameters.h>
#include <phasefield/core/statistics.h>

namespace PhaseField
{
  namespace
  {
    /**
     * The lines of the CSV file @p filename after its header @p header up
     * to the first one whose first entry (the step) is @p last_kept_step:
     * the rows of the steps up to it, without a later row of the same
     * step (the level-start row of shape_from_contour repeats the last
     * step of the previous level, and it is written again on resume).
     */
    std::vector<std::string>
    rows_up_to_step(const std::string &filename,
                    const std::string &header,
                    const unsigned int last_kept_step)
    {
      std::ifstream in(filename);
      std::string   line;
      if (!in || !std::getline(in, line))
        throw std::runtime_error("Cannot continue <" + filename +
                                 ">: the file is missing or empty.");
      if (line != header)
        throw std::runtime_error(
          "Cannot continue <" + filename + ">: its columns <" + line +
          "> are not those of this run <" + header + ">.");
      std::vector<std::string> rows;
      while (std::getline(in, line))
        {
          if (line.empty())
            continue;
          const double step = std::stod(line.substr(0, line.find(',')));
          if (step > last_kept_step)
            break;
          rows.push_back(line);
          if (step == last_kept_step)
            break;
        }
      return rows;
    }
  } // namespace



  std::string
  StatisticsFile::header(const std::vector<std::string> &columns)
  {
    std::string line;
    for (std::size_t i = 0; i < columns.size(); ++i)
      line += (i ? "," : "") + columns[i];
    return line;
  }



  StatisticsFile::StatisticsFile(const std::string              &filename,
                                 const std::vector<std::string> &columns,
                                 const MPI_Comm mpi_communicator)
    : n_columns(columns.size())
    , is_root(dealii::Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
  {
    run_on_root(mpi_communicator, [&]() {
      file.open(filename);
      if (!file)
        throw InputError("Cannot write <" + filename +
                         ">: check <Output directory>.");
      file << header(columns) << std::endl;
    });
  }



  StatisticsFile::StatisticsFile(const std::string              &filename,
                                 const std::vector<std::string> &columns,
                                 const MPI_Comm     mpi_communicator,
                                 const unsigned int last_kept_step)
    : n_columns(columns.size())
    , is_root(dealii::Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
  {
    run_on_root(mpi_communicator, [&]() {
      const std::vector<std::string> rows =
        rows_up_to_step(filename, header(columns), last_kept_step);
      // rewrite under a temporary name: a kill leaves the old file intact
      const std::string temporary = filename + ".tmp";
      {
        std::ofstream out(temporary);
        out << header(columns) << '\n';
        for (const std::string &row : rows)
          out << row << '\n';
        if (!out.flush())
          throw std::runtime_error("Cannot write <" + temporary + ">.");
      }
      std::filesystem::rename(temporary, filename);
      file.open(filename, std::ios::app);
      if (!file)
        throw std::runtime_error("Cannot append to <" + filename + ">.");
    });
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
  run_on_root(const MPI_Comm               mpi_communicator,
              const std::function<void()> &function)
  {
    // what happened on rank 0: 0 success, 1 InputError, 2 another error
    enum Outcome : int
    {
      success,
      input_error,
      other_error
    };
    std::pair<int, std::string> outcome(success, "");
    if (dealii::Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      try
        {
          function();
        }
      catch (const InputError &error)
        {
          outcome = {input_error, error.what()};
        }
      catch (const std::exception &error)
        {
          outcome = {other_error, error.what()};
        }
    outcome = dealii::Utilities::MPI::broadcast(mpi_communicator, outcome, 0);
    if (outcome.first == input_error)
      throw InputError(outcome.second);
    if (outcome.first == other_error)
      throw std::runtime_error(outcome.second);
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
  return_free_heap_memory()
  {
#ifdef __GLIBC__
    malloc_trim(0);
#endif
  }



  void
  print_peak_memory(const dealii::ConditionalOStream &pcout,
                    const MPI_Comm                    mpi_communicator)
  {
    dealii::Utilities::System::MemoryStats memory;
    dealii::Utilities::System::get_memory_stats(memory);
    // VmHWM is in KiB
    constexpr double bytes_per_kib = 1024.;
    constexpr double bytes_per_mib = 1024. * bytes_per_kib;
    constexpr double bytes_per_gb  = 1e9;
    const double     peak_bytes =
      dealii::Utilities::MPI::sum(memory.VmHWM * bytes_per_kib,
                                  mpi_communicator);
    pcout << "Peak resident memory, summed over "
          << dealii::Utilities::MPI::n_mpi_processes(mpi_communicator)
          << " rank(s): " << std::fixed << std::setprecision(0)
          << peak_bytes / bytes_per_mib << " MiB (" << std::setprecision(2)
          << peak_bytes / bytes_per_gb << " GB)" << std::defaultfloat
          << std::endl;
  }
} // namespace PhaseField
