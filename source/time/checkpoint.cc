#include <algorithm>
#include <boost/serialization/string.hpp>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <phasefield/core/file_io.h>
#include <phasefield/core/parameters.h>
#include <phasefield/core/statistics.h>
#include <phasefield/mesh/saved_files.h>
#include <phasefield/time/checkpoint.h>
#include <sstream>
#include <sys/resource.h>

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
      const std::string metadata_filename  = "checkpoint.txt";
      const std::string metadata_header    = "phasefield checkpoint 1";

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
        out << "step_size_limit " << state.step_size_limit << '\n'
            << "stored_fields " << state.n_stored_fields << '\n';
        return out.str();
      }



      /**
       * Throw an InputError naming @p filename if @p state cannot be the
       * state of a checkpoint.
       */
      void
      check_sanity(const State &state, const std::string &filename)
      {
        std::string problem;
        if (state.step < state.step_offset)
          problem = "step " + std::to_string(state.step) +
                    " is before the step offset " +
                    std::to_string(state.step_offset);
        else if (!std::isfinite(state.time) || state.time < 0 ||
                 (state.step > 0 && state.time == 0))
          problem = "the time " + std::to_string(state.time) +
                    " does not belong to step " + std::to_string(state.step);
        else if (!std::isfinite(state.state_tau) || !(state.state_tau > 0))
          problem = "the step size " + std::to_string(state.state_tau) +
                    " is not a positive number";
        else if (!std::isfinite(state.step_size_limit) ||
                 state.step_size_limit < 0)
          problem = "the step size limit " +
                    std::to_string(state.step_size_limit) +
                    " is not a number >= 0";
        else if (state.pvd_records.size() > state.step + 1)
          problem = "it lists more outputs than steps";
        if (!problem.empty())
          throw InputError("The checkpoint file <" + filename +
                           "> is damaged: " + problem + ".");
      }



      /**
       * The text of checkpoint.txt for the complete files of the
       * checkpoint directory @p directory and @p parameters.
       */
      std::string
      metadata_text(const fs::path &directory, const Parameters &parameters)
      {
        std::ostringstream out;
        out << metadata_header << '\n';
        for (const auto &[name, value] : parameters)
          out << "parameter " << name << " = " << value << '\n';
        std::vector<std::string> names;
        for (const auto &entry : fs::directory_iterator(directory))
          if (entry.is_regular_file() &&
              entry.path().filename() != metadata_filename)
            names.push_back(entry.path().filename().string());
        std::sort(names.begin(), names.end());
        for (const std::string &name : names)
          out << "file " << name << ' ' << fs::file_size(directory / name)
              << ' ' << file_checksum((directory / name).string()) << '\n';
        return out.str();
      }



      /**
       * On rank 0: refuse to write a checkpoint with the mesh files
       * @p files into @p directory if the file system has less room than
       * twice their size.
       */
      void
      check_free_space(const std::string                           &directory,
                       const std::vector<SavedFiles::ExpectedFile> &files)
      {
        double bytes = 0;
        for (const SavedFiles::ExpectedFile &file : files)
          bytes += file.size;
        std::error_code      error;
        const fs::space_info space = fs::space(directory, error);
        if (error || space.available >= 2 * bytes)
          return;
        throw WriteError(
          "Cannot write a checkpoint into <" + directory +
          ">: it needs about " +
          std::to_string(static_cast<long long>(bytes / 1e6) + 1) +
          " MB, but the file system has " +
          std::to_string(static_cast<long long>(space.available / 1e6)) +
          " MB free. The run stops here: statistics.csv and the output are "
          "complete up to this step, and the last complete checkpoint (if "
          "any) is intact.");
      }



      /**
       * Refuse to write the mesh files @p files if one of them would be
       * larger than this process's file size limit (`ulimit -f`): p4est
       * aborts when its writes fail. Not collective.
       */
      void
      check_file_size_limit(const std::vector<SavedFiles::ExpectedFile> &files)
      {
        rlimit limit;
        if (::getrlimit(RLIMIT_FSIZE, &limit) != 0 ||
            limit.rlim_cur == RLIM_INFINITY)
          return;
        for (const SavedFiles::ExpectedFile &file : files)
          if (file.size > limit.rlim_cur)
            throw WriteError(
              "Cannot write the checkpoint file <" + file.filename +
              ">: it needs " + std::to_string(file.size) +
              " bytes, more than the file size limit of this process (" +
              std::to_string(limit.rlim_cur) +
              " bytes, ulimit -f). The run stops here: statistics.csv and "
              "the output are complete up to this step, and the last "
              "complete checkpoint (if any) is intact.");
      }



      /**
       * Call @p read_back with the checkpoint @p path just written; an
       * InputError of its verification is a WriteError here (the files
       * do not hold what was written).
       */
      void
      read_back_as_written(
        const std::string                              &path,
        const std::function<void(const std::string &)> &read_back)
      {
        try
          {
            read_back(path);
          }
        catch (const InputError &error)
          {
            throw WriteError(
              "The checkpoint <" + path +
              "> just written does not read back as written: " + error.what());
          }
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
          throw InputError("The checkpoint file <" + filename +
                           "> is damaged.");
        // absent in the checkpoints of earlier versions: all fields
        std::string stored_key;
        state.n_stored_fields = state.n_fields;
        if (in >> stored_key &&
            (stored_key != "stored_fields" || !(in >> state.n_stored_fields) ||
             state.n_stored_fields == 0 ||
             state.n_stored_fields > state.n_fields))
          throw InputError("The checkpoint file <" + filename +
                           "> is damaged.");
        check_sanity(state, filename);
        return state;
      }

      /**
       * Check the checkpoint file of the line `<name> <size> <checksum>`
       * @p entry of the metadata file @p metadata of the checkpoint
       * @p path.
       */
      void
      verify_file(const std::string &entry,
                  const std::string &path,
                  const std::string &metadata)
      {
        std::istringstream in(entry);
        std::string        name, checksum;
        std::uintmax_t     size = 0;
        if (!(in >> name >> size >> checksum))
          throw InputError("The checkpoint file <" + metadata +
                           "> is damaged (line <file " + entry + ">).");
        const std::string    filename = path + "/" + name;
        std::error_code      error;
        const std::uintmax_t found = fs::file_size(filename, error);
        std::string          problem;
        if (error)
          problem = "is missing";
        else if (found != size)
          problem = "has " + std::to_string(found) + " bytes instead of " +
                    std::to_string(size) + (found < size ? " (truncated)" : "");
        else if (file_checksum(filename) != checksum)
          problem = "does not have the checksum recorded in <" + metadata +
                    "> (changed or damaged)";
        if (!problem.empty())
          throw InputError("The checkpoint file <" + filename + "> " + problem +
                           ": the checkpoint <" + path +
                           "> cannot be used. Start a new run with "
                           "<Checkpoint / Resume> = false (or restore the "
                           "file).");
      }



      /**
       * Compare the line `<name> = <value>` @p entry of the metadata file
       * @p metadata with this run's @p parameters; returns whether it
       * differs by an allowed change.
       */
      bool
      verify_parameter(const std::string              &entry,
                       const std::string              &metadata,
                       const Parameters               &parameters,
                       const std::vector<std::string> &allowed_changes)
      {
        const std::size_t equals = entry.find(" = ");
        if (equals == std::string::npos)
          throw InputError("The checkpoint file <" + metadata +
                           "> is damaged (line <parameter " + entry + ">).");
        const std::string name  = entry.substr(0, equals);
        const std::string saved = entry.substr(equals + 3);
        const auto        current =
          std::find_if(parameters.begin(),
                       parameters.end(),
                       [&](const auto &p) { return p.first == name; });
        if (current == parameters.end() || current->second == saved)
          return false;
        const std::string difference =
          "<" + name + "> = " + saved + " in the checkpoint (<" + metadata +
          ">), but " + current->second + " in this run";
        if (std::find(allowed_changes.begin(), allowed_changes.end(), name) !=
            allowed_changes.end())
          {
            std::cout << "Warning: resuming with " << difference
                      << " (allowed by <Checkpoint / Allow parameter change>)."
                      << std::endl;
            return true;
          }
        throw InputError("Cannot resume: " + difference +
                         ". Resume with the parameters of the run that wrote "
                         "the checkpoint, or allow the change with <Checkpoint "
                         "/ Allow parameter change> = " +
                         name + ".");
      }
    } // namespace



    std::string
    exact_value(const double value)
    {
      std::ostringstream text;
      text.precision(std::numeric_limits<double>::max_digits10);
      text << value;
      return text.str();
    }



    std::string
    exact_values(const std::vector<double> &values)
    {
      std::string text;
      for (const double value : values)
        text += (text.empty() ? "" : ", ") + exact_value(value);
      return text;
    }



    Parameters
    geometry_parameters(const GeometryParameters &geometry)
    {
      const std::string subsection = geometry.subsection + " / ";
      return {{subsection + "Shape", geometry.shape},
              {subsection + "Center", exact_values(geometry.center)},
              {subsection + "Second center",
               exact_values(geometry.second_center)},
              {subsection + "Radius", exact_value(geometry.radius)},
              {subsection + "Sizes", exact_values(geometry.sizes)},
              {subsection + "Expression", geometry.expression}};
    }



    std::string
    mesh_filename(const std::string &path)
    {
      return path + "/" + mesh_base_filename;
    }



    template <int dim>
    void
    write(const std::string                              &directory,
          const Discretization<dim>                      &discretization,
          const BlockVector                              &state,
          const State                                    &time_stepping_state,
          const Parameters                               &parameters,
          const std::function<void(const std::string &)> &read_back)
    {
      const MPI_Comm    comm = discretization.get_mpi_communicator();
      const std::string name =
        prefix + std::to_string(time_stepping_state.step);
      const fs::path     final_path = fs::path(directory) / name;
      const fs::path     temporary  = final_path.string() + temporary_suffix;
      const std::string  mesh       = mesh_filename(temporary.string());
      const auto        &mesh_cells = discretization.get_triangulation();
      const unsigned int dofs_per_cell =
        discretization.get_dof_handler().get_fe().n_dofs_per_cell();
      const std::vector<SavedFiles::ExpectedFile> expected =
        SavedFiles::expected_files(mesh,
                                   mesh_cells,
                                   dofs_per_cell,
                                   state.n_blocks());
      run_on_every_rank(comm, [&]() { check_file_size_limit(expected); });
      run_on_root(comm, [&]() {
        check_free_space(directory, expected);
        fs::remove_all(temporary);
        fs::create_directory(temporary);
      });
      try
        {
          discretization.save(mesh, state);
          SavedFiles::check(mesh, mesh_cells, dofs_per_cell, state.n_blocks());
          run_on_root(comm, [&]() {
            write_verified((temporary / state_filename).string(),
                           to_text(time_stepping_state));
            write_verified((temporary / metadata_filename).string(),
                           metadata_text(temporary, parameters));
          });
          read_back_as_written(temporary.string(), read_back);
        }
      catch (...)
        {
          run_on_root(comm, [&]() { fs::remove_all(temporary); });
          throw;
        }
      run_on_root(comm, [&]() {
        // the rename completes the checkpoint; only then the older ones go
        fs::remove_all(final_path);
        fs::rename(temporary, final_path);
        for (const fs::path &path : checkpoint_directories(directory))
          if (path != final_path)
            fs::remove_all(path);
      });
    }



    bool
    verify(const std::string              &path,
           const Parameters               &parameters,
           const std::vector<std::string> &allowed_changes,
           const MPI_Comm                  mpi_communicator)
    {
      bool changed = false;
      run_on_root(mpi_communicator, [&]() {
        const std::string metadata = path + "/" + metadata_filename;
        std::ifstream     in(metadata);
        std::string       line;
        if (!in || !std::getline(in, line) || line != metadata_header)
          throw InputError("The checkpoint file <" + metadata +
                           "> is missing or damaged: the checkpoint <" + path +
                           "> cannot be verified (written by an older "
                           "version, or damaged). Start a new run with "
                           "<Checkpoint / Resume> = false.");
        while (std::getline(in, line))
          if (line.rfind("parameter ", 0) == 0)
            changed = verify_parameter(line.substr(10),
                                       metadata,
                                       parameters,
                                       allowed_changes) ||
                      changed;
          else if (line.rfind("file ", 0) == 0)
            verify_file(line.substr(5), path, metadata);
          else
            throw InputError("The checkpoint file <" + metadata +
                             "> is damaged (line <" + line + ">).");
      });
      return dealii::Utilities::MPI::max(static_cast<int>(changed),
                                         mpi_communicator) != 0;
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
          throw InputError("Cannot read the checkpoint file <" + filename +
                           ">.");
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
             const State &,
             const Parameters &,
             const std::function<void(const std::string &)> &);
    template void
    write<3>(const std::string &,
             const Discretization<3> &,
             const BlockVector &,
             const State &,
             const Parameters &,
             const std::function<void(const std::string &)> &);
  } // namespace Checkpoint
} // namespace PhaseField
