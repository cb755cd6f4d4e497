#ifndef phasefield_mesh_algebraic_multigrid_h
#define phasefield_mesh_algebraic_multigrid_h

#include <Epetra_RowMatrix.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <phasefield/core/linear_algebra.h>
#include <phasefield/mesh/stiffness_operator.h>

namespace PhaseField
{
  /**
   * Largest coarsest-level matrix of the multigrid hierarchies; ML
   * factorises it (KLU) at every set-up. With deal.II's default, 2000,
   * this factorisation was a large part of a 3D step's work; 200 costs a
   * few more CG iterations (doc/benchmarks.md, "Choices in the code").
   */
  constexpr unsigned int multigrid_coarse_size = 200;

  /**
   * Chebyshev sweeps (the smoother's polynomial degree) per level, before
   * and after the coarse correction, of a multigrid cycle that stands for
   * G^-1 in a CG solve with G (two sweeps need about twice the CG
   * iterations, more than three do not pay; doc/benchmarks.md, "Choices in
   * the code").
   */
  constexpr unsigned int multigrid_smoother_sweeps = 3;

  /**
   * The multigrid cycle of the Trilinos backend: an algebraic multigrid
   * (Trilinos ML) set up from the rows of a matrix, aggregation for a
   * scalar second-order operator, Chebyshev smoothing, a coarsest level of
   * at most multigrid_coarse_size unknowns.
   *
   * The near null space that the aggregation keeps on the coarse levels
   * is the constant vector, and with a slow mode also that vector: it
   * should hold the slowly varying modes of the matrix that the constant
   * misses, as the rigid body modes do for elasticity.
   */
  class AlgebraicMultigrid : public MultigridCycle
  {
  public:
    /**
     * Set up from @p matrix (an assembled matrix or the rows of
     * StiffnessPlusDiagonal), which must outlive this object. Throws on all
     * ranks if a diagonal entry of @p matrix is not positive.
     */
    AlgebraicMultigrid(
      const Epetra_RowMatrix &matrix,
      const Vector           *slow_mode       = nullptr,
      const unsigned int      smoother_sweeps = multigrid_smoother_sweeps);

    void
    vmult(Vector &dst, const Vector &src) const override;

  private:
    dealii::TrilinosWrappers::PreconditionAMG multigrid;
  };
} // namespace PhaseField

#endif
