#ifndef phasefield_schemes_augmented_lagrangian_scheme_h
#define phasefield_schemes_augmented_lagrangian_scheme_h

#include <deal.II/base/conditional_ostream.h>
#include <phasefield/core/linear_algebra.h>
#include <phasefield/core/parameters.h>
#include <phasefield/mesh/discretization.h>
#include <phasefield/schemes/augmented_lagrangian_parameters.h>
#include <phasefield/schemes/nested/nested_model.h>
#include <phasefield/schemes/nested/nested_physics.h>
#include <phasefield/schemes/time_stepping_scheme.h>
#include <phasefield/solvers/augmented_lagrangian.h>
#include <phasefield/solvers/linear_solver.h>
#include <phasefield/solvers/product_form.h>
#include <phasefield/solvers/symmetric_product_matrix.h>

/**
 * The nested step of thesis chapter 3 solved as in thesis chapter 7: the
 * minimisation of the outer energy over (U, V) under the constraint that
 * V solves the inner (Allen-Cahn) equation, by the augmented-Lagrangian
 * method (augmented_lagrangian_minimize()) with a trust-region inner
 * solver (trust_region_minimize(), Steihaug-Toint truncated CG with
 * matrix-free Hessian products).
 */
namespace PhaseField
{
  /**
   * One step as a constrained minimisation in x = (U, V) (two blocks):
   *
   *   f(U, V) = s (|U-U^k|_M^2 + a |V-U|_M^2 - 2 (tau/eps) F.U),
   *   c(U, V) = M C(U, V) = M(V-U) + c M Psi'(V) + ttau L V = R_P,
   *
   * with a = mu tau/ttau^2, c = ttau/(2 eps^2) (0 for the biharmonic
   * model), F the forcing of the biharmonic model, s = 1 (scaled, thesis
   * (7.9): f = e_out/eps) or s = eps (unscaled: f = e_out). Edge
   * restoration adds the area term 2s tau eta a_eps[U]/eps to f (its
   * gradient and Hessian from NestedPhysics::add_terms_gradient() and
   * NestedPhysics::add_terms_hessian_vmult()), and U is fixed at the DoFs of
   * OuterEnergy::fixed_u: the U-entries of the gradient, of every Hessian
   * product and of the preconditioner are 0 there, so that the trust
   * region never moves them. In short, f = 2s NestedPhysics::outer_energy().
   * The derivatives are
   *
   *   grad f = 2s (M(U-U^k) - a M(V-U) - (tau/eps) F,  a M(V-U)),
   *   f''    = 2s [(1+a)M  -aM; -aM  aM],
   *   c'(d)  = -M d_U + K(V) d_V,   c'^T y = (-M y, K(V) y),
   *   sum_i y_i c_i'' d = (0, c M[Psi'''(V) y] d_V),
   *
   * K(V) = M + c M[Psi''(V)] + ttau L applied matrix-free (nodal weights
   * of NestedWeights and the stiffness matrix). The constrained minimiser
   * is the (U, V) of the nested step's saddle point; the multipliers are
   * related by P_AL = -2 s P_nested.
   *
   * Preconditioner: B = f'' + lambda J^T M^-1 J (the Hessian without the
   * third-derivative term), inverted by eliminating U (its UU block
   * (s(1+a) + lambda) M is diagonal; here s = f_scale; the area term of
   * edge restoration is left out of it, as it is O(s tau eta h^-2) M against
   * s a M = s mu tau ttau^-2 M) and solving with
   *
   *   S_V = (lambda s (1+a)/beta) Khat M^-1 Khat
   *         + (s a/beta)(s + lambda/(1+a)) M,
   *   beta = s(1+a) + lambda,  Khat = K - a/(1+a) M,
   *
   * once per trust-region iterate: with a solver set by set_schur_solver()
   * (the direct solver, 2D) S_V is assembled and factorised; without one
   * it is approximated in product form, m G M^-1 G / gamma^2 with
   * G = gamma M + sqrt(w/m) Khat (NestedPhysics::build_schur_factor(), the
   * preconditioner of the nested scheme's iterative solver) and one
   * multigrid cycle per G^-1: memory linear in the unknowns. S_V has the
   * form of the nested scheme's Schur complement without its diagonal E,
   * with the weights w, m above (for lambda -> infinity, s times the
   * nested scheme's w = 1 + a, m = a/(1+a)).
   *
   * With U fixed at some DoFs (edge restoration) U is eliminated only at
   * the free ones; at a fixed DoF the exact S_V has the nodal weights
   * b = 0, w = lambda, m = s a instead. The direct path assembles S_V with
   * these nodal weights (with the weights of the free DoFs everywhere the
   * CG iterations of edge restoration grow by two orders of magnitude,
   * (doc/benchmarks.md, "Choices in the code")); the product form keeps the
   * weights of the free DoFs.
   */
  template <int dim>
  class AugmentedLagrangianStep : public ConstrainedMinimizationProblem
  {
  public:
    /**
     * The step from @p old_u (which must outlive this object); @p scaled:
     * s = 1, else s = epsilon.
     */
    AugmentedLagrangianStep(const Discretization<dim> &discretization,
                            const NestedCoefficients  &coefficients,
                            const Vector              &old_u,
                            const bool                 scaled);

