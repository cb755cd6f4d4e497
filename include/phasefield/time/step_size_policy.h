#ifndef phasefield_time_step_size_policy_h
#define phasefield_time_step_size_policy_h

#include <functional>
#include <memory>
#include <phasefield/core/parameters.h>
#include <phasefield/time/checkpoint.h>
#include <phasefield/time/time_loop_settings.h>

namespace PhaseField
{
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
     * @p tried_tau: after_accepted(), then state_tau() is @p tau.
     */
    void
    accept(const double tau, const double tried_tau);

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
    /** What step sizes an accepted step (accept()) changes. */
    virtual void
    after_accepted(const double tau, const double tried_tau) = 0;

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
    after_accepted(const double tau, const double tried_tau) override;

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
   * The step-size policy of @p settings, with the client's sizes
   * @p client_step_size (TimeLoopClient::next_step_size()).
   */
  std::unique_ptr<StepSizePolicy>
  create_step_size_policy(const TimeLoopSettings             &settings,
                          std::function<double(const double)> client_step_size);
} // namespace PhaseField

#endif
