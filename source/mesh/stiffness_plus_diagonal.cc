#include <Epetra_CrsMatrix.h>
#include <Epetra_MultiVector.h>
#include <Epetra_Vector.h>
#include <algorithm>
#include <cmath>
#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <phasefield/mesh/algebraic_multigrid.h>
#include <phasefield/mesh/shifted_product.h>
#include <phasefield/mesh/stiffness_plus_diagonal.h>
#include <vector>

namespace PhaseField
{
  void
  StiffnessPlusDiagonal::reinit(
    const dealii::TrilinosWrappers::SparseMatrix &stiffness_matrix,
    const double                                  factor,
    Vector                                       &diagonal_entries)
  {
    stiffness        = &stiffness_matrix;
    stiffness_factor = factor;
    diagonal.swap(diagonal_entries);
    diagonal_entries.clear();
  }



  void
  StiffnessPlusDiagonal::vmult(Vector &dst, const Vector &src) const
  {
    Assert(stiffness != nullptr, dealii::ExcNotInitialized());
    stiffness->vmult(dst, src);
    scale_and_add_diagonal(stiffness_factor, diagonal, src, dst);
  }



  dealii::types::global_dof_index
  StiffnessPlusDiagonal::m() const
  {
    return stiffness == nullptr ? 0 : stiffness->m();
  }



  std::unique_ptr<MultigridCycle>
  StiffnessPlusDiagonal::make_multigrid(
    const Vector      *slow_mode,
    const unsigned int smoother_sweeps) const
  {
    return std::make_unique<AlgebraicMultigrid>(*this,
                                                slow_mode,
                                                smoother_sweeps);
  }



  const Epetra_CrsMatrix &
  StiffnessPlusDiagonal::l() const
  {
    Assert(stiffness != nullptr, dealii::ExcNotInitialized());
    return stiffness->trilinos_matrix();
  }



  int
  StiffnessPlusDiagonal::NumMyRowEntries(int my_row, int &n_entries) const
  {
    return l().NumMyRowEntries(my_row, n_entries);
  }



  int
  StiffnessPlusDiagonal::MaxNumEntries() const
  {
    return l().MaxNumEntries();
  }



  int
  StiffnessPlusDiagonal::ExtractMyRowCopy(int     my_row,
                                          int     length,
                                          int    &n_entries,
                                          double *values,
                                          int    *indices) const
  {
    const int error =
      l().ExtractMyRowCopy(my_row, length, n_entries, values, indices);
    if (error != 0)
      return error;
    const int diagonal_column = l().ColMap().LID(l().RowMap().GID64(my_row));
    for (int k = 0; k < n_entries; ++k)
      {
        values[k] *= stiffness_factor;
        if (indices[k] == diagonal_column)
          values[k] += diagonal.begin()[my_row];
      }
    return 0;
  }



  int
  StiffnessPlusDiagonal::ExtractDiagonalCopy(Epetra_Vector &d) const
  {
    const int error = l().ExtractDiagonalCopy(d);
    if (error != 0)
      return error;
    for (int i = 0; i < d.MyLength(); ++i)
      d[i] = stiffness_factor * d[i] + diagonal.begin()[i];
    return 0;
  }



  int
  StiffnessPlusDiagonal::Multiply(const bool                transpose,
                                  const Epetra_MultiVector &x,
                                  Epetra_MultiVector       &y) const
  {
    // L and D are symmetric: the transpose is the same product
    const int error = l().Multiply(transpose, x, y);
    if (error != 0)
      return error;
    // y = f y + D x, column by column
    return y.Multiply(1., diagonal.trilinos_vector(), x, stiffness_factor);
  }



  int
  StiffnessPlusDiagonal::Solve(bool,
                               bool,
                               bool,
                               const Epetra_MultiVector &,
                               Epetra_MultiVector &) const
  {
    return -1;
  }



  int
  StiffnessPlusDiagonal::InvRowSums(Epetra_Vector &) const
  {
    return -1;
  }



  int
  StiffnessPlusDiagonal::LeftScale(const Epetra_Vector &)
  {
    return -1;
  }



  int
  StiffnessPlusDiagonal::InvColSums(Epetra_Vector &) const
  {
    return -1;
  }



  int
  StiffnessPlusDiagonal::RightScale(const Epetra_Vector &)
  {
    return -1;
  }



  bool
  StiffnessPlusDiagonal::Filled() const
  {
    return l().Filled();
  }



