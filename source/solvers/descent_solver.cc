#include <algorithm>
#include <cmath>
#include <deal.II/lac/solver_control.h>
#include <iomanip>
#include <limits>
#include <phasefield/core/constants.h>
#include <phasefield/solvers/descent_solver.h>

namespace PhaseField
{
  using namespace dealii;

  namespace
  {
    // sufficient decrease of the Armijo condition
    constexpr double armijo = 1e-4;
    // the Levenberg-Marquardt shift, in units of the mass matrix: the
    // first non-zero value, the factor of its changes, and the value at
    // which the direction is the steepest descent direction to round-off
    constexpr double first_shift  = 1;
    constexpr double shift_factor = 10;
    constexpr double max_shift    = 1e16;
    // doublings of a full step along a direction of negative curvature
    constexpr unsigned int max_expansions = 4;

    /** What the search for a descent direction found. */
    enum class Direction
    {
      descent,
      stationary,
      none
    };

    /** The state of minimizing_newton_solve() and its parts. */
    class DescentNewton
    {
    public:
      DescentNewton(MinimizationProblem      &problem,
                    BlockVector              &z,
                    const NewtonControl      &control,
                    LinearSolver             &linear_solver,
                    const ConditionalOStream &pcout,
                    const bool                verbose)
        : problem(problem)
        , z(z)
        , control(control)
        , linear_solver(linear_solver)
        , pcout(pcout)
        , verbose(verbose)
        , residual(z)
        , update(z)
        , trial(z)
      {}

      StepReport
      run();

    private:
      /**
       * Solve the shifted Newton system, raising the shift until the
       * update is a descent direction (slope R.dz < 0), or find that z
       * is a minimum to round-off.
       */
      Direction
      find_descent_direction(const unsigned int it);

      /**
       * Solve the shifted Newton system into update; where the linear
       * solver does not converge, raise the shift and return false (the
       * exception is passed on beyond max_shift).
       */
      bool
      solve_shifted_system(const unsigned int it);

      /**
       * Backtracking from the full update until the Armijo condition
       * holds; returns the number of halvings (max_damping_steps + 1: no
       * step accepted); trial, trial_merit and lambda are those of the
       * accepted step.
       */
      unsigned int
      armijo_backtracking();

      /**
       * A full step that gains more than the quadratic model of a convex
       * merit promises (half the slope) went along a direction of
       * negative curvature: longer steps gain more there. Returns the
       * number of doublings.
       */
      unsigned int
      extend_along_negative_curvature();

      void
      raise_shift()
      {
        shift = std::max(first_shift, shift * shift_factor);
      }

      MinimizationProblem      &problem;
      BlockVector              &z;
      const NewtonControl      &control;
      LinearSolver             &linear_solver;
      const ConditionalOStream &pcout;
      const bool                verbose;
      BlockVector               residual, update, trial;
      StepReport                report;
      double                    merit = 0;
      /** MinimizationProblem::energy_roundoff() of merit at z. */
      double merit_noise = 0;
      double trial_merit = 0;
      double norm        = 0;
      double target      = 0;
      double slope       = 0;
      double lambda      = 1;
      double shift       = 0;
      /** The tolerances of the linear solves. */
      internal::ForcingTerm forcing;
    };



    Direction
    DescentNewton::find_descent_direction(const unsigned int it)
    {
      forcing.set_tolerance(linear_solver, control, it, target, norm);
      for (;;)
        {
          if (!solve_shifted_system(it))
            continue;
          slope = residual * update;
          // Newton decrement -R.dz below the round-off of the merit: a
          // minimum to the precision of the merit, even if the residual
          // norm is above the target (its round-off grows with
          // a = tau/ttau^2)
          if (shift == 0 && std::abs(slope) <= merit_noise)
            {
              if (verbose)
                pcout << "    Newton iteration " << it
                      << ": stationary to round-off (residual " << norm
                      << ", Newton decrement " << -slope << ")" << std::endl;
              return Direction::stationary;
            }
          if (slope < 0)
            return Direction::descent;
          raise_shift();
          if (shift > max_shift)
            {
              pcout << "    Newton iteration " << it
                    << ": no descent direction (residual " << norm << ")."
                    << std::endl;
              return Direction::none;
            }
          if (verbose)
            pcout << "    Newton iteration " << it
                  << ": not a descent direction, shift " << shift << std::endl;
        }
    }



