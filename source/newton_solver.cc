#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <phasefield/newton_solver.h>

namespace PhaseField
{
  using namespace dealii;

  namespace
  {
    /**
     * The residual and its norm at the start of Newton's method; returns
     * the residual norm at which it stops and sets report.converged if it
     * is reached already.
     */
    double
    start(const NonlinearSystem                    &system,
          const TrilinosWrappers::MPI::BlockVector &z,
          TrilinosWrappers::MPI::BlockVector       &residual,
          const NewtonParameters                   &parameters,
          const ConditionalOStream                 &pcout,
          const bool                                verbose,
          double                                   &norm,
          StepReport                               &report)
    {
      system.residual(z, residual);
      norm                       = system.norm(residual);
      report.final_residual_norm = norm;
      const double target =
        std::max(parameters.relative_tolerance * norm,
                 parameters.absolute_tolerance * system.term_scale(z));
      if (verbose)
        pcout << "    Newton 0: residual " << norm << " (target " << target
              << ')' << std::endl;
      report.converged = std::isfinite(norm) && norm <= target;
      return target;
    }



    void
    print_failure(const ConditionalOStream &pcout,
                  const NewtonParameters   &parameters,
                  const double              norm,
                  const double              target)
    {
      pcout << "    Newton did not reach the tolerance in "
            << parameters.max_iterations << " iterations (residual " << norm
            << ", target " << target << ")." << std::endl;
    }
  } // namespace

  StepReport
  newton_solve(const NonlinearSystem              &system,
               TrilinosWrappers::MPI::BlockVector &z,
               const NewtonParameters             &parameters,
               ReducedSystemSolver                &linear_solver,
               const ConditionalOStream           &pcout,
               const bool                          verbose)
  {
    using BlockVector = TrilinosWrappers::MPI::BlockVector;
    BlockVector residual(z), update(z), trial(z);

    // The nonlinearity limits what the first update gains, so it needs
    // little accuracy; later ones are solved just accurately enough to
    // reach the target in one more iteration.
    constexpr double first_linear_tolerance = 1e-3;
    constexpr double linear_safety_factor   = 0.05;

    StepReport   report;
    double       norm = 0;
    const double target =
      start(system, z, residual, parameters, pcout, verbose, norm, report);
    if (report.converged || !std::isfinite(norm))
      return report;

    // Non-monotone "watchdog" step: once per time step a full Newton
    // update is accepted even if it increases the residual norm by up to
    // NewtonParameters::watchdog_factor; the norm of the saddle-point
    // residual is a poor merit function far from the solution, and damping
    // the first update usually costs two or three extra iterations.
    bool watchdog_used = false;
    for (unsigned int it = 1; it <= parameters.max_iterations; ++it)
      {
        linear_solver.set_tolerance(
          it == 1 ? first_linear_tolerance :
                    std::min(first_linear_tolerance,
                             linear_safety_factor * target / norm));
        const unsigned int linear_iterations =
          system.solve(z, residual, update, linear_solver);
        report.linear_iterations += linear_iterations;
        report.newton_iterations = it;

        double       lambda     = 1;
        double       trial_norm = std::numeric_limits<double>::quiet_NaN();
        unsigned int damping    = 0;
        for (; damping <= parameters.max_damping_steps;
             ++damping, lambda *= 0.5)
          {
            trial = z;
            trial.add(lambda, update);
            system.distribute_constraints(trial);
            system.residual(trial, residual);
            trial_norm = system.norm(residual);
            const bool watchdog =
              damping == 0 && !watchdog_used &&
              trial_norm < parameters.watchdog_factor * norm;
            if (std::isfinite(trial_norm) &&
                (trial_norm < norm || trial_norm <= target || watchdog))
              break;
          }
        if (damping > parameters.max_damping_steps)
          {
            pcout << "    Newton iteration " << it
                  << ": no damped update reduces the residual (residual "
                  << norm << ")." << std::endl;
            return report;
          }
        if (damping > 0)
          pcout << "    Newton iteration " << it << ": update damped by "
                << lambda << std::endl;
        if (trial_norm >= norm)
          watchdog_used = true;
        z                          = trial;
        norm                       = trial_norm;
        report.final_residual_norm = norm;
        if (verbose)
          pcout << "    Newton " << it << ": residual " << norm << " ("
                << linear_iterations << " linear iterations, "
                << linear_solver.n_factorizations() << " factorizations)"
                << std::endl;
        if (norm <= target)
          {
            report.converged = true;
            return report;
          }
      }
    print_failure(pcout, parameters, norm, target);
    return report;
  }



