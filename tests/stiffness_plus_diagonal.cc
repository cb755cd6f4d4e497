// StiffnessPlusDiagonal, the operator f L + M[w] that the nested scheme
// keeps for K(V), Khat and G instead of matrices, is the matrix that
// LumpedOperators::stiffness_plus_weighted_mass() builds, on the adaptive
// test mesh (hanging nodes) in 2D and 3D, to round-off: its product, and
// as the Epetra_RowMatrix ML reads, its rows, diagonal, product and
// infinity norm. An algebraic multigrid set up from it preconditions CG on
// the matrix as well as one set up from the matrix (the same iterations).

#include "adaptive_test_mesh.h"
#include "tests.h"

#include <Epetra_CrsMatrix.h>
#include <Epetra_Vector.h>
#include <cmath>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <phasefield/mesh/algebraic_multigrid.h>
#include <phasefield/mesh/stiffness_plus_diagonal.h>
#include <vector>

using namespace dealii;
using namespace PhaseField;
using TVector = TrilinosWrappers::MPI::Vector;

namespace
{
  const char *
  yes(const bool b)
  {
    return b ? "yes" : "NO";
  }

  /** Largest difference of the rows of @p a and @p b (same pattern). */
  double
  row_difference(const Epetra_RowMatrix &a, const Epetra_RowMatrix &b)
  {
    const int           n_max = a.MaxNumEntries();
    std::vector<double> va(n_max), vb(n_max);
    std::vector<int>    ia(n_max), ib(n_max);
    double              local = 0;
    for (int row = 0; row < a.NumMyRows(); ++row)
      {
        int na = 0, nb = 0;
        a.ExtractMyRowCopy(row, n_max, na, va.data(), ia.data());
        b.ExtractMyRowCopy(row, n_max, nb, vb.data(), ib.data());
        if (na != nb)
          return 1;
        for (int k = 0; k < na; ++k)
          local =
            std::max(local, ia[k] == ib[k] ? std::abs(va[k] - vb[k]) : 1.);
      }
    double global = 0;
    a.Comm().MaxAll(&local, &global, 1);
    return global;
  }

  /** CG iterations for @p matrix x = @p b to 1e-8 with @p amg. */
  unsigned int
  cg_iterations(const TrilinosWrappers::SparseMatrix &matrix,
                const MultigridCycle                 &amg,
                const TVector                        &b)
  {
    SolverControl     control(200, 1e-8 * b.l2_norm());
    SolverCG<TVector> cg(control);
    TVector           x(b);
    x = 0;
    cg.solve(matrix, x, b, amg);
    return control.last_step();
  }
} // namespace

template <int dim>
void
check()
{
  const Testing::AdaptiveTestMesh<dim> mesh;
  const LumpedOperators<dim>          &ops   = mesh.operators;
  const IndexSet                      &owned = ops.locally_owned_dofs;

  // positive nodal weights that vary (as those of G) and a vector
  TVector weight(ops.lumped_mass), x(ops.lumped_mass);
  for (unsigned int i = 0; i < weight.locally_owned_size(); ++i)
    {
      const double g    = owned.nth_index_in_set(i);
      weight.begin()[i] = 2. + std::cos(0.37 * g);
      x.begin()[i]      = std::sin(7. * g);
    }
  const double stiffness_factor = 0.25;

  TrilinosWrappers::SparseMatrix matrix;
  ops.stiffness_plus_weighted_mass(stiffness_factor, weight, matrix);
  std::unique_ptr<ShiftedStiffness> op;
  const bool                        empty_before = !op;
  ops.stiffness_plus_weighted_mass(stiffness_factor, weight, op);
  const Epetra_CrsMatrix &epetra_matrix = matrix.trilinos_matrix();
  const double            scale         = epetra_matrix.NormInf();
  constexpr double        roundoff      = 1e-14;

  TVector from_matrix(x), from_operator(x);
  matrix.vmult(from_matrix, x);
  op->vmult(from_operator, x);
  // the Trilinos backend's f L + D, as ML reads it
  const auto  &rows = dynamic_cast<const StiffnessPlusDiagonal &>(*op);
  const double norm = from_matrix.l2_norm();
  from_operator -= from_matrix;
  Testing::log() << dim << "D: empty before reinit: "
                 << yes(empty_before && !op->empty())
                 << ", |(f L + M[w]) x| > 0: " << yes(norm > 0)
                 << ", product = matrix product: "
                 << yes(from_operator.l2_norm() < roundoff * norm) << '\n';

  // the Epetra_RowMatrix interface
  Epetra_Vector diagonal_op(epetra_matrix.RowMap()),
    diagonal_matrix(epetra_matrix.RowMap());
  rows.ExtractDiagonalCopy(diagonal_op);
  epetra_matrix.ExtractDiagonalCopy(diagonal_matrix);
  diagonal_op.Update(-1., diagonal_matrix, 1.);
  double diagonal_difference = 0;
  diagonal_op.NormInf(&diagonal_difference);
  Epetra_Vector y_op(epetra_matrix.RowMap()), y_matrix(epetra_matrix.RowMap());
  rows.Multiply(false, x.trilinos_vector(), y_op);
  epetra_matrix.Multiply(false, x.trilinos_vector(), y_matrix);
  y_op.Update(-1., y_matrix, 1.);
  double product_difference = 0, product_norm = 0;
  y_op.Norm2(&product_difference);
  y_matrix.Norm2(&product_norm);
  Testing::log()
    << "    entries: "
    << yes(row_difference(rows, epetra_matrix) < roundoff * scale)
    << ", diagonal: " << yes(diagonal_difference < roundoff * scale)
    << ", Multiply: " << yes(product_difference < roundoff * product_norm)
    << ", NormInf: " << yes(std::abs(rows.NormInf() - scale) < roundoff * scale)
    << ", size: "
    << yes(rows.m() == matrix.m() &&
           rows.NumGlobalRows64() == static_cast<long long>(matrix.m()))
    << '\n';

  // ML set up from the operator and from the matrix
  const auto amg_op = op->make_multigrid(nullptr, multigrid_smoother_sweeps);
  const AlgebraicMultigrid amg_matrix(epetra_matrix);
  const unsigned int       its_op     = cg_iterations(matrix, *amg_op, x);
  const unsigned int       its_matrix = cg_iterations(matrix, amg_matrix, x);
  Testing::log() << "    CG + AMG of the operator: the iterations of AMG of "
                    "the matrix: "
                 << yes(its_op == its_matrix && its_op > 0) << '\n';
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check<2>();
  check<3>();
}