    double
    objective(const BlockVector &x) const override;
    void
    objective_gradient(const BlockVector &x, BlockVector &g) const override;
    void
    objective_hessian_vmult(const BlockVector &x,
                            const BlockVector &d,
                            BlockVector       &y) const override;
    void
    constraint(const BlockVector &x, Vector &c) const override;
    void
    constraint_jacobian_vmult(const BlockVector &x,
                              const BlockVector &d,
                              Vector            &jd) const override;
    void
    constraint_jacobian_tvmult(const BlockVector &x,
                               const Vector      &y,
                               BlockVector       &g) const override;
    void
    constraint_hessian_vmult(const BlockVector &x,
                             const Vector      &y,
                             const BlockVector &d,
                             BlockVector       &out) const override;
    void
    riesz(const Vector &c, Vector &out) const override;
    /** sqrt(g^T M^-1 g) over both blocks. */
    double
    gradient_norm(const BlockVector &g) const override;
    void
    setup_preconditioner(const BlockVector &x,
                         const Vector      &y,
                         const double       penalty) override;
    void
    precondition(const BlockVector &r, BlockVector &z) const override;
    void
    distribute_constraints(BlockVector &x) const override;

    /**
     * Use the exact Schur-complement preconditioner with @p solver (must
     * be of the direct type and outlive this object).
     */
    void
    set_schur_solver(LinearSolver &solver)
    {
      schur_solver = &solver;
    }

    /** The preconditioner set-ups (setup_preconditioner() calls) so far. */
    unsigned int
    n_setups() const
    {
      return setups;
    }

    /**
     * The factor 2s of f: s = 1 (@p scaled) or s = epsilon. The multipliers
     * are related by P_AL = -2s P_nested.
     */
    static double
    objective_scale(const NestedCoefficients &coefficients, const bool scaled);

    /**
     * A two-block vector (U, V) in the layout of the DoFs, zero.
     */
    BlockVector
    make_point() const;

  private:
    /**
     * S_V = w Khat M^-1 Khat + m M, Khat = K(V) - b M at V = schur_v, in
     * product form with its multigrid (no Schur solver).
     */
    void
    setup_schur_multigrid(const double b, const double w, const double m);

    /** The same S_V assembled and factorised by the Schur solver. */
    void
    factorize_schur(const double b, const double w, const double m);

    /** @p z = S_V^-1 @p r, exactly or by the multigrid product form. */
    void
    apply_schur_inverse(const Vector &r, Vector &z) const;

