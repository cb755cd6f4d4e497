// The watchdog of newton_solve() (doc/willmore_flow.md, "Newton's
// method"), on the scalar equation R(x) = x^3 - 3x + 4.4 = 0 from
// x = -0.77 (root -2.23004), exact derivatives, Watchdog factor 100, at
// most 8 halvings. Newton's full update from there jumps to x = 4.35 and
// raises |R| from 6.25 to 73.7: the watchdog takes it (a relaxed step,
// printed ", watchdog"), and it succeeds when |R| falls below 6.25 three
// iterations later. After two more relaxed steps that succeed, the fourth
// (iteration 12) leaves an iterate from which no damped update reduces
// |R|: Newton returns to the iterate before it (residual 2.49812), damps
// that update by 1/8, takes no further relaxed step, and converges in
// iteration 21. The path was traced with a Python model of the same rules
// before this test was written, and the program follows it. Without the
// return, Newton would fail in iteration 13 (no damped update); with at
// most one relaxed step, or none, it takes another path. Checked: the
// printed path, convergence and the root.

#include "tests.h"

#include <phasefield/solvers/linear_solver.h>
#include <phasefield/solvers/newton_solver.h>

using namespace PhaseField;

namespace
{
  /** R(x) = x^3 - 3x + c in a one-entry block vector. */
  class Cubic : public NonlinearSystem
  {
  public:
    static constexpr double c = 4.4;

    void
    residual(const BlockVector &z, BlockVector &r) const override
    {
      const double x = z.block(0)[0];
      r.block(0)[0]  = x * x * x - 3 * x + c;
      r.compress(dealii::VectorOperation::insert);
    }

    double
    residual_norm(const BlockVector &r) const override
    {
      return r.l2_norm();
    }

    double
    term_scale(const BlockVector &) const override
    {
      return 1;
    }

    unsigned int
    solve_jacobian(const BlockVector &z,
                   const BlockVector &r,
                   BlockVector       &dz,
                   LinearSolver &) override
    {
      const double x = z.block(0)[0];
      dz.block(0)[0] = -r.block(0)[0] / (3 * x * x - 3);
      dz.compress(dealii::VectorOperation::insert);
      return 1;
    }

    void
    distribute_constraints(BlockVector &) const override
    {}
  };
} // namespace



int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const dealii::IndexSet                   one = dealii::complete_index_set(1);
  dealii::TrilinosWrappers::MPI::BlockVector z(
    std::vector<dealii::IndexSet>{one}, MPI_COMM_WORLD);
  z.block(0)[0] = -0.77;
  z.compress(dealii::VectorOperation::insert);

  NewtonControl control;
  control.relative_tolerance = 0;
  control.absolute_tolerance = 1e-10;
  control.max_iterations     = 30;
  control.max_damping_steps  = 8;
  control.watchdog_factor    = 100;
  Cubic        cubic;
  LinearSolver solver(LinearSolverType::direct, 1e-12, 100);
  Testing::log() << std::setprecision(6);
  const dealii::ConditionalOStream out(Testing::log(), true);
  const StepReport report = newton_solve(cubic, z, control, solver, out, true);
  Testing::log() << "converged: " << (report.converged ? "yes" : "NO")
                 << ", Newton iterations " << report.newton_iterations
                 << ", x = " << z.block(0)[0] << std::endl;
}
