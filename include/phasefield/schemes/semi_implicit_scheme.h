#ifndef phasefield_schemes_semi_implicit_scheme_h
#define phasefield_schemes_semi_implicit_scheme_h

#include <deal.II/base/conditional_ostream.h>
#include <memory>
#include <phasefield/core/linear_algebra.h>
#include <phasefield/mesh/discretization.h>
#include <phasefield/schemes/energies.h>
#include <phasefield/schemes/time_stepping_scheme.h>
#include <phasefield/solvers/linear_solver.h>
#include <phasefield/solvers/nonlinear_system.h>

namespace PhaseField
{
  /** Block indices of the two fields of the semi-implicit scheme. */
  namespace SemiImplicitField
  {
    constexpr unsigned int U = 0;
    /** F = eps Lap U + (2/eps) U (1 - U^2). */
    constexpr unsigned int F = 1;
  } // namespace SemiImplicitField

  /**
   * The semi-implicit phase-field scheme of Du, Liu and Wang for Willmore
   * flow (thesis section 5.2.1-5.2.2), on Q1 elements with lumped mass.
   * The unknowns are Z = (U, F); given the previous state (U^k, F^k) and
   * G = F + F^k, g = 1 - U^2 - U U^k - (U^k)^2, the residual (the thesis'
   * F1 multiplied by tau/eps and F2 by eps, so that both blocks are of the
   * size of U) is
   *
   *   R_U = M(U-U^k) - (tau/(2 eps)) L G + (tau/eps^3) M[g] G
   *   R_F = eps M F + eps^2 L U - 2 M[1-U^2] U
   *
   * and its exact (non-symmetric) Jacobian is
   *
   *   J = [ M[1 - (tau/eps^3)(2U+U^k) G]   -(tau/(2 eps)) L + (tau/eps^3) M[g]
   * ] [ eps^2 L + M[6U^2 - 2]           eps M                              ].
   *
   * (The thesis prints -6/eps M[U^2] in dF2/dU; the sign is +.) Since M is
   * diagonal, F is eliminated exactly: dU solves
   *   S dU = -R_U + J_UF (eps M)^-1 R_F,  S = J_UU - J_UF (eps M)^-1 J_FU,
   * and dF = (eps M)^-1 (-R_F - J_FU dU).
   *
   * The Willmore energy reported is (3/4) w_eps[U] of thesis (5.4),
   * (3/4) (1/(2 eps)) Int F^2, the same geometric quantity as the nested
   * scheme's: pi/r for a circle.
   */
  template <int dim>
  class SemiImplicitStep : public NonlinearSystem
  {
  public:
    /**
     * One step of size @p tau from the state @p old_state = (U^k, F^k),
     * which must stay alive while the step is used.
     */
    SemiImplicitStep(const Discretization<dim> &discretization,
                     const double               epsilon,
                     const double               tau,
                     const BlockVector         &old_state);

    /** Residual R(Z). */
    void
    residual(const BlockVector &z, BlockVector &r) const override;

    /** sqrt(R^T M^-1 R) summed over the two blocks. */
    double
    residual_norm(const BlockVector &r) const override;

    /**
     * Size of the terms of R(z) in L2: ||U|| + (tau/(2 eps)) ||L G||_{M^-1}
     * + eps ||F||, the reference for an absolute Newton tolerance.
     */
    double
    term_scale(const BlockVector &z) const override;

    /**
     * Solve J(Z) dZ = -R for the Newton update @p dz (the solver must have
     * been constructed for non-symmetric matrices). Returns the linear
     * iterations.
     */
    unsigned int
    solve_jacobian(const BlockVector &z,
                   const BlockVector &r,
                   BlockVector       &dz,
                   LinearSolver      &solver) override;

    void
    distribute_constraints(BlockVector &z) const override;

    /** y = J(Z) x (used by tests). */
    void
    jacobian_vmult(const BlockVector &z,
                   const BlockVector &x,
                   BlockVector       &y) const;

    /** Set F from U by R_F(U, F) = 0 (a diagonal solve). */
    void
    initialize_f(BlockVector &z) const;

  private:
    /** Nodal values of G = F + F^k and g = 1 - U^2 - U U^k - (U^k)^2. */
    void
    nonlinear_coefficients(const BlockVector &z, Vector &G, Vector &g) const;

    const Discretization<dim>  &discretization;
    const LumpedOperators<dim> &ops;
    const double                epsilon;
    const double                tau;
    const BlockVector          &old_state;
  };



  /**
   * The semi-implicit scheme as a TimeSteppingScheme: state (U, F), one
   * SemiImplicitStep per time step solved by newton_solve(), F = f(U)
   * recomputed after re-meshing (F^k enters the next residual).
   */
  template <int dim>
  class SemiImplicitScheme : public TimeSteppingScheme<dim>
  {
  public:
    SemiImplicitScheme(const SchemeSettings             &settings,
                       const Discretization<dim>        &discretization,
                       const dealii::ConditionalOStream &pcout);

    std::string
    name() const override;
    std::vector<std::string>
    field_names() const override;
    std::string
    linear_solver_description() const override;
    void
    initialize(BlockVector &state, const double tau) override;
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
    /** Willmore energy (3/4) w_eps[U] and area. */
    Energies
    energies(const BlockVector &state) const override;
    unsigned int
    n_factorizations() const override
    {
      return linear_solver->n_factorizations();
    }
    /** -F / eps, the same quantity as the nested (U - V) / ttau. */
    void
    curvature(const BlockVector &state, Vector &curvature) const override;

  private:
    const SchemeSettings              settings;
    const Discretization<dim>        &discretization;
    const dealii::ConditionalOStream &pcout;
    std::unique_ptr<LinearSolver>     linear_solver;
  };
} // namespace PhaseField

#endif
