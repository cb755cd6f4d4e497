#ifndef phasefield_nested_scheme_h
#define phasefield_nested_scheme_h

#include <deal.II/base/index_set.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <memory>
#include <phasefield/lumped_operators.h>
#include <phasefield/parameters.h>

namespace PhaseField
{
  /** Block indices of the three fields. */
  namespace Field
  {
    constexpr unsigned int U = 0;
    constexpr unsigned int V = 1;
    constexpr unsigned int P = 2;
  } // namespace Field

  /** The double well Psi(v) = (1-v^2)^2 and its derivatives. */
  namespace DoubleWell
  {
    inline double
    psi(const double v)
    {
      return (1 - v * v) * (1 - v * v);
    }
    inline double
    d_psi(const double v)
    {
      return -4 * v * (1 - v * v);
    }
    inline double
    d2_psi(const double v)
    {
      return -4 + 12 * v * v;
    }
    inline double
    d3_psi(const double v)
    {
      return 24 * v;
    }
  } // namespace DoubleWell

  /**
   * Coefficients of one nested step (DESIGN.md section 2). With
   * `double_well = false` and epsilon = 1 the scheme is the biharmonic
   * model problem of thesis chapter 4.
   */
  struct NestedCoefficients
  {
    double epsilon;
    double tau;
    double inner_tau;
    bool   double_well = true;

    /**
     * Weight eta of the area term 2 tau eta a_eps[U] of the outer energy
     * (thesis (5.7), edge restoration); 0 for Willmore flow.
     */
    double area_weight = 0;

    /**
     * Global indices of the DoFs (at least the locally relevant ones) at
     * which U is held at its current value (the C^1 data of thesis
     * Definition 5.1); nullptr: U is free everywhere. V and P stay free.
     */
    const dealii::IndexSet *fixed_u = nullptr;

    /**
     * Levenberg-Marquardt shift mu of the restoration Newton matrix: the
     * UU block gains mu M at the free U values, which turns the Newton
     * direction towards the steepest descent direction -M^-1 R_U of the
     * outer energy as mu grows (minimizing_newton_solve()). Only used by
     * the 3-field system; 0 is Newton's method.
     */
    double u_shift = 0;

    /**
     * True if the area term or fixed U values are present: the UU block of
     * the Jacobian is then not diagonal, and the Newton system is solved as
     * one 3-field system (NestedScheme::solve_newton_system()).
     */
    bool
    has_restoration_terms() const
    {
      return area_weight != 0 || fixed_u != nullptr;
    }

    /** a = tau / inner_tau^2. */
    double
    a() const
    {
      return tau / (inner_tau * inner_tau);
    }
    /** Weight of M Psi'(V) in the inner equation: inner_tau/(2 eps^2). */
    double
    c() const
    {
      return double_well ? inner_tau / (2 * epsilon * epsilon) : 0.;
    }
  };

  /** Energies of a phase field in geometric units (DESIGN.md section 2). */
  struct Energies
  {
    /**
     * (3/4) (1/2) eps Int ((U-V)/ttau)^2 (nested scheme) or
     * (3/4) w_eps[U] (semi-implicit scheme): pi/r for a circle.
     */
    double willmore;
    /** (3/4) a_eps[U]: the perimeter / surface area. */
    double area;
    /** Int (1-U)/2: the measure of the inside phase. */
    double inside_measure;
  };

  /**
   * The parts of Energies that depend on U alone: area (3/4) a_eps[U] and
   * inside measure; the Willmore energy is left at zero.
   */
  template <int dim>
  Energies
  phase_field_energies(const LumpedOperators<dim>                  &operators,
                       const dealii::TrilinosWrappers::MPI::Vector &u,
                       const double                                 epsilon);

