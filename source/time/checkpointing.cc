#include <algorithm>
#include <deal.II/base/exceptions.h>
#include <phasefield/core/block_vector_tools.h>
#include <phasefield/core/file_io.h>
#include <phasefield/core/stop_request.h>
#include <phasefield/mesh/saved_files.h>
#include <phasefield/time/checkpointing.h>

namespace PhaseField
{
  using namespace dealii;



  namespace
  {
    /**
     * Throw an InputError if @p allowed_changes (`Checkpoint / Allow
     * parameter change`) names a parameter that is not among the
     * recorded @p parameters: a misspelt name would otherwise allow
     * nothing, silently.
     */
    void
    check_allowed_changes(const Checkpoint::Parameters   &parameters,
                          const std::vector<std::string> &allowed_changes)
    {
      std::string recorded;
      for (const auto &[name, value] : parameters)
        recorded += (recorded.empty() ? "" : ", ") + name;
      for (const std::string &name : allowed_changes)
        if (std::none_of(parameters.begin(),
                         parameters.end(),
                         [&](const auto &p) { return p.first == name; }))
          throw InputError("<Checkpoint / Allow parameter change> names <" +
                           name +
                           ">, which is not a parameter that this run's "
                           "checkpoints record; they record: " +
                           recorded + ".");
    }
  } // namespace



  template <int dim>
  Checkpointing<dim>::Checkpointing(const TimeLoopSettings   &settings,
                                    Discretization<dim>      &discretization,
                                    TimeSteppingScheme<dim>  &scheme,
                                    TimeLoopClient<dim>      &client,
                                    const ConditionalOStream &pcout,
                                    TimerOutput              &timer,
                                    LoopData                 &data,
                                    StepSizePolicy           &step_sizes,
                                    const Remeshing<dim>     &remeshing)
    : settings(settings)
    , discretization(discretization)
    , scheme(scheme)
    , client(client)
    , pcout(pcout)
    , timer(timer)
    , data(data)
    , step_sizes(step_sizes)
    , remeshing(remeshing)
    , n_steps(settings.n_steps())
  {
    check_allowed_changes(settings.checkpoint_parameters,
                          settings.allowed_changes);
  }



  template <int dim>
  void
  Checkpointing<dim>::check_time(const Checkpoint::State &saved,
                                 const std::string       &path) const
  {
    const double     longest  = step_sizes.latest_time(saved.step);
    constexpr double roundoff = 1e-12;
    if (saved.time <= longest * (1 + roundoff))
      return;
    throw InputError("The checkpoint <" + path + "> is after step " +
                     std::to_string(saved.step) + " at time " +
                     std::to_string(saved.time) + ", later than " +
                     std::to_string(longest) +
                     ", which steps of <Time stepping / Tau> (and the ramp-up) "
                     "reach: its state.txt is damaged, or <Time stepping / "
                     "Tau> is not that of the run that wrote it.");
  }



  template <int dim>
  Checkpoint::State
  Checkpointing<dim>::read_checked_state(const std::string &path)
  {
    const MPI_Comm comm = discretization.get_mpi_communicator();
    // before p4est or anything else reads the files
    data.changed_on_resume = Checkpoint::verify(path,
                                                settings.checkpoint_parameters,
                                                settings.allowed_changes,
                                                comm);
    if (data.changed_on_resume && scheme.has_energy_law())
      pcout << "The energy law is not checked in the first step after the "
               "checkpoint: its state belongs to the parameters it was "
               "written with."
            << std::endl;
    const Checkpoint::State saved = Checkpoint::read_state(path, comm);
    if (saved.step_offset == 0)
      check_time(saved, path);
    if (saved.n_fields != scheme.n_fields())
      throw InputError("The checkpoint <" + path + "> has " +
                       std::to_string(saved.n_fields) +
                       " fields, but the scheme <" + scheme.name() + "> has " +
                       std::to_string(scheme.n_fields()) +
                       " (<Time stepping / Scheme> must be that of the run "
                       "that wrote it).");
    return saved;
  }



  template <int dim>
  unsigned int
  Checkpointing<dim>::load_checkpoint(BlockVector &state)
  {
    TimerOutput::Scope t(timer, "checkpoint: load");
    const std::string  path =
      Checkpoint::find_last(settings.output_directory,
                            discretization.get_mpi_communicator());
    std::uint64_t stored_checksum = 0;
    return load_checkpoint_from(path, state, stored_checksum);
  }



