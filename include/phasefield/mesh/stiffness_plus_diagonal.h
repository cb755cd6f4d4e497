#ifndef phasefield_stiffness_plus_diagonal_h
#define phasefield_stiffness_plus_diagonal_h

#include <Epetra_RowMatrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <phasefield/core/linear_algebra.h>
#include <phasefield/mesh/stiffness_operator.h>

namespace PhaseField
{
  /**
   * The matrix f L + D, for the stiffness matrix L, a number f and a
   * diagonal matrix D, applied from L without being stored. The linearised
   * inner operators K(V) and Khat of the nested scheme and the factor G of
   * its Schur preconditioner have this form
   * (LumpedOperators::stiffness_plus_weighted_mass()): kept as operators,
   * each costs one vector instead of a sparse matrix of the size of L, and
   * a product with it costs the same as with the matrix
   * (doc/benchmarks.md, "Choices in the code").
   *
   * It is an Epetra_RowMatrix, so that an algebraic multigrid (ML) can be
   * set up from it: ML reads its rows one at a time (ExtractMyRowCopy())
   * and its smoothers only multiply with it. Refilled in place by reinit(),
   * it is the current operator for an ML hierarchy set up from an earlier
   * one, as a refilled sparse matrix would be. The scaling and inverse
   * functions of Epetra_RowMatrix are not provided (they return -1).
   */
  class StiffnessPlusDiagonal : public Epetra_RowMatrix, public ShiftedStiffness
  {
  public:
    /**
     * The operator @p stiffness_factor @p stiffness + diag(@p diagonal);
     * @p stiffness must outlive this object (it is not copied), the
     * contents of @p diagonal are taken over (it is left empty).
     */
    void
    reinit(const dealii::TrilinosWrappers::SparseMatrix &stiffness,
           const double                                  stiffness_factor,
           Vector                                       &diagonal);

    /** @p dst = (f L + D) @p src. */
    void
    vmult(Vector &dst, const Vector &src) const override;

    /** The number of rows (0 before reinit()). */
    dealii::types::global_dof_index
    m() const override;

    /** An AlgebraicMultigrid set up from the rows of this operator. */
    std::unique_ptr<MultigridCycle>
    make_multigrid(const Vector      *slow_mode,
                   const unsigned int smoother_sweeps) const override;

    /** @name The Epetra_RowMatrix interface (read by ML) */
    /** @{ */
    int
    NumMyRowEntries(int my_row, int &n_entries) const override;
    int
    MaxNumEntries() const override;
    int
    ExtractMyRowCopy(int     my_row,
                     int     length,
                     int    &n_entries,
                     double *values,
                     int    *indices) const override;
    int
    ExtractDiagonalCopy(Epetra_Vector &diagonal) const override;
    int
    Multiply(bool                      transpose,
             const Epetra_MultiVector &x,
             Epetra_MultiVector       &y) const override;
    int
    Solve(bool, bool, bool, const Epetra_MultiVector &, Epetra_MultiVector &)
      const override;
    int
    InvRowSums(Epetra_Vector &) const override;
    int
    LeftScale(const Epetra_Vector &) override;
    int
    InvColSums(Epetra_Vector &) const override;
    int
    RightScale(const Epetra_Vector &) override;
    bool
    Filled() const override;
    double
    NormInf() const override;
    double
    NormOne() const override;
    int
    NumGlobalNonzeros() const override;
    long long
    NumGlobalNonzeros64() const override;
    int
    NumGlobalRows() const override;
    long long
    NumGlobalRows64() const override;
    int
    NumGlobalCols() const override;
    long long
    NumGlobalCols64() const override;
    int
    NumGlobalDiagonals() const override;
    long long
    NumGlobalDiagonals64() const override;
    int
    NumMyNonzeros() const override;
    int
    NumMyRows() const override;
    int
    NumMyCols() const override;
    int
    NumMyDiagonals() const override;
    bool
    LowerTriangular() const override;
    bool
    UpperTriangular() const override;
    const Epetra_Map &
    RowMatrixRowMap() const override;
    const Epetra_Map &
    RowMatrixColMap() const override;
    const Epetra_Import *
    RowMatrixImporter() const override;
    int
    SetUseTranspose(bool use_transpose) override;
    int
    Apply(const Epetra_MultiVector &x, Epetra_MultiVector &y) const override;
    int
    ApplyInverse(const Epetra_MultiVector &,
                 Epetra_MultiVector &) const override;
    const char *
    Label() const override;
    bool
    UseTranspose() const override;
    bool
    HasNormInf() const override;
    const Epetra_Comm &
    Comm() const override;
    const Epetra_Map &
    OperatorDomainMap() const override;
    const Epetra_Map &
    OperatorRangeMap() const override;
    const Epetra_BlockMap &
    Map() const override;
    /** @} */

  private:
    /** L as Epetra matrix. */
    const Epetra_CrsMatrix &
    l() const;

    const dealii::TrilinosWrappers::SparseMatrix *stiffness        = nullptr;
    double                                        stiffness_factor = 0;
    Vector                                        diagonal;
  };
} // namespace PhaseField

#endif
