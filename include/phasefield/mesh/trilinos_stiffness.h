#ifndef phasefield_mesh_trilinos_stiffness_h
#define phasefield_mesh_trilinos_stiffness_h

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <phasefield/core/linear_algebra.h>
#include <phasefield/mesh/stiffness_operator.h>
#include <vector>

namespace PhaseField
{
  /**
   * The stiffness operator L as an assembled Trilinos matrix (the
   * assembled operator backend, `Linear solver / Type` = iterative or
   * direct). Its shifted operators f L + D are
   * StiffnessPlusDiagonal, which an algebraic multigrid (ML) can read row
   * by row. The direct solvers and the assembled Jacobians read the
   * matrix itself (LumpedOperators::stiffness_matrix()).
   */
  class TrilinosStiffness : public StiffnessOperator
  {
  public:
    void
    vmult(Vector &dst, const Vector &src) const override;

    void
    diagonal(Vector &diagonal) const override;

    /** @p op becomes (or is refilled as) a StiffnessPlusDiagonal. */
    void
    shift(const double                       factor,
          Vector                            &diagonal,
          std::unique_ptr<ShiftedStiffness> &op) const override;

    std::size_t
    memory_consumption() const override;

    /**
     * Find the diagonal entries of the assembled, compressed matrix
     * (diagonal_positions); called once after the assembly.
     */
    void
    find_diagonal();

    /** Free the matrix. */
    void
    clear();

    /** The stiffness matrix L, condensed. */
    dealii::TrilinosWrappers::SparseMatrix matrix;

    /**
     * For every locally owned row of the matrix, the index of its diagonal
     * entry in compressed_rows(matrix).values.
     */
    std::vector<int> diagonal_positions;
  };
} // namespace PhaseField

#endif
