#ifndef phasefield_stiffness_square_h
#define phasefield_stiffness_square_h

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <memory>
#include <phasefield/core/linear_algebra.h>
#include <phasefield/mesh/lumped_operators.h>
#include <vector>

class Epetra_Import;

namespace PhaseField
{
  /**
   * The fourth-order matrices
   *
   *     A = w (s L + M[d]) M^-1 (s L + M[d]) + diag(e)
   *
   * for the stiffness matrix L and the lumped mass M of one
   * LumpedOperators, numbers w, s and nodal weights d, e that change from
   * call to call: the Schur complement S of the nested scheme's Newton
   * system, with Khat = ttau L + M[d], is one, in every Newton iteration.
   * Because M is diagonal,
   *
   *     A = w s^2 L M^-1 L + w s (L T + T L) + diag(w M[d] T + e),
   *     T = M^-1 M[d] (d, zero at constrained DoFs),
   *
   * and only L M^-1 L has fill-in. It is formed once per mesh (one sparse
   * matrix product); every A then costs one pass over its entries, written
   * into a matrix of the same sparsity pattern each time (so that a direct
   * solver can reuse its analysis). The sparse product of Khat with
   * itself in every Newton iteration, with its allocations and sorting,
   * was a noticeable part of a 2D run (doc/benchmarks.md, "Choices in the
   * code").
   *
   * The object refers to @p operators: build a new one when they change
   * (re-meshing).
   */
  template <int dim>
  class StiffnessSquare
  {
  public:
    explicit StiffnessSquare(const LumpedOperators<dim> &operators);
    ~StiffnessSquare();

    /**
     * @p a = @p w (@p s L + M[@p d]) M^-1 (@p s L + M[@p d]) + diag(@p e)
     * (@p d and @p e: one value per locally owned DoF). @p a gets the
     * sparsity pattern of L M^-1 L; if it has it already, only its values
     * are written.
     */
    void
    assemble(const double                            w,
             const double                            s,
             const Vector                           &d,
             const Vector                           &e,
             dealii::TrilinosWrappers::SparseMatrix &a) const;

  private:
    const LumpedOperators<dim> &operators;

    /** L M^-1 L. */
    dealii::TrilinosWrappers::SparseMatrix stiffness_square;

    /**
     * For every entry of compressed_rows(L), the index of the entry of
     * compressed_rows(L M^-1 L) in the same row and column.
     */
    std::vector<int> entry_positions;

    /** For every locally owned row, the index of its diagonal entry. */
    std::vector<int> diagonal_positions;

    /** From the locally owned DoFs to the columns of L (ghosts included). */
    std::unique_ptr<Epetra_Import> column_import;
  };
} // namespace PhaseField

#endif
