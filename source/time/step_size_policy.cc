#include <algorithm>
#include <phasefield/time/step_size_policy.h>
#include <utility>

namespace PhaseField
{
  StepSizePolicy::StepSizePolicy(const double start_tau)
    : current_tau(start_tau)
  {}



  void
  StepSizePolicy::accept(const double tau, const double tried_tau)
  {
    after_accepted(tau, tried_tau);
    current_tau = tau;
  }



  void
  StepSizePolicy::save(Checkpoint::State &saved) const
  {
    saved.state_tau = current_tau;
  }



  void
  StepSizePolicy::load(const Checkpoint::State &saved)
  {
    current_tau = saved.state_tau;
  }



  ScheduledStepSizes::ScheduledStepSizes(
    const TimeLoopSettings             &settings,
    std::function<double(const double)> client_step_size)
    : StepSizePolicy(settings.model.tau)
    , model(settings.model)
    , regrow_step_size(settings.regrow_step_size)
    , largest_step_factor(settings.largest_step_factor)
    , client_step_size(std::move(client_step_size))
  {}



  double
  ScheduledStepSizes::first_step_size(const unsigned int run_step) const
  {
    const double scheduled = client_step_size(model.step_size(run_step));
    return step_size_limit > 0 ? std::min(scheduled, step_size_limit) :
                                 scheduled;
  }



  double
  ScheduledStepSizes::latest_time(const unsigned int step) const
  {
    // the scheduled sizes are the largest a step takes
    double longest = 0;
    for (unsigned int s = 1; s <= step; ++s)
      longest += largest_step_factor * model.step_size(s);
    return longest;
  }



  void
  ScheduledStepSizes::save(Checkpoint::State &saved) const
  {
    StepSizePolicy::save(saved);
    saved.step_size_limit = step_size_limit;
  }



  void
  ScheduledStepSizes::load(const Checkpoint::State &saved)
  {
    StepSizePolicy::load(saved);
    step_size_limit = saved.step_size_limit;
  }



  void
  ScheduledStepSizes::after_accepted(const double tau, const double tried_tau)
  {
    if (regrow_step_size)
      step_size_limit = tau < tried_tau ? tau : 2 * tau;
  }



  std::unique_ptr<StepSizePolicy>
  create_step_size_policy(const TimeLoopSettings             &settings,
                          std::function<double(const double)> client_step_size)
  {
    return std::make_unique<ScheduledStepSizes>(settings,
                                                std::move(client_step_size));
  }
} // namespace PhaseField
