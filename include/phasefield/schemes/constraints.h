#ifndef phasefield_schemes_constraints_h
#define phasefield_schemes_constraints_h

#include <memory>
#include <phasefield/core/linear_algebra.h>
#include <phasefield/core/parameters.h>
#include <phasefield/mesh/lumped_operators.h>
#include <phasefield/schemes/energy_term_registry.h>
#include <phasefield/schemes/energy_terms.h>
#include <phasefield/schemes/outer_energy.h>
#include <string>
#include <vector>

/**
 * Scalar constraints of a vesicle: the inside measure and the area
 * functional held fixed in every step of the nested scheme by Lagrange
 * multipliers (`Constraints / Volume`, `Constraints / Area`).
 *
 * In geometric units (Energies) the step of size tau minimises
 *
 *   eps ||U-U^k||^2_M / (2 tau) + W + sum_j mu_j (g_j[U] - g_j*)
 *
 * over (U, V, P) and the multipliers mu_j, with the constraints
 * g_volume[U] = Int (1-U)/2 (lumped) and g_area[U] = (3/4) a_eps[U]. The
 * multipliers are the physical ones: mu_area is the tension sigma,
 * -mu_volume the pressure p (E = W + sigma A - p V). In the units of the
 * nested step's residual (the outer energy divided by 2 eps, thesis
 * units times 4/3) the step adds lambda_j (g_j - g_j*) with
 * lambda_j = (4 tau / (3 eps)) mu_j (to_residual_units()).
 * ConstrainedNestedStep solves the bordered Newton system in (U, V, P,
 * lambda).
 */
namespace PhaseField
{
  /** The kind of a scalar constraint. */
  enum class ScalarConstraint
  {
    volume,
    area
  };

  /**
   * The constraints of a run, their targets g_j* and the multipliers mu_j
   * of the last step that converged. Shared (std::shared_ptr in
   * OuterEnergy::registered_terms under name()) by the problem, the
   * nested scheme, which solves for the multipliers, and the energy term
   * (ConstraintTerm), which adds them to the step.
   */
  class ScalarConstraints
  {
  public:
    /** The constraints of @p parameters for the phase field width @p epsilon.
     */
    ScalarConstraints(const ConstraintParameters &parameters,
                      const double                epsilon);

    /** The name in the registry of model terms. */
    static std::string
    name();

    /** The constraints of @p outer, nullptr if it has none. */
    static std::shared_ptr<ScalarConstraints>
    of(const OuterEnergy &outer);

    /** The number of constraints. */
    unsigned int
    size() const
    {
      return kinds.size();
    }

    /** The kind of constraint @p j. */
    ScalarConstraint
    kind(const unsigned int j) const
    {
      return kinds[j];
    }

    /**
     * The constraint functional of @p kind at @p u in geometric units,
     * whether it is held or not. Collective.
     */
    template <int dim>
    double
    value_of(const ScalarConstraint      kind,
             const LumpedOperators<dim> &operators,
             const Vector               &u) const;

    /** g_j[@p u] in geometric units. Collective. */
    template <int dim>
    double
    value(const unsigned int          j,
          const LumpedOperators<dim> &operators,
          const Vector               &u) const;

    /** @p g += @p factor grad g_j[@p u] (a dual vector). */
    template <int dim>
    void
    add_gradient(const unsigned int          j,
                 const LumpedOperators<dim> &operators,
                 const Vector               &u,
                 const double                factor,
                 Vector                     &g) const;

    /** @p y += @p factor (Hessian of g_j at @p u) @p d. */
    template <int dim>
    void
    add_hessian_vmult(const unsigned int          j,
                      const LumpedOperators<dim> &operators,
                      const Vector               &u,
                      const Vector               &d,
                      const double                factor,
                      Vector                     &y) const;

    /**
     * Set the targets that the parameters left at 0 to the values of
     * @p u (the initial phase field, or that of a resumed run), once; with
     * `Reduced volume` the volume's from the area's target.
     */
    template <int dim>
    void
    set_missing_targets(const LumpedOperators<dim> &operators, const Vector &u);

    /** The target g_j*. */
    double
    target(const unsigned int j) const
    {
      return targets[j];
    }

    /** The multiplier mu_j of the last converged step (geometric units). */
    double
    multiplier(const unsigned int j) const
    {
      return multipliers[j];
    }

    /** Set the multiplier mu_j (geometric units). */
    void
    set_multiplier(const unsigned int j, const double mu)
    {
      multipliers[j] = mu;
    }

    /** The factor 4 tau / (3 eps) from mu_j to lambda_j for a step tau. */
    double
    to_residual_units(const double tau) const;

    /**
     * The multipliers lambda_j in the units of the nested step's residual
     * that ConstraintTerm adds to the step: those of the current Newton
     * iterate of ConstrainedNestedStep.
     */
    const std::vector<double> &
    step_multipliers() const
    {
      return lambda;
    }

    /** Set step_multipliers() to @p values. */
    void
    set_step_multipliers(const std::vector<double> &values)
    {
      lambda = values;
    }

    /** The pressure p = -mu_volume (0 if the volume is free). */
    double
    pressure() const;

    /** The tension sigma = mu_area (0 if the area is free). */
    double
    tension() const;

  private:
    /** The index of the constraint @p kind, size() if there is none. */
    unsigned int
    index(const ScalarConstraint kind) const;

    const double epsilon;
    /** ConstraintParameters::reduced_volume. */
    const double                  reduced_volume;
    std::vector<ScalarConstraint> kinds;
    /** g_j*; 0 until set_missing_targets() where the parameters gave 0. */
    std::vector<double> targets;
    std::vector<double> multipliers;
    std::vector<double> lambda;
  };



  /**
   * The constraints' part of the step in the units of the nested step's
   * residual: sum_j lambda_j (g_j[U] - g_j*) with the multipliers
   * lambda_j = ScalarConstraints::step_multipliers() (ConstrainedNestedStep
   * sets them to those of its iterate before every evaluation).
   */
  template <int dim>
  class ConstraintTerm : public EnergyTerm
  {
  public:
    /** The term of @p constraints on @p operators (both referred to). */
    ConstraintTerm(const ScalarConstraints    &constraints,
                   const LumpedOperators<dim> &operators);

    std::string
    name() const override
    {
      return ScalarConstraints::name();
    }
    double
    value(const Vector &u) const override;
    void
    add_gradient(const Vector &u,
                 const double  factor,
                 Vector       &g) const override;
    void
    add_hessian_vmult(const Vector &u,
                      const Vector &d,
                      const double  factor,
                      Vector       &y) const override;

  private:
    const ScalarConstraints    &constraints;
    const LumpedOperators<dim> &ops;
  };



  /**
   * The registry entry of the constraints (ScalarConstraints::name()):
   * the factory of ConstraintTerm and the statistics columns pressure,
   * tension, volume_change and area_change (relative to the targets) and
   * reduced_volume (3D: 6 sqrt(pi) V / A^(3/2); 2D: 4 pi V / A^2).
   */
  ModelTermEntry
  constraints_entry();
} // namespace PhaseField

#endif
