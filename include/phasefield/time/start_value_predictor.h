#ifndef phasefield_time_start_value_predictor_h
#define phasefield_time_start_value_predictor_h

#include <phasefield/core/linear_algebra.h>
#include <phasefield/schemes/time_stepping_scheme.h>
#include <vector>

namespace PhaseField
{
  /**
   * The start value of a time step extrapolated from the last two steps.
   *
   * Near a stationary state the changes of consecutive steps of one size
   * tau decay by a roughly constant factor; then the next change is about
   * theta times the last one, theta = |dU_n| / |dU_(n-1)| (norms of the
   * U field, so that the ratio measures the motion of the interface), and
   *
   *   start of step n+1 = S_n + min(theta, 1) (S_n - S_(n-1))
   *
   * for all fields S = (U, V, P, ...) (U optionally in its profile
   * variable, StartExtrapolation): the geometric series of the
   * changes, at most the linear extrapolation. Right after a fast
   * transient theta is small and the prediction stays near S_n, where the
   * linear one would overshoot (the level-8 cube, steps 3-5). It needs two
   * changes of the same step size: a step of another size starts the
   * history anew. A change of the mesh transfers the history with the
   * state (history()); forget() where the DoFs change without a
   * transfer (a checkpoint's reload in p4est order). The norms of the
   * changes are taken on the meshes of their steps: the changes lie in
   * the band of finest cells, whose nodal density a re-meshing keeps.
   * Only the start of the iteration changes, not the step solved.
   */
  class StartValuePredictor
  {
  public:
    /**
     * Record the step of size @p tau from @p before to @p after (both on
     * the current mesh); the next prediction extrapolates U as @p how
     * says (a change of it starts the history anew).
     */
    void
    record(const BlockVector       &before,
           const BlockVector       &after,
           const double             tau,
           const StartExtrapolation how);

    /**
     * If the history allows a prediction for a step of size @p tau,
     * overwrite @p state (the last result, the plain start) with the
     * predicted start and return true; otherwise leave it and return
     * false.
     */
    bool
    predict(BlockVector &state, const double tau) const;

    /**
     * The vectors of the history, to be transferred to a new mesh with
     * the state (empty without a history).
     */
    std::vector<BlockVector *>
    history();

    /** Drop the history (the DoFs changed without a transfer). */
    void
    forget();

  private:
    /**
     * S_n - S_(n-1), valid if n_changes > 0; its U block is
     * artanh(U_n) - artanh(U_(n-1)) for StartExtrapolation::profile.
     */
    BlockVector last_change;
    /** How U is extrapolated. */
    StartExtrapolation extrapolation = StartExtrapolation::linear;
    /** |U_n - U_(n-1)| and |U_(n-1) - U_(n-2)| (l2 norms of the U block). */
    double last_change_norm     = 0;
    double previous_change_norm = 0;
    /** The step size of the recorded changes. */
    double tau = 0;
    /** Consecutive recorded changes of size tau on this mesh (at most 2). */
    unsigned int n_changes = 0;
  };
} // namespace PhaseField

#endif
