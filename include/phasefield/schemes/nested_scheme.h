#ifndef phasefield_schemes_nested_scheme_h
#define phasefield_schemes_nested_scheme_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/index_set.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <memory>
#include <phasefield/core/constants.h>
#include <phasefield/core/parameters.h>
#include <phasefield/mesh/discretization.h>
#include <phasefield/mesh/stiffness_square.h>
#include <phasefield/schemes/double_well.h>
#include <phasefield/schemes/outer_energy.h>
#include <phasefield/schemes/time_stepping_scheme.h>
#include <phasefield/solvers/linear_solver.h>
#include <phasefield/solvers/nonlinear_system.h>

/**
 * The nested variational time discretization of Willmore flow (thesis
 * chapter 3) for Q1 elements with lumped mass: one step is the saddle
 * point of the Lagrangian (3.19) of the outer problem (3.18a) constrained
 * by the inner (Allen-Cahn) problem (3.18b), with the discrete energies
 * (3.17a), (3.17b) (Definition 3.13), solved by Newton's method.
 */
namespace PhaseField
{
  /** Block indices of the three fields. */
  namespace Field
  {
    constexpr unsigned int U = 0;
    constexpr unsigned int V = 1;
    constexpr unsigned int P = 2;
  } // namespace Field

  /**
   * The coefficients of one nested step. With `double_well = false` and
   * epsilon = 1 the scheme is the biharmonic model problem of thesis
   * chapter 4.
   */
  struct NestedCoefficients
  {
    double      epsilon;
    double      tau;
    double      inner_tau;
    bool        double_well = true;
    OuterEnergy outer;
  };

  /**
   * The one definition of the nodal weights of the nested step's residual
   * and Jacobian (see NestedStep), computed once from NestedCoefficients:
   * every block of J is M[weight] + factor L with a weight and a factor
   * from here.
   */
  struct NestedWeights
  {
    explicit NestedWeights(const NestedCoefficients &coefficients)
      : a(coefficients.outer.willmore_weight *
          (coefficients.tau /
           (coefficients.inner_tau * coefficients.inner_tau)))
      , c(coefficients.double_well ?
            coefficients.inner_tau /
              (2 * coefficients.epsilon * coefficients.epsilon) :
            0.)
      , inner_tau(coefficients.inner_tau)
      , area_factor(coefficients.tau * coefficients.outer.area_weight)
      , area_potential_factor(1. /
                              (2 * coefficients.epsilon * coefficients.epsilon))
    {}

    /** a = mu tau / ttau^2: weight of M(V-U) in R_U and R_V. */
    const double a;
    /** c = ttau/(2 eps^2): weight of M Psi'(V) in R_P (0 without Psi). */
    const double c;
    /** ttau: factor of L in K(V) (the VP and PV blocks). */
    const double inner_tau;
    /** tau eta: factor of the area term in R_U and of L in J_UU. */
    const double area_factor;
    /** 1/(2 eps^2): weight of M Psi'(U) in the area term. */
    const double area_potential_factor;

    /**
     * Nodal weight of K(V) - shift M = M[k] + ttau L, the Hessian of the
     * inner energy: 1 - shift + c Psi''(v).
     */
    double
    k(const double v, const double shift = 0) const
    {
      return 1 - shift + c * DoubleWell::d2_psi(v);
    }
    /** Nodal weight of E = M[e] in J_VV = a M + E: c Psi'''(v) p. */
    double
    e(const double v, const double p) const
    {
      return c * DoubleWell::d3_psi(v) * p;
    }
    /**
     * Nodal weight of the mass part of J_UU = M[uu] + tau eta L:
     * 1 + a + shift + tau eta Psi''(u)/(2 eps^2), with a Levenberg-Marquardt
     * @p shift.
     */
    double
    uu(const double u, const double shift = 0) const
    {
      return (1 + a + shift) +
             area_factor * area_potential_factor * DoubleWell::d2_psi(u);
    }
  };

