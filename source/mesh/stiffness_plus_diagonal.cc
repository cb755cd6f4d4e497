#include <phasefield/mesh/stiffness_plus_diagonal.h>

namespace PhaseField
{
  void
  StiffnessPlusDiagonal::reinit(
    const dealii::TrilinosWrappers::SparseMatrix &stiffness_matrix,
    const double                                  factor,
    dealii::TrilinosWrappers::MPI::Vector        &diagonal_entries)
  {
    stiffness        = &stiffness_matrix;
    stiffness_factor = factor;
    diagonal.swap(diagonal_entries);
    diagonal_entries.clear();
  }



  void
  StiffnessPlusDiagonal::vmult(
    dealii::TrilinosWrappers::MPI::Vector       &dst,
    const dealii::TrilinosWrappers::MPI::Vector &src) const
  {
    Assert(stiffness != nullptr, dealii::ExcNotInitialized());
    stiffness->vmult(dst, src);
    const unsigned int n = dst.locally_owned_size();
    const double      *d = diagonal.begin();
    const double      *x = src.begin();
    double            *y = dst.begin();
    for (unsigned int i = 0; i < n; ++i)
      y[i] = stiffness_factor * y[i] + d[i] * x[i];
  }



  bool
  StiffnessPlusDiagonal::empty() const
  {
    return stiffness == nullptr;
  }
} // namespace PhaseField
