#ifndef phasefield_solvers_augmented_lagrangian_h
#define phasefield_solvers_augmented_lagrangian_h

#include <deal.II/base/conditional_ostream.h>
#include <phasefield/core/linear_algebra.h>
#include <phasefield/solvers/trust_region.h>

/**
 * The augmented-Lagrangian method of thesis Algorithm 2.1 (LANCELOT,
 * Nocedal-Wright Algorithm 17.4) for min f(x) subject to c(x) = 0, with
 * trust_region_minimize() as inner solver. Interfaces, no physics.
 */
namespace PhaseField
{
  /**
   * min f(x) s.t. c(x) = 0 as augmented_lagrangian_minimize() sees it.
   * Gradients and constraint values c are dual vectors; riesz() maps a
   * dual vector of the constraint space to the primal one (M^-1 c), so
   * that ||C||^2 = c.riesz(c) and the augmented Lagrangian is
   *
   *   l_A(x; P, lambda) = f(x) - c(x).P + (lambda/2) c(x).riesz(c(x)),
   *
   * with gradient grad f + J^T Y and Hessian H_f + lambda J^T M^-1 J +
   * sum_i Y_i c_i'' where Y = -P + lambda riesz(c) (J = c').
   */
  class ConstrainedMinimizationProblem
  {
  public:
    virtual ~ConstrainedMinimizationProblem() = default;

    /** f(@p x). */
    virtual double
    objective(const BlockVector &x) const = 0;
    /** @p g = grad f(@p x). */
    virtual void
    objective_gradient(const BlockVector &x, BlockVector &g) const = 0;
    /** @p y = f''(@p x) @p d. */
    virtual void
    objective_hessian_vmult(const BlockVector &x,
                            const BlockVector &d,
                            BlockVector       &y) const = 0;
    /** @p c = c(@p x) (dual). */
    virtual void
    constraint(const BlockVector &x, Vector &c) const = 0;
    /** @p jd = c'(@p x) @p d. */
    virtual void
    constraint_jacobian_vmult(const BlockVector &x,
                              const BlockVector &d,
                              Vector            &jd) const = 0;
    /** @p g = c'(@p x)^T @p y (@p y primal). */
    virtual void
    constraint_jacobian_tvmult(const BlockVector &x,
                               const Vector      &y,
                               BlockVector       &g) const = 0;
    /** @p out = sum_i y_i c_i''(@p x) @p d. */
    virtual void
    constraint_hessian_vmult(const BlockVector &x,
                             const Vector      &y,
                             const BlockVector &d,
                             BlockVector       &out) const = 0;
    /** @p out = M^-1 @p c (dual to primal in the constraint space). */
    virtual void
    riesz(const Vector &c, Vector &out) const = 0;
    /** The norm of a gradient (the L2 norm of the functional). */
    virtual double
    gradient_norm(const BlockVector &g) const = 0;
    /**
     * Set up a symmetric positive definite approximation B of the Hessian
     * of l_A at @p x for the multiplier estimate @p y = -P + lambda M^-1 c
     * and the penalty @p penalty.
     */
    virtual void
    setup_preconditioner(const BlockVector &x,
                         const Vector      &y,
                         const double       penalty) = 0;
    /** @p z = B^-1 @p r. */
    virtual void
    precondition(const BlockVector &r, BlockVector &z) const = 0;
    /** Make @p x conforming (hanging nodes, boundary values). */
    virtual void
    distribute_constraints(BlockVector &x) const = 0;
  };

  /** Tolerances and limits of augmented_lagrangian_minimize(). */
  struct AugmentedLagrangianControl
  {
    /** w*. */
    double gradient_tolerance = 1e-8;
    /** eta*. */
    double constraint_tolerance = 1e-8;
    /** lambda at the start. */
    double       initial_penalty      = 10;
    unsigned int max_outer_iterations = 30;
    /**
     * Limit of the trust-region iterations summed over the outer
     * iterations: each inner minimisation may use what is left of it (at
     * most trust_region.max_iterations).
     */
    unsigned int max_total_trust_region_iterations = 1000;
    /** Limit of the truncated-CG iterations summed likewise. */
    unsigned int max_total_cg_iterations = 20000;
    /** The inner solver (its gradient tolerance is set per iteration). */
    TrustRegionControl trust_region;
    /**
     * true: the inner minimisation by Trilinos ROL
     * (rol_trust_region_minimize()) instead of trust_region_minimize().
     */
    bool rol_trust_region = false;
  };

