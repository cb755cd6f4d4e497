#include <algorithm>
#include <cmath>
#include <phasefield/solvers/nonlinear_system.h>
#include <sstream>

namespace PhaseField
{
  using namespace dealii;

  NewtonControl::NewtonControl(const NewtonParameters &parameters)
    : relative_tolerance(parameters.relative_tolerance)
    , absolute_tolerance(parameters.absolute_tolerance)
    , max_iterations(parameters.max_iterations)
    , max_damping_steps(parameters.max_damping_steps)
    , watchdog_factor(parameters.watchdog_factor)
  {}



  StepReport
  combine(const StepReport &first, const StepReport &second)
  {
    StepReport sum = second;
    sum.newton_iterations += first.newton_iterations;
    sum.linear_iterations += first.linear_iterations;
    for (const auto &[name, count] : first.counts)
      sum.add_count(name, count);
    sum.initial_residual_norm = first.initial_residual_norm;
    return sum;
  }



  namespace internal
  {
    double
    start_newton(const NonlinearSystem    &system,
                 const BlockVector        &z,
                 BlockVector              &residual,
                 const NewtonControl      &control,
                 const ConditionalOStream &pcout,
                 const bool                verbose,
                 double                   &norm,
                 StepReport               &report)
    {
      system.residual(z, residual);
      norm                         = system.residual_norm(residual);
      report.initial_residual_norm = norm;
      report.final_residual_norm   = norm;
      const double target =
        std::max(control.relative_tolerance * norm,
                 control.absolute_tolerance * system.term_scale(z));
      if (verbose)
        pcout << "    Newton 0: residual " << norm << " (target " << target
              << ')' << std::endl;
      report.converged = std::isfinite(norm) && norm <= target;
      return target;
    }



    void
    print_newton_failure(const ConditionalOStream &pcout,
                         const NewtonControl      &control,
                         const double              norm,
                         const double              target)
    {
      pcout << "    Newton did not reach the tolerance in "
            << control.max_iterations << " iterations (residual " << norm
            << ", target " << target << ")." << std::endl;
    }



    void
    ForcingTerm::set_tolerance(LinearSolver        &linear_solver,
                               const NewtonControl &control,
                               const unsigned int   iteration,
                               const double         target,
                               const double         norm)
    {
      if (!control.adapt_linear_tolerance)
        return;
      // Eisenstat and Walker's choice 2 with gamma = 0.9, alpha = 2; the
      // direct solver has no such term (see the class documentation)
      constexpr double gamma                = 0.9;
      constexpr double linear_safety_factor = 0.05;
      constexpr double direct_forcing       = 1e-3;
      // a solve to half the target leaves room for the quadratic remainder
      constexpr double first_solve_share = 0.5;
      const bool   direct    = linear_solver.type() == LinearSolverType::direct;
      const double cap       = direct ? direct_forcing : max_forcing;
      const double reduction = target / norm;
      double       forcing;
      if (iteration == 1)
        forcing = reduction >= min_reachable_reduction ?
                    std::min(cap, first_solve_share * reduction) :
                    cap;
      else
        {
          const double ratio = norm / previous_norm;
          forcing            = std::min(cap,
                             std::max(direct ? 0. : gamma * ratio * ratio,
                                      linear_safety_factor * reduction));
        }
      previous_norm = norm;
      linear_solver.set_tolerance(forcing);
    }



    void
    print_linear_solver_failure(const ConditionalOStream &pcout,
                                const unsigned int        iteration,
                                const ExceptionBase      &exc)
    {
      std::ostringstream info;
      exc.print_info(info);
      pcout << "    Newton iteration " << iteration
            << ": the linear solver failed, the Newton solve did not "
               "converge: "
            << info.str() << std::endl;
    }
  } // namespace internal
} // namespace PhaseField
