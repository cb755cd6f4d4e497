#ifndef phasefield_core_linear_algebra_h
#define phasefield_core_linear_algebra_h

#include <deal.II/lac/trilinos_parallel_block_vector.h>
#include <deal.II/lac/trilinos_vector.h>

namespace PhaseField
{
  /**
   * The distributed vector of one scalar Q1 field (its locally owned
   * entries): the one place that names the linear algebra backend of the
   * fields. Everything above mesh/ and solvers/ writes `Vector` and
   * `BlockVector`. Below them, the assembled backend and the direct solver
   * read the Epetra vector inside (trilinos_vector() in
   * StiffnessPlusDiagonal, StiffnessSquare and DirectFactorization) and
   * the Trilinos matrices multiply it, so another vector type changes
   * these two lines and those places; MatrixFreeStiffness computes on
   * deal.II's distributed vectors and copies from and to `Vector` at its
   * vmult().
   */
  using Vector = dealii::TrilinosWrappers::MPI::Vector;

  /** The state of a scheme: one Vector per field, U first. */
  using BlockVector = dealii::TrilinosWrappers::MPI::BlockVector;
} // namespace PhaseField

#endif
