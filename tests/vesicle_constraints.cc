// Willmore flow at fixed volume and area (Constraints / Volume = Area =
// fixed): the bordered Newton system of ConstrainedNestedStep and a short
// run.
//
// - The bordered Jacobian [J B^T; B 0] of a nested step with both
//   constraints and nonzero multipliers (2D adaptive mesh with hanging
//   nodes) against central differences of the extended residual, in the
//   U block (which holds the multipliers' forces and the area's Hessian)
//   and in the constraint rows; its solve leaves |J dz + R| / |R| at the
//   linear tolerance.
// - An ellipse of reduced area 0.7 for 6 steps (level 6, adaptive mesh):
//   every step converges, the inside measure and the area functional stay
//   at their initial values to 1e-9 (relative), the Willmore energy does
//   not rise in any step (by more than 1e-9 relative, once stationary), and the
//   multipliers are nonzero. Without the constraints the same flow changes the
//   inside measure by more than 1e-3 in its first step: a solver that ignores
//   them fails. (The sampled ellipse has the semi-axes of a sharp nu = 0.7;
//   with the phase field's area functional its reduced area is near 0.7.)

#include "adaptive_test_mesh.h"
#include "tests.h"

#include <phasefield/problems/willmore_problem.h>
#include <phasefield/schemes/constraints.h>
#include <phasefield/schemes/nested/constrained_nested_step.h>

namespace
{
  using namespace PhaseField;

  void
  check_bordered_jacobian()
  {
    const MPI_Comm                     comm = MPI_COMM_WORLD;
    const Testing::AdaptiveTestMesh<2> mesh;
    const LumpedOperators<2>          &ops = mesh.operators;
    ConstraintParameters               parameters;
    parameters.volume = parameters.area = true;
    ScalarConstraints constraints(parameters, mesh.eps);

    NestedCoefficients coeff;
    coeff.epsilon   = mesh.eps;
    coeff.tau       = 0.03 * mesh.h;
    coeff.inner_tau = mesh.h * mesh.h;
    // a shared_ptr that does not own the constraints of this function
    coeff.outer.registered_terms[ScalarConstraints::name()] =
      std::shared_ptr<ScalarConstraints>(&constraints,
                                         [](ScalarConstraints *) {});

    Vector old_u(ops.locally_owned_dofs, comm);
    mesh.discretization.interpolate(Shapes::PhaseFieldProfile<2>(mesh.sphere,
                                                                 mesh.eps),
                                    old_u);
    mesh.constraints.distribute(old_u);
    constraints.set_missing_targets(ops, old_u);
    NestedStep<2> step(mesh.discretization, coeff, old_u);
    LinearSolver  solver(LinearSolverType::direct, 1e-12, 2000);
    step.set_inner_solver(solver);
    ConstrainedNestedStep<2> system(step, constraints, mesh.discretization);

    const std::vector<dealii::IndexSet> parts(3, ops.locally_owned_dofs);
    BlockVector                         nested(parts, comm);
    nested.block(Field::U) = old_u;
    Vector direction(old_u);
    Testing::fill_smoothly(direction, 1, 2.9);
    mesh.constraints.set_zero(direction);
    mesh.constraints.distribute(direction);
    nested.block(Field::U).add(0.02, direction);
    step.initialize_v_and_p(nested, solver, 1e-10);
    const double scale = constraints.to_residual_units(coeff.tau);
    BlockVector  z = system.extended_state(nested, {-2 * scale, 0.5 * scale});
    BlockVector  x(z), r(z), jx(z), zp(z), zm(z), rp(z), rm(z);
    for (unsigned int b = 0; b < 3; ++b)
      {
        x.block(b) = direction;
        x.block(b) *= (b + 1.);
      }
    const BlockVector dlambda = system.extended_state(nested, {0.3, -0.7});
    x.block(3)                = dlambda.block(3);
    x.block(3) *= scale;

    const double fd_step = 1e-6;
    zp.add(fd_step, x);
    zm.add(-fd_step, x);
    system.residual(zp, rp);
    system.residual(zm, rm);
    rp -= rm;
    rp /= 2 * fd_step;
    system.jacobian_vmult(z, x, jx);
    const std::vector<double> fd_rows = system.multipliers(rp);
    const std::vector<double> j_rows  = system.multipliers(jx);
    rp -= jx;
    Testing::log() << "bordered Jacobian: block U |J x - FD| / |J x| "
                   << Testing::below(ops.dual_norm(rp.block(Field::U)) /
                                       ops.dual_norm(jx.block(Field::U)),
                                     1e-6)
                   << std::endl;
    for (unsigned int j = 0; j < 2; ++j)
      Testing::log() << "  constraint row " << j << ": |B x - FD| / |B x| "
                     << Testing::below(std::abs(fd_rows[j] - j_rows[j]) /
                                         std::abs(j_rows[j]),
                                       1e-6)
                     << std::endl;

    BlockVector dz(z);
    system.residual(z, r);
    system.solve_jacobian(z, r, dz, solver);
    system.jacobian_vmult(z, dz, jx);
    jx += r;
    Testing::log() << "  |J dz + R| / |R| "
                   << Testing::below(system.residual_norm(jx) /
                                       system.residual_norm(r),
                                     1e-6)
                   << std::endl;
  }

