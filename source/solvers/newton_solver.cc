#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <phasefield/solvers/newton_solver.h>

namespace PhaseField
{
  using namespace dealii;

  namespace
  {
    /** Where the backtracking along a Newton update stopped. */
    struct Backtracking
    {
      /** Number of halvings (max_damping_steps + 1: none accepted). */
      unsigned int damping;
      /** The step length taken. */
      double lambda;
      /** The residual norm there. */
      double norm;
    };



    /**
     * trial = z + lambda update for lambda = 1, 1/2, ... until the
     * residual norm decreases below @p norm, reaches @p target, or (the
     * full step, if @p watchdog_available) stays below
     * NewtonControl::watchdog_factor times @p norm; without line search
     * the full step. @p residual holds R(trial) on return.
     */
    Backtracking
    backtrack(NonlinearSystem                          &system,
              const TrilinosWrappers::MPI::BlockVector &z,
              const TrilinosWrappers::MPI::BlockVector &update,
              TrilinosWrappers::MPI::BlockVector       &trial,
              TrilinosWrappers::MPI::BlockVector       &residual,
              const NewtonControl                      &control,
              const double                              norm,
              const double                              target,
              const bool                                watchdog_available)
    {
      Backtracking b{0, 1, std::numeric_limits<double>::quiet_NaN()};
      for (; b.damping <= control.max_damping_steps;
           ++b.damping, b.lambda *= 0.5)
        {
          trial = z;
          trial.add(b.lambda, update);
          system.distribute_constraints(trial);
          system.residual(trial, residual);
          b.norm              = system.residual_norm(residual);
          const bool watchdog = b.damping == 0 && watchdog_available &&
                                b.norm < control.watchdog_factor * norm;
          if (!control.line_search ||
              (std::isfinite(b.norm) &&
               (b.norm < norm || b.norm <= target || watchdog)))
            break;
        }
      return b;
    }



    /**
     * Take the update that backtrack() found in Newton iteration @p it:
     * z = @p trial and @p norm = its residual norm, the watchdog spent if
     * the norm rose. False (and nothing changed) if no damped update was
     * accepted.
     */
    bool
    accept_update(const Backtracking                       &step,
                  const unsigned int                        it,
                  const NewtonControl                      &control,
                  const ConditionalOStream                 &pcout,
                  const TrilinosWrappers::MPI::BlockVector &trial,
                  TrilinosWrappers::MPI::BlockVector       &z,
                  double                                   &norm,
                  bool                                     &watchdog_used)
    {
      if (step.damping > control.max_damping_steps)
        {
          pcout << "    Newton iteration " << it
                << ": no damped update reduces the residual (residual " << norm
                << ")." << std::endl;
          return false;
        }
      if (step.damping > 0)
        pcout << "    Newton iteration " << it << ": update damped by "
              << step.lambda << std::endl;
      if (step.norm >= norm)
        watchdog_used = true;
      z    = trial;
      norm = step.norm;
      return true;
    }



    /**
     * Whether @p norm (after an iteration that started at @p previous_norm)
     * reached @p target or stagnates below @p roundoff_level.
     */
    bool
    reached_target(const double norm,
                   const double previous_norm,
                   const double target,
                   const double roundoff_level)
    {
      // at round-off the residual stagnates above a tight target
      const bool stagnating = roundoff_level > 0 && norm <= roundoff_level &&
                              norm >= 0.5 * previous_norm;
      return norm <= target || stagnating;
    }
  } // namespace



  StepReport
  newton_solve(NonlinearSystem                    &system,
               TrilinosWrappers::MPI::BlockVector &z,
               const NewtonControl                &control,
               LinearSolver                       &linear_solver,
               const ConditionalOStream           &pcout,
               const bool                          verbose)
  {
    using BlockVector = TrilinosWrappers::MPI::BlockVector;
    BlockVector residual(z), update(z), trial(z);

    StepReport   report;
    double       norm   = 0;
    const double target = internal::start_newton(
      system, z, residual, control, pcout, verbose, norm, report);
    if (report.converged || !std::isfinite(norm))
      return report;
    const double roundoff_level =
      std::max(control.roundoff_level, system.roundoff_level(z));

    // Non-monotone "watchdog" step: once per solve a full Newton update is
    // accepted even if it increases the residual norm by up to
    // NewtonControl::watchdog_factor; the norm of the saddle-point
    // residual is a poor merit function far from the solution, and damping
    // the first update usually costs two or three extra iterations.
    bool                  watchdog_used = false;
    internal::ForcingTerm forcing;
    for (unsigned int it = 1; it <= control.max_iterations; ++it)
      {
        forcing.set_tolerance(linear_solver, control, it, target, norm);
        unsigned int linear_iterations = 0;
        try
          {
            linear_iterations =
              system.solve_jacobian(z, residual, update, linear_solver);
          }
        catch (const ExceptionBase &exc)
          {
            // a Krylov solve is collective: it fails on all ranks
            internal::print_linear_solver_failure(pcout, it, exc);
            return report;
          }
        report.linear_iterations += linear_iterations;
        report.newton_iterations = it;

        const Backtracking step          = backtrack(system,
                                            z,
                                            update,
                                            trial,
                                            residual,
                                            control,
                                            norm,
                                            target,
                                            !watchdog_used);
        const double       previous_norm = norm;
        // at round-off no update reduces the residual any further: that
        // is convergence as the stagnation in reached_target() is
        if (step.damping > control.max_damping_steps &&
            reached_target(norm, previous_norm, target, roundoff_level))
          {
            report.converged           = true;
            report.final_residual_norm = norm;
            return report;
          }
        if (!accept_update(
              step, it, control, pcout, trial, z, norm, watchdog_used))
          return report;
        report.final_residual_norm = norm;
        if (verbose)
          pcout << "    Newton " << it << ": residual " << norm << " ("
                << linear_iterations << " linear iterations, "
                << linear_solver.n_factorizations() << " factorizations)"
                << std::endl;
        if (reached_target(norm, previous_norm, target, roundoff_level))
          {
            report.converged = true;
            return report;
          }
        if (!std::isfinite(norm))
          return report;
      }
    internal::print_newton_failure(pcout, control, norm, target);
    return report;
  }



} // namespace PhaseField
