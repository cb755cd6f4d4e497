#ifndef phasefield_time_time_loop_h
#define phasefield_time_time_loop_h

#include <boost/signals2/connection.hpp>
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <limits>
#include <optional>
#include <phasefield/core/linear_algebra.h>
#include <phasefield/core/parameters.h>
#include <phasefield/core/statistics.h>
#include <phasefield/mesh/discretization.h>
#include <phasefield/schemes/energies.h>
#include <phasefield/schemes/outer_energy.h>
#include <phasefield/schemes/time_stepping_scheme.h>
#include <phasefield/time/checkpoint.h>
#include <phasefield/time/start_value_predictor.h>
#include <string>
#include <utility>
#include <vector>

namespace PhaseField
{
  /**
   * The time loop of every time-dependent program: steps of the sizes of
   * ModelParameters::step_size() (ramp-up, then Tau), each retried with
   * half the step if the scheme's solver fails or its result breaks the
   * energy law (thesis Cor. 3.3, for schemes that have one) or changes the
   * inside measure by more than `Time stepping / Largest inside change
   * factor` (a jump to another branch of solutions), narrow-band
   * re-meshing every `Mesh / Refinement interval` steps, a row of
   * statistics.csv and a progress line per step, VTU output every
   * `Output / VTU interval` steps, a checkpoint every `Checkpoint /
   * Interval` steps (checkpoint.h) and resume() from the newest one. It
   * never asks which scheme it runs.
   *
   * What a problem adds to the loop, it says through a TimeLoop::Client.
   */
  template <int dim>
  class TimeLoop
  {
  public:
    /** The problem's part of the loop; every function has a default. */
    class Client
    {
    public:
      virtual ~Client() = default;

      /**
       * One time step of size @p tau from @p old_state into @p state
       * (which holds the start value). The default is one step of
       * @p scheme; a split step (shape from contour) is several.
       */
      virtual StepReport
      advance(TimeSteppingScheme<dim> &scheme,
              const BlockVector       &old_state,
              BlockVector             &state,
              const double             tau)
      {
        return scheme.advance(old_state, state, tau);
      }

      /**
       * Does the energy law of the scheme (TimeSteppingScheme::
       * has_energy_law()) hold for a step of advance()? Not for a split
       * step with a sub-step of another energy.
       */
      virtual bool
      energy_law_applies() const
      {
        return true;
      }

      /**
       * Is a step whose interface left the band of finest cells repeated
       * on the mesh refined there (TimeLoop::advance_on_resolving_mesh())?
       */
      virtual bool
      repeats_unresolved_steps() const
      {
        return true;
      }

      /**
       * The size the next step tries first, for the scheduled size
       * @p scheduled (ramp-up, Tau). The default takes the schedule; a
       * client with a step-size control of its own (shape from contour)
       * returns another, at most Settings::largest_step_factor times
       * @p scheduled.
       */
      virtual double
      next_step_size(const double scheduled) const
      {
        return scheduled;
      }

      /**
       * After step @p step was accepted: it went from @p old_state (with
       * @p old_energies) to @p state (with @p energies) with size @p tau,
       * tried first with @p tried_tau, as @p report says. The data of a
       * step-size control (next_step_size()).
       */
      virtual void
      step_accepted(const unsigned int step,
                    const BlockVector &old_state,
                    const Energies    &old_energies,
                    const BlockVector &state,
                    const Energies    &energies,
                    const StepReport  &report,
                    const double       tau,
                    const double       tried_tau)
      {
        (void)step;
        (void)old_state;
        (void)old_energies;
        (void)state;
        (void)energies;
        (void)report;
        (void)tau;
        (void)tried_tau;
      }

      /**
       * After the statistics row of step @p step with the @p energies of
       * @p state: should the run end here, before its last step? (The
       * automatic level transition of shape from contour.)
       */
      virtual bool
      finished(const unsigned int step,
               const BlockVector &state,
               const Energies    &energies)
      {
        (void)step;
        (void)state;
        (void)energies;
        return false;
      }

      /**
       * After the fields were transferred to a new mesh, before the
       * constraints are distributed and the scheme restores its fields
       * (edge restoration: the fixed values on the new mesh).
       */
      virtual void
      after_remesh(BlockVector &state)
      {
        (void)state;
      }