    const Discretization<dim>  &discretization;
    const LumpedOperators<dim> &ops;
    const NestedCoefficients    coeff;
    const NestedWeights         weights;
    const Vector               &old_u;
    /** The factor 2s of f. */
    const double f_scale;
    /** R_P of the nested step: c(x). */
    const NestedPhysics<dim> physics;
    /**
     * The product form of S_V (no Schur solver): G, its multigrid, 1 - V^2
     * and gamma^2/m.
     */
    std::unique_ptr<ShiftedStiffness>    schur_factor;
    std::unique_ptr<SchurPreconditioner> schur_multigrid;
    Vector                               interface_mode;
    double                               schur_inverse_scale = 0;
    /** The direct solver of S_V, or null. */
    LinearSolver *schur_solver = nullptr;
    /** S_V, the V of the iterate and the coefficients of B. */
    SymmetricProductMatrix schur;
    Vector                 schur_v;
    double                 schur_beta    = 0;
    double                 schur_penalty = 0;
    unsigned int           setups        = 0;
  };

  /**
   * `Time stepping / Scheme = augmented lagrangian`: state (U, V, P) with
   * P the multiplier of the augmented Lagrangian, one
   * augmented_lagrangian_minimize() of an AugmentedLagrangianStep per time
   * step, warm-started from the last state. A step whose result has a
   * higher outer energy than its start (more than
   * AugmentedLagrangian::monotonicity_tolerance relative) is repeated from
   * the start with the start penalty times penalty_growth, at most
   * AugmentedLagrangian::max_monotonicity_retries times, and then
   * reported as not converged (the time loop halves it). The penalty
   * starts at
   * `Initial penalty` and each later step at max(lambda_final /
   * `Penalty reduction per step`, `Initial penalty`); reset_solver()
   * resets it. Initialisation, energies,
   * curvature and the energy law are those of NestedScheme (the same
   * discrete problem), except that P starts at `Initial multiplier`.
   */
  template <int dim>
  class AugmentedLagrangianScheme : public TimeSteppingScheme<dim>
  {
  public:
    AugmentedLagrangianScheme(const SchemeSettings             &settings,
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
    StepReport
    advance(const BlockVector &old_state,
            BlockVector       &state,
            const double       tau) override;
    void
    before_remesh() override;

    void
    after_remesh(BlockVector &state, const double tau) override;
    bool
    restores_after_remesh(const unsigned int field) const override;
    void
    reset_solver() override;
    Energies
    energies(const BlockVector &state) const override;
    /**
     * Preconditioner set-ups so far: one per gradient evaluation (the
     * factorisation of S_V or the multigrid hierarchy of its product form).
     */
    unsigned int
    n_factorizations() const override
    {
      return preconditioner_setups;
    }
    void
    curvature(const BlockVector &state, Vector &curvature) const override;
    bool
    has_energy_law() const override
    {
      return true;
    }
    double
    energy_law_energy(const Energies &energies) const override;

    /**
     * AugmentedLagrangian::monotonicity_tolerance: the round-off of the
     * outer energy at the end of a step is about eta* / ttau relative.
     */
    double
    energy_law_tolerance() const override
    {
      return AugmentedLagrangian::monotonicity_tolerance;
    }
    double
    dissipation(const BlockVector &old_state,
                const BlockVector &state,
                const double       tau) const override;

  private:
    /** The control of augmented_lagrangian_minimize() from the settings. */
    AugmentedLagrangianControl
    control() const;

    /** Add the iterations of @p al to @p report, and its residuals. */
    static void
    add_to_report(const AugmentedLagrangianReport &al, StepReport &report);

    /** The message of a step whose outer loop did not converge. */
    void
    report_failure(const AugmentedLagrangianReport &al) const;

    const SchemeSettings settings;
    /** The subsection `Augmented Lagrangian`, which the scheme owns. */
    const AugmentedLagrangianParameters parameters;
    const Discretization<dim>          &discretization;
    const dealii::ConditionalOStream   &pcout;
    /** Initialisation, energies and energy law of the same problem. */
    NestedModel<dim> model;
    /** The type of the linear solvers (`Linear solver / Type` resolved). */
    const LinearSolverType solver_type;
    /** The penalty the next step starts with. */
    double next_penalty;
    /** Sum of AugmentedLagrangianStep::n_setups() over the steps. */
    unsigned int preconditioner_setups = 0;
    /** The solver of the Schur preconditioner (direct type only). */
    std::unique_ptr<LinearSolver> schur_solver;
  };
} // namespace PhaseField

#endif
