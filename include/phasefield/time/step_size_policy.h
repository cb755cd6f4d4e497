#ifndef phasefield_time_step_size_policy_h
#define phasefield_time_step_size_policy_h

#include <functional>
#include <memory>
#include <optional>
#include <phasefield/core/linear_algebra.h>
#include <phasefield/core/parameters.h>
#include <phasefield/time/checkpoint.h>
#include <phasefield/time/local_error_estimate.h>
#include <phasefield/time/time_loop_settings.h>
#include <string>
#include <vector>

namespace PhaseField
{
  /**
   * The rule every step-size control of this library ends with: the next
   * size is the last one times a factor, at most the last one after a
   * step that was halved (a grown step that fails is retried at the size
   * that worked), within [smallest, largest] (0: no limit). The adaptive
   * control (AdaptiveStepSizes) and shape from contour's
   * (ContourProblem::step_accepted()) choose only the factor.
   */
  struct StepSizeLimits
  {
    double smallest = 0;
    double largest  = 0;

    /**
     * The size after a step of size @p tau, tried first with
     * @p tried_tau, with the growth @p factor.
     */
    double
    next(const double tau, const double tried_tau, const double factor) const;
  };



  /**
   * The step sizes of the time loop: the size each step tries first, what
   * an accepted step changes, the time a checkpoint may have reached, and
   * the state of all that which a checkpoint records. The loop halves a
   * size that fails (StepAttempt); a policy only chooses first sizes.
   *
   * The policy also keeps the size of the last accepted step (state_tau(),
   * the step size the multipliers of the current state belong to).
   */
  class StepSizePolicy
  {
  public:
    /** @p start_tau: the step size of the initial state. */
    explicit StepSizePolicy(const double start_tau);

    virtual ~StepSizePolicy() = default;

    /**
     * The size step @p run_step of this run (counted from the step offset
     * of TimeLoop::continue_run()) tries first.
     */
    virtual double
    first_step_size(const unsigned int run_step) const = 0;

    /**
     * After a step was accepted at size @p tau, tried first with
     * @p tried_tau, from @p before to @p after: after_accepted(), then
     * state_tau() is @p tau.
     */
    void
    accept(const double       tau,
           const double       tried_tau,
           const BlockVector &before,
           const BlockVector &after);

    /**
     * Why the converged step of size @p tau from @p before to @p after is
     * not taken (its error is too large); empty if it is. The default
     * takes every step.
     */
    virtual std::string
    rejection(const BlockVector &before,
              const BlockVector &after,
              const double       tau) const;

    /**
     * The vectors the policy keeps on the mesh, to be transferred with the
     * state when the mesh changes; default: none.
     */
    virtual std::vector<BlockVector *>
    history();

    /** Names of the policy's own statistics.csv columns; default: none. */
    virtual std::vector<std::string>
    statistics_columns() const;

    /** Values of statistics_columns() for the step accepted last. */
    virtual std::vector<double>
    statistics_values() const;

    /** The step size the multipliers of the current state belong to. */
    double
    state_tau() const
    {
      return current_tau;
    }

    /**
     * The latest time a run without step offset may have reached after
     * step @p step (Checkpointing::check_time()).
     */
    virtual double
    latest_time(const unsigned int step) const = 0;

    /** Record the policy's state in the checkpoint state @p saved. */
    virtual void
    save(Checkpoint::State &saved) const;

    /** Restore the policy's state from the checkpoint state @p saved. */
    virtual void
    load(const Checkpoint::State &saved);

  protected:
    /**
     * What step sizes an accepted step (accept()) of size @p tau from
     * @p before to @p after changes.
     */
    virtual void
    after_accepted(const double       tau,
                   const double       tried_tau,
                   const BlockVector &before,
                   const BlockVector &after) = 0;

  private:
    double current_tau;
  };



  /**
   * The sizes of ModelParameters::step_size() (ramp-up, then Tau) as the
   * client changes them (TimeLoopClient::next_step_size()), at most
   * twice the last size taken if Settings::regrow_step_size and the last
   * step was not halved, else at most that size.
   */
  class ScheduledStepSizes : public StepSizePolicy
  {
  public:
    /**
     * @p client_step_size: the client's size for a scheduled size
     * (TimeLoopClient::next_step_size()).
     */
    ScheduledStepSizes(const TimeLoopSettings             &settings,
                       std::function<double(const double)> client_step_size);

    double
    first_step_size(const unsigned int run_step) const override;

    /** The scheduled sizes (times Settings::largest_step_factor) summed. */
    double
    latest_time(const unsigned int step) const override;

