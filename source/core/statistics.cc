#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <cerrno>
#include <cmath>
#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>
#include <filesystem>
#include <iomanip>
#ifdef __GLIBC__
#  include <malloc.h>
#endif
#include <phasefield/core/file_io.h>
#include <phasefield/core/parameters.h>
#include <phasefield/core/statistics.h>
#include <sstream>

namespace PhaseField
{
  namespace
  {
    /**
     * Whether @p entry of a statistics row is a number as add_row() writes
     * it (also nan, the l2_error of shapes without an exact solution, and
     * inf).
     */
    bool
    is_statistics_number(const std::string &entry)
    {
      std::size_t consumed = 0;
      try
        {
          std::stod(entry, &consumed);
        }
      catch (...)
        {
          return false;
        }
      return !entry.empty() && consumed == entry.size();
    }



    /**
     * The step (first entry) of the row @p line, line @p line_number of
     * @p filename, whose header has @p n_columns columns; throws
     * InputError naming both if the row does not have n_columns entries
     * that are numbers (is_statistics_number()), or the step is not a
     * non-negative integer.
     */
    double
    step_of_row(const std::string &line,
                const std::string &filename,
                const unsigned int line_number,
                const std::size_t  n_columns)
    {
      const std::vector<std::string> entries =
        dealii::Utilities::split_string_list(line, ',');
      std::string problem;
      if (entries.size() != n_columns)
        problem = "has " + std::to_string(entries.size()) +
                  " entries instead of " + std::to_string(n_columns);
      for (std::size_t i = 0; i < entries.size() && problem.empty(); ++i)
        if (!is_statistics_number(entries[i]))
          problem = "has <" + entries[i].substr(0, 40) + "> in column " +
                    std::to_string(i + 1) + ", which is not a number";
      const double step = problem.empty() ? std::stod(entries[0]) : -1;
      if (problem.empty() && !(step >= 0 && step == std::floor(step)))
        problem = "does not begin with a step number";
      if (!problem.empty())
        throw InputError("Cannot continue <" + filename + ">: line " +
                         std::to_string(line_number) + " <" +
                         line.substr(0, 80) + "> " + problem +
                         ": it is not a row of statistics (damaged file?).");
      return step;
    }



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
        throw InputError("Cannot continue <" + filename +
                         ">: the file is missing or empty.");
      if (line != header)
        throw InputError("Cannot continue <" + filename + ">: its columns <" +
                         line + "> are not those of this run <" + header +
                         ">.");
      const std::size_t n_columns =
        dealii::Utilities::split_string_list(header, ',').size();
      std::vector<std::string> rows;
      for (unsigned int line_number = 2; std::getline(in, line); ++line_number)
        {
          if (line.empty())
            continue;
          const double step =
            step_of_row(line, filename, line_number, n_columns);
          if (step > last_kept_step)
            break;
          rows.push_back(line);
          if (step == last_kept_step)
            return rows;
        }
      throw InputError(
        "Cannot continue <" + filename + ">: it has no row of step " +
        std::to_string(last_kept_step) +
        ", the step of the checkpoint (the file is shorter than the "
        "checkpoint: was it replaced or truncated?). Resume from the output "
        "directory of the run that wrote the checkpoint.");
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
    , mpi_communicator(mpi_communicator)
    , filename(filename)
  {
    run_on_root(mpi_communicator, [&]() {
      file.open(filename);
      if (!file)
        throw InputError("Cannot write <" + filename +
                         ">: check <Output directory>.");
      errno = 0;
      file << header(columns) << std::endl;
      if (!file)
        throw WriteError(write_failure_message(filename, errno));
    });
  }



  StatisticsFile::StatisticsFile(const std::string              &filename,
                                 const std::vector<std::string> &columns,
                                 const MPI_Comm     mpi_communicator,
                                 const unsigned int last_kept_step)
    : n_columns(columns.size())
    , mpi_communicator(mpi_communicator)
    , filename(filename)
  {
    run_on_root(mpi_communicator, [&]() {
      const std::vector<std::string> rows =
        rows_up_to_step(filename, header(columns), last_kept_step);
      // rewrite under a temporary name: a kill leaves the old file intact
      const std::string temporary = filename + ".tmp";
      write_checked(temporary, [&](std::ostream &out) {
        out << header(columns) << '\n';
        for (const std::string &row : rows)
          out << row << '\n';
      });
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
    // collective: a failed write stops every rank
    run_on_root(mpi_communicator, [&]() {
      std::ostringstream row;
      row << std::setprecision(10);
      for (std::size_t i = 0; i < values.size(); ++i)
        {
          if (i)
            row << ',';
          if (std::isnan(values[i]))
            row << "nan";
          else
            row << values[i];
        }
      const std::streamoff complete = file.tellp();
      errno                         = 0;
      file << row.str() << std::endl;
      if (!file)
        {
          const int error = errno;
          // no partial row: a resume can continue the file
          file.close();
          std::error_code ignored;
          if (complete > 0)
            std::filesystem::resize_file(filename, complete, ignored);
          throw WriteError(write_failure_message(filename, error));
        }
    });
  }



  void
  run_on_root(const MPI_Comm               mpi_communicator,
              const std::function<void()> &function)
  {
    run_on_every_rank(mpi_communicator, [&]() {
      if (dealii::Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
        function();
    });
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
    lock_output_directory(directory, mpi_communicator);
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