  template <int dim>
  unsigned int
  Checkpointing<dim>::load_checkpoint_from(const std::string &path,
                                           BlockVector       &state,
                                           std::uint64_t     &stored_checksum)
  {
    const Checkpoint::State saved = read_checked_state(path);
    BlockVector             stored(saved.n_stored_fields);
    discretization.load(Checkpoint::mesh_filename(path), stored);
    stored_checksum =
      SavedFiles::field_checksum(discretization.get_dof_handler(), stored);
    discretization.reinit(state, saved.n_fields);
    const bool restores = saved.n_stored_fields < saved.n_fields;
    const std::vector<unsigned int> blocks =
      restores ? remeshing.carried_blocks(saved.n_fields) :
                 remeshing.all_blocks(saved.n_fields);
    if (blocks.size() != saved.n_stored_fields)
      throw InputError("The checkpoint <" + path + "> holds " +
                       std::to_string(saved.n_stored_fields) + " of the " +
                       std::to_string(saved.n_fields) +
                       " fields, but the scheme <" + scheme.name() +
                       "> restores the others only with " +
                       std::to_string(blocks.size()) + " stored.");
    swap_into(blocks, stored, state);
    discretization.reinit(data.old_state, saved.n_fields);
    discretization.set_pvd_records(saved.pvd_records);
    data.time = saved.time;
    step_sizes.load(saved);
    data.step_offset = saved.step_offset;
    data.final_step  = saved.finished ? saved.step : data.step_offset + n_steps;
    client.after_load(state, saved.problem_data);
    data.state_energies.reset();
    scheme.reset_solver();
    if (restores)
      {
        scheme.after_remesh(state, step_sizes.state_tau());
        discretization.distribute_constraints(state);
      }
    // the DoFs are in p4est's order now, and a resumed run has no history
    data.predictor.forget();
    return saved.step;
  }



  template <int dim>
  void
  Checkpointing<dim>::write_checkpoint(const unsigned int step,
                                       BlockVector       &state,
                                       const bool         finished)
  {
    TimerOutput::Scope t(timer, "checkpoint: write");
    Checkpoint::State  saved;
    saved.step         = step;
    saved.time         = data.time;
    saved.n_fields     = state.n_blocks();
    saved.pvd_records  = discretization.get_pvd_records();
    saved.step_offset  = data.step_offset;
    saved.finished     = finished && step != data.final_step;
    saved.problem_data = client.checkpoint_data();
    step_sizes.save(saved);
    // the fields a change of the mesh carries: the packing of the others
    // would be the peak of the step's memory (TimeSteppingScheme::
    // restores_after_remesh()); the reload below restores them
    BlockVector carried   = remeshing.carried_part(state);
    saved.n_stored_fields = carried.n_blocks();
    const std::uint64_t written_checksum =
      SavedFiles::field_checksum(discretization.get_dof_handler(), carried);
    bool given_back = false;
    // continue from what was written, as a resumed run does: the same
    // cell and DoF order, a fresh solver; the checkpoint replaces the
    // previous one only if it reads back as written
    const auto read_back = [&](const std::string &path) {
      remeshing.give_back(carried, state, false);
      given_back                  = true;
      std::uint64_t read_checksum = 0;
      load_checkpoint_from(path, state, read_checksum);
      if (read_checksum != written_checksum)
        throw WriteError(
          "The fields read back from the checkpoint <" + path +
          "> are not those written into its mesh files (a file size limit "
          "(ulimit -f), a quota or a full disk?). The run stops here: "
          "statistics.csv and the output are complete up to this step, the "
          "incomplete checkpoint is removed, and the last complete "
          "checkpoint (if any) is intact.");
    };
    try
      {
        Checkpoint::write(settings.output_directory,
                          discretization,
                          carried,
                          saved,
                          settings.checkpoint_parameters,
                          read_back);
      }
    catch (...)
      {
        if (!given_back)
          remeshing.give_back(carried, state, false);
        throw;
      }
    pcout << "  checkpoint written after step " << step << std::endl;
  }



  template <int dim>
  void
  Checkpointing<dim>::stop_if_requested(const unsigned int step,
                                        BlockVector       &state,
                                        const bool         checkpoint_written)
  {
    const std::string signal =
      stop_requested(discretization.get_mpi_communicator());
    if (signal.empty())
      return;
    std::string checkpoint =
      "no checkpoint was written (<Checkpoint / Interval> = 0).";
    if (settings.checkpoint_interval > 0)
      {
        // the state is that of the start of the next step (re-meshed)
        if (!checkpoint_written)
          write_checkpoint(step, state, false);
        checkpoint = "the checkpoint of this step is in <" +
                     settings.output_directory + "/checkpoint-" +
                     std::to_string(step) +
                     ">: continue with <Checkpoint / Resume> = true.";
      }
    throw StopRequest("Stopped by " + signal + " after step " +
                      std::to_string(step) +
                      ": statistics.csv and the output are complete up to "
                      "this step, and " +
                      checkpoint);
  }



  template class Checkpointing<2>;
  template class Checkpointing<3>;
} // namespace PhaseField
