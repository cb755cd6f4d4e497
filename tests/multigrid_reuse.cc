// LinearSolver::solve_product_form() with set_persistent_matrices(): the
// multigrid hierarchy of G is kept for a later solve with G refilled in
// place (one set-up for two solves, and the second solve still meets its
// tolerance), is set up for every solve without persistent matrices, and
// is set up anew after a solve that needed more than multigrid_reuse_factor
// times the iterations per decade of the first one. A kept hierarchy under
// which CG does not converge within the iteration limit is replaced and
// the solve repeated, its iterations counted.
//
// S = M + Khat M^-1 Khat with Khat = L + M (Q1, unit square, lumped M, both
// as StiffnessPlusDiagonal), and
// G = M + c L for several c: c = 1 is the preconditioner the theory of
// SchurPreconditioner is for; c = 1e-3 a poor one.

#include "tests.h"

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <phasefield/mesh/stiffness_plus_diagonal.h>
#include <phasefield/solvers/linear_solver.h>

using namespace dealii;
using namespace PhaseField;
using TVector = TrilinosWrappers::MPI::Vector;
using Matrix  = TrilinosWrappers::SparseMatrix;

namespace
{
  /** Q1 Laplace matrix and lumped mass. */
  struct Operators
  {
    Matrix  laplace;
    TVector lumped_mass, inverse_lumped_mass;
  };