    void
    save(Checkpoint::State &saved) const override;

    void
    load(const Checkpoint::State &saved) override;

  protected:
    void
    after_accepted(const double       tau,
                   const double       tried_tau,
                   const BlockVector &before,
                   const BlockVector &after) override;

  private:
    const ModelParameters                     model;
    const bool                                regrow_step_size;
    const double                              largest_step_factor;
    const std::function<double(const double)> client_step_size;
    /**
     * The largest size the next step may try (Settings::regrow_step_size;
     * 0: no limit, the scheduled size).
     */
    double step_size_limit = 0;
  };



  /**
   * `Time stepping / Step control = adaptive`: the first step is the
   * scheduled first size (Tau, or the first ramp-up size); each accepted
   * step sets the next size by the PI controller of Gustafsson (Hairer and
   * Wanner, Solving ODEs II, IV.2) from the local error estimate e_k of
   * the step (LocalErrorEstimate) and e_{k-1} of the step before,
   *
   *   tau_{k+1} = tau_k * 0.9 (tol / e_k)^{0.35} (e_{k-1} / tol)^{0.2},
   *
   * the exponents 0.7 / 2 and 0.4 / 2 of a method whose local error is
   * of order tau^2; (tol / e_k)^{1/2} without e_{k-1}; the factor
   * within [0.2, 2], then StepSizeLimits. A converged step whose estimate
   * exceeds the tolerance is rejected (and halved by the time loop)
   * unless it is at the smallest size. Without an estimate (the first
   * two steps, the first after a resume) the size is kept: the first step
   * of a run relaxes the initial data to the discrete profile as well as
   * moving it, a change that is not of the order tau, and is not compared
   * with (the estimate of step 2 would fall only linearly with its size).
   */
  class AdaptiveStepSizes : public StepSizePolicy
  {
  public:
    /**
     * @p lumped_mass: the lumped mass of the current mesh, the norm of the
     * estimate (a reference that stays valid when the mesh changes).
     */
    AdaptiveStepSizes(const TimeLoopSettings &settings,
                      const Vector           &lumped_mass);

    double
    first_step_size(const unsigned int run_step) const override;

    /** The end time, or the largest steps summed (no bound without). */
    double
    latest_time(const unsigned int step) const override;

    std::string
    rejection(const BlockVector &before,
              const BlockVector &after,
              const double       tau) const override;

    std::vector<BlockVector *>
    history() override;

    /** `error_estimate`: e_k of the step accepted last (nan without). */
    std::vector<std::string>
    statistics_columns() const override;

    std::vector<double>
    statistics_values() const override;

    /** The next size, as the size limit of @p saved. */
    void
    save(Checkpoint::State &saved) const override;

    /** The next size; the history starts anew (the DoFs changed). */
    void
    load(const Checkpoint::State &saved) override;

  protected:
    void
    after_accepted(const double       tau,
                   const double       tried_tau,
                   const BlockVector &before,
                   const BlockVector &after) override;

  private:
    /** The estimate of the step of size @p tau from @p before to @p after. */
    std::optional<double>
    estimate(const BlockVector &before,
             const BlockVector &after,
             const double       tau) const;

    /** The controller's growth factor for the estimate @p error. */
    double
    growth_factor(const std::optional<double> error) const;

    /** Safety factor and exponents of the controller. */
    static constexpr double safety                = 0.9;
    static constexpr double integral_exponent     = 0.35;
    static constexpr double proportional_exponent = 0.2;
    static constexpr double elementary_exponent   = 0.5;
    /** The factor's range per step. */
    static constexpr double smallest_factor = 0.2;
    static constexpr double largest_factor  = 2;

    const double         tolerance;
    const double         end_time;
    const StepSizeLimits limits;
    const Vector        &lumped_mass;
    LocalErrorEstimate   error_estimate;
    /** The size the next step tries. */
    double next_tau;
    /** e_k of the step accepted last. */
    std::optional<double> last_error;
    /** Whether the next step accepted is the first of the run. */
    bool first_step = true;
  };



  /**
   * The step-size policy of @p settings, with the client's sizes
   * @p client_step_size (TimeLoopClient::next_step_size()); an adaptive
   * one measures its error with the lumped mass @p lumped_mass.
   */
  std::unique_ptr<StepSizePolicy>
  create_step_size_policy(const TimeLoopSettings             &settings,
                          std::function<double(const double)> client_step_size,
                          const Vector                       &lumped_mass);
} // namespace PhaseField

#endif
