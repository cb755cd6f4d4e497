#ifndef phasefield_schemes_nested_nested_step_h
#define phasefield_schemes_nested_nested_step_h

#include <phasefield/core/constants.h>
#include <phasefield/core/linear_algebra.h>
#include <phasefield/mesh/discretization.h>
#include <phasefield/schemes/nested/nested_linear_systems.h>
#include <phasefield/schemes/nested/nested_physics.h>
#include <phasefield/solvers/linear_solver.h>
#include <phasefield/solvers/nonlinear_system.h>

namespace PhaseField
{
  /**
   * One step of the nested scheme (thesis chapter 3) as the Newton and
   * descent solvers see it: the physics of NestedPhysics (residual,
   * Jacobian, outer energy) with the linear-system strategies of
   * NestedLinearSystems, and the inner problem of Algorithm 3.1.
   *
   * As a MinimizationProblem the step is the minimisation of the outer
   * energy over U, with V the inner minimiser and P its adjoint
   * (project_and_energy()); R_U is then its gradient.
   */
  template <int dim>
  class NestedStep : public MinimizationProblem
  {
  public:
    /**
     * The step from @p old_u (which must outlive this object), with the
     * per-mesh storage @p mesh_matrices of the caller, if any
     * (NestedLinearSystems).
     */
    NestedStep(const Discretization<dim> &discretization,
               const NestedCoefficients  &coefficients,
               const Vector              &old_u,
               NestedMatrices<dim>       *mesh_matrices = nullptr);

    /** Not copyable: the linear systems refer to the physics. */
    NestedStep(const NestedStep &) = delete;
    NestedStep &
    operator=(const NestedStep &) = delete;

    /** @name NonlinearSystem */
    /** @{ */
    void
    residual(const BlockVector &z, BlockVector &r) const override;
    /** NestedPhysics::residual_norm(). */
    double
    residual_norm(const BlockVector &r) const override;
    /** NestedPhysics::term_scale(). */
    double
    term_scale(const BlockVector &z) const override;
    /** NestedPhysics::roundoff_level(). */
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

    /** @name MinimizationProblem (the descent method of NestedScheme) */
    /** @{ */
    /**
     * V and P re-solved for the U of @p z (solve_inner_problem() to
     * round-off), then the outer energy there.
     */
    double
    project_and_energy(BlockVector &z) override;
    /**
     * The default plus NestedPhysics::outer_energy_error(): relative to
     * the energy, of which (a/2)|V-U|^2 is nearly all, the error of V is
     * about 2 dV / |V-U|, which grows as V - U = ttau H shrinks.
     */
    double
    energy_roundoff(const BlockVector &z, const double energy) const override;
    /**
     * The Newton system with mu M added to the UU block: the 3-field
     * solve with restoration terms, the elimination otherwise.
     */
    unsigned int
    solve_shifted_jacobian(const BlockVector &z,
                           const BlockVector &r,
                           BlockVector       &dz,
                           LinearSolver      &solver,
                           const double       shift) override;
    /** @} */

    /** NestedPhysics::jacobian_vmult() (used by tests). */
    void
    jacobian_vmult(const BlockVector &z,
                   const BlockVector &x,
                   BlockVector       &y,
                   const double       shift = 0) const;

    /** NestedPhysics::outer_energy(). */
    double
    outer_energy(const BlockVector &z) const;

    /**
     * Given U in @p z, solve the inner problem R_P(U, V) = 0 for V by
     * Newton's method (newton_solve() on InnerProblem) starting from the V
     * in @p z, until ||R_P||_{M^-1} <= @p tolerance, and then the adjoint
     * equation R_V(U, V, P) = 0 for P. Afterwards R_U is the gradient of
     * outer_energy() with respect to U. Throws if Newton fails. Returns
     * the Newton iterations.
     */
    unsigned int
    solve_inner_problem(BlockVector  &z,
                        LinearSolver &solver,
                        const double  tolerance) const;

    /**
     * Algorithm 3.1: given U in @p z, V from R_P(U, V) = 0 (Newton from
     * V = U, to @p tolerance relative to the residual there) and then P
     * from R_V(U, V, P) = 0. Returns the Newton iterations.
     */
    unsigned int
    initialize_v_and_p(BlockVector  &z,
                       LinearSolver &solver,
                       const double  tolerance) const;

    /**
     * The solver of the inner problems of project_and_energy(): a solver
     * of its own, so that it keeps the factorisation of K(V) while the
     * Newton solver factorises the 3-field matrix.
     */
    void
    set_inner_solver(LinearSolver &solver)
    {
      inner_solver = &solver;
    }

    const NestedCoefficients &
    coefficients() const
    {
      return physics.coefficients();
    }

    /**
     * Tolerance of ||R_P||_{M^-1} in the inner problems of
     * project_and_energy(): round-off is about 1e-15; an inexact V changes
     * the outer energy to first order and R_U by a = tau/ttau^2 times it.
     */
    static constexpr double inner_tolerance = Constants::roundoff;

  private:
    class InnerProblem;

    const NestedPhysics<dim> physics;
    NestedLinearSystems<dim> systems;
    /** The solver of project_and_energy()'s inner problems. */
    LinearSolver *inner_solver = nullptr;
  };
} // namespace PhaseField

#endif
