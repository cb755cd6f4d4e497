#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <phasefield/time/step_size_policy.h>
#include <sstream>
#include <utility>

namespace PhaseField
{
  double
  StepSizeLimits::next(const double tau,
                       const double tried_tau,
                       const double factor) const
  {
    const double grown =
      tau * (tau < tried_tau ? std::min(factor, 1.) : factor);
    const double above = std::max(grown, smallest);
    return largest > 0 ? std::min(above, largest) : above;
  }



  StepSizePolicy::StepSizePolicy(const double start_tau)
    : current_tau(start_tau)
  {}



  void
  StepSizePolicy::accept(const double       tau,
                         const double       tried_tau,
                         const BlockVector &before,
                         const BlockVector &after)
  {
    after_accepted(tau, tried_tau, before, after);
    current_tau = tau;
  }



  std::string
  StepSizePolicy::rejection(const BlockVector &before,
                            const BlockVector &after,
                            const double       tau) const
  {
    (void)before;
    (void)after;
    (void)tau;
    return "";
  }



  std::vector<BlockVector *>
  StepSizePolicy::history()
  {
    return {};
  }



  std::vector<std::string>
  StepSizePolicy::statistics_columns() const
  {
    return {};
  }



  std::vector<double>
  StepSizePolicy::statistics_values() const
  {
    return {};
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
  ScheduledStepSizes::after_accepted(const double       tau,
                                     const double       tried_tau,
                                     const BlockVector &before,
                                     const BlockVector &after)
  {
    (void)before;
    (void)after;
    if (regrow_step_size)
      step_size_limit = tau < tried_tau ? tau : 2 * tau;
  }



  AdaptiveStepSizes::AdaptiveStepSizes(const TimeLoopSettings &settings,
                                       const Vector           &lumped_mass)
    : StepSizePolicy(settings.model.tau)
    , tolerance(settings.model.step_control.tolerance)
    , end_time(settings.model.step_control.end_time)
    , limits{settings.model.step_control.smallest_step,
             settings.model.step_control.largest_step}
    , lumped_mass(lumped_mass)
    , next_tau(settings.model.step_size(1))
  {}



  double
  AdaptiveStepSizes::first_step_size(const unsigned int run_step) const
  {
    (void)run_step;
    return next_tau;
  }



  double
  AdaptiveStepSizes::latest_time(const unsigned int step) const
  {
    if (end_time > 0)
      return end_time;
    return limits.largest > 0 ? step * limits.largest :
                                std::numeric_limits<double>::infinity();
  }



  std::optional<double>
  AdaptiveStepSizes::estimate(const BlockVector &before,
                              const BlockVector &after,
                              const double       tau) const
  {
    return error_estimate.estimate(before.block(0),
                                   after.block(0),
                                   tau,
                                   lumped_mass);
  }



  std::string
  AdaptiveStepSizes::rejection(const BlockVector &before,
                               const BlockVector &after,
                               const double       tau) const
  {
    const std::optional<double> error = estimate(before, after, tau);
    // a step at the smallest size is taken whatever its error
    constexpr double roundoff = 1e-12;
    if (!error || *error <= tolerance ||
        tau <= limits.smallest * (1 + roundoff))
      return "";
    std::ostringstream why;
    why << std::setprecision(4) << "the estimated local error " << *error
        << " exceeds <Time stepping / Tolerance> = " << tolerance;
    return why.str();
  }



  double
  AdaptiveStepSizes::growth_factor(const std::optional<double> error) const
  {
    if (!error)
      return 1;
    if (!(*error > 0))
      return largest_factor;
    const double factor =
      last_error && *last_error > 0 ?
        safety * std::pow(tolerance / *error, integral_exponent) *
          std::pow(*last_error / tolerance, proportional_exponent) :
        safety * std::pow(tolerance / *error, elementary_exponent);
    return std::clamp(factor, smallest_factor, largest_factor);
  }



  void
  AdaptiveStepSizes::after_accepted(const double       tau,
                                    const double       tried_tau,
                                    const BlockVector &before,
                                    const BlockVector &after)
  {
    const std::optional<double> error = estimate(before, after, tau);
    next_tau   = limits.next(tau, tried_tau, growth_factor(error));
    last_error = error;
    if (!first_step)
      error_estimate.record(before.block(0), after.block(0), tau);
    first_step = false;
  }



  std::vector<BlockVector *>
  AdaptiveStepSizes::history()
  {
    return error_estimate.history();
  }



  std::vector<std::string>
  AdaptiveStepSizes::statistics_columns() const
  {
    return {"error_estimate"};
  }



  std::vector<double>
  AdaptiveStepSizes::statistics_values() const
  {
    return {last_error ? *last_error :
                         std::numeric_limits<double>::quiet_NaN()};
  }



  void
  AdaptiveStepSizes::save(Checkpoint::State &saved) const
  {
    StepSizePolicy::save(saved);
    saved.step_size_limit = next_tau;
  }



  void
  AdaptiveStepSizes::load(const Checkpoint::State &saved)
  {
    StepSizePolicy::load(saved);
    if (saved.step_size_limit > 0)
      next_tau = saved.step_size_limit;
    error_estimate.forget();
    last_error.reset();
    first_step = false;
  }



  std::unique_ptr<StepSizePolicy>
  create_step_size_policy(const TimeLoopSettings             &settings,
                          std::function<double(const double)> client_step_size,
                          const Vector                       &lumped_mass)
  {
    if (settings.model.step_control.control == StepControl::adaptive)
      return std::make_unique<AdaptiveStepSizes>(settings, lumped_mass);
    return std::make_unique<ScheduledStepSizes>(settings,
                                                std::move(client_step_size));
  }
} // namespace PhaseField
