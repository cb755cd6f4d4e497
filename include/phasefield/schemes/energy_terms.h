#ifndef phasefield_schemes_energy_terms_h
#define phasefield_schemes_energy_terms_h

#include <memory>
#include <phasefield/core/linear_algebra.h>
#include <phasefield/mesh/lumped_operators.h>
#include <phasefield/schemes/energies.h>
#include <phasefield/schemes/outer_energy.h>
#include <string>
#include <vector>

namespace PhaseField
{
  /**
   * One term of the energy that a time step minimises, as a function of
   * the phase field U alone: its value, gradient and Hessian-vector
   * product (or a Gauss-Newton product where the Hessian is not defined,
   * gauss_newton()). The nested step adds the terms of its outer energy
   * (make_outer_energy_terms(), energy_term_registry.h: area, forcing) to its
   * residual, outer energy and Jacobian; the augmented Lagrangian adds them to
   * its objective; the contour problem's explicit mismatch step (thesis
   * Algorithm 6.1) uses the gradient of MismatchTerm.
   *
   * The Willmore term (mu/2) eps ||(V-U)/ttau||^2 couples U with the
   * inner minimiser V and is part of the nested step itself
   * (NestedWeights::a); the fixed U values of edge restoration are a
   * constraint, not an energy (NestedPhysics::zero_fixed_u()).
   */
  class EnergyTerm
  {
  public:
    virtual ~EnergyTerm() = default;

    /**
     * Does the nested step's Jacobian hold the term's Hessian already (in
     * NestedWeights: the area term; the forcing has none)? Otherwise
     * NestedPhysics applies its Hessian product matrix-free.
     */
    virtual bool
    in_nested_jacobian() const
    {
      return false;
    }

    /** The name, for messages. */
    virtual std::string
    name() const = 0;

    /** Is add_hessian_vmult() a Gauss-Newton product? */
    virtual bool
    gauss_newton() const
    {
      return false;
    }

    /** The term's value at @p u. Collective. */
    virtual double
    value(const Vector &u) const = 0;

    /** @p g += @p factor times the gradient at @p u (a dual vector). */
    virtual void
    add_gradient(const Vector &u, const double factor, Vector &g) const = 0;

    /**
     * @p y += @p factor H(@p u) @p d with the Hessian H (or its Gauss-Newton
     * approximation).
     */
    virtual void
    add_hessian_vmult(const Vector &u,
                      const Vector &d,
                      const double  factor,
                      Vector       &y) const = 0;

    /**
     * The model of the term that a time step from @p u0 minimises (a
     * term without kinks: nullptr, the term itself). A term that is
     * piecewise smooth with kinks (the mismatch: alpha[U] is piecewise
     * linear in U) returns its Gauss-Newton model at @p u0, which equals
     * the term wherever U has the kink pattern of @p u0 and is smooth
     * everywhere, so that Newton's method converges on it; the time loop
     * judges the step by the term itself (the energy law).
     */
    virtual std::unique_ptr<EnergyTerm>
    step_model(const Vector &u0) const
    {
      (void)u0;
      return nullptr;
    }
  };



  /**
   * The area term s a_eps[U] / eps of the outer energy (thesis (5.7),
   * (6.3)), a_eps[u] = (1/2) Int eps |grad u|^2 + Psi(u)/eps, with
   * s = tau eta: gradient s (L U + M Psi'(U) / (2 eps^2)), Hessian
   * s (L + M[Psi''(U)] / (2 eps^2)).
   */
  template <int dim>
  class AreaTerm : public EnergyTerm
  {
  public:
    /** The term with the factor @p scale = tau eta on @p operators. */
    AreaTerm(const LumpedOperators<dim> &operators,
             const double                scale,
             const double                epsilon);

    std::string
    name() const override
    {
      return "area";
    }
    bool
    in_nested_jacobian() const override
    {
      return true;
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
    /**
     * @p y += @p factor s (L @p x + M p / (2 eps^2)) with the nodal
     * values p_i = @p potential(i): the one loop of the gradient (x = U,
     * p = Psi'(U)) and the Hessian product (x = d, p = Psi''(U) d).
     */
    template <typename NodalPotential>
    void
    add_term(const Vector         &x,
             const double          factor,
             const NodalPotential &potential,
             Vector               &y) const;

    const LumpedOperators<dim> &ops;
    const double                scale;
    const double                epsilon;
  };



  /**
   * The forcing term -s F.U of the outer energy (the biharmonic model
   * problem, thesis chapter 4), with F = M I_h(f) and s = tau / eps:
   * gradient -s F, Hessian 0.
   */
  class ForcingEnergyTerm : public EnergyTerm
  {
  public:
    /** The term with the nodal forcing @p forcing (referred to). */
    ForcingEnergyTerm(const Vector &forcing, const double scale);

    std::string
    name() const override
    {
      return "forcing";
    }
    bool
    in_nested_jacobian() const override
    {
      return true;
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
    const Vector &forcing;
    const double  scale;
  };



  /**
   * A term @p scale times another term (referred to, which must outlive
   * this one): OuterEnergy::data_term in the units of the nested step's
   * residual.
   */
  class ScaledTerm : public EnergyTerm
  {
  public:
    ScaledTerm(const EnergyTerm &term, const double scale);

    /** @p scale times the term @p owned, which this one keeps. */
    ScaledTerm(std::unique_ptr<EnergyTerm> owned, const double scale);

    std::string
    name() const override
    {
      return term.name();
    }
    bool
    gauss_newton() const override
    {
      return term.gauss_newton();
    }
    bool
    in_nested_jacobian() const override
    {
      return term.in_nested_jacobian();
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
    /** The term, if this one owns it. */
    const std::unique_ptr<EnergyTerm> owned;
    const EnergyTerm                 &term;
    const double                      scale;
  };



  /**
   * OuterEnergy::data_term of @p outer for a step of size @p tau from
   * @p old_u in the units of the nested step's residual (the outer energy
   * divided by 2 eps): tau / eps times the term's step model at @p old_u
   * (EnergyTerm::step_model(); the mismatch's Gauss-Newton model), or
   * the term itself if it has none; nullptr if @p outer has no data term.
   */
  std::unique_ptr<EnergyTerm>
  make_data_term(const OuterEnergy &outer,
                 const double       tau,
                 const double       epsilon,
                 const Vector      &old_u);



  /**
   * mu W + eta A for the energies @p e with the weights of @p outer: the
   * one place that combines them (the energy law, the contour problem's
   * total energy).
   */
  double
  weighted_regularisation(const OuterEnergy &outer, const Energies &e);
} // namespace PhaseField

#endif
