#ifndef phasefield_solvers_nonlinear_system_h
#define phasefield_solvers_nonlinear_system_h

#include <cmath>
#include <deal.II/base/conditional_ostream.h>
#include <phasefield/core/constants.h>
#include <phasefield/core/linear_algebra.h>
#include <phasefield/core/parameters.h>
#include <phasefield/solvers/linear_solver.h>
#include <string>
#include <utility>
#include <vector>

/**
 * What the nonlinear solvers see of a problem: interfaces, no physics. A
 * time-stepping scheme (or the inner problem of one, or a linear model
 * problem) implements NonlinearSystem for newton_solve(); a problem that
 * is the minimisation of an energy under a constraint also implements
 * MinimizationProblem for minimizing_newton_solve().
 */
namespace PhaseField
{
  /** What one solve of a nonlinear system did. */
  struct StepReport
  {
    bool         converged             = false;
    unsigned int newton_iterations     = 0;
    unsigned int linear_iterations     = 0;
    double       initial_residual_norm = 0;
    double       final_residual_norm   = 0;
    /**
     * Counts of a solver's own, each with its name (a time-stepping scheme
     * writes them into the statistics.csv columns of these names, e.g.
     * al_iterations); combine() sums them by name.
     */
    std::vector<std::pair<std::string, double>> counts;

    /** Add @p value to the count @p name (a new count if there is none). */
    void
    add_count(const std::string &name, const double value)
    {
      for (auto &[count_name, count] : counts)
        if (count_name == name)
          {
            count += value;
            return;
          }
      counts.emplace_back(name, value);
    }

    /** The count @p name, 0 if this report has none. */
    double
    count(const std::string &name) const
    {
      for (const auto &[count_name, count] : counts)
        if (count_name == name)
          return count;
      return 0;
    }

    /** The counts @p names, in their order (0 for each it has not). */
    std::vector<double>
    counts_of(const std::vector<std::string> &names) const
    {
      std::vector<double> values;
      for (const std::string &name : names)
        values.push_back(count(name));
      return values;
    }
  };

  /**
   * The report of two solves one after the other: the iteration counts
   * and the named counts summed, the initial residual of @p first, the
   * rest of @p second.
   */
  StepReport
  combine(const StepReport &first, const StepReport &second);

  /** A nonlinear system R(z) = 0 for a block vector z. */
  class NonlinearSystem
  {
  public:
    virtual ~NonlinearSystem() = default;

    /** @p r = R(@p z). */
    virtual void
    residual(const BlockVector &z, BlockVector &r) const = 0;

    /** Norm of a residual (the L2 norm of the functions it represents). */
    virtual double
    residual_norm(const BlockVector &r) const = 0;

    /**
     * Size of the individual terms of R(z), so that an absolute tolerance
     * is relative to the round-off of the residual evaluation.
     */
    virtual double
    term_scale(const BlockVector &z) const = 0;

    /**
     * The residual norm that the round-off of evaluating R(z) alone can
     * produce (0: not known). newton_solve() stops as converged when the
     * residual stagnates below it (as below
     * NewtonControl::roundoff_level): a tighter target cannot be reached.
     */
    virtual double
    roundoff_level(const BlockVector & /*z*/) const
    {
      return 0;
    }

    /**
     * Solve J(z) dz = -r with @p solver; returns the number of Krylov
     * iterations.
     */
    virtual unsigned int
    solve_jacobian(const BlockVector &z,
                   const BlockVector &r,
                   BlockVector       &dz,
                   LinearSolver      &solver) = 0;

    /** Make a trial state conforming (hanging nodes, boundary values). */
    virtual void
    distribute_constraints(BlockVector &z) const = 0;
  };

  /**
   * The minimisation of an energy phi over the free fields of z, the other
   * fields being determined by a constraint (edge restoration: the outer
   * energy over U, with V the inner minimiser and P its adjoint). The
   * residual of the free fields is the gradient of phi whenever the
   * constraint holds.
   */
  class MinimizationProblem : public NonlinearSystem
  {
  public:
    /**
     * Re-solve the dependent fields of @p z for its free ones (the
     * constraint) and return the energy phi there.
     */
    virtual double
    project_and_energy(BlockVector &z) = 0;

    /**
     * How much the @p energy that project_and_energy() returned at @p z
     * can differ from the exact energy there through round-off and the
     * tolerance of the projection: changes of phi below it are not
     * significant (the descent method's stationarity and Armijo tests).
     * The default: Constants::roundoff relative to the energy, for an
     * energy computed to machine precision from terms of its own size.
     */
    virtual double
    energy_roundoff(const BlockVector &z, const double energy) const
    {
      (void)z;
      return Constants::roundoff * std::abs(energy);
    }

    /**
     * solve_jacobian() with the Hessian of the free fields shifted by
     * @p shift times the mass matrix (a Levenberg-Marquardt shift).
     */
    virtual unsigned int
    solve_shifted_jacobian(const BlockVector &z,
                           const BlockVector &r,
                           BlockVector       &dz,
                           LinearSolver      &solver,
                           const double       shift) = 0;
  };

