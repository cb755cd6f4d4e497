#include <algorithm>
#include <cmath>
#include <phasefield/core/constants.h>
#include <phasefield/time/start_value_predictor.h>

namespace PhaseField
{
  namespace
  {
    /**
     * artanh(U) at every locally owned node, |U| clamped below 1: the
     * distance to the interface in units of the profile's width where
     * U = tanh(d/eps).
     */
    Vector
    profile_variable(const Vector &u)
    {
      constexpr double largest = 1 - Constants::roundoff;
      Vector           phi(u);
      for (double &value : phi)
        value = std::atanh(std::clamp(value, -largest, largest));
      return phi;
    }
  } // namespace



  void
  StartValuePredictor::record(const BlockVector       &before,
                              const BlockVector       &after,
                              const double             step_size,
                              const StartExtrapolation how)
  {
    if (n_changes > 0 && (step_size != tau || how != extrapolation))
      n_changes = 0;
    tau           = step_size;
    extrapolation = how;
    last_change   = after;
    last_change -= before;
    previous_change_norm = last_change_norm;
    last_change_norm     = last_change.block(0).l2_norm();
    if (extrapolation == StartExtrapolation::profile)
      {
        last_change.block(0) = profile_variable(after.block(0));
        last_change.block(0) -= profile_variable(before.block(0));
      }
    n_changes = std::min(n_changes + 1, 2u);
  }



  bool
  StartValuePredictor::predict(BlockVector &state, const double step_size) const
  {
    if (n_changes < 2 || step_size != tau || previous_change_norm <= 0)
      return false;
    const double theta = std::min(last_change_norm / previous_change_norm, 1.);
    if (extrapolation == StartExtrapolation::linear)
      {
        state.add(theta, last_change);
        return true;
      }
    Vector            &u    = state.block(0);
    const Vector       phi  = profile_variable(u);
    const double      *p    = phi.begin();
    const double      *dp   = last_change.block(0).begin();
    double            *uu   = u.begin();
    const unsigned int size = u.locally_owned_size();
    for (unsigned int i = 0; i < size; ++i)
      uu[i] += std::tanh(p[i] + theta * dp[i]) - std::tanh(p[i]);
    u.compress(dealii::VectorOperation::insert);
    for (unsigned int b = 1; b < state.n_blocks(); ++b)
      state.block(b).add(theta, last_change.block(b));
    return true;
  }



  std::vector<BlockVector *>
  StartValuePredictor::history()
  {
    if (n_changes == 0)
      return {};
    return {&last_change};
  }



  void
  StartValuePredictor::forget()
  {
    n_changes = 0;
  }
} // namespace PhaseField
