#ifndef phasefield_mesh_stiffness_operator_h
#define phasefield_mesh_stiffness_operator_h

#include <cstddef>
#include <deal.II/base/types.h>
#include <memory>
#include <phasefield/core/linear_algebra.h>

namespace PhaseField
{
  /**
   * One multigrid cycle for an operator f L + D (ShiftedStiffness::
   * make_multigrid()): an approximate inverse that the Krylov solvers use
   * as preconditioner.
   */
  class MultigridCycle
  {
  public:
    virtual ~MultigridCycle() = default;

    /** @p dst = B @p src for the cycle B, an approximation of (f L + D)^-1. */
    virtual void
    vmult(Vector &dst, const Vector &src) const = 0;
  };



  /**
   * An operator f L + D for the stiffness operator L of a mesh, a number f
   * and a diagonal matrix D, as StiffnessOperator::shift() makes it: the
   * nested scheme's K(V), Khat and the factor G of its Schur
   * preconditioner. Schemes apply it; solvers precondition it with the
   * multigrid cycle of its backend (make_multigrid()).
   */
  class ShiftedStiffness
  {
  public:
    virtual ~ShiftedStiffness() = default;

    /** @p dst = (f L + D) @p src. */
    virtual void
    vmult(Vector &dst, const Vector &src) const = 0;

    /** The number of rows (0 before the first StiffnessOperator::shift()). */
    virtual dealii::types::global_dof_index
    m() const = 0;

    /**
     * A multigrid cycle for this operator, set up now from its current
     * values, with @p smoother_sweeps Chebyshev sweeps per level before
     * and after the coarse correction. The coarse levels represent the
     * constant and, if given, @p slow_mode (locally owned values): a
     * slowly varying mode of the operator that the constant misses (the
     * nested scheme's interface mode, SchurPreconditioner). If the
     * operator is refilled in place later (StiffnessOperator::shift()),
     * the cycle keeps the hierarchy of its set-up and multiplies with the
     * current operator on the finest level.
     */
    virtual std::unique_ptr<MultigridCycle>
    make_multigrid(const Vector      *slow_mode,
                   const unsigned int smoother_sweeps) const = 0;

    /** Whether it has not been filled yet. */
    bool
    empty() const
    {
      return m() == 0;
    }
  };



  /**
   * The stiffness operator L of one mesh (the Q1 Laplacian, condensed with
   * the hanging-node constraints), as schemes and the time loop see it:
   * the seam between the physics and a linear-algebra backend. Every
   * nonlinear term of the schemes is nodal (lumped mass), so L is the only
   * mesh operator: a backend implements these functions, and the schemes
   * do not change. The implementations are those of the registered
   * operator backends (mesh/operator_backend.h): TrilinosStiffness (an
   * assembled Trilinos matrix) and MatrixFreeStiffness (cell by cell).
   */
  class StiffnessOperator
  {
  public:
    virtual ~StiffnessOperator() = default;

    /** @p dst = L @p src. */
    virtual void
    vmult(Vector &dst, const Vector &src) const = 0;

    /** @p diagonal = the diagonal of L (one value per locally owned DoF). */
    virtual void
    diagonal(Vector &diagonal) const = 0;

    /**
     * @p op = @p factor L + diag(@p diagonal), with the contents of
     * @p diagonal taken over (it is left empty). If @p op holds an operator
     * of this backend already, it is refilled in place, so that a
     * preconditioner set up from it applies the current operator;
     * otherwise a new one is made.
     */
    virtual void
    shift(const double                       factor,
          Vector                            &diagonal,
          std::unique_ptr<ShiftedStiffness> &op) const = 0;

    /**
     * Bytes this rank keeps for L (the matrix, or the cell data and the
     * multigrid levels of a matrix-free backend).
     */
    virtual std::size_t
    memory_consumption() const = 0;
  };
} // namespace PhaseField

#endif
