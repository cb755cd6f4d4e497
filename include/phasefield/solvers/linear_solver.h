#ifndef phasefield_solvers_linear_solver_h
#define phasefield_solvers_linear_solver_h

#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <memory>
#include <phasefield/core/linear_algebra.h>
#include <phasefield/core/parameters.h>
#include <phasefield/mesh/stiffness_operator.h>
#include <phasefield/solvers/direct_factorization.h>

namespace PhaseField
{
  class SchurPreconditioner;
  class ProductFormMatrix;

  /**
   * The linear solver of the Newton systems of all schemes (the reduced
   * systems of NestedScheme and SemiImplicitScheme, the inner problem's
   * K(V), the 3-field matrix of edge restoration).
   *
   * Direct: GMRES preconditioned with a sparse LU factorisation (MUMPS
   * through Trilinos Amesos) of an earlier S. The factorisation is
   * computed at the first solve and kept while GMRES needs at most
   * `refactorization_threshold` iterations, so the first Newton
   * iteration after a factorisation is an exact solve and later ones (or
   * later time steps on the same mesh) cost a few matrix-vector products.
   * A GMRES solve with an earlier factorisation is given up after
   * `stale_iteration_limit` iterations (0: `max_iterations`), and the
   * matrix is factorised (GMRES may stagnate on an indefinite matrix). A
   * new factorisation of a matrix with the sparsity pattern of the
   * previous one reuses MUMPS's analysis (DirectFactorization::
   * refactorize()). Call reset() when the mesh changes.
   *
   * Iterative: CG (GMRES for a non-symmetric matrix) with algebraic
   * multigrid (Trilinos ML), memory linear in the unknowns. The nested
   * scheme's S is never assembled in this case: solve_product_form()
   * applies it as a product of second-order matrices and preconditions it
   * with multigrid cycles on a second-order matrix.
   */
  class LinearSolver
  {
  public:
    /**
     * GMRES iterations with an earlier factorisation above which the next
     * solve factorises its matrix (the reduced systems); measured in
     * doc/benchmarks.md, "The refactorisation threshold".
     */
    static constexpr unsigned int default_refactorization_threshold = 4;

    /**
     * Iterative type with set_persistent_matrices(): the multigrid
     * hierarchies of solve_product_form() are kept for the following
     * solves on the same mesh while the interface has not moved
     * (interface_mode_tolerance), and a solve with them may take this
     * factor times the iterations of the first solve after their set-up
     * (scaled by the ratio of the tolerances in decades beyond
     * free_start_decades); beyond, the hierarchy is set up anew and the
     * solve repeated (doc/benchmarks.md, "Keeping the multigrid
     * hierarchy").
     */
    static constexpr double multigrid_reuse_factor = 1.5;

    /**
     * The decades of residual reduction that a preconditioned CG solve
     * from zero gains at almost no cost, for the iteration model of the
     * kept hierarchies: a solve to D decades takes about r (D - 0.5)
     * iterations (doc/benchmarks.md, "Choices in the code").
     */
    static constexpr double free_start_decades = 0.5;

    /**
     * Largest change of the interface mode 1 - V^2 (SchurPreconditioner)
     * since the set-up of a kept hierarchy: for V = tanh(d/eps),
     * |d/dd (1 - V^2)| <= 0.77/eps, so 0.2 allows the interface to move by
     * at least a quarter of eps (doc/benchmarks.md, "Keeping the multigrid
     * hierarchy" and "Choices in the code").
     */
    static constexpr double interface_mode_tolerance = 0.2;

    LinearSolver(const LinearSolverType type,
                 const double           relative_tolerance,
                 const unsigned int     max_iterations,
                 const bool             symmetric = true,
                 const unsigned int     refactorization_threshold =
                   default_refactorization_threshold,
                 const unsigned int stale_iteration_limit = 0);
    ~LinearSolver();

    /**
     * Factorise @p matrix now (direct type): with set_constant_matrix(),
     * every following solve() applies this factorisation once. A matrix
     * with the sparsity pattern of the one factorised before reuses
     * MUMPS's analysis (DirectFactorization::refactorize()); reset()
     * forgets it.
     */
    void
    factorize(const dealii::TrilinosWrappers::SparseMatrix &matrix);

