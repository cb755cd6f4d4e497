#include <phasefield/solvers/symmetric_product_matrix.h>

namespace PhaseField
{
  template <int dim>
  void
  SymmetricProductMatrix::assemble(const LumpedOperators<dim> &ops,
                                   const double                f,
                                   const Vector               &k,
                                   const Vector               &c,
                                   const Vector               &w,
                                   const Vector               &e)
  {
    dealii::TrilinosWrappers::SparseMatrix a;
    ops.stiffness_plus_weighted_mass(f, k, a);
    ops.add_to_diagonal(c, a);
    a.mmult(matrix, a, w);
    ops.add_to_diagonal(e, matrix);
  }



  void
  SymmetricProductMatrix::factorize(LinearSolver &solver) const
  {
    solver.set_constant_matrix(true);
    solver.factorize(matrix);
  }



  void
  SymmetricProductMatrix::solve(LinearSolver &solver,
                                Vector       &x,
                                const Vector &rhs) const
  {
    solver.solve(matrix, x, rhs);
  }



  template void
  SymmetricProductMatrix::assemble(const LumpedOperators<2> &,
                                   const double,
                                   const Vector &,
                                   const Vector &,
                                   const Vector &,
                                   const Vector &);
  template void
  SymmetricProductMatrix::assemble(const LumpedOperators<3> &,
                                   const double,
                                   const Vector &,
                                   const Vector &,
                                   const Vector &,
                                   const Vector &);
} // namespace PhaseField
