#include <boost/serialization/string.hpp>
#include <deal.II/base/utilities.h>
#include <filesystem>
#include <fstream>
#include <limits>
#include <phasefield/core/parameters.h>
#include <phasefield/core/statistics.h>
#include <phasefield/time/checkpoint.h>
#include <sstream>

namespace PhaseField
{
  namespace Checkpoint
  {
    namespace
    {
      namespace fs = std::filesystem;

      const std::string prefix             = "checkpoint-";
      const std::string temporary_suffix   = ".tmp";
      const std::string state_filename     = "state.txt";
      const std::string mesh_base_filename = "mesh";

      /**
       * The step of the checkpoint directory @p name ("checkpoint-<step>",
       * with @p suffix after the step), -1 if it is not one.
       */
      long
      step_of(const std::string &name, const std::string &suffix = "")
      {
        if (name.size() <= prefix.size() + suffix.size() ||
            name.compare(0, prefix.size(), prefix) != 0 ||
            name.compare(name.size() - suffix.size(), suffix.size(), suffix) !=
              0)
          return -1;
        const std::string digits =
          name.substr(prefix.size(),
                      name.size() - prefix.size() - suffix.size());
        if (digits.find_first_not_of("0123456789") != std::string::npos)
          return -1;
        return std::stol(digits);
      }



      /** Checkpoint directories in @p directory (complete or temporary). */
      std::vector<fs::path>
      checkpoint_directories(const std::string &directory)
      {
        std::vector<fs::path> paths;
        if (!fs::is_directory(directory))
          return paths;
        for (const auto &entry : fs::directory_iterator(directory))
          {
            const std::string name = entry.path().filename().string();
            if (entry.is_directory() &&
                (step_of(name) >= 0 || step_of(name, temporary_suffix) >= 0))
              paths.push_back(entry.path());
          }
        return paths;
      }



      /** @p state as the text of state.txt (doubles to the last bit). */
      std::string
      to_text(const State &state)
      {
        std::ostringstream out;
        out.precision(std::numeric_limits<double>::max_digits10);
        out << "step " << state.step << '\n'
            << "time " << state.time << '\n'
            << "state_tau " << state.state_tau << '\n'
            << "n_fields " << state.n_fields << '\n'
            << "pvd_records " << state.pvd_records.size() << '\n';
        for (const auto &[time, file] : state.pvd_records)
          out << time << ' ' << file << '\n';
        out << "step_offset " << state.step_offset << '\n'
            << "finished " << state.finished << '\n'
            << "problem_data " << state.problem_data.size() << '\n';
        for (const double value : state.problem_data)
          out << value << '\n';
        out << "step_size_limit " << state.step_size_limit << '\n';
        return out.str();
      }



      /** The State in the text @p text of the state file @p filename. */
      State
      from_text(const std::string &text, const std::string &filename)
      {
        std::istringstream in(text);
        State              state;
        std::string        key[5];
        std::size_t        n_records = 0;
        in >> key[0] >> state.step >> key[1] >> state.time >> key[2] >>
          state.state_tau >> key[3] >> state.n_fields >> key[4] >> n_records;
        for (std::size_t i = 0; in && i < n_records; ++i)
          {
            std::pair<double, std::string> record;
            in >> record.first >> record.second;
            state.pvd_records.push_back(record);
          }
        std::string tail_key[3];
        std::size_t n_data = 0;
        in >> tail_key[0] >> state.step_offset >> tail_key[1] >>
          state.finished >> tail_key[2] >> n_data;
        state.problem_data.resize(in ? n_data : 0);
        for (double &value : state.problem_data)
          in >> value;
        std::string limit_key;
        in >> limit_key >> state.step_size_limit;
        if (!in || limit_key != "step_size_limit" || key[0] != "step" ||
            key[4] != "pvd_records" || tail_key[0] != "step_offset" ||
            tail_key[2] != "problem_data")
          throw std::runtime_error("The checkpoint file <" + filename +
                                   "> is damaged.");
        return state;
      }
    } // namespace



    std::string
    mesh_filename(const std::string &path)
    {
      return path + "/" + mesh_base_filename;
    }



    template <int dim>
    void
    write(const std::string         &directory,
          const Discretization<dim> &discretization,
          const BlockVector         &state,
          const State               &time_stepping_state)
    {
      const MPI_Comm    comm = discretization.get_mpi_communicator();
      const std::string name =
        prefix + std::to_string(time_stepping_state.step);
      const fs::path final_path = fs::path(directory) / name;
      const fs::path temporary  = final_path.string() + temporary_suffix;
      run_on_root(comm, [&]() {
        fs::remove_all(temporary);
        fs::create_directory(temporary);
      });
      discretization.save(mesh_filename(temporary.string()), state);
      run_on_root(comm, [&]() {
        {
          std::ofstream out(temporary / state_filename);
          out << to_text(time_stepping_state);
          if (!out.flush())
            throw std::runtime_error("Cannot write the checkpoint file <" +
                                     (temporary / state_filename).string() +
                                     ">.");
        }
        // the rename completes the checkpoint; only then the older ones go
        fs::remove_all(final_path);
        fs::rename(temporary, final_path);
        for (const fs::path &path : checkpoint_directories(directory))
          if (path != final_path)
            fs::remove_all(path);
      });
    }



    std::string
    find_last(const std::string &directory, const MPI_Comm mpi_communicator)
    {
      std::string last;
      run_on_root(mpi_communicator, [&]() {
        long last_step = -1;
        for (const fs::path &path : checkpoint_directories(directory))
          {
            const long step = step_of(path.filename().string());
            if (step > last_step && fs::exists(path / state_filename))
              {
                last_step = step;
                last      = path.string();
              }
          }
      });
      last = dealii::Utilities::MPI::broadcast(mpi_communicator, last, 0);
      if (last.empty())
        throw InputError(
          "<Checkpoint / Resume> = true, but the output directory <" +
          directory +
          "> contains no checkpoint (a directory checkpoint-<step> written "
          "by a run with <Checkpoint / Interval> > 0).");
      return last;
    }



    State
    read_state(const std::string &path, const MPI_Comm mpi_communicator)
    {
      const std::string filename = path + "/" + state_filename;
      std::string       text;
      run_on_root(mpi_communicator, [&]() {
        std::ifstream in(filename);
        if (!in)
          throw std::runtime_error("Cannot read the checkpoint file <" +
                                   filename + ">.");
        text.assign(std::istreambuf_iterator<char>(in),
                    std::istreambuf_iterator<char>());
        from_text(text, filename);
      });
      text = dealii::Utilities::MPI::broadcast(mpi_communicator, text, 0);
      return from_text(text, filename);
    }



    void
    remove_all(const std::string &directory, const MPI_Comm mpi_communicator)
    {
      run_on_root(mpi_communicator, [&]() {
        for (const fs::path &path : checkpoint_directories(directory))
          fs::remove_all(path);
      });
    }



    template void
    write<2>(const std::string &,
             const Discretization<2> &,
             const BlockVector &,
             const State &);
    template void
    write<3>(const std::string &,
             const Discretization<3> &,
             const BlockVector &,
             const State &);
  } // namespace Checkpoint
} // namespace PhaseField