    /**
     * Solve; returns the number of Krylov iterations (1 when a fresh
     * factorisation was applied once).
     */
    unsigned int
    solve(const dealii::TrilinosWrappers::SparseMatrix &matrix,
          Vector                                       &solution,
          const Vector                                 &rhs);

    /**
     * Solve with an operator that is not stored as a matrix (iterative
     * type only): Krylov iterations with an AMG set up from its rows.
     */
    unsigned int
    solve(const ShiftedStiffness &op, Vector &solution, const Vector &rhs);

    /**
     * Solve S x = r for S = diag(d) + w Khat M^-1 Khat given in product
     * form (never assembled: two sparse matrix-vector products with the
     * second-order matrix Khat per application), with CG preconditioned by
     * G^-1 M G^-1 for a second-order matrix G given by the caller, each
     * G^-1 being one algebraic multigrid cycle. With d = beta M and
     * G = M + sqrt(w/beta) Khat, beta G M^-1 G = S + 2 sqrt(w beta) Khat,
     * and for positive semi-definite Khat the preconditioned matrix has
     * its spectrum in [1/2, 1] (the Schur complement preconditioner of
     * Boyanova, Do-Quang and Neytcheva for Cahn-Hilliard systems). The
     * multigrid hierarchies are built for every call, or with
     * set_persistent_matrices() kept while they precondition well
     * (multigrid_reuse_factor); each set-up counts as a
     * "factorization" in n_factorizations(). @p interface_mode, if given, joins
     * the constant in the near null space of these hierarchies
     * (SchurPreconditioner). Returns the CG iterations.
     */
    unsigned int
    solve_product_form(const ShiftedStiffness &k_hat,
                       const double            w,
                       const Vector           &d,
                       const ShiftedStiffness &g,
                       const Vector           &mass,
                       const Vector           &inverse_mass,
                       Vector                 &solution,
                       const Vector           &rhs,
                       const Vector           *interface_mode = nullptr);

    /**
     * Solve @p op x = @p rhs by flexible GMRES with the preconditioner
     * @p preconditioner, which may itself be an inexact iterative solve
     * (vmult(dst, src) both), to the current tolerance; for block systems
     * whose preconditioner is built by the caller. Returns the
     * iterations.
     */
    template <typename Operator, typename Preconditioner, typename VectorType>
    unsigned int
    solve_flexible(const Operator       &op,
                   VectorType           &solution,
                   const VectorType     &rhs,
                   const Preconditioner &preconditioner)
    {
      dealii::SolverControl            control(max_iterations,
                                    tolerance * rhs.l2_norm(),
                                    false,
                                    false);
      dealii::SolverFGMRES<VectorType> fgmres(
        control,
        typename dealii::SolverFGMRES<VectorType>::AdditionalData(
          gmres_restart));
      solution = 0;
      fgmres.solve(op, solution, rhs, preconditioner);
      last_iterations = control.last_step();
      return last_iterations;
    }

    /**
     * Relative tolerance of the next solves (an inexact Newton method
     * sets it per iteration); never tighter than the one given to the
     * constructor.
     */
    void
    set_tolerance(const double relative_tolerance);

    /** The relative tolerance of the next solves. */
    double
    get_tolerance() const
    {
      return tolerance;
    }

    /**
     * Factorise indefinite matrices (the 3-field Newton matrix of edge
     * restoration): MUMPS gets @p percent per cent extra workspace for
     * delayed pivots. 0 (the default): the matrices are definite.
     */
    void
    set_pivoting_workspace(const unsigned int percent)
    {
      pivoting_workspace_percent = percent;
    }

    /**
     * Forget the stored factorisation and multigrid hierarchy (e.g. after
     * re-meshing).
     */
    void
    reset();

    /**
     * Declare whether every following solve is with the matrices of the
     * first one (a linear problem whose matrices are constant on a mesh).
     * If so, solve() applies the stored factorisation once instead of
     * running GMRES with it (the first solve still factorises), and
     * solve_product_form() keeps the multigrid hierarchies of its first
     * call.
     */
    void
    set_constant_matrix(const bool constant)
    {
      constant_matrix = constant;
    }