  StepReport
  minimizing_newton_solve(const NonlinearSystem              &system,
                          TrilinosWrappers::MPI::BlockVector &z,
                          const NewtonParameters             &parameters,
                          ReducedSystemSolver                &linear_solver,
                          const ConditionalOStream           &pcout,
                          const bool                          verbose)
  {
    using BlockVector = TrilinosWrappers::MPI::BlockVector;
    Assert(system.project_and_merit && system.solve_shifted,
           ExcMessage("minimizing_newton_solve() needs a merit function and "
                      "a shifted solve."));
    BlockVector residual(z), update(z), trial(z);

    // sufficient decrease of the Armijo condition
    constexpr double armijo = 1e-4;
    // the merit function is a sum of terms of its own size: relative
    // round-off below which a change is not significant
    constexpr double merit_roundoff = 1e-14;
    // the Levenberg-Marquardt shift, in units of the mass matrix: the
    // first non-zero value, the factor of its changes, and the value at
    // which the direction is the steepest descent direction to round-off
    constexpr double first_shift  = 1;
    constexpr double shift_factor = 10;
    constexpr double max_shift    = 1e16;
    // doublings of a full step along a direction of negative curvature
    constexpr unsigned int max_expansions = 4;

    double       merit = system.project_and_merit(z);
    StepReport   report;
    double       norm = 0;
    const double target =
      start(system, z, residual, parameters, pcout, verbose, norm, report);
    if (report.converged || !std::isfinite(norm) || !std::isfinite(merit))
      return report;

    double     shift       = 0;
    const auto raise_shift = [&]() {
      shift = std::max(first_shift, shift * shift_factor);
    };
    for (unsigned int it = 1; it <= parameters.max_iterations; ++it)
      {
        report.newton_iterations = it;
        // a descent direction: raise the shift until R.dz < 0
        double slope = 0;
        for (;;)
          {
            report.linear_iterations +=
              system.solve_shifted(z, residual, update, linear_solver, shift);
            slope = residual * update;
            // Newton decrement -R.dz below the round-off of the merit: a
            // minimum to machine precision, even if the residual norm is
            // above the target (its round-off grows with a = tau/ttau^2)
            if (shift == 0 &&
                std::abs(slope) <= merit_roundoff * std::abs(merit))
              {
                if (verbose)
                  pcout << "    Newton iteration " << it
                        << ": stationary to round-off (residual " << norm
                        << ", Newton decrement " << -slope << ")" << std::endl;
                report.converged = true;
                return report;
              }
            if (slope < 0)
              break;
            raise_shift();
            if (shift > max_shift)
              {
                pcout << "    Newton iteration " << it
                      << ": no descent direction (residual " << norm << ")."
                      << std::endl;
                return report;
              }
            if (verbose)
              pcout << "    Newton iteration " << it
                    << ": not a descent direction, shift " << shift
                    << std::endl;
          }

        // backtracking line search on the merit function
        double       lambda      = 1;
        double       trial_merit = std::numeric_limits<double>::quiet_NaN();
        unsigned int damping     = 0;
        for (; damping <= parameters.max_damping_steps;
             ++damping, lambda *= 0.5)
          {
            trial = z;
            trial.add(lambda, update);
            system.distribute_constraints(trial);
            trial_merit = system.project_and_merit(trial);
            if (std::isfinite(trial_merit) &&
                trial_merit <= merit + armijo * lambda * slope +
                                 merit_roundoff * std::abs(merit))
              break;
          }
        if (damping > parameters.max_damping_steps)
          {
            // the quadratic model is poor: closer to steepest descent
            raise_shift();
            pcout << "    Newton iteration " << it
                  << ": no damped update decreases the energy, shift " << shift
                  << std::endl;
            continue;
          }
        // A full step that gains more than the quadratic model of a
        // convex merit promises (half the slope) went along a direction of
        // negative curvature: longer steps gain more there.
        unsigned int expansions = 0;
        if (damping == 0)
          while (expansions < max_expansions &&
                 merit - trial_merit > -0.5 * lambda * slope)
            {
              BlockVector longer(z);
              longer.add(2 * lambda, update);
              system.distribute_constraints(longer);
              const double longer_merit = system.project_and_merit(longer);
              if (!(longer_merit < trial_merit))
                break;
              trial       = longer;
              trial_merit = longer_merit;
              lambda *= 2;
              ++expansions;
            }
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

        z     = trial;
        merit = trial_merit;
        system.residual(z, residual);
        norm                       = system.norm(residual);
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
    print_failure(pcout, parameters, norm, target);
    return report;
  }
} // namespace PhaseField
