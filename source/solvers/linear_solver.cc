#include <cmath>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <phasefield/mesh/algebraic_multigrid.h>
#include <phasefield/solvers/linear_solver.h>
#include <phasefield/solvers/product_form.h>

namespace PhaseField
{
  using namespace dealii;

  LinearSolver::LinearSolver(const LinearSolverType type,
                             const double           relative_tolerance,
                             const unsigned int     max_iterations,
                             const bool             symmetric,
                             const unsigned int     refactorization_threshold,
                             const unsigned int     stale_iteration_limit)
    : solver_type(type)
    , relative_tolerance(relative_tolerance)
    , max_iterations(max_iterations)
    , symmetric(symmetric)
    , refactorization_threshold(refactorization_threshold)
    , stale_iteration_limit(stale_iteration_limit == 0 ? max_iterations :
                                                         stale_iteration_limit)
    , tolerance(relative_tolerance)
  {}



  LinearSolver::~LinearSolver() = default;



  void
  LinearSolver::set_tolerance(const double relative_tolerance)
  {
    tolerance = std::max(relative_tolerance, this->relative_tolerance);
  }



  void
  LinearSolver::factorize(const TrilinosWrappers::SparseMatrix &matrix)
  {
    Assert(solver_type == LinearSolverType::direct, ExcInternalError());
    factorize_for_solve(matrix);
  }



  void
  LinearSolver::reset()
  {
    factorization.reset();
    schur_preconditioner.reset();
    setup_interface_mode.clear();
    last_iterations = 0;
  }



  unsigned int
  LinearSolver::solve(const TrilinosWrappers::SparseMatrix &matrix,
                      Vector                               &solution,
                      const Vector                         &rhs)
  {
    if (solver_type == LinearSolverType::direct)
      {
        if (constant_matrix && factorization &&
            factorization->size() == matrix.m())
          {
            factorization->vmult(solution, rhs);
            last_iterations = 1;
            return last_iterations;
          }
        solution        = 0;
        last_iterations = solve_direct(matrix, solution, rhs);
        return last_iterations;
      }
    return solve_with_multigrid(matrix,
                                AlgebraicMultigrid(matrix.trilinos_matrix()),
                                solution,
                                rhs);
  }



  unsigned int
  LinearSolver::solve(const ShiftedStiffness &op,
                      Vector                 &solution,
                      const Vector           &rhs)
  {
    AssertThrow(solver_type == LinearSolverType::iterative,
                ExcMessage("A direct solver needs the matrix, not an "
                           "operator."));
    return solve_with_multigrid(op,
                                *op.make_multigrid(nullptr,
                                                   multigrid_smoother_sweeps),
                                solution,
                                rhs);
  }



  template <typename Operator>
  unsigned int
  LinearSolver::solve_with_multigrid(const Operator       &op,
                                     const MultigridCycle &multigrid,
                                     Vector               &solution,
                                     const Vector         &rhs)
  {
    SolverControl control(max_iterations,
                          tolerance * rhs.l2_norm(),
                          false,
                          false);
    solution = 0;
    if (symmetric)
      {
        SolverCG<Vector> cg(control);
        cg.solve(op, solution, rhs, multigrid);
      }
    else
      gmres_solve(op, solution, rhs, multigrid, control);
    last_iterations = control.last_step();
    return last_iterations;
  }



  unsigned int
  LinearSolver::solve_direct(const TrilinosWrappers::SparseMatrix &matrix,
                             Vector                               &solution,
                             const Vector                         &rhs)
  {
    const double tolerance_norm = tolerance * rhs.l2_norm();
    const bool fresh = !factorization || factorization->size() != matrix.m() ||
                       last_iterations > refactorization_threshold;
    if (fresh)
      factorize_for_solve(matrix);
    // an earlier factorisation that preconditions this matrix poorly is
    // given up after stale_iteration_limit iterations
    SolverControl control(fresh ?
                            max_iterations :
                            std::min(max_iterations, stale_iteration_limit),
                          tolerance_norm,
                          false,
                          false);
    try
      {
        gmres_solve(matrix, solution, rhs, *factorization, control);
        return control.last_step();
      }
    catch (const SolverControl::NoConvergence &)
      {
        if (fresh)
          throw;
      }
    // factorise this matrix, once
    factorize_for_solve(matrix);
    SolverControl fresh_control(max_iterations, tolerance_norm, false, false);
    solution = 0;
    gmres_solve(matrix, solution, rhs, *factorization, fresh_control);
    return fresh_control.last_step();
  }