  /**
   * One step of the nested scheme from U^k: the saddle-point system of
   * thesis (3.19) in Z = (U, V, P), divided by 2 eps,
   *
   *   R_U = M(U-U^k) - a M(V-U) - M P   [+ tau eta (L U + M Psi'(U)/(2 eps^2))
   *                                      - (tau/eps) F]
   *   R_V = a M(V-U) + K(V) P,   K(V) = M + c M[Psi''(V)] + ttau L
   *   R_P = M(V-U) + c M Psi'(V) + ttau L V
   *
   * with a = mu tau/ttau^2, c = ttau/(2 eps^2), and the exact, symmetric
   * Jacobian
   *
   *   J = [ (1+a)M [+ tau eta (L + M[Psi''(U)]/(2 eps^2))]  -aM    -M   ]
   *       [ -aM                                    aM + E   K(V) ]
   *       [ -M                                     K(V)     0    ]
   *
   * with E = c M[Psi'''(V) P]; all nodal weights come from
   * NestedCoefficients. Without restoration terms M is the whole UU block
   * and J dZ = -R is solved exactly by elimination: dV solves
   *   S dV = -R_V + a R_P - K M^-1 ((1+a) R_P + R_U),
   *   S = b M + E + (1+a) Khat M^-1 Khat,  Khat = K - b M, b = a/(1+a),
   * then dU = M^-1 (K dV + R_P) and
   * dP = M^-1 (((1+a) K - a M) dV + (1+a) R_P + R_U).
   *
   * With the area term of edge restoration (thesis (5.7)) and U held
   * fixed at the DoFs of OuterEnergy::fixed_u (thesis Definition 5.1:
   * the U-row of R is zero there, the U-row and U-column of J are those of
   * the identity), the UU block is neither diagonal nor eliminable row by
   * row; J is then assembled as one sparse matrix (unknowns interleaved,
   * (U_i, V_i, P_i)) and solved by the direct solver (2D).
   *
   * As a MinimizationProblem the step is the minimisation of the outer
   * energy over U, with V the inner minimiser and P its adjoint
   * (project_and_energy()); R_U is then its gradient.
   */
  template <int dim>
  class NestedStep : public MinimizationProblem
  {
  public:
    using Vector      = dealii::TrilinosWrappers::MPI::Vector;
    using BlockVector = dealii::TrilinosWrappers::MPI::BlockVector;

    /**
     * The two matrices of the reduced Newton system at a state: K(V) and
     * the Schur complement S, assembled (direct solver) or in product
     * form (iterative solver). K(V), Khat and G are kept as operators on
     * the stiffness matrix (StiffnessPlusDiagonal), not as matrices. For the
     * biharmonic model (no double well) they are independent of the state.
     */
    struct ReducedMatrices
    {
      StiffnessPlusDiagonal k;
      /** S assembled (only for the direct solver). */
      dealii::TrilinosWrappers::SparseMatrix s;
      /** L M^-1 L, from which S is assembled (direct solver). */
      std::unique_ptr<StiffnessSquare<dim>> stiffness_square;
      /** Product form of S (iterative solver): Khat, diag b M + E, G. */
      StiffnessPlusDiagonal k_hat;
      Vector                diagonal;
      StiffnessPlusDiagonal g;
      /** 1 - V^2, the near kernel of G (SchurPreconditioner). */
      Vector interface_mode;
      /**
       * The weight w of the UU block w M that S eliminates: 1 + a, plus
       * the Levenberg-Marquardt shift of a shifted system.
       */
      double uu_weight = 0;
      /**
       * The direct solver of S when the reduced system preconditions the
       * 3-field system of an area term without fixed U values (the
       * contour problem): it keeps its factorisation of S across Newton
       * iterations as the scheme's solver does for willmore_flow.
       */
      std::unique_ptr<LinearSolver> preconditioner_solver;
      /**
       * The assembled 3-field Jacobian (restoration terms): its sparsity
       * pattern depends on the mesh only, so it is built once per mesh and
       * only its values are refilled in every Newton iteration (which also
       * lets the direct solver keep MUMPS's analysis).
       */
      dealii::TrilinosWrappers::SparseMatrix full_jacobian;
    };

    /**
     * The step from @p old_u (which must outlive this object).
     * @p mesh_matrices, if given, is storage that the caller keeps per
     * mesh: the reduced matrices are built into it, so that their
     * sparsity patterns (and L M^-1 L) are built once per mesh and only
     * their values in every Newton iteration; if the Jacobian does not
     * depend on the state (no double well, no restoration terms), the
     * reduced matrices are built once and reused; with restoration terms
     * it holds the 3-field Jacobian, whose pattern is then built once per
     * mesh.
     */
    NestedStep(const Discretization<dim> &discretization,
               const NestedCoefficients  &coefficients,
               const Vector              &old_u,
               ReducedMatrices           *mesh_matrices = nullptr);