  /** What augmented_lagrangian_minimize() did. */
  struct AugmentedLagrangianReport
  {
    bool         converged        = false;
    unsigned int outer_iterations = 0;
    unsigned int tr_iterations    = 0;
    unsigned int cg_iterations    = 0;
    double       final_penalty    = 0;
    /** ||grad l_A|| (initial P and lambda) and ||C|| at the start. */
    double initial_gradient_norm   = 0;
    double initial_constraint_norm = 0;
    /** ||grad l_A|| and ||C|| at the end. */
    double gradient_norm   = 0;
    double constraint_norm = 0;
  };

  /**
   * Thesis Algorithm 2.1 with lambda0 = control.initial_penalty,
   * w0 = 1/lambda0, eta0 = lambda0^-AugmentedLagrangian::eta_exponent.
   * Loop: minimise l_A(.; P, lambda) over x by trust_region_minimize()
   * until ||grad l_A|| <= max(w, w*). If ||C|| <= eta: stop if ||C|| <=
   * eta* and ||grad l_A|| <= w*, else P <- P - lambda M^-1 c,
   * eta <- eta / lambda^AugmentedLagrangian::eta_decay_exponent,
   * w <- w / lambda. Otherwise lambda <- AugmentedLagrangian::penalty_growth
   * lambda, eta <- lambda^-eta_exponent, w <- 1/lambda. @p x and @p p are
   * updated in place (warm start and result). Not converged: the trust
   * region failed, or max_outer_iterations,
   * max_total_trust_region_iterations or max_total_cg_iterations were
   * used.
   */
  AugmentedLagrangianReport
  augmented_lagrangian_minimize(ConstrainedMinimizationProblem   &problem,
                                BlockVector                      &x,
                                Vector                           &p,
                                const AugmentedLagrangianControl &control,
                                const dealii::ConditionalOStream &pcout,
                                const bool                        verbose);

  /**
   * The trust-region objective x -> l_A(x; P, lambda) of @p problem
   * (exposed for the finite-difference tests).
   */
  class AugmentedLagrangianObjective : public TrustRegionObjective
  {
  public:
    /** @p p must outlive this object. */
    AugmentedLagrangianObjective(ConstrainedMinimizationProblem &problem,
                                 const Vector                   &p,
                                 const double                    penalty);

    double
    value(const BlockVector &x) override;
    void
    gradient(const BlockVector &x, BlockVector &g) override;
    void
    hessian_vmult(const BlockVector &d, BlockVector &hd) const override;
    void
    precondition(const BlockVector &r, BlockVector &z) const override;
    double
    gradient_norm(const BlockVector &g) const override;
    void
    distribute_constraints(BlockVector &x) const override;

  private:
    ConstrainedMinimizationProblem &problem;
    const Vector                   &p;
    const double                    penalty;
    /** The point of the last gradient() and Y = -P + lambda M^-1 c. */
    BlockVector point;
    Vector      y;
  };

  /** The constants of thesis Algorithm 2.1. */
  namespace AugmentedLagrangian
  {
    /** lambda <- penalty_growth lambda when the constraint lags. */
    constexpr double penalty_growth = 100;
    /** eta = lambda^-eta_exponent after a penalty increase. */
    constexpr double eta_exponent = 0.1;
    /** eta <- eta / lambda^eta_decay_exponent after a multiplier update. */
    constexpr double eta_decay_exponent = 0.9;
    /**
     * A step of the augmented-Lagrangian scheme whose outer energy ends
     * higher than at its start by more than this, relative, is repeated
     * with a larger penalty. The outer energy's round-off at the end of a
     * step is about eta* / ttau relative (the curvature (U-V)/ttau carries
     * ||C||): the rises at stationary states lie far below this
     * tolerance, the rises it guards against far above it
     * (doc/benchmarks.md, "Choices in the code").
     */
    constexpr double monotonicity_tolerance = 1e-3;
    /** Repetitions of a step with a rising outer energy. */
    constexpr unsigned int max_monotonicity_retries = 2;
  } // namespace AugmentedLagrangian
} // namespace PhaseField

#endif
