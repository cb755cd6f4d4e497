#ifndef phasefield_time_checkpointing_h
#define phasefield_time_checkpointing_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <phasefield/core/linear_algebra.h>
#include <phasefield/mesh/discretization.h>
#include <phasefield/schemes/time_stepping_scheme.h>
#include <phasefield/time/checkpoint.h>
#include <phasefield/time/loop_data.h>
#include <phasefield/time/remeshing.h>
#include <phasefield/time/step_size_policy.h>
#include <phasefield/time/time_loop_client.h>
#include <phasefield/time/time_loop_settings.h>
#include <string>

namespace PhaseField
{
  /**
   * The checkpoints of the time loop (checkpoint.h): writing one after a
   * step and continuing from it, loading the newest one with the checks
   * of its parameters and time, and the stop on SIGTERM, SIGINT or SIGHUP.
   */
  template <int dim>
  class Checkpointing
  {
  public:
    Checkpointing(const TimeLoopSettings           &settings,
                  Discretization<dim>              &discretization,
                  TimeSteppingScheme<dim>          &scheme,
                  TimeLoopClient<dim>              &client,
                  const dealii::ConditionalOStream &pcout,
                  dealii::TimerOutput              &timer,
                  LoopData                         &data,
                  StepSizePolicy                   &step_sizes,
                  const Remeshing<dim>             &remeshing);

    /**
     * Load the newest checkpoint into @p state and restore the time, the
     * step-size policy's state (StepSizePolicy::load()), the step offset,
     * the last step and the .pvd records; returns its step.
     */
    unsigned int
    load_checkpoint(BlockVector &state);

    /**
     * Write the checkpoint after step @p step (@p finished: the run ends
     * with it), then continue from it as a
     * resumed run would (load_checkpoint()): the same mesh in the order
     * of p4est (Discretization::load()), the same state and a fresh solver
     * (TimeSteppingScheme::reset_solver()). Only so are the following
     * steps bitwise those of a run resumed from this checkpoint on the
     * same number of ranks. The reload happens before the checkpoint
     * replaces the previous one, and the fields read back must have the
     * checksum of the fields written (SavedFiles::field_checksum());
     * otherwise a WriteError names the checkpoint.
     */
    void
    write_checkpoint(const unsigned int step,
                     BlockVector       &state,
                     const bool         finished);

    /**
     * At the end of step @p step (not the last one): if SIGTERM, SIGINT or
     * SIGHUP reached any rank (stop_requested()), write the checkpoint of
     * @p state if checkpoints are on and @p checkpoint_written is false,
     * and throw a StopRequest on every rank that says so.
     */
    void
    stop_if_requested(const unsigned int step,
                      BlockVector       &state,
                      const bool         checkpoint_written);

  private:
    /**
     * Throw an InputError if the time of the checkpoint @p saved (at
     * @p path, of a run without step offset) is later than the step sizes
     * reach by its step (StepSizePolicy::latest_time()).
     */
    void
    check_time(const Checkpoint::State &saved, const std::string &path) const;

    /**
     * The state of the checkpoint at @p path, after its parameters were
     * verified (Checkpoint::verify(), which sets LoopData::
     * changed_on_resume), its time (check_time()) and its number of
     * fields.
     */
    Checkpoint::State
    read_checked_state(const std::string &path);

    /**
     * load_checkpoint() from the checkpoint at @p path; returns its step
     * and sets @p stored_checksum to the SavedFiles::field_checksum() of
     * the fields read from its mesh files.
     */
    unsigned int
    load_checkpoint_from(const std::string &path,
                         BlockVector       &state,
                         std::uint64_t     &stored_checksum);

    const TimeLoopSettings           &settings;
    Discretization<dim>              &discretization;
    TimeSteppingScheme<dim>          &scheme;
    TimeLoopClient<dim>              &client;
    const dealii::ConditionalOStream &pcout;
    dealii::TimerOutput              &timer;
    LoopData                         &data;
    StepSizePolicy                   &step_sizes;
    const Remeshing<dim>             &remeshing;
    /** Number of steps of a run (ramp-up and Tau). */
    const unsigned int n_steps;
  };
} // namespace PhaseField

#endif
