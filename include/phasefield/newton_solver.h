#ifndef phasefield_newton_solver_h
#define phasefield_newton_solver_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>
#include <functional>
#include <phasefield/nested_scheme.h>
#include <phasefield/parameters.h>

namespace PhaseField
{
  /** What one time step of the Newton solver did. */
  struct StepReport
  {
    bool         converged           = false;
    unsigned int newton_iterations   = 0;
    unsigned int linear_iterations   = 0;
    double       final_residual_norm = 0;
  };

  /**
   * One nonlinear system R(Z) = 0 of a time step, as seen by
   * newton_solve(): the time-stepping schemes (NestedScheme,
   * SemiImplicitScheme) provide these operations.
   */
  struct NonlinearSystem
  {
    using BlockVector = dealii::TrilinosWrappers::MPI::BlockVector;

    /** r = R(z). */
    std::function<void(const BlockVector &z, BlockVector &r)> residual;
    /** Norm of a residual (the L2 norm of the functions it represents). */
    std::function<double(const BlockVector &r)> norm;
    /**
     * Solve J(z) dz = -r with the linear solver passed to newton_solve();
     * returns the number of Krylov iterations.
     */
    std::function<unsigned int(const BlockVector   &z,
                               const BlockVector   &r,
                               BlockVector         &dz,
                               ReducedSystemSolver &solver)>
      solve;
    /** Make a trial state conforming (hanging nodes). */
    std::function<void(BlockVector &z)> distribute_constraints;
    /**
     * Size of the individual terms of R(z), so that the absolute tolerance
     * is relative to the round-off of the residual evaluation.
     */
    std::function<double(const BlockVector &z)> term_scale;

    /**
     * Only for minimizing_newton_solve(): re-solve the dependent fields of
     * @p z for its free ones (the constraint of a constrained minimisation
     * problem) and return the merit function there, an energy whose
     * gradient with respect to the free fields is their residual.
     */
    std::function<double(BlockVector &z)> project_and_merit;

    /**
     * Only for minimizing_newton_solve(): solve() with the Jacobian shifted
     * by @p shift times the mass matrix in the free fields (a
     * Levenberg-Marquardt shift).
     */
    std::function<unsigned int(const BlockVector   &z,
                               const BlockVector   &r,
                               BlockVector         &dz,
                               ReducedSystemSolver &solver,
                               const double         shift)>
      solve_shifted;
  };

  /**
   * Damped inexact Newton method for @p system, starting from and
   * overwriting @p z. Stops when the residual norm has dropped by
   * NewtonParameters::relative_tolerance or is below
   * NewtonParameters::absolute_tolerance times the term scale. The first
   * linear solve uses a loose relative tolerance, later ones just enough
   * to reach the target; an update that does not decrease the residual
   * is halved up to NewtonParameters::max_damping_steps times. On failure
   * the report says so and @p z holds the last accepted iterate.
   */
  StepReport
  newton_solve(const NonlinearSystem                      &system,
               dealii::TrilinosWrappers::MPI::BlockVector &z,
               const NewtonParameters                     &parameters,
               ReducedSystemSolver                        &linear_solver,
               const dealii::ConditionalOStream           &pcout,
               const bool                                  verbose);

  /**
   * Newton's method as a descent method for a constrained minimisation
   * problem: the minimisation of NonlinearSystem::project_and_merit over
   * the free fields (edge restoration: the outer energy over U, with V the
   * inner minimiser and P its adjoint). Every iterate satisfies the
   * constraint, so that the residual of the free fields is the gradient of
   * the merit function and the Newton direction is a descent direction
   * whenever the shifted reduced Hessian is positive definite.
   *
   * Each iteration solves the shifted Newton system
   * (NonlinearSystem::solve_shifted) with the current shift mu (0 at the
   * start of a step); if the update is not a descent direction, mu is
   * raised (1, then 10 times larger) and the system solved again. The
   * update is then halved until the merit function decreases by the
   * Armijo condition phi(z + lambda dz) <= phi(z) + 1e-4 lambda R.dz (up
   * to its round-off); a full step that gains more than a convex
   * quadratic model promises (negative curvature along dz) is doubled
   * while the merit keeps decreasing, at most 4 times. A full step lowers
   * mu tenfold, a step damped twice or more raises it. Unlike
   * newton_solve(), the merit never increases, so that the method cannot
   * converge to a maximum or saddle point of the merit it started below.
   * Stopping test and report as in newton_solve(), and also when the
   * Newton decrement |R.dz| (mu = 0) is below 1e-14 times the merit, i.e.
   * at a minimum to round-off, where the residual norm may stagnate above
   * a tight target.
   */
  StepReport
  minimizing_newton_solve(const NonlinearSystem                      &system,
                          dealii::TrilinosWrappers::MPI::BlockVector &z,
                          const NewtonParameters           &parameters,
                          ReducedSystemSolver              &linear_solver,
                          const dealii::ConditionalOStream &pcout,
                          const bool                        verbose);
} // namespace PhaseField

#endif
