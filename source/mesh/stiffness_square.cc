#include <Epetra_Import.h>
#include <Epetra_Vector.h>
#include <algorithm>
#include <deal.II/base/exceptions.h>
#include <phasefield/mesh/stiffness_square.h>

namespace PhaseField
{
  using namespace dealii;

  namespace
  {
    /**
     * Index, among all entries of @p rows, of the local column @p column in
     * the local row @p row.
     */
    int
    entry_index(const CompressedRows &rows, const int row, const int column)
    {
      const int *begin = rows.columns + rows.offsets[row];
      const int *end   = rows.columns + rows.offsets[row + 1];
      const int *found = std::find(begin, end, column);
      AssertThrow(found != end, ExcMessage("L M^-1 L lacks an entry of L."));
      return static_cast<int>(found - rows.columns);
    }
  } // namespace



  template <int dim>
  StiffnessSquare<dim>::StiffnessSquare(const LumpedOperators<dim> &operators)
    : operators(operators)
  {
    const auto &l = operators.stiffness_matrix();
    l.mmult(stiffness_square, l, operators.inverse_lumped_mass);

    const Epetra_CrsMatrix &lm     = l.trilinos_matrix();
    const Epetra_CrsMatrix &sq     = stiffness_square.trilinos_matrix();
    const CompressedRows    l_rows = compressed_rows(l);
    const CompressedRows    rows   = compressed_rows(stiffness_square);
    column_import = std::make_unique<Epetra_Import>(lm.ColMap(), lm.RowMap());
    entry_positions.resize(l_rows.offsets[lm.NumMyRows()]);
    diagonal_positions.resize(lm.NumMyRows());
    for (int row = 0; row < lm.NumMyRows(); ++row)
      {
        for (int k = l_rows.offsets[row]; k < l_rows.offsets[row + 1]; ++k)
          entry_positions[k] =
            entry_index(rows, row, sq.LCID(lm.GCID(l_rows.columns[k])));
        diagonal_positions[row] = entry_index(rows, row, sq.LCID(lm.GRID(row)));
      }
  }



  template <int dim>
  StiffnessSquare<dim>::~StiffnessSquare() = default;



  template <int dim>
  void
  StiffnessSquare<dim>::assemble(const double                    w,
                                 const double                    s,
                                 const Vector                   &d,
                                 const Vector                   &e,
                                 TrilinosWrappers::SparseMatrix &a) const
  {
    // T = M^-1 M[d] on the owned DoFs and on the columns of L
    Vector t(d);
    t.scale(operators.lumped_mass);
    t.scale(operators.inverse_lumped_mass);
    const Epetra_CrsMatrix &lm = operators.stiffness_matrix().trilinos_matrix();
    Epetra_Vector           t_columns(lm.ColMap());
    t_columns.Import(t.trilinos_vector(), *column_import, Insert);

    // w s^2 L M^-1 L, then w s (L T + T L) on the entries of L and
    // w M[d] T + e on the diagonal
    if (!share_pattern(a, stiffness_square))
      a.copy_from(stiffness_square);
    const CompressedRows square = compressed_rows(stiffness_square);
    const CompressedRows l      = compressed_rows(operators.stiffness_matrix());
    const CompressedRows out    = compressed_rows(a);
    const int            n_rows = lm.NumMyRows();
    for (int k = 0; k < square.offsets[n_rows]; ++k)
      out.values[k] = w * s * s * square.values[k];
    const double *m = operators.lumped_mass.begin();
    for (int row = 0; row < n_rows; ++row)
      {
        const double t_row = t.begin()[row];
        for (int k = l.offsets[row]; k < l.offsets[row + 1]; ++k)
          out.values[entry_positions[k]] +=
            w * s * l.values[k] * (t_row + t_columns[l.columns[k]]);
        out.values[diagonal_positions[row]] +=
          w * m[row] * d.begin()[row] * t_row + e.begin()[row];
      }
  }



  template class StiffnessSquare<2>;
  template class StiffnessSquare<3>;
} // namespace PhaseField
