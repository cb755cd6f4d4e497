#ifndef phasefield_schemes_nested_constrained_nested_step_h
#define phasefield_schemes_nested_constrained_nested_step_h

#include <phasefield/core/linear_algebra.h>
#include <phasefield/mesh/discretization.h>
#include <phasefield/schemes/constraints.h>
#include <phasefield/schemes/nested/nested_step.h>
#include <phasefield/solvers/linear_solver.h>
#include <phasefield/solvers/nonlinear_system.h>
#include <vector>

namespace PhaseField
{
  /**
   * The nested step with scalar constraints g_j[U] = g_j* (ScalarConstraints)
   * as one nonlinear system in Z = (U, V, P, lambda), lambda the
   * multipliers in the units of the nested step's residual (block 3, one
   * entry per constraint, all on rank 0):
   *
   *   R(Z)   = R_nested(U, V, P) + sum_j lambda_j B_j^T   (ConstraintTerm)
   *   R_j(Z) = g_j[U] - g_j*
   *
   * with B_j = (grad g_j, 0, 0). Its Newton system is bordered,
   *
   *   [ J   B^T ] [ dZ      ]     [ R   ]
   *   [ B   0   ] [ dlambda ] = - [ R_c ],
   *
   * J the nested step's Jacobian with the constraints' Hessians
   * lambda_j grad^2 g_j in its UU block. It is solved with the nested
   * step's own solver, by three (two with one constraint) solves with J:
   * J x = -R and J Y_j = B_j^T, then the small system
   * (B Y) dlambda = B x + R_c and dZ = x - Y dlambda. B Y is B (J^-1)_UU
   * B^T, with (J^-1)_UU the inverse of the Hessian of the outer energy in
   * U (V and P eliminated), which is positive definite where the step is
   * a minimiser.
   */
  template <int dim>
  class ConstrainedNestedStep : public NonlinearSystem
  {
  public:
    /** Block of the multipliers in the extended state. */
    static constexpr unsigned int multiplier_block = 3;

    /**
     * The system of @p step with @p constraints (both must outlive this
     * object, whose evaluations set
     * ScalarConstraints::step_multipliers()).
     */
    ConstrainedNestedStep(NestedStep<dim>           &step,
                          ScalarConstraints         &constraints,
                          const Discretization<dim> &discretization);

    /**
     * The extended state (U, V, P, lambda) of the nested state @p state
     * and the multipliers @p lambda.
     */
    BlockVector
    extended_state(const BlockVector         &state,
                   const std::vector<double> &lambda) const;

    /**
     * The entries of block 3 of @p z on every rank: the multipliers lambda
     * of a state, the constraint violations R_c of a residual.
     */
    std::vector<double>
    multipliers(const BlockVector &z) const;

    /** The nested state (U, V, P) of an extended one into @p state. */
    static void
    copy_nested_state(const BlockVector &z, BlockVector &state);

    /** @name NonlinearSystem */
    /** @{ */
    void
    residual(const BlockVector &z, BlockVector &r) const override;
    /** sqrt(||R||^2 + sum_j R_j^2), the nested norm for R. */
    double
    residual_norm(const BlockVector &r) const override;
    /** The nested step's scale plus sum_j |g_j*|. */
    double
    term_scale(const BlockVector &z) const override;
    double
    roundoff_level(const BlockVector &z) const override;
    unsigned int
    solve_jacobian(const BlockVector &z,
                   const BlockVector &r,
                   BlockVector       &dz,
                   LinearSolver      &solver) override;
    void
    distribute_constraints(BlockVector &z) const override;
    /** @} */

    /**
     * y = [J B^T; B 0] x, the bordered Jacobian applied to @p x (for
     * tests).
     */
    void
    jacobian_vmult(const BlockVector &z,
                   const BlockVector &x,
                   BlockVector       &y) const;

  private:
    /** Set ScalarConstraints::step_multipliers() to those of @p z. */
    void
    use_multipliers_of(const BlockVector &z) const;

    /** The nested blocks (U, V, P) of @p z as a block vector of their own. */
    BlockVector
    nested_part(const BlockVector &z) const;

    /** grad g_j at @p u with the constrained DoFs zero. */
    Vector
    constraint_gradient(const unsigned int j, const Vector &u) const;

    /** Write @p values into the multiplier block @p block (rank 0 owns it). */
    static void
    set_scalars(Vector &block, const std::vector<double> &values);

    NestedStep<dim>           &step;
    ScalarConstraints         &constraints;
    const Discretization<dim> &discretization;
  };
} // namespace PhaseField

#endif
