#ifndef phasefield_solvers_product_form_h
#define phasefield_solvers_product_form_h

#include <memory>
#include <phasefield/core/linear_algebra.h>
#include <phasefield/mesh/stiffness_operator.h>

/**
 * The pieces of the iterative solver of Schur complements in product form,
 * S = diag(d) + w Khat M^-1 Khat with a sparse second-order matrix Khat
 * and a diagonal M (LinearSolver::solve_product_form()): S is applied
 * without being assembled, and preconditioned by G^-1 M G^-1 with one
 * multigrid cycle of the operator's backend (schur_smoother_sweeps) for
 * each G^-1.
 */
namespace PhaseField
{
  /**
   * Chebyshev sweeps of the cycles inside the product G^-1 M G^-1
   * (SchurPreconditioner). There the cycle's error matters in the norm of
   * M, not of G, and more smoothing reduces the part that the G-norm
   * hides: 6 sweeps need far fewer CG iterations per Newton system than 3
   * (doc/benchmarks.md, "Choices in the code").
   */
  constexpr unsigned int schur_smoother_sweeps = 6;

  /**
   * dst = A diag(@p diagonal) A src for a symmetric operator A, i.e. the
   * symmetric product of A, a diagonal and A; @p tmp is scratch space.
   */
  template <typename Operator>
  void
  apply_symmetric_product(const Operator &a,
                          const Vector   &diagonal,
                          Vector         &tmp,
                          Vector         &dst,
                          const Vector   &src)
  {
    a.vmult(tmp, src);
    tmp.scale(diagonal);
    a.vmult(dst, tmp);
  }



  /** S = diag(d) + w Khat M^-1 Khat applied to a vector. */
  class ProductFormMatrix
  {
  public:
    ProductFormMatrix(const ShiftedStiffness &k_hat,
                      const double            w,
                      const Vector           &d,
                      const Vector           &inverse_mass)
      : k_hat(k_hat)
      , w(w)
      , d(d)
      , inverse_mass(inverse_mass)
      , tmp(d)
    {}

    void
    vmult(Vector &dst, const Vector &src) const
    {
      apply_symmetric_product(k_hat, inverse_mass, tmp, dst, src);
      dst *= w;
      tmp = src;
      tmp.scale(d);
      dst += tmp;
    }

  private:
    const ShiftedStiffness &k_hat;
    const double            w;
    const Vector           &d;
    const Vector           &inverse_mass;
    mutable Vector          tmp;
  };



  /**
   * The preconditioner G^-1 M G^-1 of
   * LinearSolver::solve_product_form(), with one multigrid cycle
   * for each G^-1.
   *
   * For the nested scheme, G = gamma M + s Khat with Khat = ttau (L +
   * M[Psi''(V)]/(2 eps^2)) + (1-b) M, the linearised Allen-Cahn operator.
   * Its near kernel is not the constant but the translation of the
   * diffuse interface: for V = tanh(d/eps), d_n V = (1 - V^2)/eps, and
   * (-d^2 + Psi''(V)/(2 eps^2)) (1 - V^2) = 0 across a flat interface. A
   * normal displacement g along the interface, (1 - V^2) g, is then a
   * slowly varying mode of G with a Rayleigh quotient near gamma, far
   * below the s/h^2 of the other oscillating modes, and the aggregation
   * can only represent it on coarse levels if it is in the near null
   * space: pass @p interface_mode = 1 - V^2 (see NestedStep's
   * schur_mass_shift for the measured effect).
   */
  class SchurPreconditioner
  {
  public:
    SchurPreconditioner(const ShiftedStiffness &g,
                        const Vector           &mass,
                        const Vector           *interface_mode = nullptr)
      : multigrid(g.make_multigrid(interface_mode, schur_smoother_sweeps))
      , mass(mass)
      , tmp(mass)
    {}

    void
    vmult(Vector &dst, const Vector &src) const
    {
      apply_symmetric_product(*multigrid, mass, tmp, dst, src);
    }

    /** Number of rows of the preconditioned matrix. */
    dealii::types::global_dof_index
    size() const
    {
      return mass.size();
    }

  private:
    std::unique_ptr<MultigridCycle> multigrid;
    const Vector                   &mass;
    mutable Vector                  tmp;
  };
} // namespace PhaseField

#endif