    /** @name NonlinearSystem */
    /** @{ */
    void
    residual(const BlockVector &z, BlockVector &r) const override;
    /** sqrt(R^T M^-1 R) summed over the three blocks. */
    double
    residual_norm(const BlockVector &r) const override;
    /**
     * Size of the terms of R(z) in L2: ||U|| + a ||V-U|| + ||P||, the
     * reference for an absolute Newton tolerance.
     */
    double
    term_scale(const BlockVector &z) const override;
    /**
     * DBL_EPSILON (||U|| + a (||U|| + ||V||) + ||P||) in the M-norm: a M (V -
     * U) in R_U and R_V is computed from V and U of size 1, so its
     * round-off grows with a = tau/ttau^2 (h^-2 for tau = ttau = h^2). At
     * h = 2^-10 (quarter circle) the residual stagnated at 1e-11 to 4.5e-11,
     * above the relative target of 3.8e-11, and every step was halved.
     */
    double
    roundoff_level(const BlockVector &z) const override;
    unsigned int
    solve_jacobian(const BlockVector &z,
                   const BlockVector &r,
                   BlockVector       &dz,
                   LinearSolver      &solver) override;
    void
    distribute_constraints(BlockVector &z) const override;
    /** @} */

    /** @name MinimizationProblem (the descent method of NestedScheme) */
    /** @{ */
    /**
     * V and P re-solved for the U of @p z (solve_inner_problem() to
     * round-off), then the outer energy there.
     */
    double
    project_and_energy(BlockVector &z) override;
    /**
     * The default plus a |V-U|_M (||R_P(U, V)||_{M^-1} + DBL_EPSILON
     * (|U|_M + |V|_M)): the term (a/2)|V-U|_M^2 of outer_energy() changes
     * by a (V-U)^T M dV for an error dV of V, which the inner problem
     * leaves at the size of its residual (its Jacobian is about M) and
     * the subtraction V - U at the round-off of U and V. Relative to the
     * energy, of which (a/2)|V-U|^2 is nearly all, this is about
     * 2 dV / |V-U|: it grows as V - U = ttau H shrinks (the cross at
     * level 10, a = 3.2e7: the energy did not change in 12 digits while
     * the default allowance of 1e-14 failed every Armijo test).
     */
    double
    energy_roundoff(const BlockVector &z, const double energy) const override;
    /**
     * The Newton system with mu M added to the UU block: the 3-field
     * solve with restoration terms, the elimination otherwise.
     */
    unsigned int
    solve_shifted_jacobian(const BlockVector &z,
                           const BlockVector &r,
                           BlockVector       &dz,
                           LinearSolver      &solver,
                           const double       shift) override;
    /** @} */

    /**
     * y = J(Z) x: the Jacobian (with @p shift M added to the UU block)
     * applied to a vector (used by tests).
     */
    void
    jacobian_vmult(const BlockVector &z,
                   const BlockVector &x,
                   BlockVector       &y,
                   const double       shift = 0) const;

    /**
     * The outer energy at the state @p z, divided by 2 eps like the
     * residual:
     *   (1/2)|U-U^k|_M^2 + (a/2)|V-U|_M^2 + tau eta a_eps[U] / eps.
     * With V = V(U) the inner miniser (solve_inner_problem()) this is a
     * function of U alone whose gradient is R_U.
     */
    double
    outer_energy(const BlockVector &z) const;

    /**
     * Given U in @p z, solve the inner problem R_P(U, V) = 0 for V by
     * Newton's method (newton_solve() on InnerProblem) starting from the V
     * in @p z, until ||R_P||_{M^-1} <= @p tolerance, and then the adjoint
     * equation R_V(U, V, P) = 0 for P. Afterwards R_U is the gradient of
     * outer_energy() with respect to U. Throws if Newton fails. Returns
     * the Newton iterations.
     */
    unsigned int
    solve_inner_problem(BlockVector  &z,
                        LinearSolver &solver,
                        const double  tolerance) const;

    /**
     * Algorithm 3.1: given U in @p z, V from R_P(U, V) = 0 (Newton from
     * V = U, to @p tolerance relative to the residual there) and then P
     * from R_V(U, V, P) = 0. Returns the Newton iterations.
     */
    unsigned int
    initialize_v_and_p(BlockVector  &z,
                       LinearSolver &solver,
                       const double  tolerance) const;