      /**
       * The problem's own state for a checkpoint, beyond mesh and fields
       * (shape from contour: the level and the energy history of the
       * automatic transition); after_load() gets it back.
       */
      virtual std::vector<double>
      checkpoint_data() const
      {
        return {};
      }

      /**
       * After a checkpoint was loaded into @p state on a new mesh: rebuild
       * the problem's own data on the mesh (edge restoration: the fixed
       * DoFs and values) and from the @p problem_data that
       * checkpoint_data() gave when it was written, leaving @p state as it
       * is.
       */
      virtual void
      after_load(BlockVector &state, const std::vector<double> &problem_data)
      {
        (void)state;
        (void)problem_data;
      }

      /**
       * ||U - U_exact(@p time)||_L2 where an exact evolution is known,
       * NaN otherwise.
       */
      virtual double
      l2_error(const BlockVector &state, const double time) const
      {
        (void)state;
        (void)time;
        return std::numeric_limits<double>::quiet_NaN();
      }

      /**
       * Names of the problem's own statistics.csv columns; the progress
       * line of each step shows them too.
       */
      virtual std::vector<std::string>
      extra_columns() const
      {
        return {};
      }

      /** Values of extra_columns() at @p state with @p energies. */
      virtual std::vector<double>
      extra_values(const BlockVector &state, const Energies &energies) const
      {
        (void)state;
        (void)energies;
        return {};
      }

      /**
       * The outer energy of the problem's scheme: its model terms write
       * their statistics columns (energy_term_columns()) before
       * extra_columns(). Default: none.
       */
      virtual OuterEnergy
      outer_energy() const
      {
        return OuterEnergy();
      }
    };

    /** The parameters the loop needs. */
    struct Settings
    {
      /** Step sizes (ramp-up, Tau) and the number of steps. */
      ModelParameters model;
      unsigned int    max_step_halvings;
      /**
       * ModelParameters::max_inside_change_factor: the largest factor by
       * which one step may change the inside measure (0: any change).
       */
      double max_inside_change_factor;
      /** NewtonParameters::regrow_step_size. */
      bool         regrow_step_size;
      bool         adaptive;
      unsigned int refinement_interval;
      unsigned int vtu_interval;
      bool         verbose;
      std::string  output_directory;
      /** Write a checkpoint every this many steps (0: never). */
      unsigned int checkpoint_interval;
      /**
       * Start steps of a scheme that iterates from its start value from
       * the StartValuePredictor's extrapolation.
       */
      bool extrapolated_start;
      /**
       * The parameters a checkpoint records and a resume compares
       * (Checkpoint::Parameters: program, Dimension, levels, Epsilon,
       * scheme, Inner tau, Adaptive).
       */
      std::vector<std::pair<std::string, std::string>> checkpoint_parameters;
      /** CheckpointParameters::allowed_changes. */
      std::vector<std::string> allowed_changes;
      /**
       * Is a resume whose checkpoint is at or after the last step
       * (nothing to do) an InputError? Not for a stage of a series
       * (shape from contour's levels), which then continues with the next
       * stage.
       */
      bool refuse_empty_resume = true;
      /**
       * The largest factor by which Client::next_step_size() may exceed the
       * scheduled sizes: the time a checkpoint may have reached by its
       * step (check_time()).
       */
      double largest_step_factor = 1;

      /**
       * The settings of the Willmore-flow parameters of the program
       * @p program_name.
       */
      static Settings
      from(const WillmoreParameters &parameters,
           const std::string        &program_name = "");
    };

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
      return time;
    }

    /** The last step taken (Client::finished() may end a run early). */
    unsigned int
    get_last_step() const
    {
      return last_step;
    }

  private:
    /** A step taken: its report, its size and the energies of its result. */
    struct StepResult
    {
      StepReport report;
      double     tau;
      Energies   energies;
    };

    /**
     * One try of a time step: its size and whether its start value is the
     * predictor's extrapolation (if it fails, the step is tried from the
     * last result before it is halved).
     */
    struct Attempt
    {
      double tau;
      bool   from_extrapolation;
    };

    /**
     * Replace the start value @p state of step @p step, of size @p tau (the
     * last result), by the predictor's extrapolation where the settings
     * and the scheme ask for it, the history allows it and the scheme
     * takes it (TimeSteppingScheme::take_extrapolated_start()). Returns
     * the attempt of the step.
     */
    Attempt
    predict_start_value(const unsigned int step,
                        BlockVector       &state,
                        const double       tau);

