#ifndef phasefield_time_local_error_estimate_h
#define phasefield_time_local_error_estimate_h

#include <optional>
#include <phasefield/core/linear_algebra.h>
#include <vector>

namespace PhaseField
{
  /**
   * The local error of a time step, estimated from the step and the one
   * before it (Milne's device with the linear extrapolation of the last
   * two states as the predictor).
   *
   * The outer steps of the nested and augmented Lagrangian schemes are
   * implicit Euler steps of the gradient flow U' = f(U) (a minimising
   * movement): U^{k+1} - U^k = tau f(U^{k+1}). Their local error is
   * e = (tau^2 / 2) U'' + O(tau^3). Since U^k - U^{k-1} = tau_p f(U^k)
   * exactly, the linear extrapolation of the last two states,
   *
   *   X = U^k + (tau / tau_p) (U^k - U^{k-1}) = U^k + tau f(U^k),
   *
   * is the explicit Euler step, whose local error is -e, and
   *
   *   D = U^{k+1} - X = tau (f(U^{k+1}) - f(U^k)) = tau^2 U'' + O(tau^3),
   *
   * so e = D / 2 whatever the ratio of tau and tau_p. The estimate is
   * ||D||_L2 / 2 over the domain, with the lumped mass (Gauss-Lobatto on
   * the vertices): a norm of the field, independent of how many DoFs a
   * mesh has. The semi-implicit scheme is linearly implicit, not implicit
   * Euler: for it the estimate is of the right order, its constant not
   * exact.
   */
  class LocalErrorEstimate
  {
  public:
    /**
     * Record the step of size @p tau from @p before to @p after (the U
     * blocks, on the current mesh): the next estimate compares with it.
     */
    void
    record(const Vector &before, const Vector &after, const double tau);

    /**
     * ||D||_L2 / 2 (see the class documentation) of the step of size @p tau
     * from @p before to @p after, with the lumped mass @p lumped_mass of
     * the mesh; none without a recorded step. Collective.
     */
    std::optional<double>
    estimate(const Vector &before,
             const Vector &after,
             const double  tau,
             const Vector &lumped_mass) const;

    /**
     * The vectors of the history, to be transferred to a new mesh with the
     * state (empty without a history).
     */
    std::vector<BlockVector *>
    history();

    /** Drop the history (the DoFs changed without a transfer). */
    void
    forget();

  private:
    /** U^k - U^{k-1} (one block), valid if has_change. */
    BlockVector last_change;
    /** The size of the step of last_change. */
    double last_tau   = 0;
    bool   has_change = false;
  };
} // namespace PhaseField

#endif