    /**
     * The solver of the inner problems of project_and_energy(): a direct
     * solver of its own, so that it keeps the factorisation of K(V) while
     * the Newton solver factorises the 3-field matrix.
     */
    void
    set_inner_solver(LinearSolver &solver)
    {
      inner_solver = &solver;
    }

    const NestedCoefficients &
    coefficients() const
    {
      return coeff;
    }

    /**
     * Tolerance of ||R_P||_{M^-1} in the inner problems of
     * project_and_energy(): round-off is about 1e-15; an inexact V changes
     * the outer energy to first order and R_U by a = tau/ttau^2 times it.
     */
    static constexpr double inner_tolerance = Constants::roundoff;

    /**
     * r = R_P(U, V) = M(V-U) + c M Psi'(V) + ttau L V: the inner equation,
     * M times the constraint C(U, V) of the augmented Lagrangian scheme.
     */
    void
    inner_residual(const Vector &u, const Vector &v, Vector &r) const;

    /**
     * @p g += @p factor tau eta (L U + M Psi'(U) / (2 eps^2)): the gradient
     * of the area term tau eta a_eps[U] / eps of outer_energy() (edge
     * restoration, the U-row of R); nothing without an area weight.
     */
    void
    add_area_gradient(const Vector &u, const double factor, Vector &g) const;

    /**
     * @p y += @p factor tau eta (L d + M[Psi''(U)] d / (2 eps^2)): the
     * Hessian of the same area term applied to @p d (matrix-free);
     * nothing without an area weight.
     */
    void
    add_area_hessian_vmult(const Vector &u,
                           const Vector &d,
                           const double  factor,
                           Vector       &y) const;

    /**
     * Set @p u_block to 0 at the DoFs of OuterEnergy::fixed_u (a gradient
     * or a direction in U that must leave the fixed values unchanged).
     */
    void
    zero_fixed_u(Vector &u_block) const;

    /**
     * K(V) - shift M = M[k_weight] + ttau L, as a matrix (for a solver
     * that needs its entries) ...
     */
    void
    build_k(const Vector                           &v,
            const double                            shift,
            dealii::TrilinosWrappers::SparseMatrix &k) const;

    /** ... or as an operator that applies L (one vector of storage). */
    void
    build_k(const Vector          &v,
            const double           shift,
            StiffnessPlusDiagonal &k) const;

    /**
     * Solve K(V) @p x = @p rhs with @p solver: K as an operator for the
     * iterative type, as a matrix for the direct one. Returns the
     * iterations.
     */
    unsigned int
    solve_with_k(const Vector &v,
                 LinearSolver &solver,
                 Vector       &x,
                 const Vector &rhs) const;

    /**
     * The factor G of the product-form preconditioner of
     * S = w Khat M^-1 Khat + m M (+ a diagonal), Khat = K(V) - b M:
     * G = gamma M + sqrt(w/m) Khat with gamma = schur_mass_shift, so that
     * m G M^-1 G / gamma^2 approximates S, and the interface translation
     * mode 1 - V^2 for its multigrid (SchurPreconditioner). Serves the
     * iterative solver of this scheme (b = a/(1+a), w = 1+a) and the
     * preconditioner of the augmented Lagrangian's trust region.
     */
    void
    build_schur_factor(const Vector          &v,
                       const double           b,
                       const double           w,
                       const double           m,
                       StiffnessPlusDiagonal &g,
                       Vector                &interface_mode) const;

    /**
     * The shift gamma of build_schur_factor(). The preconditioner of the
     * iterative solver uses
     * G = gamma M + s Khat, s = sqrt((1+a)/b), with gamma =
     * schur_mass_shift, and its multigrid keeps the interface translation
     * mode 1 - V^2 on the coarse levels (SchurPreconditioner). CG
     * iterations of the first step (eps = 4h, tau = 0.03h, ttau = h^2,
     * 2 ranks; sphere r = 0.35: 4 Newton iterations, cube: 9-10), before
     * (constant near null space, gamma = 4 + s c) and after:
     * sphere level 6 154 -> 82, level 7 272 -> 132; cube level 6 363 ->
     * 243. With the mode, gamma = 1.5 / 2.5 / 4 / 12 gave 92 / 85 / 82 /
     * 161 on the level-6 sphere. Without it, gamma had to grow with the
     * level (the nodal mass weight of Khat, 1 - b + c Psi''(V), is about
     * -4c where V = 0, and s c grows like h^-1.5): the multigrid could not
     * represent the nearly singular translations.
     */
    static constexpr double schur_mass_shift = 4;

