#ifndef phasefield_schemes_nested_scheme_h
#define phasefield_schemes_nested_scheme_h

#include <deal.II/base/conditional_ostream.h>
#include <memory>
#include <phasefield/core/linear_algebra.h>
#include <phasefield/core/parameters.h>
#include <phasefield/mesh/discretization.h>
#include <phasefield/schemes/constraints.h>
#include <phasefield/schemes/nested/nested_linear_systems.h>
#include <phasefield/schemes/nested/nested_model.h>
#include <phasefield/schemes/nested/nested_physics.h>
#include <phasefield/schemes/nested/nested_step.h>
#include <phasefield/schemes/time_stepping_scheme.h>
#include <phasefield/solvers/linear_solver.h>
#include <phasefield/solvers/nonlinear_system.h>

/**
 * The nested variational time discretization of Willmore flow (thesis
 * chapter 3): one step is the saddle point of the Lagrangian (3.19) of the
 * outer problem (3.18a) constrained by the inner (Allen-Cahn) problem
 * (3.18b), with the discrete energies (3.17a), (3.17b) (Definition 3.13),
 * solved by Newton's method. The physics of a step is NestedPhysics, the
 * solves of its Newton systems NestedLinearSystems, both in
 * schemes/nested/.
 */
namespace PhaseField
{
  /**
   * The nested scheme as a TimeSteppingScheme: state (U, V, P),
   * initialisation by Algorithm 3.1, one NestedStep per time step solved
   * by newton_solve() (or, with restoration terms, by
   * minimizing_newton_solve(), so that the outer energy decreases at
   * every iteration), the energy law of thesis Cor. 3.3 (NestedModel).
   */
  template <int dim>
  class NestedScheme : public TimeSteppingScheme<dim>
  {
  public:
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
    /** NestedModel::prepare_step(): P scaled to the new tau. */
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
     * @p extrapolated than at @p last_result (an extrapolation of V and P
     * with U is not consistent in the stiff inner equations).
     *
     * Where it is taken by the descent method (solves_by_descent()):
     * always, with U extrapolated in its profile variable
     * (start_extrapolation()) and V and P re-solved for it (the inner
     * problem). Neither the residual nor the outer energy tells there
     * which start is nearer the minimiser (doc/benchmarks.md, "Start
     * values of the nested scheme").
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
    bool
    restores_after_remesh(const unsigned int field) const override;
    void
    reset_solver() override;
    /** NestedModel::energies(). */
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
    /** NestedModel::energy_law_energy(). */
    double
    energy_law_energy(const Energies &energies) const override;

    /**
     * The default, or with a data term (OuterEnergy::data_term) the
     * tolerance data_term_energy_law_tolerance.
     */
    double
    energy_law_tolerance() const override;

    /**
     * The energy law's tolerance with a data term: the step minimises the
     * term's step model (EnergyTerm::step_model(); for the mismatch its
     * Gauss-Newton model with the curvature of the majoriser, floored),
     * which bounds the term from above only up to the floor and where
     * alpha crosses alpha*, so that the energy law with the term itself
     * holds to second order in the step, not to round-off: near a
     * stationary state the rises stay an order of magnitude below this
     * (doc/benchmarks.md, "Choices in the code").
     */
    static constexpr double data_term_energy_law_tolerance = 1e-4;
    /** NestedModel::dissipation(). */
    double
    dissipation(const BlockVector &old_state,
                const BlockVector &state,
                const double       tau) const override;

    /**
     * False with volume or area constraints where @p old_state misses a
     * held value by more than feasibility_tolerance (relative).
     */
    bool
    energy_law_applies_from(const BlockVector &old_state) const override;

    /**
     * The relative miss of a held value below which a state counts as on
     * the constraints: above the Newton tolerance's drift of the area
     * functional, far below the change of a first step onto them.
     */
    static constexpr double feasibility_tolerance = 1e-7;

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
     * this indefinite matrix): a factorisation costs as many instructions
     * as about 60 solves with it (doc/benchmarks.md, "Refactorisation of
     * the 3-field Jacobian").
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

    /**
     * newton_solve() of the bordered system of @p step with the volume and
     * area constraints (ConstrainedNestedStep) from @p state, the
     * multipliers starting from those of the last converged step; the
     * targets are set from @p old_u where the parameters left them open.
     * No descent fallback: a failed step is halved.
     */
    StepReport
    constrained_solve(NestedStep<dim>     &step,
                      const Vector        &old_u,
                      BlockVector         &state,
                      const double         tau,
                      const NewtonControl &control);

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
    const NestedModel<dim>            model;
    std::unique_ptr<LinearSolver>     linear_solver;
    /**
     * Matrices kept per mesh: the reduced matrices of the biharmonic model,
     * the 3-field Jacobian with restoration terms.
     */
    std::unique_ptr<NestedMatrices<dim>> mesh_matrices;
    /** The volume and area constraints, nullptr without. */
    const std::shared_ptr<ScalarConstraints> constraints;
    /**
     * The next step is the first after initialize(), whose state (the
     * sampled initial shape, or a level transition of the contour problem
     * with the U of the coarser epsilon) is far from the nested step's
     * equilibrium. With restoration terms (area term, all U free) it is
     * taken by the descent method directly (Newton's method failed in the
     * first step of levels 8 and 9 of Fig. 6.5); without, the descent
     * method takes over where Newton's method fails in it.
     */
    bool first_step_from_initial_data = false;
  };
} // namespace PhaseField

#endif