    /**
     * Do steps start from the predictor's extrapolation (settings and
     * scheme)? Only then does the loop keep the history of the steps.
     */
    bool
    extrapolates() const;

    /** The columns of statistics.csv. */
    std::vector<std::string>
    statistics_columns() const;

    /**
     * Steps @p first_step, ..., n_steps from @p state, with re-meshing and
     * checkpoints; the iteration of @p first_step starts from
     * @p first_start_value if given.
     */
    void
    run_steps(const unsigned int first_step,
              BlockVector       &state,
              const BlockVector *first_start_value = nullptr);

    /**
     * Load the newest checkpoint into @p state and restore time,
     * state_tau, the step offset, the last step and the .pvd records;
     * returns its step.
     */
    unsigned int
    load_checkpoint(BlockVector &state);

    /**
     * Throw an InputError if the time of the checkpoint @p saved (at
     * @p path, of a run without step offset) is later than the scheduled
     * step sizes reach by its step.
     */
    void
    check_time(const Checkpoint::State &saved, const std::string &path) const;

    /**
     * Write the checkpoint after step @p step (@p finished: the run ends
     * with it), then continue from it as a
     * resumed run would (load_checkpoint()): the same mesh in the order
     * of p4est (Discretization::load()), the same state and a fresh solver
     * (TimeSteppingScheme::reset_solver()). Only so are the following
     * steps bitwise those of a run resumed from this checkpoint on the
     * same number of ranks.
     */
    void
    write_checkpoint(const unsigned int step,
                     BlockVector       &state,
                     const bool         finished);

    /**
     * At the end of step @p step (not the last one): if SIGTERM or SIGINT
     * reached any rank (stop_requested()), write the checkpoint of
     * @p state if checkpoints are on and @p checkpoint_written is false,
     * and throw a StopRequest on every rank that says so.
     */
    void
    stop_if_requested(const unsigned int step,
                      BlockVector       &state,
                      const bool         checkpoint_written);

    /**
     * Step @p step from old_state into @p state by @p attempt, halved on
     * failure or rejection(); returns the report and the step size taken.
     * Where
     * the interface of the result left the band of finest cells
     * (Discretization::resolves_band()), the mesh is refined there and
     * the step repeated from old_state on it, with the result as the
     * start value: a minimiser computed on coarser cells is not the
     * minimiser on a mesh that resolves it, and its energy changes at the
     * next re-meshing (edge restoration at level 10: by half or more).
     */
    StepResult
    advance_on_resolving_mesh(const unsigned int step,
                              BlockVector       &state,
                              const Attempt      attempt);

    /**
     * Step @p step from old_state into @p state by @p attempt, halved on
     * failure or rejection(); returns the report and the step size taken.
     * @p start_tau is the step size of which @p state (the start value) is
     * the result.
     */
    StepResult
    advance_with_halving(const unsigned int step,
                         BlockVector       &state,
                         const double       start_tau,
                         Attempt            attempt);

    /**
     * Refine the mesh, never coarsen it, to the band of @p state, and
     * restore what the transfer broke in @p state (a result of step size
     * @p tau) and old_state.
     */
    void
    refine_to_band(BlockVector &state, const double tau);

    /**
     * After a transfer to a new mesh, restore what it broke in @p fields,
     * a state of step size @p tau: the client's data (fixed values), the
     * constraints, the scheme's fields (Client::after_remesh(),
     * TimeSteppingScheme::after_remesh()).
     */
    void
    restore_after_transfer(BlockVector &fields, const double tau);

    /**
     * @p fields and the vectors of the predictor's history: what a change
     * of the mesh transfers.
     */
    std::vector<BlockVector *>
    with_history(std::vector<BlockVector *> fields);

    /**
     * The blocks of @p fields that a change of the mesh carries: all but
     * those the scheme restores after it (TimeSteppingScheme::
     * restores_after_remesh()), swapped out of @p fields into a block
     * vector of their own for the transfer; give_back() returns them.
     */
    BlockVector
    carried_part(BlockVector &fields) const;

    /**
     * Swap the blocks of @p carried back into @p fields, after moving
     * @p fields to the new mesh (zero there) if the mesh @p changed.
     */
    void
    give_back(BlockVector &carried,
              BlockVector &fields,
              const bool   changed) const;

    /** The indices of the blocks carried_part() takes from @p n_fields. */
    std::vector<unsigned int>
    carried_blocks(const unsigned int n_fields) const;