  private:
    class InnerProblem;

    /**
     * Build K(V) and S at the state @p z, S for the UU block
     * (1 + a + @p shift) M: with w = 1 + a + shift,
     *   S = w Khat M^-1 Khat + a (1 - a/w) M + E,  Khat = K - (a/w) M,
     * which is the S of the class documentation for shift = 0.
     */
    void
    build_reduced_matrices(const BlockVector     &z,
                           ReducedMatrices       &matrices,
                           const LinearSolverType type,
                           const double           shift = 0) const;

    /** J dZ = -R by elimination with the matrices of the state. */
    unsigned int
    solve_reduced_system(const ReducedMatrices &matrices,
                         const BlockVector     &r,
                         BlockVector           &dz,
                         LinearSolver          &solver) const;

    /**
     * The 3-field Jacobian (UU block shifted by @p shift M) as one sparse
     * matrix J' = S J(Z) S, S = diag(1, 1, a), unknown (field b, DoF i) at
     * row 3 i + b, with the rows and columns of fixed and hanging-node
     * constrained U values replaced by those of the identity. Without the
     * scaling of P the entries differ by the factor a = tau/ttau^2 (up to
     * 10^7) and the pivoting of the sparse LU fills in badly.
     */
    void
    assemble_full_jacobian(const BlockVector                      &z,
                           const double                            shift,
                           dealii::TrilinosWrappers::SparseMatrix &j) const;

    /**
     * The reduced matrices of the eliminated system: those kept in the
     * per-mesh storage, or @p local where the step has none.
     */
    ReducedMatrices &
    reduced_matrix_storage(ReducedMatrices &local) const;

    /**
     * The 3-field Jacobian of assemble_full_jacobian(): the one kept in
     * the per-mesh storage (pattern built at its first use), or @p local.
     */
    dealii::TrilinosWrappers::SparseMatrix &
    full_jacobian_storage(dealii::TrilinosWrappers::SparseMatrix &local) const;

    /** The sparsity pattern of assemble_full_jacobian() in @p j. */
    void
    reinit_full_jacobian(dealii::TrilinosWrappers::SparseMatrix &j) const;

    /**
     * J dZ = -R for the Jacobian with the area term (shifted by shift M):
     * with fixed U values by the assembled 3-field Jacobian, otherwise by
     * solve_area_system().
     */
    unsigned int
    solve_full_system(const BlockVector &z,
                      const BlockVector &r,
                      BlockVector       &dz,
                      LinearSolver      &solver,
                      const double       shift) const;

    /**
     * J dZ = -R for the Jacobian with an area term and no fixed U values
     * (the contour problem): flexible GMRES on J (applied matrix-free),
     * preconditioned by the elimination of the Jacobian without the area
     * term, whose UU block is (1 + a + shift) M. The area term's part of
     * the UU block, tau eta (L + M[Psi''(U)]/(2 eps^2)), is smaller than
     * (1 + a) M by about eta ttau^2/h^2 (eta h^2 for ttau = h^2), so a few
     * GMRES iterations suffice, and only the scalar S is factorised
     * instead of the 3-field matrix. Returns the GMRES iterations.
     */
    unsigned int
    solve_area_system(const BlockVector &z,
                      const BlockVector &r,
                      BlockVector       &dz,
                      LinearSolver      &solver,
                      const double       shift) const;

    /** y = J(Z) x as jacobian_vmult(), with K(V) given as @p k. */
    void
    apply_jacobian(const StiffnessPlusDiagonal &k,
                   const BlockVector           &z,
                   const BlockVector           &x,
                   BlockVector                 &y,
                   const double                 shift) const;

    /** Is the U value at locally owned index @p i held fixed? */
    bool
    u_is_fixed(const unsigned int i) const;

    /**
     * @p y += @p factor tau eta (L @p x + M p / (2 eps^2)) with the nodal
     * values p_i = @p potential(i): the one loop of add_area_gradient()
     * (x = U, p = Psi'(U)) and add_area_hessian_vmult() (x = d,
     * p = Psi''(U) d); nothing without an area weight.
     */
    template <typename NodalPotential>
    void
    add_area_term(const Vector         &x,
                  const double          factor,
                  const NodalPotential &potential,
                  Vector               &y) const;