  /**
   * Solver of the reduced Newton system S dV = r (see
   * NestedScheme::solve_newton_system()).
   *
   * Direct: GMRES preconditioned with a sparse LU factorisation (MUMPS
   * through Trilinos Amesos) of an earlier S. The factorisation is
   * computed at the first solve and kept while GMRES needs at most
   * `refactorization_threshold` iterations, so the first Newton
   * iteration after a factorisation is an exact solve and later ones (or
   * later time steps on the same mesh) cost a few matrix-vector products.
   * Call reset() when the mesh changes.
   *
   * Iterative: CG (GMRES for a non-symmetric matrix) with algebraic
   * multigrid (Trilinos ML), memory linear in the unknowns. The nested
   * scheme's S is never assembled in this case: solve_product_form()
   * applies it as a product of second-order matrices and preconditions it
   * with multigrid cycles on a second-order matrix.
   */
  class ReducedSystemSolver
  {
  public:
    ReducedSystemSolver(const LinearSolverType type,
                        const double           relative_tolerance,
                        const unsigned int     max_iterations,
                        const bool             symmetric                 = true,
                        const unsigned int     refactorization_threshold = 8);
    ~ReducedSystemSolver();

    /**
     * Solve; returns the number of Krylov iterations (1 when a fresh
     * factorisation was applied once).
     */
    unsigned int
    solve(const dealii::TrilinosWrappers::SparseMatrix &matrix,
          dealii::TrilinosWrappers::MPI::Vector        &solution,
          const dealii::TrilinosWrappers::MPI::Vector  &rhs);

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
     * multigrid hierarchy is built anew at every call (one "factorization"
     * in n_factorizations()). Returns the CG iterations.
     */
    unsigned int
    solve_product_form(
      const dealii::TrilinosWrappers::SparseMatrix &k_hat,
      const double                                  w,
      const dealii::TrilinosWrappers::MPI::Vector  &d,
      const dealii::TrilinosWrappers::SparseMatrix &g,
      const dealii::TrilinosWrappers::MPI::Vector  &mass,
      const dealii::TrilinosWrappers::MPI::Vector  &inverse_mass,
      dealii::TrilinosWrappers::MPI::Vector        &solution,
      const dealii::TrilinosWrappers::MPI::Vector  &rhs);

    /**
     * Relative tolerance of the next solves (an inexact Newton method
     * sets it per iteration); never tighter than the one given to the
     * constructor.
     */
    void
    set_tolerance(const double relative_tolerance);

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

    /** Forget the stored factorisation (e.g. after re-meshing). */
    void
    reset();

    /**
     * Declare whether every following solve() is with the matrix of the
     * stored factorisation (a linear problem whose matrix is constant on
     * a mesh). If so, solve() applies the factorisation once instead of
     * running GMRES with it (the first solve still factorises). Only
     * meaningful for the direct type.
     */
    void
    set_constant_matrix(const bool constant)
    {
      constant_matrix = constant;
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
    class Factorization;

    const LinearSolverType         solver_type;
    const double                   relative_tolerance;
    const unsigned int             max_iterations;
    const bool                     symmetric;
    const unsigned int             refactorization_threshold;
    double                         tolerance;
    std::unique_ptr<Factorization> factorization;
    unsigned int                   last_iterations            = 0;
    unsigned int                   factorization_count        = 0;
    bool                           constant_matrix            = false;
    unsigned int                   pivoting_workspace_percent = 0;
  };