  void
  assemble(const DoFHandler<2> &dofs, Operators &ops)
  {
    const IndexSet                   &owned = dofs.locally_owned_dofs();
    TrilinosWrappers::SparsityPattern pattern(owned, MPI_COMM_WORLD);
    DoFTools::make_sparsity_pattern(dofs, pattern);
    pattern.compress();
    ops.laplace.reinit(pattern);
    ops.lumped_mass.reinit(owned, MPI_COMM_WORLD);

    const QGauss<2>                      quadrature(2);
    FEValues<2>                          fe_values(dofs.get_fe(),
                          quadrature,
                          update_values | update_gradients | update_JxW_values);
    const unsigned int                   n = dofs.get_fe().n_dofs_per_cell();
    FullMatrix<double>                   cell_laplace(n, n), cell_mass(n, n);
    std::vector<types::global_dof_index> indices(n);
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          cell_laplace = 0;
          cell_mass    = 0;
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            for (unsigned int i = 0; i < n; ++i)
              for (unsigned int j = 0; j < n; ++j)
                {
                  cell_laplace(i, j) += fe_values.shape_grad(i, q) *
                                        fe_values.shape_grad(j, q) *
                                        fe_values.JxW(q);
                  cell_mass(i, j) += fe_values.shape_value(i, q) *
                                     fe_values.shape_value(j, q) *
                                     fe_values.JxW(q);
                }
          cell->get_dof_indices(indices);
          ops.laplace.add(indices, cell_laplace);
          for (unsigned int i = 0; i < n; ++i)
            for (unsigned int j = 0; j < n; ++j)
              ops.lumped_mass(indices[i]) += cell_mass(i, j);
        }
    ops.laplace.compress(VectorOperation::add);
    ops.lumped_mass.compress(VectorOperation::add);
    ops.inverse_lumped_mass = ops.lumped_mass;
    for (auto &value : ops.inverse_lumped_mass)
      value = 1. / value;
  }

  /** Refill @p g in place with M + c L. */
  void
  refill(const Operators &ops, const double c, StiffnessPlusDiagonal &g)
  {
    TVector mass(ops.lumped_mass);
    g.reinit(ops.laplace, c, mass);
  }

  /** ||S x - b|| / ||b|| for S = M + Khat M^-1 Khat. */
  double
  relative_residual(const Operators             &ops,
                    const StiffnessPlusDiagonal &k_hat,
                    const TVector               &x,
                    const TVector               &b)
  {
    TVector tmp(b), sx(b);
    k_hat.vmult(tmp, x);
    tmp.scale(ops.inverse_lumped_mass);
    k_hat.vmult(sx, tmp);
    tmp = x;
    tmp.scale(ops.lumped_mass);
    sx += tmp;
    sx -= b;
    return sx.l2_norm() / b.l2_norm();
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  auto                            &log = Testing::log();
  const auto yes = [](const bool b) { return b ? "yes" : "NO"; };

  parallel::distributed::Triangulation<2> tria(MPI_COMM_WORLD);
  GridGenerator::hyper_cube(tria);
  tria.refine_global(6);
  const FE_Q<2> fe(1);
  DoFHandler<2> dofs(tria);
  dofs.distribute_dofs(fe);
  Operators ops;
  assemble(dofs, ops);

  StiffnessPlusDiagonal k_hat;
  TVector               lumped_mass(ops.lumped_mass);
  k_hat.reinit(ops.laplace, 1., lumped_mass);
  StiffnessPlusDiagonal g;
  TVector               b(ops.lumped_mass), x(ops.lumped_mass);
  for (unsigned int i = 0; i < b.locally_owned_size(); ++i)
    b.begin()[i] =
      std::sin(7. * b.locally_owned_elements().nth_index_in_set(i));

  constexpr double tolerance = 1e-8;
  const auto       solve     = [&](LinearSolver &solver) {
    const unsigned int iterations =
      solver.solve_product_form(k_hat,
                                1.,
                                ops.lumped_mass,
                                g,
                                ops.lumped_mass,
                                ops.inverse_lumped_mass,
                                x,
                                b);
    return std::make_pair(iterations,
                          relative_residual(ops, k_hat, x, b) < 2 * tolerance);
  };

  // kept for a refilled G
  LinearSolver kept(LinearSolverType::iterative, tolerance, 1000);
  kept.set_persistent_matrices(true);
  refill(ops, 1., g);
  const auto first = solve(kept);
  refill(ops, 1.1, g);
  const auto second = solve(kept);
  log << "persistent: 1 set-up for 2 solves: "
      << yes(kept.n_factorizations() == 1)
      << ", both solved: " << yes(first.second && second.second) << '\n';

  // set up for every solve otherwise
  LinearSolver plain(LinearSolverType::iterative, tolerance, 1000);
  refill(ops, 1., g);
  solve(plain);
  refill(ops, 1.1, g);
  solve(plain);
  log << "not persistent: 2 set-ups for 2 solves: "
      << yes(plain.n_factorizations() == 2) << '\n';

  // a worn hierarchy: the solve with the poor G would need more than the
  // factor times the first iterations; it is given up there, the
  // hierarchy set up for this G and the solve repeated
  refill(ops, 1e-3, g);
  const auto worn = solve(kept);
  log << "hierarchy of c = 1 for c = 1e-3: given up after "
      << LinearSolver::multigrid_reuse_factor
      << " times the iterations and set up anew: "
      << yes(kept.n_factorizations() == 2 &&
             worn.first > LinearSolver::multigrid_reuse_factor * first.first)
      << ", solved: " << yes(worn.second) << '\n';

  // a kept hierarchy under which CG hits the iteration limit is replaced:
  // set up for c = 1e-3 (solved loosely, to stay within the limit) and
  // applied to c = 1, whose own hierarchy needs first.first iterations
  LinearSolver limited(LinearSolverType::iterative, tolerance, first.first + 2);
  limited.set_persistent_matrices(true);
  limited.set_tolerance(0.5);
  refill(ops, 1e-3, g);
  solve(limited);
  limited.set_tolerance(tolerance);
  refill(ops, 1., g);
  bool         failed     = false;
  unsigned int iterations = 0;
  bool         solved     = false;
  try
    {
      std::tie(iterations, solved) = solve(limited);
    }
  catch (const SolverControl::NoConvergence &)
    {
      failed = true;
    }
  log << "kept hierarchy over the iteration limit: solve repeated with a new "
         "one: "
      << yes(!failed && limited.n_factorizations() == 2 && solved)
      << ", iterations of both counted: " << yes(iterations > first.first + 2)
      << '\n';

  // the interface mode: a hierarchy is kept while the mode changes by at
  // most interface_mode_tolerance, and set up anew beyond
  LinearSolver moving(LinearSolverType::iterative, tolerance, 1000);
  moving.set_persistent_matrices(true);
  refill(ops, 1., g);
  TVector mode(ops.lumped_mass);
  mode                       = 0.5;
  const auto solve_with_mode = [&]() {
    moving.solve_product_form(k_hat,
                              1.,
                              ops.lumped_mass,
                              g,
                              ops.lumped_mass,
                              ops.inverse_lumped_mass,
                              x,
                              b,
                              &mode);
    return relative_residual(ops, k_hat, x, b) < 2 * tolerance;
  };
  bool mode_solved = solve_with_mode();
  mode.add(0.9 * LinearSolver::interface_mode_tolerance);
  mode_solved                      = solve_with_mode() && mode_solved;
  const bool kept_for_small_change = moving.n_factorizations() == 1;
  mode(mode.locally_owned_elements().nth_index_in_set(0)) +=
    0.2 * LinearSolver::interface_mode_tolerance;
  mode.compress(VectorOperation::insert);
  mode_solved = solve_with_mode() && mode_solved;
  log << "interface mode changed by 0.9 x the tolerance: kept: "
      << yes(kept_for_small_change) << "; at one node by 1.1 x: set up anew: "
      << yes(moving.n_factorizations() == 2) << ", solved: " << yes(mode_solved)
      << '\n';
}