    /** The nodal weights k_weight(V, shift) of K(V) - shift M. */
    Vector
    k_weights(const Vector &v, const double shift) const;



    /**
     * Relative tolerance and iteration limit of the solves of S that
     * precondition solve_area_system() (direct: GMRES with a kept
     * factorisation of S, refactorised when it needs more than
     * LinearSolver::default_refactorization_threshold iterations;
     * iterative: CG with one multigrid hierarchy per Newton system).
     * Measured against 1e-4: fig6_5_disc.prm, 10 level-6 steps, 1 rank,
     * 1.65 s instead of 2.02 s of user time (GMRES iterations 11-14
     * instead of 9-11 per step); the 3D test shape_from_contour_3d with
     * eta = 1, 8.5 s instead of 14.8 s for the first step (29 instead of
     * 25 FGMRES iterations; both under load).
     */
    static constexpr double       area_preconditioner_tolerance      = 1e-2;
    static constexpr unsigned int area_preconditioner_max_iterations = 100;

    const Discretization<dim>  &discretization;
    const LumpedOperators<dim> &ops;
    const NestedCoefficients    coeff;
    const NestedWeights         weights;
    const Vector               &old_u;
    /** Per-mesh storage of the caller (may be nullptr). */
    ReducedMatrices *mesh_matrices;
    /** Does the Jacobian not depend on the state (biharmonic model)? */
    const bool constant_jacobian;
    /** The solver of project_and_energy()'s inner problems. */
    LinearSolver *inner_solver = nullptr;
  };

  /**
   * The nested scheme as a TimeSteppingScheme: state (U, V, P),
   * initialisation by Algorithm 3.1, one NestedStep per time step solved
   * by newton_solve() (or, with restoration terms, by
   * minimizing_newton_solve(), so that the outer energy decreases at
   * every iteration), the energy law of thesis Cor. 3.3.
   */
  template <int dim>
  class NestedScheme : public TimeSteppingScheme<dim>
  {
  public:
    using Vector      = dealii::TrilinosWrappers::MPI::Vector;
    using BlockVector = dealii::TrilinosWrappers::MPI::BlockVector;

    NestedScheme(const SchemeSettings             &settings,
                 const Discretization<dim>        &discretization,
                 const dealii::ConditionalOStream &pcout);

    std::string
    name() const override;
    std::vector<std::string>
    field_names() const override;
    std::string
    linear_solver_description() const override;
    std::vector<std::string>
    warnings() const override;
    void
    initialize(BlockVector &state, const double tau) override;
    void
    prepare_step(BlockVector &state,
                 const double state_tau,
                 const double tau) const override;
    /** Newton's method (or the descent method) from the start value. */
    bool
    iterates_from_start_value() const override
    {
      return true;
    }
    /**
     * Profile where the descent method takes the step
     * (solves_by_descent()), linear where Newton's method does (see
     * take_extrapolated_start()).
     */
    StartExtrapolation
    start_extrapolation() const override;

    /**
     * Where the step is taken by Newton's method: if the residual
     * sqrt(R . M^-1 R) of NestedStep::residual() is smaller at
     * @p extrapolated than at @p last_result. An extrapolation of V and P
     * with U is not consistent in the stiff inner equations: in the 2D
     * quarter circle the residual is 8x larger there, and the last
     * result is kept.
     *
     * Where it is taken by the descent method (solves_by_descent()):
     * always, with U extrapolated in its profile variable
     * (start_extrapolation(): the restored edge moves by several
     * epsilon per step early on) and V and P re-solved for it (the inner
     * problem). Newton's method keeps the linear extrapolation of all
     * fields: U extrapolated in the profile variable and V linearly are
     * not consistent in R_P (the level-5 cube of the test
     * extrapolated_start lost its gain in steps 4 and 5). Neither the residual
     * nor the outer energy tells which start is nearer the minimiser: in the
     * damaged circle at level 9, step 4, the extrapolated start had the
     * residual 49.6 against 0.0295 and the outer energy 0.113703 against
     * 0.112548 at the last result, and the descent method took 6 iterations
     * from it against 28-29 from the last result, to the same step. The outer
     * energy is flat along the motion of the interface (a small gradient far
     * from the minimiser) and steep across the profile (a large gradient that
     * one Newton update removes).
     */
    bool
    take_extrapolated_start(const BlockVector &old_state,
                            const BlockVector &last_result,
                            BlockVector       &extrapolated,
                            const double       tau) const override;
    StepReport
    advance(const BlockVector &old_state,
            BlockVector       &state,
            const double       tau) override;
    void
    before_remesh() override;

