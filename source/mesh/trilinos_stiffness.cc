#include <algorithm>
#include <deal.II/base/exceptions.h>
#include <phasefield/mesh/lumped_operators.h>
#include <phasefield/mesh/stiffness_plus_diagonal.h>
#include <phasefield/mesh/trilinos_stiffness.h>

namespace PhaseField
{
  void
  TrilinosStiffness::vmult(Vector &dst, const Vector &src) const
  {
    matrix.vmult(dst, src);
  }



  void
  TrilinosStiffness::diagonal(Vector &diagonal) const
  {
    const CompressedRows rows = compressed_rows(matrix);
    diagonal.reinit(matrix.locally_owned_range_indices(),
                    matrix.get_mpi_communicator());
    for (unsigned int i = 0; i < diagonal_positions.size(); ++i)
      diagonal.begin()[i] = rows.values[diagonal_positions[i]];
  }



  void
  TrilinosStiffness::shift(const double                       factor,
                           Vector                            &diagonal,
                           std::unique_ptr<ShiftedStiffness> &op) const
  {
    auto *trilinos_op = dynamic_cast<StiffnessPlusDiagonal *>(op.get());
    if (trilinos_op == nullptr)
      {
        auto fresh  = std::make_unique<StiffnessPlusDiagonal>();
        trilinos_op = fresh.get();
        op          = std::move(fresh);
      }
    trilinos_op->reinit(matrix, factor, diagonal);
  }



  void
  TrilinosStiffness::find_diagonal()
  {
    const Epetra_CrsMatrix &l    = matrix.trilinos_matrix();
    const CompressedRows    rows = compressed_rows(matrix);
    diagonal_positions.resize(l.NumMyRows());
    for (int row = 0; row < l.NumMyRows(); ++row)
      {
        const int *begin = rows.columns + rows.offsets[row];
        const int *end   = rows.columns + rows.offsets[row + 1];
        const int *found = std::find(begin, end, l.LCID(l.GRID(row)));
        AssertThrow(found != end,
                    dealii::ExcMessage(
                      "The stiffness matrix lacks a diagonal entry."));
        diagonal_positions[row] = static_cast<int>(found - rows.columns);
      }
  }



  std::size_t
  TrilinosStiffness::memory_consumption() const
  {
    return matrix.memory_consumption() +
           diagonal_positions.capacity() * sizeof(int);
  }



  void
  TrilinosStiffness::clear()
  {
    matrix.clear();
    std::vector<int>().swap(diagonal_positions);
  }
} // namespace PhaseField
