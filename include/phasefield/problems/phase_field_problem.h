#ifndef phasefield_problems_phase_field_problem_h
#define phasefield_problems_phase_field_problem_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/function.h>
#include <deal.II/base/timer.h>
#include <memory>
#include <phasefield/core/linear_algebra.h>
#include <phasefield/core/parameters.h>
#include <phasefield/core/quiet_timer_output.h>
#include <phasefield/mesh/discretization.h>
#include <phasefield/schemes/outer_energy.h>
#include <phasefield/schemes/time_stepping_scheme.h>
#include <phasefield/time/checkpoint.h>
#include <phasefield/time/time_loop.h>
#include <string>

namespace PhaseField
{
  /**
   * A gradient flow of a phase field from an initial shape, in the shape
   * of the deal.II tutorials: create the narrow-band mesh around the
   * shape, initialise the fields (U = tanh(d/eps), the others by the
   * scheme), run the TimeLoop. It owns the Discretization, the scheme
   * (made by create_time_stepping_scheme()) and the state; the programs'
   * problems derive from it and add what is their own through the
   * TimeLoop::Client functions (WillmoreProblem: the exact solution;
   * RestorationProblem: the fixed region and its pictures).
   */
  template <int dim>
  class PhaseFieldProblem : public TimeLoop<dim>::Client
  {
  public:
    /**
     * Run the whole simulation: from the initial shape, or with
     * `Checkpoint / Resume` from the newest checkpoint in the output
     * directory (TimeLoop::resume()). Throws on failure.
     *
     * A template method: the set-up common to every program (output
     * directory, set_first_level(), the scheme, print_header(), the
     * initial mesh and fields unless resumed) and the final summary
     * (timers, peak memory, partition balance) are here once, and
     * run_time_loops() in between is what a program changes.
     */
    virtual void
    run();

    /** The state after run() ((U, V, P) or (U, F)), e.g. for tests. */
    const BlockVector &
    state() const
    {
      return solution;
    }

    /** The discretisation of state() (e.g. for pictures and tests). */
    const Discretization<dim> &
    get_discretization() const
    {
      return discretization;
    }

    /** What a program chooses beyond the parameters. */
    struct Setup
    {
      /** Name printed in the first line of the log. */
      std::string program_name;
      /** Signed distance of the initial shape. */
      std::shared_ptr<dealii::Function<dim>> signed_distance;
      /** Weights and fixed values of the outer energy. */
      OuterEnergy outer_energy;
      /** Narrow-band hysteresis (Discretization::Settings). */
      double coarsening_band_factor = 1;
      /**
       * The finest level of all meshes of the run, if finer than `Mesh /
       * Finest level` of the parameters (shape from contour: the last of
       * `Multilevel / Levels`); 0: that of the parameters. The mesh starts
       * on the level of set_first_level() (Discretization::
       * start_at_level()), and Discretization::refine_to_level() moves it
       * up to this one.
       */
      unsigned int finest_level = 0;
    };

  protected:
    PhaseFieldProblem(const WillmoreParameters &parameters, const Setup &setup);

    /**
     * U = tanh(d/eps) at the nodes, then the other fields by the scheme.
     * Called once the mesh exists.
     */
    virtual void
    initialize_fields();

    /**
     * Make the scheme of @p parameters (Time stepping / Scheme, epsilon,
     * inner tau, Newton and linear-solver settings) with the outer energy
     * of the setup.
     */
    void
    create_scheme(const WillmoreParameters &parameters);

    /**
     * The outer energy of the schemes that create_scheme() makes: the
     * setup's. A problem whose steps minimise a term of its own returns it
     * with OuterEnergy::data_term set (shape from contour's monolithic
     * coupling).
     */
    virtual OuterEnergy
    scheme_outer_energy() const
    {
      return setup.outer_energy;
    }

    /** The outer energy of the scheme (scheme_outer_energy()). */
    OuterEnergy
    outer_energy() const override
    {
      return scheme_outer_energy();
    }

    /** The first lines of the log: what runs, with which solver. */
    virtual void
    print_header() const;

