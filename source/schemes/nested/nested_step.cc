#include <deal.II/base/conditional_ostream.h>
#include <iostream>
#include <phasefield/schemes/nested/nested_step.h>
#include <phasefield/solvers/newton_solver.h>

namespace PhaseField
{
  using namespace dealii;

  // ---------------------------------------------------------------------
  // The inner problem (3.18b): R_P(U, V) = 0 for V at fixed U
  // ---------------------------------------------------------------------

  /**
   * The inner (Allen-Cahn) problem R_P(U, V) = 0 in V for a fixed U, as a
   * NonlinearSystem in the one-block vector (V). Its Jacobian K(V) is
   * positive definite for ttau < eps^2/2 (a convex inner energy).
   */
  template <int dim>
  class NestedStep<dim>::InnerProblem : public NonlinearSystem
  {
  public:
    InnerProblem(const NestedStep<dim> &step, const Vector &u)
      : step(step)
      , u(u)
    {}

    void
    residual(const BlockVector &z, BlockVector &r) const override
    {
      step.physics.inner_residual(u, z.block(0), r.block(0));
    }

    double
    residual_norm(const BlockVector &r) const override
    {
      return step.physics.operators().dual_norm(r.block(0));
    }

    /** The tolerance of the inner problem is absolute. */
    double
    term_scale(const BlockVector &) const override
    {
      return 1;
    }

    unsigned int
    solve_jacobian(const BlockVector &z,
                   const BlockVector &r,
                   BlockVector       &dz,
                   LinearSolver      &solver) override
    {
      Vector rhs(r.block(0));
      rhs *= -1;
      const unsigned int iterations =
        step.systems.solve_with_k(z.block(0), solver, dz.block(0), rhs);
      step.physics.operators().zero_constrained(dz.block(0));
      return iterations;
    }

    void
    distribute_constraints(BlockVector &z) const override
    {
      step.physics.get_discretization().get_constraints().distribute(
        z.block(0));
    }

  private:
    const NestedStep<dim> &step;
    const Vector          &u;
  };



  // ---------------------------------------------------------------------
  // The step: NestedPhysics with NestedLinearSystems
  // ---------------------------------------------------------------------

  template <int dim>
  NestedStep<dim>::NestedStep(const Discretization<dim> &discretization,
                              const NestedCoefficients  &coefficients,
                              const Vector              &old_u,
                              NestedMatrices<dim>       *mesh_matrices)
    : physics(discretization, coefficients, old_u)
    , systems(physics, mesh_matrices)
  {}



  template <int dim>
  void
  NestedStep<dim>::residual(const BlockVector &z, BlockVector &r) const
  {
    physics.residual(z, r);
  }



  template <int dim>
  double
  NestedStep<dim>::residual_norm(const BlockVector &r) const
  {
    return physics.residual_norm(r);
  }



  template <int dim>
  double
  NestedStep<dim>::term_scale(const BlockVector &z) const
  {
    return physics.term_scale(z);
  }



  template <int dim>
  double
  NestedStep<dim>::roundoff_level(const BlockVector &z) const
  {
    return physics.roundoff_level(z);
  }



  template <int dim>
  unsigned int
  NestedStep<dim>::solve_jacobian(const BlockVector &z,
                                  const BlockVector &r,
                                  BlockVector       &dz,
                                  LinearSolver      &solver)
  {
    return systems.solve_jacobian(z, r, dz, solver);
  }



  template <int dim>
  void
  NestedStep<dim>::distribute_constraints(BlockVector &z) const
  {
    physics.get_discretization().distribute_constraints(z);
  }



  template <int dim>
  double
  NestedStep<dim>::energy_roundoff(const BlockVector &z,
                                   const double       energy) const
  {
    return MinimizationProblem::energy_roundoff(z, energy) +
           physics.outer_energy_error(z);
  }



  template <int dim>
  unsigned int
  NestedStep<dim>::solve_shifted_jacobian(const BlockVector &z,
                                          const BlockVector &r,
                                          BlockVector       &dz,
                                          LinearSolver      &solver,
                                          const double       shift)
  {
    return systems.solve_shifted_jacobian(z, r, dz, solver, shift);
  }



  template <int dim>
  void
  NestedStep<dim>::jacobian_vmult(const BlockVector &z,
                                  const BlockVector &x,
                                  BlockVector       &y,
                                  const double       shift) const
  {
    physics.jacobian_vmult(z, x, y, shift);
  }



  template <int dim>
  double
  NestedStep<dim>::outer_energy(const BlockVector &z) const
  {
    return physics.outer_energy(z);
  }



  template <int dim>
  unsigned int
  NestedStep<dim>::initialize_v_and_p(BlockVector  &z,
                                      LinearSolver &solver,
                                      const double  tolerance) const
  {
    z.block(Field::V) = z.block(Field::U);
    Vector r(z.block(Field::U));
    physics.inner_residual(z.block(Field::U), z.block(Field::V), r);
    return solve_inner_problem(z,
                               solver,
                               std::max(tolerance *
                                          physics.operators().dual_norm(r),
                                        Constants::roundoff));
  }



  template <int dim>
  unsigned int
  NestedStep<dim>::solve_inner_problem(BlockVector  &z,
                                       LinearSolver &solver,
                                       const double  tolerance) const
  {
    // V: Newton on R_P(U, V) = 0 with full steps (a convex problem), to
    // the absolute tolerance or until the residual stagnates at round-off
    // (about 1e-15 in this norm); inexact, as the outer Newton method:
    // each linear solve only as tight as the next Newton residual needs
    NewtonControl control;
    control.absolute_tolerance      = tolerance;
    control.max_iterations          = 50;
    control.line_search             = false;
    control.roundoff_level          = 1e-12;
    const LumpedOperators<dim> &ops = physics.operators();
    const MPI_Comm comm = physics.get_discretization().get_mpi_communicator();
    BlockVector    v(std::vector<IndexSet>(1, ops.locally_owned_dofs), comm);
    v.block(0) = z.block(Field::V);
    InnerProblem     inner(*this, z.block(Field::U));
    const StepReport report = newton_solve(
      inner, v, control, solver, ConditionalOStream(std::cout, false), false);
    AssertThrow(report.converged,
                ExcMessage("The inner problem (V for given U, Algorithm "
                           "3.1) did not converge in 50 Newton "
                           "iterations."));
    z.block(Field::V) = v.block(0);

    // P: K(V) P = -a M (V - U), at the solver's own tolerance, not the
    // last one of the Newton solve
    Vector r;
    physics.adjoint_rhs(z, r);
    solver.set_tolerance(0);
    systems.solve_with_k(z.block(Field::V), solver, z.block(Field::P), r);
    ops.zero_constrained(z.block(Field::P));
    return report.newton_iterations;
  }



  template <int dim>
  double
  NestedStep<dim>::project_and_energy(BlockVector &z)
  {
    AssertThrow(inner_solver != nullptr,
                ExcMessage("NestedStep::project_and_energy() needs a solver "
                           "of the inner problem (set_inner_solver())."));
    solve_inner_problem(z, *inner_solver, inner_tolerance);
    return outer_energy(z);
  }



  template class NestedStep<2>;
  template class NestedStep<3>;
} // namespace PhaseField