  /**
   * Residual and Newton step of the nested variational time discretization
   * (thesis (3.17)-(3.19)) for Q1 elements with lumped mass. With
   * Z = (U, V, P) and the Lagrangian divided by 2 eps, the residual is
   *
   *   R_U = M(U-U^k) - a M(V-U) - M P
   *   R_V = a M(V-U) + K(V) P,   K(V) = M + c M[Psi''(V)] + ttau L
   *   R_P = M(V-U) + c M Psi'(V) + ttau L V
   *
   * with a = tau/ttau^2, c = ttau/(2 eps^2), and the exact Jacobian is the
   * symmetric matrix
   *
   *   J = [ (1+a)M   -aM                 -M   ]
   *       [ -aM      aM + c M[Psi'''(V)P] K(V) ]
   *       [ -M       K(V)                 0   ].
   *
   * Since M is diagonal, J dZ = -R is solved exactly by elimination:
   * dV solves S dV = -R_V + a R_P - K M^-1 ((1+a) R_P + R_U) with
   *   S = b M + D + (1+a) Khat M^-1 Khat,  Khat = K - b M, b = a/(1+a),
   *   D = c M[Psi'''(V) P];
   * then dU = M^-1 (K dV + R_P) and
   * dP = M^-1 (((1+a) K - a M) dV + (1+a) R_P + R_U).
   *
   * Edge restoration (NestedCoefficients::has_restoration_terms()): the
   * outer energy gains 2 tau eta a_eps[U], a_eps[u] = (1/2) Int eps
   * |grad u|^2 + Psi(u)/eps, so that (divided by 2 eps)
   *
   *   R_U += tau eta (L U + M Psi'(U) / (2 eps^2)),
   *   J_UU = (1+a) M + tau eta (L + M[Psi''(U)] / (2 eps^2)),
   *
   * and at the DoFs in NestedCoefficients::fixed_u the U-row of R is zero,
   * the U-row and U-column of J are those of the identity (thesis 5.3).
   * The UU block is then neither diagonal nor, with fixed U, eliminable
   * row by row; J is assembled as one sparse matrix (unknowns interleaved,
   * (U_i, V_i, P_i)) and solved by the direct solver (2D).
   */
  template <int dim>
  class NestedScheme
  {
  public:
    using Vector      = dealii::TrilinosWrappers::MPI::Vector;
    using BlockVector = dealii::TrilinosWrappers::MPI::BlockVector;

    NestedScheme(const LumpedOperators<dim> &operators,
                 const NestedCoefficients   &coefficients);

    /**
     * Residual R(Z) for the previous outer state @p old_u. The optional
     * @p forcing F (a nodal vector, already multiplied by M) enters the
     * outer energy as -2 tau F.U, i.e. R_U -= tau F / eps.
     */
    void
    residual(const Vector      &old_u,
             const BlockVector &z,
             BlockVector       &r,
             const Vector      *forcing = nullptr) const;

    /** sqrt(R^T M^-1 R) summed over the three blocks. */
    double
    residual_norm(const BlockVector &r) const;

    /**
     * Size of the terms of R(z) in L2: ||U|| + a ||V-U|| + ||P||, the
     * reference for an absolute Newton tolerance.
     */
    double
    term_scale(const BlockVector &z) const;

    /**
     * Solve J(Z) dZ = -R for the Newton update @p dz. Returns the
     * iterations of the linear solver.
     */
    unsigned int
    solve_newton_system(const BlockVector   &z,
                        const BlockVector   &r,
                        BlockVector         &dz,
                        ReducedSystemSolver &solver) const;

    /**
     * The two matrices of the reduced Newton system at a state: K(V) and
     * the Schur complement S (see the class documentation). For the
     * biharmonic model (no double well) both are independent of the state,
     * so they can be built once per mesh and reused in every time step.
     */
    struct ReducedMatrices
    {
      dealii::TrilinosWrappers::SparseMatrix k;
      /** S assembled (only for the direct solver). */
      dealii::TrilinosWrappers::SparseMatrix s;
      /** Product form of S (iterative solver): Khat, diag b M + D, G. */
      dealii::TrilinosWrappers::SparseMatrix k_hat;
      Vector                                 diagonal;
      dealii::TrilinosWrappers::SparseMatrix g;
    };

    /** Build K(V) and S at the state @p z. */
    void
    build_reduced_matrices(const BlockVector     &z,
                           ReducedMatrices       &matrices,
                           const LinearSolverType type) const;

    /**
     * Solve J dZ = -R with matrices built by build_reduced_matrices()
     * (possibly at an earlier state, which is exact when they do not
     * depend on the state). Returns the iterations of the linear solver.
     */
    unsigned int
    solve_newton_system(const ReducedMatrices &matrices,
                        const BlockVector     &r,
                        BlockVector           &dz,
                        ReducedSystemSolver   &solver) const;

    /** y = J(Z) x: the Jacobian applied to a vector (used by tests). */
    void
    jacobian_vmult(const BlockVector &z,
                   const BlockVector &x,
                   BlockVector       &y) const;

