#include <algorithm>
#include <phasefield/time/start_value_predictor.h>

namespace PhaseField
{
  void
  StartValuePredictor::record(const BlockVector &before,
                              const BlockVector &after,
                              const double       step_size)
  {
    if (n_changes > 0 && step_size != tau)
      n_changes = 0;
    tau         = step_size;
    last_change = after;
    last_change -= before;
    previous_change_norm = last_change_norm;
    last_change_norm     = last_change.block(0).l2_norm();
    n_changes            = std::min(n_changes + 1, 2u);
  }



  bool
  StartValuePredictor::predict(BlockVector &state, const double step_size) const
  {
    if (n_changes < 2 || step_size != tau || previous_change_norm <= 0)
      return false;
    const double theta = std::min(last_change_norm / previous_change_norm, 1.);
    state.add(theta, last_change);
    return true;
  }



  void
  StartValuePredictor::forget()
  {
    n_changes = 0;
  }
} // namespace PhaseField