    bool
    DescentNewton::solve_shifted_system(const unsigned int it)
    {
      try
        {
          report.linear_iterations += problem.solve_shifted_jacobian(
            z, residual, update, linear_solver, shift);
          return true;
        }
      catch (const SolverControl::NoConvergence &exc)
        {
          // a Krylov solve is collective: it fails on all ranks. A larger
          // shift is better conditioned (CG on the first step of the
          // level-8 cube needs one)
          report.linear_iterations += exc.last_step;
          raise_shift();
          if (shift > max_shift)
            throw;
          pcout << "    Newton iteration " << it
                << ": the linear solver did not converge (residual "
                << exc.last_residual << " after " << exc.last_step
                << " iterations), shift " << shift << std::endl;
          return false;
        }
    }



    unsigned int
    DescentNewton::armijo_backtracking()
    {
      lambda               = 1;
      trial_merit          = std::numeric_limits<double>::quiet_NaN();
      unsigned int damping = 0;
      for (; damping <= control.max_damping_steps; ++damping, lambda *= 0.5)
        {
          trial = z;
          trial.add(lambda, update);
          problem.distribute_constraints(trial);
          trial_merit = problem.project_and_energy(trial);
          if (std::isfinite(trial_merit) &&
              trial_merit <= merit + armijo * lambda * slope + merit_noise)
            break;
        }
      return damping;
    }



    unsigned int
    DescentNewton::extend_along_negative_curvature()
    {
      unsigned int expansions = 0;
      while (expansions < max_expansions &&
             merit - trial_merit > -0.5 * lambda * slope)
        {
          BlockVector longer(z);
          longer.add(2 * lambda, update);
          problem.distribute_constraints(longer);
          const double longer_merit = problem.project_and_energy(longer);
          if (!(longer_merit < trial_merit))
            break;
          trial       = longer;
          trial_merit = longer_merit;
          lambda *= 2;
          ++expansions;
        }
      return expansions;
    }



    StepReport
    DescentNewton::run()
    {
      merit       = problem.project_and_energy(z);
      merit_noise = problem.energy_roundoff(z, merit);
      target      = internal::start_newton(
        problem, z, residual, control, pcout, verbose, norm, report);
      if (report.converged || !std::isfinite(norm) || !std::isfinite(merit))
        return report;

      for (unsigned int it = 1; it <= control.max_iterations; ++it)
        {
          report.newton_iterations = it;
          Direction direction      = Direction::none;
          try
            {
              direction = find_descent_direction(it);
            }
          catch (const ExceptionBase &exc)
            {
              // a Krylov solve is collective: it fails on all ranks
              internal::print_linear_solver_failure(pcout, it, exc);
              return report;
            }
          if (direction != Direction::descent)
            {
              report.converged = (direction == Direction::stationary);
              return report;
            }
          const unsigned int damping = armijo_backtracking();
          if (damping > control.max_damping_steps)
            {
              // the quadratic model is poor: closer to steepest descent
              raise_shift();
              pcout << "    Newton iteration " << it
                    << ": no damped update decreases the energy, shift "
                    << shift << std::endl;
              continue;
            }
          const unsigned int expansions =
            damping == 0 ? extend_along_negative_curvature() : 0;
          if (damping > 0 || expansions > 0)
            pcout << "    Newton iteration " << it << ": update "
                  << (damping > 0 ? "damped" : "extended") << " by " << lambda
                  << " (shift " << shift << ")" << std::endl;
          // full steps: back towards Newton's method; repeated halving:
          // towards steepest descent
          if (damping == 0)
            shift =
              shift / shift_factor < first_shift ? 0. : shift / shift_factor;
          else if (damping >= 2)
            raise_shift();

          z           = trial;
          merit       = trial_merit;
          merit_noise = problem.energy_roundoff(z, merit);
          problem.residual(z, residual);
          norm                       = problem.residual_norm(residual);
          report.final_residual_norm = norm;
          if (verbose)
            pcout << "    Newton " << it << ": residual " << norm << ", energy "
                  << std::setprecision(12) << merit << std::setprecision(6)
                  << std::endl;
          if (norm <= target)
            {
              report.converged = true;
              return report;
            }
        }
      internal::print_newton_failure(pcout, control, norm, target);
      return report;
    }
  } // namespace



  StepReport
  minimizing_newton_solve(MinimizationProblem      &problem,
                          BlockVector              &z,
                          const NewtonControl      &control,
                          LinearSolver             &linear_solver,
                          const ConditionalOStream &pcout,
                          const bool                verbose)
  {
    return DescentNewton(problem, z, control, linear_solver, pcout, verbose)
      .run();
  }
} // namespace PhaseField
