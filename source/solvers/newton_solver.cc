#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <memory>
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
      /** The residual norm after the full update. */
      double full_norm;
    };



    /**
     * trial = z + lambda update for lambda = 1, 1/2, ... until the
     * residual norm decreases below @p norm, reaches @p target, or (the
     * full step, if @p may_relax: the watchdog's relaxed step) stays below
     * NewtonControl::watchdog_factor times @p norm; without line search
     * the full step. @p residual holds R(trial) on return.
     */
    Backtracking
    backtrack(NonlinearSystem     &system,
              const BlockVector   &z,
              const BlockVector   &update,
              BlockVector         &trial,
              BlockVector         &residual,
              const NewtonControl &control,
              const double         norm,
              const double         target,
              const bool           may_relax)
    {
      Backtracking b{0, 1, std::numeric_limits<double>::quiet_NaN(), 0};
      for (; b.damping <= control.max_damping_steps;
           ++b.damping, b.lambda *= 0.5)
        {
          trial = z;
          trial.add(b.lambda, update);
          system.distribute_constraints(trial);
          system.residual(trial, residual);
          b.norm = system.residual_norm(residual);
          if (b.damping == 0)
            b.full_norm = b.norm;
          const bool watchdog = b.damping == 0 && may_relax &&
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
     * z = @p trial and @p norm = its residual norm. False (and nothing
     * changed) if no damped update was accepted.
     */
    bool
    accept_update(const Backtracking       &step,
                  const unsigned int        it,
                  const NewtonControl      &control,
                  const ConditionalOStream &pcout,
                  const BlockVector        &trial,
                  BlockVector              &z,
                  double                   &norm)
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
              << step.lambda << " (full update: residual " << step.full_norm
              << ")" << std::endl;
      z    = trial;
      norm = step.norm;
      return true;
    }



    /**
     * The watchdog technique of Chamberlain, Powell, Lemarechal and
     * Pedersen (Math. Programming Study 16 (1982) 1-17) for the residual
     * norm as merit function: a full Newton update that raises the norm
     * (by less than NewtonControl::watchdog_factor) is taken anyway, the
     * relaxed step. If the next NewtonParameters::watchdog_iterations
     * monotone iterations do not bring the norm below its value before the
     * relaxed step, the iterate returns there and that update is damped as
     * usual. After a success the watchdog may relax again, after a failure
     * not in this Newton solve.
     */
    class Watchdog
    {
    public:
      /** Whether the next full update may raise the norm. */
      bool
      may_relax() const
      {
        return available && !base;
      }

      /** Remember @p z, @p update and @p norm before a relaxed step. */
      void
      start(const BlockVector &z, const BlockVector &update, const double norm)
      {
        base      = std::make_unique<State>(State{z, update, norm});
        remaining = NewtonParameters::watchdog_iterations;
      }

      /**
       * After a monotone iteration that reached @p norm: whether a trial
       * under way has failed (then restore()). A norm below the one before
       * the relaxed step ends the trial as a success.
       */
      bool
      trial_failed(const double norm)
      {
        if (!base)
          return false;
        if (norm < base->norm)
          {
            base.reset();
            return false;
          }
        return --remaining == 0;
      }

      /**
       * Back to the iterate before the relaxed step: @p z, its @p norm and
       * the @p update taken there.
       */
      void
      restore(BlockVector &z, BlockVector &update, double &norm)
      {
        z         = base->z;
        update    = base->update;
        norm      = base->norm;
        available = false;
        base.reset();
      }

      /** Whether a trial is under way. */
      bool
      in_trial() const
      {
        return base != nullptr;
      }

    private:
      /** The iterate before the relaxed step. */
      struct State
      {
        BlockVector z;
        BlockVector update;
        double      norm;
      };
      bool                   available = true;
      unsigned int           remaining = 0;
      std::unique_ptr<State> base;
    };



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


    /**
     * Solve for the @p update of Newton iteration @p it at @p z with
     * @p residual; adds the linear iterations to @p report. False (and the
     * failure printed) if the linear solver failed: a Krylov solve is
     * collective, so it fails on all ranks.
     */
    bool
    solve_for_update(NonlinearSystem          &system,
                     const BlockVector        &z,
                     const BlockVector        &residual,
                     BlockVector              &update,
                     LinearSolver             &linear_solver,
                     const ConditionalOStream &pcout,
                     const unsigned int        it,
                     StepReport               &report)
    {
      try
        {
          report.linear_iterations +=
            system.solve_jacobian(z, residual, update, linear_solver);
          report.newton_iterations = it;
          return true;
        }
      catch (const ExceptionBase &exc)
        {
          internal::print_linear_solver_failure(pcout, it, exc);
          return false;
        }
    }



    /** The iterate of newton_solve() and its work vectors. */
    struct Iterate
    {
      NonlinearSystem     &system;
      const NewtonControl &control;
      BlockVector         &z;
      BlockVector          residual;
      BlockVector          update;
      BlockVector          trial;
      /** The residual norm at z. */
      double norm = 0;
      /** The residual norm to reach. */
      double target = 0;

      /** backtrack() along update from z. */
      Backtracking
      search(const bool may_relax)
      {
        return backtrack(
          system, z, update, trial, residual, control, norm, target, may_relax);
      }
    };



    /**
     * The watchdog's part of Newton iteration @p it after the line search
     * found @p step: a full update that raised the norm starts a trial
     * (the relaxed step: returns true); after a trial that failed, the
     * iterate returns to the trial's start, and its update is backtracked
     * as usual into @p step.
     */
    bool
    watch(Watchdog                 &watchdog,
          Iterate                  &iterate,
          Backtracking             &step,
          const ConditionalOStream &pcout,
          const unsigned int        it)
    {
      const NewtonControl &control = iterate.control;
      // without line search every update is taken: no watchdog
      const bool relaxed = control.line_search && step.damping == 0 &&
                           step.norm >= iterate.norm &&
                           step.norm > iterate.target;
      if (relaxed)
        watchdog.start(iterate.z, iterate.update, iterate.norm);
      const bool failed_trial =
        (step.damping > control.max_damping_steps && watchdog.in_trial()) ||
        (!relaxed && watchdog.trial_failed(step.norm));
      if (failed_trial)
        {
          watchdog.restore(iterate.z, iterate.update, iterate.norm);
          pcout << "    Newton iteration " << it
                << ": watchdog failed, back to residual " << iterate.norm
                << std::endl;
          step = iterate.search(false);
        }
      return relaxed;
    }
  } // namespace



  StepReport
  newton_solve(NonlinearSystem          &system,
               BlockVector              &z,
               const NewtonControl      &control,
               LinearSolver             &linear_solver,
               const ConditionalOStream &pcout,
               const bool                verbose)
  {
    Iterate    iterate{system, control, z, z, z, z};
    StepReport report;
    iterate.target = internal::start_newton(system,
                                            z,
                                            iterate.residual,
                                            control,
                                            pcout,
                                            verbose,
                                            iterate.norm,
                                            report);
    if (report.converged || !std::isfinite(iterate.norm))
      return report;
    const double roundoff_level =
      std::max(control.roundoff_level, system.roundoff_level(z));

    Watchdog              watchdog;
    internal::ForcingTerm forcing;
    for (unsigned int it = 1; it <= control.max_iterations; ++it)
      {
        forcing.set_tolerance(
          linear_solver, control, it, iterate.target, iterate.norm);
        const unsigned int linear_before = report.linear_iterations;
        if (!solve_for_update(system,
                              z,
                              iterate.residual,
                              iterate.update,
                              linear_solver,
                              pcout,
                              it,
                              report))
          return report;
        Backtracking step          = iterate.search(watchdog.may_relax());
        const double previous_norm = iterate.norm;
        // at round-off no update reduces the residual any further: that
        // is convergence as the stagnation in reached_target() is
        if (step.damping > control.max_damping_steps &&
            reached_target(
              iterate.norm, previous_norm, iterate.target, roundoff_level))
          {
            report.converged           = true;
            report.final_residual_norm = iterate.norm;
            return report;
          }
        const bool relaxed = watch(watchdog, iterate, step, pcout, it);
        if (!accept_update(
              step, it, control, pcout, iterate.trial, z, iterate.norm))
          return report;
        report.final_residual_norm = iterate.norm;
        if (verbose)
          pcout << "    Newton " << it << ": residual " << iterate.norm << " ("
                << report.linear_iterations - linear_before
                << " linear iterations to a relative "
                << linear_solver.get_tolerance() << ", "
                << linear_solver.n_factorizations()
                << " factorizations)" << (relaxed ? ", watchdog" : "")
                << std::endl;
        if (reached_target(
              iterate.norm, previous_norm, iterate.target, roundoff_level))
          {
            report.converged = true;
            return report;
          }
        if (!std::isfinite(iterate.norm))
          return report;
      }
    internal::print_newton_failure(pcout,
                                   control,
                                   iterate.norm,
                                   iterate.target);
    return report;
  }



} // namespace PhaseField
