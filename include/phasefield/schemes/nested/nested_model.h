#ifndef phasefield_schemes_nested_nested_model_h
#define phasefield_schemes_nested_nested_model_h

#include <memory>
#include <phasefield/core/linear_algebra.h>
#include <phasefield/core/parameters.h>
#include <phasefield/mesh/discretization.h>
#include <phasefield/schemes/energies.h>
#include <phasefield/schemes/nested/nested_physics.h>
#include <phasefield/schemes/time_stepping_scheme.h>
#include <phasefield/solvers/linear_solver.h>
#include <string>
#include <vector>

namespace PhaseField
{
  /**
   * The nested discretization (thesis chapter 3) as functions of a state
   * (U, V, P), whatever solves its steps: the coefficients of a step,
   * Algorithm 3.1 (initialisation), the energies, the curvature and the
   * energy law of Cor. 3.3. NestedScheme (Newton) and
   * AugmentedLagrangianScheme (thesis chapter 7) both compute the nested
   * step and share this.
   */
  template <int dim>
  class NestedModel
  {
  public:
    /** The model of @p settings on @p discretization (which must outlive it).
     */
    NestedModel(const SchemeSettings      &settings,
                const Discretization<dim> &discretization);

    /** The coefficients of a step of size @p tau. */
    NestedCoefficients
    coefficients(const double tau) const;

    /** Warnings about the parameters (a non-convex inner energy). */
    std::vector<std::string>
    warnings() const;

    /**
     * Algorithm 3.1: given U in @p state, V from R_P(U, V) = 0 and P from
     * R_V(U, V, P) = 0 for the step size @p tau, with a solver of type
     * @p type of its own; constraints distributed.
     */
    void
    initialize(BlockVector     &state,
               const double     tau,
               LinearSolverType type) const;

    /**
     * V and P of @p state re-solved for its U (the inner problem to
     * round-off, NestedStep::solve_inner_problem()) for the step size
     * @p tau, with a solver of type @p type of its own.
     */
    void
    solve_inner_problem(BlockVector           &state,
                        const double           tau,
                        const LinearSolverType type) const;

    /**
     * P is proportional to tau at the start of a step (R_V = 0 with
     * a = tau / ttau^2): scale the P of a state of step size
     * @p state_tau to @p tau.
     */
    void
    prepare_step(BlockVector &state,
                 const double state_tau,
                 const double tau) const;

    /** Willmore energy (3/4) (1/2) eps Int ((U-V)/ttau)^2 and area. */
    Energies
    energies(const BlockVector &state) const;

    /** (U - V) / inner tau. */
    void
    curvature(const BlockVector &state, Vector &curvature) const;

    /**
     * mu W + eta A of a state with the @p energies (the weights of the
     * outer energy, combined by weighted_regularisation()), plus (3/4) d
     * for a data term d (Energies::data_term) and (3/4) T for the
     * registered terms (Energies::registered_terms): the energy that the
     * step decreases, in geometric units.
     */
    double
    energy_law_energy(const Energies &energies) const;

    /**
     * eps ||U - U^k||^2_M / (2 tau) in geometric units: by thesis
     * Cor. 3.3, on a fixed mesh energy_law_energy() after a step plus this
     * is at most energy_law_energy() before it, if the step found the
     * minimiser.
     */
    double
    dissipation(const BlockVector &old_state,
                const BlockVector &state,
                const double       tau) const;

    /** A solver of type @p type with the tolerances of `Linear solver`. */
    std::unique_ptr<LinearSolver>
    make_solver(const LinearSolverType type) const;

  private:
    const SchemeSettings       settings;
    const Discretization<dim> &discretization;
  };
} // namespace PhaseField

#endif
