#ifndef phasefield_schemes_nested_nested_physics_h
#define phasefield_schemes_nested_nested_physics_h

#include <memory>
#include <phasefield/core/linear_algebra.h>
#include <phasefield/mesh/discretization.h>
#include <phasefield/mesh/lumped_operators.h>
#include <phasefield/mesh/stiffness_operator.h>
#include <phasefield/schemes/double_well.h>
#include <phasefield/schemes/energy_terms.h>
#include <phasefield/schemes/outer_energy.h>
#include <vector>

/**
 * The physics of one step of the nested variational time discretization
 * of Willmore flow (thesis chapter 3) for Q1 elements with lumped mass:
 * its coefficients, residual, Jacobian product, inner problem, outer
 * energy and area term. No linear algebra beyond products: the solves of
 * its Newton systems are NestedLinearSystems
 * (schemes/nested/nested_linear_systems.h).
 */
namespace PhaseField
{
  /** Block indices of the three fields of the nested scheme's state. */
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
   * and Jacobian (see NestedPhysics), computed once from NestedCoefficients:
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
   * with E = c M[Psi'''(V) P]; all nodal weights come from NestedWeights.
   * With a data term d (OuterEnergy::data_term), R_U has (tau/eps) d'(U)
   * and J_UU (tau/eps) d''(U) besides (for the mismatch j the Gauss-Newton
   * product J^T 2 gamma W J, which is its Hessian away from the kinks of
   * the labeling: alpha[U] is piecewise linear in U).
   * With U held fixed at the DoFs of OuterEnergy::fixed_u (thesis
   * Definition 5.1) the U-row of R is zero there and the U-row and
   * U-column of J are those of the identity.
   *
   * The step reaches the stiffness operator L only through
   * StiffnessOperator (LumpedOperators::stiffness_operator()).
   */
  template <int dim>
  class NestedPhysics
  {
  public:
    /** The step from @p old_u (which must outlive this object). */
    NestedPhysics(const Discretization<dim> &discretization,
                  const NestedCoefficients  &coefficients,
                  const Vector              &old_u);

    /** @p r = R(@p z), zero at constrained DoFs. */
    void
    residual(const BlockVector &z, BlockVector &r) const;

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
     * DBL_EPSILON (||U|| + a (||U|| + ||V||) + ||P||) in the M-norm: a M (V -
     * U) in R_U and R_V is computed from V and U of size 1, so its
     * round-off grows with a = tau/ttau^2 (h^-2 for tau = ttau = h^2;
     * doc/benchmarks.md, "Round-off of the nested residual").
     */
    double
    roundoff_level(const BlockVector &z) const;

    /**
     * y = J(Z) x: the Jacobian (with @p shift M added to the UU block)
     * applied to a vector.
     */
    void
    jacobian_vmult(const BlockVector &z,
                   const BlockVector &x,
                   BlockVector       &y,
                   const double       shift = 0) const;

    /** y = J(Z) x as jacobian_vmult(), with K(V) given as @p k. */
    void
    apply_jacobian(const ShiftedStiffness &k,
                   const BlockVector      &z,
                   const BlockVector      &x,
                   BlockVector            &y,
                   const double            shift) const;

    /**
     * r = R_P(U, V) = M(V-U) + c M Psi'(V) + ttau L V: the inner equation,
     * M times the constraint C(U, V) of the augmented Lagrangian scheme.
     */
    void
    inner_residual(const Vector &u, const Vector &v, Vector &r) const;

    /**
     * r = -a M (V - U): the right-hand side of the adjoint equation
     * K(V) P = r, which is R_V(U, V, P) = 0.
     */
    void
    adjoint_rhs(const BlockVector &z, Vector &r) const;

    /** @p kd = K(V) @p d = ttau L d + M[k(V)] d, matrix-free. */
    void
    k_vmult(const Vector &v, const Vector &d, Vector &kd) const;

    /**
     * The outer energy at the state @p z, divided by 2 eps like the
     * residual:
     *   (1/2)|U-U^k|_M^2 + (a/2)|V-U|_M^2 + tau eta a_eps[U] / eps
     *   - (tau/eps) F.U.
     * With V = V(U) the inner minimiser this is a function of U alone
     * whose gradient is R_U.
     */
    double
    outer_energy(const BlockVector &z) const;

    /**
     * The error of outer_energy() that an inexact V and round-off leave:
     * a |V-U|_M (||R_P(U, V)||_{M^-1} + DBL_EPSILON (|U|_M + |V|_M)). The
     * term (a/2)|V-U|_M^2 changes by a (V-U)^T M dV for an error dV of V,
     * which the inner problem leaves at the size of its residual (its
     * Jacobian is about M) and the subtraction V - U at the round-off of U
     * and V (doc/benchmarks.md, "Energy round-off of the descent method").
     */
    double
    outer_energy_error(const BlockVector &z) const;

    /**
     * @p g += @p factor times the gradient of the outer energy's terms
     * beyond the distance and Willmore terms (make_outer_energy_terms():
     * area, forcing, registered terms; and the data term, make_data_term())
     * at @p u: part of R_U.
     */
    void
    add_terms_gradient(const Vector &u, const double factor, Vector &g) const;

    /**
     * @p y += @p factor times the Hessian of the same terms at @p u applied
     * to @p d (matrix-free). apply_jacobian() and the assembled 3-field
     * Jacobian (NestedLinearSystems) hold the area term's Hessian in the
     * assembled form M[uu] + tau eta L (NestedWeights::uu());
     * apply_jacobian() adds the products of the other terms
     * (EnergyTerm::in_nested_jacobian() false: registered terms) and of the
     * data term (a Gauss-Newton product for the mismatch) matrix-free.
     */
    void
    add_terms_hessian_vmult(const Vector &u,
                            const Vector &d,
                            const double  factor,
                            Vector       &y) const;

    /**
     * Set @p u_block to 0 at the DoFs of OuterEnergy::fixed_u (a gradient
     * or a direction in U that must leave the fixed values unchanged).
     */
    void
    zero_fixed_u(Vector &u_block) const;

    /** Is the U value at locally owned index @p i held fixed? */
    bool
    u_is_fixed(const unsigned int i) const;

    /** The nodal weights k(V, shift) of K(V) - shift M. */
    Vector
    k_weights(const Vector &v, const double shift) const;

    /**
     * K(V) - shift M = M[k_weights()] + ttau L as an operator that applies
     * L (StiffnessOperator::shift(); refilled in place).
     */
    void
    build_k(const Vector                      &v,
            const double                       shift,
            std::unique_ptr<ShiftedStiffness> &k) const;

    /**
     * The factor G of the product-form preconditioner of
     * S = w Khat M^-1 Khat + m M (+ a diagonal), Khat = K(V) - b M:
     * G = gamma M + sqrt(w/m) Khat with gamma = schur_mass_shift, so that
     * m G M^-1 G / gamma^2 approximates S, and the interface translation
     * mode 1 - V^2 for its multigrid (SchurPreconditioner). Serves the
     * iterative solver of the nested scheme (b = a/(1+a), w = 1+a) and the
     * preconditioner of the augmented Lagrangian's trust region.
     */
    void
    build_schur_factor(const Vector                      &v,
                       const double                       b,
                       const double                       w,
                       const double                       m,
                       std::unique_ptr<ShiftedStiffness> &g,
                       Vector                            &interface_mode) const;

    /**
     * The shift gamma of build_schur_factor(): with the interface mode
     * 1 - V^2 in the multigrid's near null space, gamma = 4 gave the
     * fewest CG iterations on the level-6 sphere among 1.5, 2.5, 4 and 12
     * (doc/benchmarks.md, "The Schur preconditioner's mass shift").
     */
    static constexpr double schur_mass_shift = 4;

    const NestedCoefficients &
    coefficients() const
    {
      return coeff;
    }

    const NestedWeights &
    get_weights() const
    {
      return weights;
    }

    const LumpedOperators<dim> &
    operators() const
    {
      return ops;
    }

    const Discretization<dim> &
    get_discretization() const
    {
      return discretization;
    }

  private:
    /** |x|_M. */
    double
    mass_norm(const Vector &x) const;

    const Discretization<dim>  &discretization;
    const LumpedOperators<dim> &ops;
    const StiffnessOperator    &stiffness;
    const NestedCoefficients    coeff;
    const NestedWeights         weights;
    const Vector               &old_u;
    /** The outer energy's terms (make_outer_energy_terms()). */
    const std::vector<std::unique_ptr<EnergyTerm>> terms;
    /**
     * OuterEnergy::data_term scaled to the residual's units
     * (make_data_term()), or nullptr; its Hessian is applied matrix-free in
     * apply_jacobian().
     */
    const std::unique_ptr<EnergyTerm> data_term;
  };
} // namespace PhaseField

#endif