  /** How newton_solve() and minimizing_newton_solve() iterate and stop. */
  struct NewtonControl
  {
    /** Stop when ||R|| <= relative_tolerance ||R_0|| ... */
    double relative_tolerance = 0;
    /** ... or ||R|| <= absolute_tolerance * term_scale(z). */
    double       absolute_tolerance = 0;
    unsigned int max_iterations     = 0;
    /** Backtracking halvings of one update before giving up. */
    unsigned int max_damping_steps = 0;
    /** Once per solve a full update may raise ||R|| by this factor. */
    double watchdog_factor = 1;
    /**
     * false: every full update is accepted (Newton's method for a convex
     * problem from a start where the residual need not decrease).
     */
    bool line_search = true;
    /**
     * true: the first linear solve is loose and later ones just accurate
     * enough for the target (inexact Newton); false: the solver's own
     * tolerance throughout.
     */
    bool adapt_linear_tolerance = true;
    /**
     * If positive: also stop when ||R|| is below this level and has
     * decreased by less than half in the last iteration (round-off).
     */
    double roundoff_level = 0;

    NewtonControl() = default;
    /** The control of `Subsection Newton`. */
    explicit NewtonControl(const NewtonParameters &parameters);
  };

  namespace internal
  {
    /**
     * The residual @p residual at @p z and its norm @p norm at the start of
     * a Newton method; returns the residual norm at which it stops and sets
     * report.converged if it is reached already.
     */
    double
    start_newton(const NonlinearSystem            &system,
                 const BlockVector                &z,
                 BlockVector                      &residual,
                 const NewtonControl              &control,
                 const dealii::ConditionalOStream &pcout,
                 const bool                        verbose,
                 double                           &norm,
                 StepReport                       &report);

    /**
     * The tolerances of the linear solves of an inexact Newton method
     * (if NewtonControl::adapt_linear_tolerance): the forcing terms of
     * Eisenstat and Walker's "choice 2" (SIAM J. Sci. Comput. 17 (1996)
     * 16-32), eta_k = 0.9 (|R_k| / |R_(k-1)|)^2, at most max_forcing
     * (their safeguard against a sudden drop of eta_k, 0.9 eta_(k-1)^2
     * where that is above 0.1, cannot act below it) and, as Kelley's
     * safeguard against oversolving, at least 0.05 target / |R_k| (the
     * last update need not be more accurate than what reaches the
     * target). The first solve of a Newton method gets max_forcing: far
     * from the solution the nonlinearity, not the linear solve, limits
     * the update. A Newton method that starts within reach of its target,
     * |R_0| <= target / min_reachable_reduction (a nearly stationary time
     * step), instead solves its first system to half the target, so that
     * one update can end it. With the direct solver, whose tight solves are
     * cheap, the cap is 1e-3 and there is no Eisenstat-Walker term: the
     * first solve gets 1e-3 (less only where target / |R_0| is between 1e-3
     * and 2e-3) and later ones 0.05 target / |R_k|, at most 1e-3. One
     * object per Newton solve.
     */
    class ForcingTerm
    {
    public:
      /**
       * Set the tolerance of @p linear_solver for Newton iteration
       * @p iteration (from 1) at the residual norm @p norm, for a Newton
       * method that stops at @p target.
       */
      void
      set_tolerance(LinearSolver        &linear_solver,
                    const NewtonControl &control,
                    const unsigned int   iteration,
                    const double         target,
                    const double         norm);

      /**
       * Largest (and first) forcing term, 0.1, chosen against 0.3 and
       * against a fixed first tolerance 1e-3
       * (doc/benchmarks.md, "Eisenstat-Walker forcing terms; Newton
       * tolerances of nearly stationary steps").
       */
      static constexpr double max_forcing = 0.1;

      /**
       * Smallest reduction target / |R_0| that the first linear solve
       * aims at directly: three decades, the first tolerance of the direct
       * solver. Four decades gave nothing: there
       * the linear model no longer held (doc/benchmarks.md, "Choices in the
       * code").
       */
      static constexpr double min_reachable_reduction = 1e-3;

    private:
      double previous_norm = 0;
    };

    /** The message of a Newton method that ran out of iterations. */
    void
    print_newton_failure(const dealii::ConditionalOStream &pcout,
                         const NewtonControl              &control,
                         const double                      norm,
                         const double                      target);

    /**
     * The message of a Newton method whose linear solver failed (e.g.
     * dealii::SolverControl::NoConvergence) in iteration @p iteration; the
     * Newton solve then reports `converged = false`, so that the time loop
     * retries with half the step.
     */
    void
    print_linear_solver_failure(const dealii::ConditionalOStream &pcout,
                                const unsigned int                iteration,
                                const dealii::ExceptionBase      &exc);
  } // namespace internal
} // namespace PhaseField

#endif