  const std::string ellipse = R"(
set Dimension = 2
subsection Geometry
  set Shape = ellipsoid
  set Sizes = 0.35, 0.12658
end
subsection Mesh
  set Finest level = 6
  set Coarsest level = 3
end
subsection Phase field
  set Epsilon = 2*h
end
subsection Time stepping
  set Tau = h^2
  set Number of steps = 6
end
subsection Output
  set VTU interval = 0
end
)";

  const std::string fixed = R"(
subsection Constraints
  set Volume = fixed
  set Area = fixed
end
)";

  void
  check_flow()
  {
    std::vector<std::string> header, free_header;
    const auto rows = Testing::run_willmore(ellipse + fixed, header, "fixed");
    const auto free_rows = Testing::run_willmore(
      ellipse + "subsection Time stepping\n set Number of steps = 1\nend\n",
      free_header,
      "free");
    const int newton = Testing::column(header, "newton_iterations");
    const int w      = Testing::column(header, "willmore_energy");
    const int dv     = Testing::column(header, "volume_change");
    const int da     = Testing::column(header, "area_change");
    const int p      = Testing::column(header, "pressure");
    const int sigma  = Testing::column(header, "tension");
    const int nu     = Testing::column(header, "reduced_volume");
    const int inside = Testing::column(free_header, "inside_measure");
    Testing::log() << "initial reduced area "
                   << (std::abs(rows[0][nu] - 0.7) < 0.05 ? "0.7 +- 0.05" :
                                                            "NOT NEAR 0.7")
                   << std::endl;
    for (unsigned int i = 1; i < rows.size(); ++i)
      Testing::log()
        << "step " << rows[i][0] << ": Newton "
        << (rows[i][newton] > 0 ? "converged" : "FAILED") << ", volume change "
        << Testing::below(std::abs(rows[i][dv]), 1e-9) << ", area change "
        << Testing::below(std::abs(rows[i][da]), 1e-9) << ", W "
        << (rows[i][w] < rows[i - 1][w] * (1 + 1e-9) ? "did not rise" : "ROSE")
        << ", multipliers "
        << (rows[i][p] != 0 && rows[i][sigma] != 0 ? "nonzero" : "ZERO")
        << std::endl;
    const double free_change =
      std::abs(free_rows.back()[inside] / free_rows[0][inside] - 1);
    Testing::log() << "without constraints the inside measure changes by "
                   << (free_change > 1e-3 ? "more than 1e-3" : "LESS THAN 1e-3")
                   << std::endl;
  }
} // namespace



int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check_bordered_jacobian();
  check_flow();
}