    /**
     * Algorithm 3.1: given U in @p z, solve R_P(U, V) = 0 for V (Newton
     * from V = U, to @p tolerance relative to the residual there) and then
     * R_V(U, V, P) = 0 for P (solve_inner_problem()). Returns Newton
     * iterations.
     */
    unsigned int
    initialize_v_and_p(BlockVector         &z,
                       ReducedSystemSolver &solver,
                       const double         tolerance) const;

    /**
     * Given U in @p z, solve the inner problem R_P(U, V) = 0 for V by
     * Newton's method starting from the V in @p z, until
     * ||R_P||_{M^-1} <= @p tolerance, and then the adjoint equation
     * R_V(U, V, P) = 0 for P. Afterwards R_U is the gradient of the
     * reduced outer energy outer_energy() with respect to U. Returns the
     * Newton iterations.
     */
    unsigned int
    solve_inner_problem(BlockVector         &z,
                        ReducedSystemSolver &solver,
                        const double         tolerance) const;

    /**
     * The outer energy of the step from @p old_u at the state @p z,
     * divided by 2 eps like the residual:
     *   (1/2)|U-U^k|_M^2 + (a/2)|V-U|_M^2
     *     + tau eta ((1/2) U.LU + M Psi(U).1 / (2 eps^2)).
     * With V = V(U) the inner minimiser (solve_inner_problem()) this is a
     * function of U alone whose gradient is R_U, the merit function of
     * minimizing_newton_solve().
     */
    double
    outer_energy(const Vector &old_u, const BlockVector &z) const;

    /** Energies of the state @p z in geometric units. */
    Energies
    energies(const BlockVector &z) const;

    const NestedCoefficients &
    coefficients() const
    {
      return coeff;
    }

    /**
     * The 3-field Jacobian of the restoration scheme as one sparse matrix
     * J' = S J(Z) S, S = diag(1, 1, full_system_p_scale()), unknown
     * (field b, DoF i) at row 3 i + b, with the rows and columns of fixed
     * and hanging-node constrained U values replaced by those of the
     * identity. Without the scaling of P the entries differ by the factor
     * a = tau/ttau^2 (up to 10^7) and the pivoting of the sparse LU fills
     * in badly.
     */
    void
    assemble_full_jacobian(const BlockVector                      &z,
                           dealii::TrilinosWrappers::SparseMatrix &j) const;

    /** Scaling of the P unknowns in assemble_full_jacobian(): a. */
    double
    full_system_p_scale() const
    {
      return coeff.a();
    }

  private:
    /** solve_newton_system() with the area term and fixed U values. */
    unsigned int
    solve_full_newton_system(const BlockVector   &z,
                             const BlockVector   &r,
                             BlockVector         &dz,
                             ReducedSystemSolver &solver) const;

    /** Is the U value at locally owned index @p i held fixed? */
    bool
    u_is_fixed(const unsigned int i) const;


    /**
     * The preconditioner of the iterative solver uses
     * G = gamma M + sqrt((1+a)/b) Khat with this gamma. Khat is indefinite
     * near the interface (Psi'' < 0 there), and gamma = 1 can make G nearly
     * singular; a larger gamma keeps G definite at the price of a weaker
     * approximation of S. Measured on the 3D cube at level 6 (first step,
     * 10 Newton iterations, 2 ranks): 398 / 363 / 331 / 392 CG iterations
     * in all for gamma = 1 / 2 / 4 / 8.
     */
    static constexpr double schur_mass_shift = 4;

    /** r = R_P(U, V) = M(V-U) + c M Psi'(V) + ttau L V. */
    void
    inner_residual(const Vector &u, const Vector &v, Vector &r) const;

    /** The nodal weight 1 - shift + c Psi''(V) of the mass in build_k(). */
    Vector
    k_hat_weight(const Vector &v, const double shift) const;

    /** K(V) = M + c M[Psi''(V)] + ttau L, shifted by -shift*M. */
    void
    build_k(const Vector                           &v,
            const double                            shift,
            dealii::TrilinosWrappers::SparseMatrix &k) const;

    const LumpedOperators<dim> &ops;
    const NestedCoefficients    coeff;
  };
} // namespace PhaseField

#endif