  void
  LinearSolver::factorize_for_solve(
    const TrilinosWrappers::SparseMatrix &matrix)
  {
    if (factorization && factorization->size() == matrix.m())
      factorization->refactorize(matrix);
    else
      {
        // free the old factors before the new ones are computed: both at
        // once would raise the peak memory
        factorization.reset();
        factorization =
          std::make_unique<DirectFactorization>(matrix,
                                                pivoting_workspace_percent);
      }
    ++factorization_count;
  }



  template <typename Operator, typename Preconditioner>
  void
  LinearSolver::gmres_solve(const Operator       &op,
                            Vector               &solution,
                            const Vector         &rhs,
                            const Preconditioner &preconditioner,
                            SolverControl        &control) const
  {
    SolverGMRES<Vector> gmres(control,
                              SolverGMRES<Vector>::AdditionalData(
                                gmres_restart, /*right_preconditioning=*/true));
    gmres.solve(op, solution, rhs, preconditioner);
  }

  unsigned int
  LinearSolver::solve_product_form(const ShiftedStiffness &k_hat,
                                   const double            w,
                                   const Vector           &d,
                                   const ShiftedStiffness &g,
                                   const Vector           &mass,
                                   const Vector           &inverse_mass,
                                   Vector                 &solution,
                                   const Vector           &rhs,
                                   const Vector           *interface_mode)
  {
    Assert(solver_type == LinearSolverType::iterative, ExcInternalError());
    const ProductFormMatrix s(k_hat, w, d, inverse_mass);
    const bool              kept_is_valid =
      schur_preconditioner && schur_preconditioner->size() == g.m();
    unsigned int failed_iterations = 0;
    if (kept_is_valid &&
        (constant_matrix ||
         (persistent_matrices && !interface_moved(interface_mode))))
      {
        try
          {
            return cg_solve_product_form(s,
                                         solution,
                                         rhs,
                                         constant_matrix ?
                                           max_iterations :
                                           kept_iteration_limit());
          }
        catch (const SolverControl::NoConvergence &failure)
          {
            // a kept hierarchy of other values: set it up for these
            if (constant_matrix)
              throw;
            failed_iterations = failure.last_step;
          }
      }
    // free the old multigrid hierarchy before the new one is built
    schur_preconditioner.reset();
    schur_preconditioner =
      std::make_unique<SchurPreconditioner>(g, mass, interface_mode);
    ++factorization_count;
    if (interface_mode != nullptr)
      setup_interface_mode = *interface_mode;
    else
      setup_interface_mode.clear();
    cg_solve_product_form(s, solution, rhs, max_iterations);
    fresh_solve = {last_iterations, -std::log10(tolerance)};
    last_iterations += failed_iterations;
    return last_iterations;
  }



  unsigned int
  LinearSolver::cg_solve_product_form(const ProductFormMatrix &s,
                                      Vector                  &solution,
                                      const Vector            &rhs,
                                      const unsigned int       iteration_limit)
  {
    SolverControl    control(iteration_limit,
                          tolerance * rhs.l2_norm(),
                          false,
                          false);
    SolverCG<Vector> cg(control);
    solution = 0;
    cg.solve(s, solution, rhs, *schur_preconditioner);
    last_iterations = control.last_step();
    return last_iterations;
  }



  unsigned int
  LinearSolver::kept_iteration_limit() const
  {
    // a tighter tolerance needs proportionally more iterations per decade
    // beyond the first half, a looser one is not credited
    const double fresh_decades = fresh_solve.decades - free_start_decades;
    if (fresh_decades <= 0)
      return max_iterations;
    const double decades = -std::log10(tolerance) - free_start_decades;
    const double expected =
      fresh_solve.iterations * std::max(1., decades / fresh_decades);
    return std::min<unsigned int>(max_iterations,
                                  std::max(1.,
                                           multigrid_reuse_factor * expected));
  }



  bool
  LinearSolver::interface_moved(const Vector *interface_mode) const
  {
    if (interface_mode == nullptr ||
        setup_interface_mode.size() != interface_mode->size())
      return interface_mode != nullptr;
    Vector change(*interface_mode);
    change -= setup_interface_mode;
    return change.linfty_norm() > interface_mode_tolerance;
  }
} // namespace PhaseField
