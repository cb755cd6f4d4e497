#ifndef phasefield_time_time_loop_h
#define phasefield_time_time_loop_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <memory>
#include <phasefield/core/linear_algebra.h>
#include <phasefield/core/parameters.h>
#include <phasefield/core/statistics.h>
#include <phasefield/mesh/discretization.h>
#include <phasefield/schemes/energies.h>
#include <phasefield/schemes/time_stepping_scheme.h>
#include <phasefield/time/checkpoint.h>
#include <phasefield/time/checkpointing.h>
#include <phasefield/time/loop_data.h>
#include <phasefield/time/recording.h>
#include <phasefield/time/remeshing.h>
#include <phasefield/time/start_value_predictor.h>
#include <phasefield/time/step_attempt.h>
#include <phasefield/time/step_size_policy.h>
#include <phasefield/time/time_loop_client.h>
#include <phasefield/time/time_loop_settings.h>

namespace PhaseField
{
  /**
   * The time loop of every time-dependent program: steps of the sizes of
   * a StepSizePolicy (ScheduledStepSizes: ModelParameters::step_size(),
   * ramp-up, then Tau; AdaptiveStepSizes: `Time stepping / Step control =
   * adaptive`), up to `Number of steps` or `End time`, or until the energy
   * is stationary (`Stationary tolerance`), each retried with half the step if
   * the scheme's solver fails or its result breaks the energy law (thesis
   * Cor. 3.3, for schemes that have one) or changes the inside measure by more
   * than `Time stepping / Largest inside change factor` (StepAttempt),
   * narrow-band re-meshing every `Mesh / Refinement interval` steps
   * (Remeshing), a row of statistics.csv and a progress line per step and
   * VTU output every `Output / VTU interval` steps (StepRecorder), a
   * checkpoint every `Checkpoint / Interval` steps and resume() from the
   * newest one (Checkpointing). It never asks which scheme it runs.
   *
   * What a problem adds to the loop, it says through a TimeLoop::Client.
   */
  template <int dim>
  class TimeLoop
  {
  public:
    /** The problem's part of the loop (TimeLoopClient). */
    using Client = TimeLoopClient<dim>;

    /** The parameters the loop needs (TimeLoopSettings). */
    using Settings = TimeLoopSettings;

    TimeLoop(const Settings                   &settings,
             Discretization<dim>              &discretization,
             TimeSteppingScheme<dim>          &scheme,
             Client                           &client,
             const dealii::ConditionalOStream &pcout,
             dealii::TimerOutput              &timer);

    /**
     * Run all steps from the initialised @p state (time 0, step 0 is
     * recorded first). The iteration of step 1 starts from
     * @p first_start_value if given (on the mesh of @p state, initialised
     * for step size `Tau`), otherwise from @p state. Throws if a step fails
     * after all halvings; the statistics and output up to the previous
     * step are then complete.
     */
    void
    run(BlockVector &state, const BlockVector *first_start_value = nullptr);

    /**
     * Instead of run(): load the newest checkpoint of the output directory
     * (on any number of ranks) into @p state on a new mesh, keep the rows
     * of statistics.csv and the .pvd records up to its step k, and run
     * steps k+1, ..., as the run that wrote it would have (none if that
     * run ended with step k). The checkpoint may have been written by
     * continue_run(): its step offset is restored. Throws InputError if
     * there is no checkpoint, or if it has another number of fields than
     * the scheme.
     */
    void
    resume(BlockVector &state);

    /**
     * Instead of run(): continue a series of runs on one statistics.csv
     * and .pvd (the levels of a multilevel schedule, each with its own
     * loop): append the row of @p state as step @p previous_step at
     * @p start_time (no VTU output for it: the previous run wrote that
     * step) and run steps previous_step + 1, ..., previous_step + the
     * number of steps of the settings.
     */
    void
    continue_run(BlockVector       &state,
                 const unsigned int previous_step,
                 const double       start_time);

    /** The time reached. */
    double
    get_time() const
    {
      return data.time;
    }

    /** The last step taken (Client::finished() may end a run early). */
    unsigned int
    get_last_step() const
    {
      return last_step;
    }

  private:
    /**
     * Steps @p first_step, ..., final_step from @p state, with re-meshing
     * and checkpoints; the iteration of @p first_step starts from
     * @p first_start_value if given.
     */
    void
    run_steps(const unsigned int first_step,
              BlockVector       &state,
              const BlockVector *first_start_value = nullptr);

    /**
     * Take the accepted @p result of step @p step into @p state, tried
     * first with @p tried_tau: the predictor's history, the step sizes,
     * the client, the time and the record of the step. Returns whether the
     * run ends with it (end time reached, or stationary()).
     */
    bool
    accept_step(const unsigned int                       step,
                const BlockVector                       &state,
                const typename StepAttempt<dim>::Result &result,
                const double                             tried_tau);

    /**
     * After the record of step @p step (@p finished: the run ends with it):
     * re-mesh @p state if due and write the checkpoint if due; returns
     * whether a checkpoint was written.
     */
    bool
    end_step(const unsigned int step, BlockVector &state, const bool finished);

    /**
     * @p tau, shortened to end at `End time` where it would pass it (or
     * end within round-off of it).
     */
    double
    within_end_time(const double tau) const;

    /** Has the run reached `End time` (if it has one)? */
    bool
    reached_end_time() const;

    /**
     * Is the relative change of the client's stationarity energy from
     * old_state to @p state (with @p energies), a step of size @p tau,
     * per unit time below `Stationary tolerance`? Says so if it is.
     */
    bool
    stationary(const unsigned int step,
               const BlockVector &state,
               const Energies    &energies,
               const double       tau) const;

    const Settings                    settings;
    Discretization<dim>              &discretization;
    TimeSteppingScheme<dim>          &scheme;
    Client                           &client;
    const dealii::ConditionalOStream &pcout;

    /** Number of steps of this run (TimeLoopSettings::n_steps()). */
    const unsigned int n_steps;
    /** The last step taken. */
    unsigned int last_step = 0;
    /** Time, steps and the start of the current step. */
    LoopData                        data;
    std::unique_ptr<StepSizePolicy> step_sizes;
    StepAttempt<dim>                step_attempt;
    Remeshing<dim>                  remeshing;
    StepRecorder<dim>               recorder;
    Checkpointing<dim>              checkpointing;
  };
} // namespace PhaseField

#endif
