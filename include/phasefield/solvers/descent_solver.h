#ifndef phasefield_solvers_descent_solver_h
#define phasefield_solvers_descent_solver_h

#include <deal.II/base/conditional_ostream.h>
#include <phasefield/core/linear_algebra.h>
#include <phasefield/solvers/linear_solver.h>
#include <phasefield/solvers/nonlinear_system.h>

namespace PhaseField
{
  /**
   * Newton's method as a descent method for a constrained minimisation
   * problem: the minimisation of MinimizationProblem::project_and_energy
   * over the free fields. Every iterate satisfies the constraint, so that
   * the residual of the free fields is the gradient of the energy and the
   * Newton direction is a descent direction whenever the shifted reduced
   * Hessian is positive definite.
   *
   * Each iteration solves the shifted Newton system
   * (MinimizationProblem::solve_shifted_jacobian) with the current shift mu
   * (0 at the start); if the update is not a descent direction, mu is
   * raised (1, then 10 times larger) and the system solved again. The
   * update is then halved until the energy decreases by the Armijo
   * condition phi(z + lambda dz) <= phi(z) + 1e-4 lambda R.dz (up to its
   * round-off); a full step that gains more than a convex quadratic model
   * promises (negative curvature along dz) is doubled while the energy
   * keeps decreasing, at most 4 times. A full step lowers mu tenfold, a
   * step damped twice or more raises it. Unlike newton_solve(), the energy
   * never increases, so that the method cannot converge to a maximum or
   * saddle point of an energy it started below. Stopping test and report
   * as in newton_solve(), and also when the Newton decrement |R.dz|
   * (mu = 0) is below the round-off of the energy, i.e. at a minimum to
   * round-off, where the residual norm may stagnate above a tight target.
   */
  StepReport
  minimizing_newton_solve(MinimizationProblem              &problem,
                          BlockVector                      &z,
                          const NewtonControl              &control,
                          LinearSolver                     &linear_solver,
                          const dealii::ConditionalOStream &pcout,
                          const bool                        verbose);
} // namespace PhaseField

#endif