    /** The indices 0, ..., @p n_fields - 1. */
    static std::vector<unsigned int>
    all_blocks(const unsigned int n_fields);

    /** Distribute the constraints in the transferred history. */
    void
    distribute_history_constraints();

    /**
     * Print why step @p step at size @p tau failed with a residual that is
     * not finite, naming the parameters that scale it.
     */
    void
    non_finite_residual_message(const unsigned int step,
                                const double       tau) const;

    /**
     * Why the converged result @p state, with @p energies, of a step of
     * size @p tau from old_state is not taken; empty if it is. Thesis
     * Cor. 3.3: on a fixed mesh the minimiser of the outer energy satisfies
     * E^{k+1} + dissipation <= E^k (for schemes with an energy law and
     * steps to which it applies), so a result above that is another
     * critical point. A flow moves the interface continuously, so a result
     * whose inside measure is more than Settings::max_inside_change_factor
     * times larger or smaller than old_state's has jumped to another branch
     * (the augmented Lagrangian's level-6 cube vanished in one step).
     */
    std::string
    rejection(const BlockVector &state,
              const Energies    &energies,
              const double       tau) const;

    /** The energies of @p state, computed unless state_energies has them. */
    Energies
    energies_of(const BlockVector &state) const;

    /** Adapt the mesh to the state and restore what the transfer broke. */
    void
    remesh(BlockVector &state);

    /**
     * Statistics row, progress line and (if due and @p with_output) VTU
     * output of step @p step with the @p energies of @p state, taken at
     * size @p tau after @p halvings halvings (column `step_halvings`); the
     * energies are kept as state_energies.
     */
    void
    record(const unsigned int step,
           const BlockVector &state,
           const Energies    &energies,
           const StepReport  &report,
           const double       tau,
           const unsigned int halvings    = 0,
           const bool         with_output = true);

    /** VTU output of the fields and the curvature. */
    void
    output_results(const unsigned int step, const BlockVector &state);

    /**
     * The size step @p step tries first: the scheduled size, at most
     * step_size_limit.
     */
    double
    first_step_size(const unsigned int step) const;

    const Settings                    settings;
    Discretization<dim>              &discretization;
    TimeSteppingScheme<dim>          &scheme;
    Client                           &client;
    const dealii::ConditionalOStream &pcout;
    dealii::TimerOutput              &timer;
    dealii::Timer                     wall_timer;
    std::unique_ptr<StatisticsFile>   statistics;

    /** Number of steps of this run (ramp-up and Tau). */
    const unsigned int n_steps;
    /** The step before the first step of this run (continue_run()). */
    unsigned int step_offset = 0;
    /** The last step of this run, step_offset + n_steps. */
    unsigned int final_step;
    /** The last step taken. */
    unsigned int last_step = 0;
    double       time      = 0;
    /**
     * Repetitions of a step on refined meshes (advance_on_resolving_mesh())
     * before the result is kept with a warning: each one refines where the
     * interface of the last result went, which the next result leaves
     * only if it moves on by the band margin.
     */
    static constexpr unsigned int max_step_repetitions = 3;
    /** The step size the multipliers of the current state belong to. */
    double state_tau;
    /**
     * The largest size the next step may try (Settings::regrow_step_size;
     * 0: no limit, the scheduled size).
     */
    double      step_size_limit = 0;
    BlockVector old_state;
    /**
     * The energies of old_state on the mesh of the current step, which
     * rejection() compares a result with.
     */
    Energies old_energies;
    /**
     * The energies of the state recorded last, while neither its mesh nor
     * its values changed since (remesh(), load_checkpoint() reset it): so
     * the energies of a state are computed once, where it is the result
     * of one step and the start of the next.
     */
    std::optional<Energies> state_energies;
    /**
     * Whether the last checkpoint loaded was written with other values of
     * its recorded parameters (Checkpoint / Allow parameter change): the
     * energy of its state belongs to those, and the energy law is not
     * checked in the first step after it (rejection()).
     */
    bool changed_on_resume = false;
    /** The history of the last steps (if extrapolates()). */
    StartValuePredictor predictor;
    /**
     * TimeSteppingScheme::before_remesh() on the triangulation's
     * pre_distributed_refinement signal: only when the mesh does change, so
     * that a step on an unchanged mesh keeps its solver.
     */
    boost::signals2::scoped_connection scheme_before_remesh;
  };
} // namespace PhaseField

#endif