    /**
     * Declare whether the matrices passed to the following solves are the
     * same objects, refilled in place, until the next reset(): a
     * multigrid hierarchy refers to its fine-level matrix, so only then
     * may solve_product_form() keep it for later solves with other values
     * (see multigrid_reuse_factor). Its fine-level smoother then applies
     * the current matrix, its coarse levels those of the set-up.
     */
    void
    set_persistent_matrices(const bool persistent)
    {
      persistent_matrices = persistent;
    }

    /**
     * Number of preconditioner set-ups so far: LU factorisations (direct)
     * or multigrid hierarchies of solve_product_form() (iterative).
     */
    unsigned int
    n_factorizations() const
    {
      return factorization_count;
    }

    LinearSolverType
    type() const
    {
      return solver_type;
    }

  private:
    /** GMRES restart length. */
    static constexpr unsigned int gmres_restart = 50;

    /**
     * CG on @p s preconditioned with the stored SchurPreconditioner, at
     * most @p iteration_limit iterations; throws
     * SolverControl::NoConvergence.
     */
    unsigned int
    cg_solve_product_form(const ProductFormMatrix &s,
                          Vector                  &solution,
                          const Vector            &rhs,
                          const unsigned int       iteration_limit);

    /**
     * Iterations allowed to a solve with a kept SchurPreconditioner:
     * multigrid_reuse_factor times those of the first solve after its
     * set-up, scaled up by the ratio of the tolerances in decades beyond
     * free_start_decades where this one is tighter; the iteration limit
     * if the first solve asked for no more than free_start_decades.
     */
    unsigned int
    kept_iteration_limit() const;

    /**
     * Whether @p interface_mode differs from the one of the set-up of the
     * stored SchurPreconditioner by more than interface_mode_tolerance
     * (at some node).
     */
    bool
    interface_moved(const Vector *interface_mode) const;

    /** Direct type: GMRES preconditioned with a (possibly earlier) LU. */
    unsigned int
    solve_direct(const dealii::TrilinosWrappers::SparseMatrix &matrix,
                 Vector                                       &solution,
                 const Vector                                 &rhs);

    /**
     * Factorise @p matrix, reusing the analysis of the stored
     * factorisation if the pattern is the same.
     */
    void
    factorize_for_solve(const dealii::TrilinosWrappers::SparseMatrix &matrix);

    /**
     * CG (GMRES if not symmetric) for @p op, preconditioned with
     * @p multigrid, a cycle for the same operator.
     */
    template <typename Operator>
    unsigned int
    solve_with_multigrid(const Operator       &op,
                         const MultigridCycle &multigrid,
                         Vector               &solution,
                         const Vector         &rhs);

    /** Right-preconditioned GMRES. */
    template <typename Operator, typename Preconditioner>
    void
    gmres_solve(const Operator        &op,
                Vector                &solution,
                const Vector          &rhs,
                const Preconditioner  &preconditioner,
                dealii::SolverControl &control) const;

    const LinearSolverType solver_type;
    const double           relative_tolerance;
    const unsigned int     max_iterations;
    const bool             symmetric;
    const unsigned int     refactorization_threshold;
    /**
     * GMRES iterations allowed with an earlier factorisation before this
     * matrix is factorised.
     */
    const unsigned int                   stale_iteration_limit;
    double                               tolerance;
    std::unique_ptr<DirectFactorization> factorization;
    unsigned int                         last_iterations     = 0;
    unsigned int                         factorization_count = 0;
    /**
     * The product-form preconditioner, kept with set_constant_matrix() or
     * set_persistent_matrices().
     */
    std::unique_ptr<SchurPreconditioner> schur_preconditioner;
    /** Iterations of a CG solve and its tolerance in decades. */
    struct SolveRecord
    {
      unsigned int iterations = 0;
      double       decades    = 1;
    };
    /** The first solve after the set-up of schur_preconditioner. */
    SolveRecord fresh_solve;
    /** The interface mode of the set-up of schur_preconditioner. */
    Vector       setup_interface_mode;
    bool         constant_matrix            = false;
    bool         persistent_matrices        = false;
    unsigned int pivoting_workspace_percent = 0;
  };
} // namespace PhaseField

#endif
