#ifndef phasefield_time_step_attempt_h
#define phasefield_time_step_attempt_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <phasefield/core/linear_algebra.h>
#include <phasefield/schemes/energies.h>
#include <phasefield/schemes/time_stepping_scheme.h>
#include <phasefield/time/loop_data.h>
#include <phasefield/time/step_size_policy.h>
#include <phasefield/time/time_loop_client.h>
#include <phasefield/time/time_loop_settings.h>
#include <string>

namespace PhaseField
{
  /**
   * One time step of the time loop on a fixed mesh: from LoopData::
   * old_state into the state by the client's advance(), from the
   * predictor's extrapolation where it is taken, retried with half the
   * step if the scheme's solver fails or rejection() rejects the result.
   */
  template <int dim>
  class StepAttempt
  {
  public:
    /** A step taken: its report, its size and the energies of its result. */
    struct Result
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

    StepAttempt(const TimeLoopSettings           &settings,
                TimeSteppingScheme<dim>          &scheme,
                TimeLoopClient<dim>              &client,
                const dealii::ConditionalOStream &pcout,
                dealii::TimerOutput              &timer,
                LoopData                         &data,
                const StepSizePolicy             &step_sizes);

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

    /**
     * Step @p step from old_state into @p state by @p attempt, halved on
     * failure or rejection(); returns the report and the step size taken.
     * @p start_tau is the step size of which @p state (the start value) is
     * the result.
     */
    Result
    advance_with_halving(const unsigned int step,
                         BlockVector       &state,
                         const double       start_tau,
                         Attempt            attempt);

  private:
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

    /**
     * The step-size policy's rejection() of the result @p state of step
     * @p step of size @p tau from old_state (an adaptive control's error
     * estimate), after @p halvings halvings: after the last halving the
     * step is taken with a warning instead, as the estimate does not fall
     * with the step size then.
     */
    std::string
    error_rejection(const unsigned int step,
                    const BlockVector &state,
                    const double       tau,
                    const unsigned int halvings) const;

    const TimeLoopSettings           &settings;
    TimeSteppingScheme<dim>          &scheme;
    TimeLoopClient<dim>              &client;
    const dealii::ConditionalOStream &pcout;
    dealii::TimerOutput              &timer;
    LoopData                         &data;
    const StepSizePolicy             &step_sizes;
  };
} // namespace PhaseField

#endif