  double
  StiffnessPlusDiagonal::NormInf() const
  {
    std::vector<double> values(MaxNumEntries());
    std::vector<int>    indices(MaxNumEntries());
    double              local_norm = 0;
    for (int row = 0; row < NumMyRows(); ++row)
      {
        int n = 0;
        ExtractMyRowCopy(row, values.size(), n, values.data(), indices.data());
        double sum = 0;
        for (int k = 0; k < n; ++k)
          sum += std::abs(values[k]);
        local_norm = std::max(local_norm, sum);
      }
    double norm = 0;
    Comm().MaxAll(&local_norm, &norm, 1);
    return norm;
  }



  double
  StiffnessPlusDiagonal::NormOne() const
  {
    // symmetric
    return NormInf();
  }



  int
  StiffnessPlusDiagonal::NumGlobalNonzeros() const
  {
    return l().NumGlobalNonzeros();
  }



  long long
  StiffnessPlusDiagonal::NumGlobalNonzeros64() const
  {
    return l().NumGlobalNonzeros64();
  }



  int
  StiffnessPlusDiagonal::NumGlobalRows() const
  {
    return l().NumGlobalRows();
  }



  long long
  StiffnessPlusDiagonal::NumGlobalRows64() const
  {
    return l().NumGlobalRows64();
  }



  int
  StiffnessPlusDiagonal::NumGlobalCols() const
  {
    return l().NumGlobalCols();
  }



  long long
  StiffnessPlusDiagonal::NumGlobalCols64() const
  {
    return l().NumGlobalCols64();
  }



  int
  StiffnessPlusDiagonal::NumGlobalDiagonals() const
  {
    return l().NumGlobalDiagonals();
  }



  long long
  StiffnessPlusDiagonal::NumGlobalDiagonals64() const
  {
    return l().NumGlobalDiagonals64();
  }



  int
  StiffnessPlusDiagonal::NumMyNonzeros() const
  {
    return l().NumMyNonzeros();
  }



  int
  StiffnessPlusDiagonal::NumMyRows() const
  {
    return l().NumMyRows();
  }



  int
  StiffnessPlusDiagonal::NumMyCols() const
  {
    return l().NumMyCols();
  }



  int
  StiffnessPlusDiagonal::NumMyDiagonals() const
  {
    return l().NumMyDiagonals();
  }



  bool
  StiffnessPlusDiagonal::LowerTriangular() const
  {
    return l().LowerTriangular();
  }



  bool
  StiffnessPlusDiagonal::UpperTriangular() const
  {
    return l().UpperTriangular();
  }



  const Epetra_Map &
  StiffnessPlusDiagonal::RowMatrixRowMap() const
  {
    return l().RowMatrixRowMap();
  }



  const Epetra_Map &
  StiffnessPlusDiagonal::RowMatrixColMap() const
  {
    return l().RowMatrixColMap();
  }



  const Epetra_Import *
  StiffnessPlusDiagonal::RowMatrixImporter() const
  {
    return l().RowMatrixImporter();
  }



  int
  StiffnessPlusDiagonal::SetUseTranspose(const bool)
  {
    // symmetric: the transpose is the operator itself
    return 0;
  }



  int
  StiffnessPlusDiagonal::Apply(const Epetra_MultiVector &x,
                               Epetra_MultiVector       &y) const
  {
    return Multiply(false, x, y);
  }



  int
  StiffnessPlusDiagonal::ApplyInverse(const Epetra_MultiVector &,
                                      Epetra_MultiVector &) const
  {
    return -1;
  }



  const char *
  StiffnessPlusDiagonal::Label() const
  {
    return "PhaseField::StiffnessPlusDiagonal";
  }



  bool
  StiffnessPlusDiagonal::UseTranspose() const
  {
    return false;
  }



  bool
  StiffnessPlusDiagonal::HasNormInf() const
  {
    return true;
  }



  const Epetra_Comm &
  StiffnessPlusDiagonal::Comm() const
  {
    return l().Comm();
  }



  const Epetra_Map &
  StiffnessPlusDiagonal::OperatorDomainMap() const
  {
    return l().OperatorDomainMap();
  }



  const Epetra_Map &
  StiffnessPlusDiagonal::OperatorRangeMap() const
  {
    return l().OperatorRangeMap();
  }



  const Epetra_BlockMap &
  StiffnessPlusDiagonal::Map() const
  {
    return l().Map();
  }
} // namespace PhaseField
