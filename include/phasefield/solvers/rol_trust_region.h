#ifndef phasefield_solvers_rol_trust_region_h
#define phasefield_solvers_rol_trust_region_h

#include <phasefield/core/linear_algebra.h>
#include <phasefield/solvers/trust_region.h>

/**
 * The trust-region minimisation of trust_region.h done by Trilinos ROL
 * (ROL::TypeU::TrustRegionAlgorithm with ROL's truncated CG,
 * ROL::TruncatedCG_U), for comparison with our own implementation:
 * `Augmented Lagrangian / Trust-region solver = rol`. Interfaces, no
 * physics.
 */
namespace PhaseField
{
  /**
   * Minimise @p objective from @p x (updated in place) with ROL's
   * trust-region algorithm and truncated-CG subproblem solver, configured
   * to the constants of trust_region_minimize() where ROL has them
   * (acceptance, shrinking and growing ratios and rates, CG forcing
   * TrustRegion::cg_forcing relative to the l2 norm of the gradient
   * coefficients, the initial radius). The vectors are deal.II's
   * Rol::VectorAdaptor of the block vector; the Hessian products and the
   * preconditioner are those of @p objective; trial points are made
   * conforming before evaluation. Stops, as trust_region_minimize(), when
   * objective.gradient_norm() <= control.gradient_tolerance (converged)
   * or after control.max_iterations (not converged). cg_iterations counts
   * Hessian products; at_roundoff is never set.
   */
  TrustRegionReport
  rol_trust_region_minimize(TrustRegionObjective     &objective,
                            BlockVector              &x,
                            const TrustRegionControl &control);
} // namespace PhaseField

#endif