    void
    after_remesh(BlockVector &state, const double tau) override;
    void
    reset_solver() override;
    /** Willmore energy (3/4) (1/2) eps Int ((U-V)/ttau)^2 and area. */
    Energies
    energies(const BlockVector &state) const override;
    unsigned int
    n_factorizations() const override
    {
      return linear_solver->n_factorizations();
    }
    /** (U - V) / inner tau. */
    void
    curvature(const BlockVector &state, Vector &curvature) const override;
    bool
    has_energy_law() const override
    {
      return true;
    }
    double
    energy_law_energy(const BlockVector &state) const override;
    /**
     * eps ||U - U^k||^2_M / (2 tau) in geometric units: by thesis
     * Cor. 3.3, on a fixed mesh energy_law_energy() after a step plus this
     * is at most energy_law_energy() before it, if the step found the
     * minimiser.
     */
    double
    dissipation(const BlockVector &old_state,
                const BlockVector &state,
                const double       tau) const override;

    /** The coefficients of a step of size @p tau. */
    NestedCoefficients
    coefficients(const double tau) const;

  private:
    /**
     * One attempt at the step of size @p tau from @p old_state, starting
     * from @p state: Newton's method, and the descent method where it is
     * needed (with U fixed outside a region, with restoration terms in the
     * first step, and where Newton's method fails in the first step).
     */
    StepReport
    attempt_step(const BlockVector &old_state,
                 BlockVector       &state,
                 const double       tau);

    /**
     * GMRES iterations with an earlier factorisation of the 3-field
     * Jacobian (restoration terms) after which it is given up and the
     * Newton matrix is factorised (LinearSolver; GMRES may stagnate on
     * this indefinite matrix). One MUMPS factorisation of the 3-field
     * matrix costs as many instructions as about 60 solves with it at
     * level 6 of Fig. 6.5 (22,000 unknowns; callgrind), so a factorisation
     * kept for several Newton iterations pays even at 20 GMRES iterations
     * each; in 2 steps there (21 Newton iterations) a factorisation per
     * iteration took 40.8e9 instructions, the reduced systems' threshold 8
     * 28.7e9 (11 factorisations) and 40 23.8e9 (4). With a limit of 80
     * stagnating solves (Levenberg-Marquardt shifts of edge restoration at
     * level 9) cost more than the factorisations they were to save.
     */
    static constexpr unsigned int full_system_refactorization_threshold = 20;

    /**
     * minimizing_newton_solve() of @p step from @p state: Newton's method
     * as a descent method for the outer energy, with V and P re-solved for
     * every trial U (edge restoration).
     */
    StepReport
    descent_solve(NestedStep<dim>     &step,
                  BlockVector         &state,
                  const NewtonControl &control);

    /** A solver of type @p type with the tolerances of `Linear solver`. */
    std::unique_ptr<LinearSolver>
    make_solver(const LinearSolverType type) const;

    /**
     * Is every step after the first taken by the descent method (U fixed
     * outside a region: edge restoration)? See attempt_step().
     */
    bool
    solves_by_descent() const;

    /**
     * The biharmonic model (no double well, no restoration terms): the
     * Newton system is linear with the same matrices in every step on a
     * mesh.
     */
    bool
    linear_model() const;

    const SchemeSettings              settings;
    const Discretization<dim>        &discretization;
    const dealii::ConditionalOStream &pcout;
    std::unique_ptr<LinearSolver>     linear_solver;
    /**
     * Matrices kept per mesh: the reduced matrices of the biharmonic model,
     * the 3-field Jacobian with restoration terms.
     */
    std::unique_ptr<typename NestedStep<dim>::ReducedMatrices> mesh_matrices;
    /**
     * The next step is the first after initialize(), whose state (the
     * sampled initial shape, or a level transition of the contour problem
     * with the U of the coarser epsilon) is far from the nested step's
     * equilibrium. With restoration terms (area term, all U free) it is
     * taken by the descent method directly: in the Fig. 6.5 run Newton's
     * method failed in the first step of levels 8 and 9 (W = 2862 and
     * 11405 at their start, 11.5 after the step). Without, the descent
     * method takes over where Newton's method fails in it.
     */
    bool first_step_from_initial_data = false;
  };
} // namespace PhaseField

#endif