    /**
     * The problem's own parameters that change the meaning of its state,
     * which a checkpoint records and a resume compares (refused unless
     * listed in `Checkpoint / Allow parameter change`), beyond those of
     * TimeLoop::Settings::from(). The default: none.
     */
    virtual Checkpoint::Parameters
    own_checkpoint_parameters() const
    {
      return {};
    }

    /**
     * The TimeLoop settings of @p parameters for this program, with
     * own_checkpoint_parameters() among the recorded parameters.
     */
    typename TimeLoop<dim>::Settings
    time_loop_settings(const WillmoreParameters &parameters) const;

    /**
     * Hook of run(), after the output directory exists and before the
     * scheme is made: set level_parameters to the parameters of the level
     * the run starts on. The default keeps willmore_parameters (a coarse
     * start level is the business of the initial state, not of a resume).
     */
    virtual void
    set_first_level();

    /**
     * Hook of run(), after the initial fields are set (or, with
     * `Checkpoint / Resume`, before anything is loaded): the TimeLoop(s)
     * of the run. The default is one TimeLoop on willmore_parameters,
     * whose step 1 starts from coarse_start_value() if the initial state
     * is on a coarse start level, or which resumes from the checkpoint.
     */
    virtual void
    run_time_loops();

    /**
     * Nested iteration for the first step (`Time stepping / Coarse start
     * level`): from the mesh and initial fields of level_parameters, the level
     * WillmoreParameters::start_level(), compute step 1 there, carry its
     * result to the next finer level (refine the narrow band of the result
     * and of the initial data there, sharpen the profile to the finer
     * epsilon, the fields of the scheme for it) and repeat up to Finest
     * level - 1. Returns the start value of step 1 on Finest level, or an
     * empty vector if a coarse step did not converge (step 1 then starts
     * from the initial data). The mesh, the initial fields, the scheme and
     * level_parameters are then those of Finest level. The step on Finest level
     * is the same step: only the start of its iteration changes. A
     * minimiser found on a coarser level is close to the fine one where
     * the coarse epsilon is small against the distance the interface
     * travels (the gap of a damaged edge).
     */
    BlockVector
    coarse_start_value();

    /** U = tanh(d/eps) at the nodes, with the epsilon of level_parameters. */
    void
    interpolate_initial_u(Vector &u) const;

    /**
     * U <- tanh(@p ratio artanh(U)) at every locally owned node: the
     * profile tanh(d/eps_old) becomes tanh(d/eps_new) for
     * @p ratio = eps_old/eps_new, with the zero level set unchanged.
     */
    static void
    sharpen_profile(Vector &u, const double ratio);

    /**
     * Refine the mesh to the finest level @p level
     * (Discretization::refine_to_level()) carrying only U, block 0 of
     * @p state; the other blocks come back zero on the new mesh. For a
     * level transition after which TimeSteppingScheme::initialize() sets
     * them from U: their packing would raise the transition's memory
     * peak for nothing.
     */
    void
    refine_u_to_level(const unsigned int level,
                      BlockVector       &state,
                      const double       band_scale);

    const WillmoreParameters &willmore_parameters;
    /**
     * The parameters of the level the fields are on: willmore_parameters, or a
     * coarser level (coarse_start_value(), shape from contour's schedule).
     */
    WillmoreParameters         level_parameters;
    const Setup                setup;
    const MPI_Comm             mpi_communicator;
    dealii::ConditionalOStream pcout;
    /** Quiet when destroyed by an exception (QuietTimerOutput). */
    QuietTimerOutput    computing_timer;
    Discretization<dim> discretization;
    BlockVector         solution;

    std::unique_ptr<TimeSteppingScheme<dim>> scheme;

  private:
    /**
     * The mesh around the initial shape and the initial fields, on the
     * coarse start level (WillmoreParameters::start_level()) of
     * level_parameters if it has one, with the scheme of that level.
     */
    void
    create_initial_state();

    /**
     * Step 1 on the level of level_parameters from the initial fields into
     * @p start (which holds the start value). Returns whether it
     * converged.
     */
    bool
    solve_coarse_step(BlockVector &start);

    /**
     * Carry the coarse result @p start and the initial fields to the
     * finer level @p level (coarse_start_value()).
     */
    void
    move_start_to_level(const unsigned int level, BlockVector &start);
  };
} // namespace PhaseField

#endif
