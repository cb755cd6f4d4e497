#ifndef phasefield_solvers_newton_solver_h
#define phasefield_solvers_newton_solver_h

#include <deal.II/base/conditional_ostream.h>
#include <phasefield/core/linear_algebra.h>
#include <phasefield/solvers/linear_solver.h>
#include <phasefield/solvers/nonlinear_system.h>

namespace PhaseField
{
  /**
   * Damped inexact Newton method for @p system, starting from and
   * overwriting @p z. Stops when the residual norm has dropped by
   * NewtonControl::relative_tolerance or is below
   * NewtonControl::absolute_tolerance times the term scale (or stagnates
   * at NewtonControl::roundoff_level). The first linear solve uses a loose
   * relative tolerance, later ones just enough to reach the target; an
   * update that does not decrease the residual is halved up to
   * NewtonControl::max_damping_steps times, except where the watchdog
   * takes the full update (NewtonControl::watchdog_factor,
   * NewtonParameters::watchdog_iterations). On failure the report says so
   * and @p z holds the last accepted iterate.
   */
  StepReport
  newton_solve(NonlinearSystem                  &system,
               BlockVector                      &z,
               const NewtonControl              &control,
               LinearSolver                     &linear_solver,
               const dealii::ConditionalOStream &pcout,
               const bool                        verbose);
} // namespace PhaseField

#endif
