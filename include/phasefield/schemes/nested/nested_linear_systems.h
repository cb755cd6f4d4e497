#ifndef phasefield_schemes_nested_nested_linear_systems_h
#define phasefield_schemes_nested_nested_linear_systems_h

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <memory>
#include <phasefield/core/linear_algebra.h>
#include <phasefield/core/parameters.h>
#include <phasefield/mesh/stiffness_operator.h>
#include <phasefield/mesh/stiffness_square.h>
#include <phasefield/schemes/nested/nested_physics.h>
#include <phasefield/solvers/linear_solver.h>

namespace PhaseField
{
  /**
   * The matrices of the nested step's Newton systems that are kept per
   * mesh (NestedScheme) or per step: K(V) and the Schur complement S of
   * the elimination, assembled (direct solver) or in product form
   * (iterative solver), and the assembled 3-field Jacobian of edge
   * restoration. K(V), Khat and G are operators on the stiffness
   * operator (StiffnessOperator::shift()), not matrices. For the
   * biharmonic model (no double well) they are independent of the state.
   */
  template <int dim>
  struct NestedMatrices
  {
    std::unique_ptr<ShiftedStiffness> k;
    /** S assembled (only for the direct solver). */
    dealii::TrilinosWrappers::SparseMatrix s;
    /** L M^-1 L, from which S is assembled (direct solver). */
    std::unique_ptr<StiffnessSquare<dim>> stiffness_square;
    /** Product form of S (iterative solver): Khat, diag b M + E, G. */
    std::unique_ptr<ShiftedStiffness> k_hat;
    Vector                            diagonal;
    std::unique_ptr<ShiftedStiffness> g;
    /** 1 - V^2, the near kernel of G (SchurPreconditioner). */
    Vector interface_mode;
    /**
     * The weight w of the UU block w M that S eliminates: 1 + a, plus
     * the Levenberg-Marquardt shift of a shifted system.
     */
    double uu_weight = 0;
    /**
     * The solver of S when the elimination preconditions the 3-field
     * system of an area term without fixed U values (the contour
     * problem): it keeps its factorisation of S across Newton iterations
     * as the scheme's solver does for willmore_flow.
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
   * The linear-system strategies of the nested step's Newton systems
   * J dZ = -R (NestedPhysics):
   *
   * - without restoration terms M is the whole UU block, and the system is
   *   solved exactly by elimination: dV solves
   *     S dV = -R_V + a R_P - K M^-1 ((1+a) R_P + R_U),
   *     S = b M + E + (1+a) Khat M^-1 Khat,  Khat = K - b M, b = a/(1+a),
   *   then dU = M^-1 (K dV + R_P) and
   *   dP = M^-1 (((1+a) K - a M) dV + (1+a) R_P + R_U); S is assembled
   *   from L M^-1 L (StiffnessSquare) for the direct solver, or applied in
   *   product form with the preconditioner G^-1 M G^-1 (iterative);
   * - with the area term and U held fixed (edge restoration), J is
   *   assembled as one sparse matrix (unknowns interleaved, (U_i, V_i,
   *   P_i)) and solved by the direct solver (2D);
   * - with the area term and all U free (the contour problem), flexible
   *   GMRES on J preconditioned by the elimination without the area term.
   */
  template <int dim>
  class NestedLinearSystems
  {
  public:
    /**
     * The systems of @p physics (which must outlive this object).
     * @p mesh_matrices, if given, is storage that the caller keeps per
     * mesh: the matrices are built into it, so that their sparsity
     * patterns (and L M^-1 L) are built once per mesh and only their
     * values in every Newton iteration; if the Jacobian does not depend on
     * the state (no double well, no restoration terms), the reduced
     * matrices are built once and reused.
     */
    NestedLinearSystems(const NestedPhysics<dim> &physics,
                        NestedMatrices<dim>      *mesh_matrices = nullptr);

    /** J(@p z) @p dz = -@p r. Returns the linear iterations. */
    unsigned int
    solve_jacobian(const BlockVector &z,
                   const BlockVector &r,
                   BlockVector       &dz,
                   LinearSolver      &solver);

    /**
     * The same with @p shift M added to the UU block (the
     * Levenberg-Marquardt shift of the descent method).
     */
    unsigned int
    solve_shifted_jacobian(const BlockVector &z,
                           const BlockVector &r,
                           BlockVector       &dz,
                           LinearSolver      &solver,
                           const double       shift);

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

  private:
    /**
     * Build K(V) and S at the state @p z, S for the UU block
     * (1 + a + @p shift) M: with w = 1 + a + shift,
     *   S = w Khat M^-1 Khat + a (1 - a/w) M + E,  Khat = K - (a/w) M,
     * which is the S of the class documentation for shift = 0.
     */
    void
    build_reduced_matrices(const BlockVector     &z,
                           NestedMatrices<dim>   &matrices,
                           const LinearSolverType type,
                           const double           shift = 0) const;

    /** J dZ = -R by elimination with the matrices of the state. */
    unsigned int
    solve_reduced_system(const NestedMatrices<dim> &matrices,
                         const BlockVector         &r,
                         BlockVector               &dz,
                         LinearSolver              &solver) const;

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
     * instead of the 3-field matrix. The data term's Hessian H_d of the
     * monolithic contour coupling is left to GMRES; an elimination that
     * holds it (S + K M^-1 H_d M^-1 K by inner CG, commit 73c3b27) took
     * fewer GMRES iterations but more time (doc/benchmarks.md, "Choices in the
     * code"). Returns the GMRES iterations.
     */
    unsigned int
    solve_area_system(const BlockVector &z,
                      const BlockVector &r,
                      BlockVector       &dz,
                      LinearSolver      &solver,
                      const double       shift) const;

    /** The kept matrices, or @p local where the step has none. */
    NestedMatrices<dim> &
    storage(NestedMatrices<dim> &local) const;

    /** K(V) - shift M as a matrix (for the direct solver). */
    void
    build_k_matrix(const Vector                           &v,
                   const double                            shift,
                   dealii::TrilinosWrappers::SparseMatrix &k) const;

    /**
     * Relative tolerance and iteration limit of the solves of S that
     * precondition solve_area_system() (direct: GMRES with a kept
     * factorisation of S; iterative: CG with one multigrid hierarchy per
     * Newton system); 1e-2 against 1e-4: doc/benchmarks.md, "The area
     * term's preconditioner tolerance".
     */
    static constexpr double       area_preconditioner_tolerance      = 1e-2;
    static constexpr unsigned int area_preconditioner_max_iterations = 100;

    const NestedPhysics<dim>   &physics;
    const LumpedOperators<dim> &ops;
    const NestedCoefficients   &coeff;
    const NestedWeights        &weights;
    /** Per-mesh storage of the caller (may be nullptr). */
    NestedMatrices<dim> *mesh_matrices;
    /** Does the Jacobian not depend on the state (biharmonic model)? */
    const bool constant_jacobian;
  };
} // namespace PhaseField

#endif
