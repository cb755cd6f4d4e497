// internal::ForcingTerm, the tolerances of the linear solves of an inexact
// Newton method (doc/willmore_flow.md, "Newton's method"), for a residual
// history |R_k| = 1, 0.5, 0.05, 1e-4, 1e-7 and a target of 1e-8:
// - iterative solver (Eisenstat-Walker choice 2): 0.1 first, then
//   min(0.1, max(0.9 (|R_k|/|R_(k-1)|)^2, 0.05 target/|R_k|)), i.e.
//   0.1 (0.225 capped), 0.009, 5e-6 (0.9 * 0.002^2 = 3.6e-6 is below
//   the floor 0.05 * 1e-8 / 1e-4), 5e-3 (the floor is 5e-3; a quadratic
//   drop of 1e-3 would give 9e-7);
// - direct solver: 1e-3 first, then min(1e-3, 0.05 target/|R_k|);
// - a new object (a new Newton solve) starts again at its first value, for
//   |R_0| = 1e-3 and 2e-5; at |R_0| = 2e-6 and 6.25e-6 the target is
//   within reach of one solve (target/|R_0| = 5e-3 and 1.6e-3, >= 1e-3),
//   and the first tolerance is min(cap, 0.5 target/|R_0|): 2.5e-3 and
//   8e-4 for the iterative solver (cap 0.1), 1e-3 and 8e-4 for the direct
//   one (cap 1e-3);
// - without NewtonControl::adapt_linear_tolerance the tolerance given to
//   the solver stays, and no tolerance is set below it.

#include "tests.h"

#include <phasefield/solvers/linear_solver.h>
#include <phasefield/solvers/nonlinear_system.h>

using namespace PhaseField;

namespace
{
  void
  print_history(const LinearSolverType type, const bool adapt)
  {
    LinearSolver  solver(type, 1e-12, 100);
    NewtonControl control;
    control.adapt_linear_tolerance = adapt;
    const double          target   = 1e-8;
    internal::ForcingTerm forcing;
    unsigned int          iteration = 0;
    for (const double norm : {1., 0.5, 0.05, 1e-4, 1e-7})
      {
        forcing.set_tolerance(solver, control, ++iteration, target, norm);
        Testing::log() << ' ' << solver.get_tolerance();
      }
    Testing::log() << " | new solves:";
    for (const double norm : {1e-3, 2e-5, 2e-6, 6.25e-6})
      {
        internal::ForcingTerm next_solve;
        next_solve.set_tolerance(solver, control, 1, target, norm);
        Testing::log() << ' ' << solver.get_tolerance();
      }
    Testing::log() << std::endl;
  }
} // namespace



int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  Testing::log() << std::setprecision(6);
  Testing::log() << "iterative:";
  print_history(LinearSolverType::iterative, true);
  Testing::log() << "direct:";
  print_history(LinearSolverType::direct, true);
  Testing::log() << "not adapted:";
  print_history(LinearSolverType::iterative, false);
}
