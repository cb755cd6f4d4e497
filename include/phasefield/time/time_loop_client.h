#ifndef phasefield_time_time_loop_client_h
#define phasefield_time_time_loop_client_h

#include <limits>
#include <phasefield/core/linear_algebra.h>
#include <phasefield/schemes/energies.h>
#include <phasefield/schemes/outer_energy.h>
#include <phasefield/schemes/time_stepping_scheme.h>
#include <string>
#include <vector>

namespace PhaseField
{
  /**
   * The problem's part of the time loop (TimeLoop::Client); every function
   * has a default.
   */
  template <int dim>
  class TimeLoopClient
  {
  public:
    virtual ~TimeLoopClient() = default;

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
     * advance() by @p tau from @p old_state into @p state, a start value
     * of step size @p start_tau, with @p state prepared for the steps of
     * the scheme (sub_step_size()) and the result for @p tau
     * (TimeSteppingScheme::prepare_step()).
     */
    StepReport
    prepared_advance(TimeSteppingScheme<dim> &scheme,
                     const BlockVector       &old_state,
                     BlockVector             &state,
                     const double             start_tau,
                     const double             tau)
    {
      const double sub_tau = sub_step_size(tau);
      scheme.prepare_step(state, start_tau, tau);
      scheme.prepare_step(state, tau, sub_tau);
      const StepReport report = advance(scheme, old_state, state, tau);
      scheme.prepare_step(state, sub_tau, tau);
      return report;
    }

    /**
     * The size of the steps of the scheme within a step of size @p tau of
     * advance(): the loop prepares the start value for it before
     * advance() and the result for @p tau after it (TimeSteppingScheme::
     * prepare_step(), which scales the multipliers to a step size). The
     * default is @p tau; a split step (shape from contour) has sub-steps
     * of tau/2.
     */
    virtual double
    sub_step_size(const double tau) const
    {
      return tau;
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
     * on the mesh refined there (Remeshing::advance_on_resolving_mesh())?
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
     * returns another, at most TimeLoopSettings::largest_step_factor times
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
     * The energy whose relative change per unit time `Time stepping /
     * Stationary tolerance` compares, of @p state with @p energies; the
     * default is that of the scheme's energy law.
     */
    virtual double
    stationarity_energy(const TimeSteppingScheme<dim> &scheme,
                        const BlockVector             &state,
                        const Energies                &energies) const
    {
      (void)state;
      return scheme.energy_law_energy(energies);
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
} // namespace PhaseField

#endif
