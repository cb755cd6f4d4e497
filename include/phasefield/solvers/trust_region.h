#ifndef phasefield_solvers_trust_region_h
#define phasefield_solvers_trust_region_h

#include <deal.II/base/conditional_ostream.h>
#include <limits>
#include <phasefield/core/linear_algebra.h>

/**
 * A trust-region method with the Steihaug-Toint truncated conjugate
 * gradient method as subproblem solver (Conn, Gould, Toint, Trust-Region
 * Methods, Algorithm 7.5.1; Nocedal, Wright, Algorithm 7.2) for a smooth
 * function of a distributed block vector, with matrix-free Hessian
 * products and a preconditioner. Interfaces, no physics.
 */
namespace PhaseField
{
  /**
   * A smooth function as trust_region_minimize() sees it. Gradients are
   * dual vectors (nodal values of functionals); precondition() maps them
   * to primal ones.
   */
  class TrustRegionObjective
  {
  public:
    virtual ~TrustRegionObjective() = default;

    /** The value at @p x. */
    virtual double
    value(const BlockVector &x) = 0;

    /**
     * The gradient @p g at @p x. @p x also becomes the point at which the
     * Hessian products and the preconditioner act.
     */
    virtual void
    gradient(const BlockVector &x, BlockVector &g) = 0;

    /** @p hd = H d at the point of the last gradient(). */
    virtual void
    hessian_vmult(const BlockVector &d, BlockVector &hd) const = 0;

    /**
     * @p z = B^-1 @p r with a symmetric positive definite B that
     * approximates the Hessian; the trust region is a ball in the B norm.
     */
    virtual void
    precondition(const BlockVector &r, BlockVector &z) const = 0;

    /** The norm of a gradient (e.g. the L2 norm of the functional). */
    virtual double
    gradient_norm(const BlockVector &g) const = 0;

    /** Make a trial point conforming (hanging nodes, boundary values). */
    virtual void
    distribute_constraints(BlockVector &x) const = 0;
  };

  /** Limits and tolerances of trust_region_minimize(). */
  struct TrustRegionControl
  {
    /** Stop when gradient_norm(g) <= this. */
    double       gradient_tolerance = 1e-8;
    unsigned int max_iterations     = 200;
    /** Truncated-CG iterations per trust-region step. */
    unsigned int max_cg_iterations = 2000;
    /**
     * Truncated-CG iterations of the whole minimisation: it stops (not
     * converged) when they are used (trust_region_minimize() only).
     */
    unsigned int max_total_cg_iterations =
      std::numeric_limits<unsigned int>::max();
    /**
     * The radius at the start (B norm); 0: the B norm of the
     * preconditioned gradient B^-1 g, the step a preconditioned gradient
     * method would take.
     */
    double initial_radius = 0;
    /**
     * If set, a progress line (iteration, gradient norm, radius, CG
     * iterations so far) every TrustRegion::progress_interval iterations:
     * a trust-region solve may take minutes in 3D.
     */
    const dealii::ConditionalOStream *progress = nullptr;
  };

  /** What trust_region_minimize() did. */
  struct TrustRegionReport
  {
    bool         converged     = false;
    unsigned int iterations    = 0;
    unsigned int cg_iterations = 0;
    double       gradient_norm = 0;
    /**
     * Stopped (converged) at round-off: the last accepted step changed
     * neither the value nor the model measurably and the gradient norm
     * fell by less than TrustRegion::stagnation.
     */
    bool at_roundoff = false;
    /** The radius at the end (to start the next minimisation with). */
    double radius = 0;
  };

  /** What one truncated-CG solve of the subproblem did. */
  struct TruncatedCGResult
  {
    unsigned int iterations = 0;
    /** The step ends on the boundary of the trust region. */
    bool on_boundary = false;
    /** -m(s) = -(g.s + s.Hs/2) >= 0. */
    double model_decrease = 0;
    /** ||s||_B. */
    double step_norm = 0;
  };

  /**
   * Steihaug-Toint: approximately minimise m(s) = g.s + s.Hs/2 over
   * ||s||_B <= @p radius by preconditioned CG from s = 0, stopping on
   * negative curvature or at the boundary (the step is then extended to
   * it), when the residual g + Hs has gradient_norm() <= @p tolerance, or
   * after @p max_iterations.
   */
  TruncatedCGResult
  truncated_cg(const TrustRegionObjective &objective,
               const BlockVector          &g,
               const double                radius,
               const double                tolerance,
               const unsigned int          max_iterations,
               BlockVector                &s);

  /**
   * Minimise @p objective from @p x (updated in place) by the trust-region
   * method with truncated_cg() steps. Acceptance and radius update: rho =
   * (actual decrease) / (model decrease); the step is taken if rho >
   * TrustRegion::accept_ratio; the radius shrinks to TrustRegion::shrink
   * ||s|| if rho < TrustRegion::shrink_ratio and doubles (up to
   * TrustRegion::max_radius_factor times the initial one) if rho >
   * TrustRegion::grow_ratio and the step reached the boundary. When both
   * decreases are below round-off of the value, rho = 1. The CG tolerance
   * is min(TrustRegion::cg_forcing, sqrt(|g|)) |g| (superlinear
   * convergence). Converged: the gradient tolerance is met, or round-off
   * is reached (TrustRegionReport::at_roundoff). Not converged: max_iterations
   * reached, a non-finite value at every trial, or the radius below
   * TrustRegion::min_radius times the initial one.
   */
  TrustRegionReport
  trust_region_minimize(TrustRegionObjective     &objective,
                        BlockVector              &x,
                        const TrustRegionControl &control);

  /** The constants of trust_region_minimize(). */
  namespace TrustRegion
  {
    /** Accept a step if rho exceeds this (Conn-Gould-Toint eta_1). */
    constexpr double accept_ratio = 1e-4;
    /** Shrink the radius if rho is below this. */
    constexpr double shrink_ratio = 0.25;
    /** Grow the radius if rho is above this (and the step hit it). */
    constexpr double grow_ratio = 0.75;
    /** The new radius after a poor step, relative to the step length. */
    constexpr double shrink = 0.25;
    /** The factor of a radius increase. */
    constexpr double grow = 2;
    /** Largest radius relative to the initial one. */
    constexpr double max_radius_factor = 1e8;
    /** Smallest radius relative to the initial one before giving up. */
    constexpr double min_radius = 1e-12;
    /** See TrustRegionReport::at_roundoff. */
    constexpr double stagnation = 0.5;
    /** Largest relative CG tolerance. */
    constexpr double cg_forcing = 0.1;
    /** Iterations between two lines of TrustRegionControl::progress. */
    constexpr unsigned int progress_interval = 20;
  } // namespace TrustRegion
} // namespace PhaseField

#endif
