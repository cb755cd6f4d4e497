// The exact Jacobian of the nested scheme (NestedStep::jacobian_vmult)
// agrees with central finite differences of the residual, and the
// eliminated Newton solve (NestedStep::solve_jacobian) solves
// J dZ = -R, in 2D and 3D, on an adaptive mesh with hanging nodes; in 2D
// also with the area term of edge restoration (eta > 0) and U held fixed
// at the DoFs with x < 0.3 (the 3-field solve, also with a
// Levenberg-Marquardt shift of the UU block), and with the area term but
// no fixed U (GMRES preconditioned by the elimination without the area
// term, with and without a shift). With the area term, R_U at a
// state with V, P re-solved for U (NestedStep::solve_inner_problem) is
// the gradient of the outer energy NestedStep::outer_energy, the merit
// function of minimizing_newton_solve.

#include "adaptive_test_mesh.h"
#include "tests.h"

#include <cmath>
#include <deal.II/base/function.h>
#include <deal.II/base/function_lib.h>
#include <deal.II/base/point.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/numerics/vector_tools.h>
#include <map>
#include <phasefield/geometry/shapes.h>
#include <phasefield/schemes/nested_scheme.h>

using namespace dealii;
using namespace PhaseField;

template <int dim>
void
check(const LinearSolverType solver_type,
      const double           eta      = 0,
      const bool             fix_some = false,
      const double           shift    = 0)
{
  const MPI_Comm                       comm = MPI_COMM_WORLD;
  const Testing::AdaptiveTestMesh<dim> mesh;
  const double                         eps         = mesh.eps;
  const double                         h           = mesh.h;
  const auto                          &dof_handler = mesh.dof_handler;
  const auto                          &constraints = mesh.constraints;
  const auto                          &sphere      = mesh.sphere;
  const LumpedOperators<dim>          &ops         = mesh.operators;

  NestedCoefficients coeff;
  coeff.epsilon           = eps;
  coeff.tau               = 0.03 * h;
  coeff.inner_tau         = h * h;
  coeff.outer.area_weight = eta;
  IndexSet fixed(dof_handler.n_dofs());
  if (fix_some)
    {
      std::map<types::global_dof_index, Point<dim>> points;
      DoFTools::map_dofs_to_support_points(MappingQ1<dim>(),
                                           dof_handler,
                                           points);
      for (const auto &[dof, point] : points)
        if (point[0] < 0.3)
          fixed.add_index(dof);
      fixed.compress();
      coeff.outer.fixed_u = &fixed;
    }
  TrilinosWrappers::MPI::Vector old_u(ops.locally_owned_dofs, comm);
  NestedStep<dim>               scheme(mesh.discretization, coeff, old_u);
  LinearSolver                  solver(solver_type, 1e-12, 2000);

  using BlockVector = TrilinosWrappers::MPI::BlockVector;
  const std::vector<IndexSet> parts(3, ops.locally_owned_dofs);
  BlockVector z(parts, comm), x(parts, comm), r(parts, comm), rp(parts, comm),
    rm(parts, comm), jx(parts, comm), dz(parts, comm);
  const Shapes::PhaseFieldProfile<dim> u0(sphere, eps);
  VectorTools::interpolate(dof_handler, u0, z.block(Field::U));
  scheme.initialize_v_and_p(z, solver, 1e-10);

  // A generic state and direction: smooth perturbations of every field.
  Functions::CosineFunction<dim> wave;
  TrilinosWrappers::MPI::Vector  w(ops.locally_owned_dofs, comm);
  VectorTools::interpolate(dof_handler, wave, w);
  old_u = z.block(Field::U);
  old_u.add(0.05, w);
  z.block(Field::V).add(0.02, w);
  z.block(Field::P).add(0.5 * z.block(Field::P).linfty_norm(), w);
  for (unsigned int b = 0; b < 3; ++b)
    {
      x.block(b) = w;
      x.block(b) *= (b + 1.);
      ops.zero_constrained(x.block(b));
    }
  // directions keep fixed U values fixed
  for (unsigned int i = 0; i < x.block(0).locally_owned_size(); ++i)
    if (fixed.is_element(ops.locally_owned_dofs.nth_index_in_set(i)))
      x.block(Field::U).begin()[i] = 0;

  // central differences
  const double step = 1e-6;
  BlockVector  zp(z), zm(z);
  zp.add(step, x);
  zm.add(-step, x);
  scheme.residual(zp, rp);
  scheme.residual(zm, rm);
  rp -= rm;
  rp /= 2 * step;
  scheme.jacobian_vmult(z, x, jx);
  BlockVector difference(jx);
  difference -= rp;
  if (eta > 0)
    Testing::log() << "eta = " << eta
                   << (fix_some ? ", U fixed at x < 0.3" : "")
                   << (shift > 0 ? ", shift " + std::to_string(int(shift)) :
                                   std::string())
                   << ": ";
  Testing::log() << dim << "D, " << dof_handler.n_dofs() << " DoFs, "
                 << constraints.n_constraints() << " hanging-node constraints"
                 << (constraints.n_constraints() > 0 ? " (> 0)" : "")
                 << std::endl;
  // the shifted matrix is not the Jacobian: only its solve is checked
  for (unsigned int b = 0; b < 3 && shift == 0; ++b)
    {
      const double rel =
        ops.dual_norm(difference.block(b)) / ops.dual_norm(jx.block(b));
      Testing::log() << "  block " << b << ": |J x - FD| / |J x| "
                     << (rel < 1e-6 ? "< 1e-6" : "TOO LARGE") << std::endl;
      if (rel >= 1e-6)
        Testing::log() << "    value " << rel << std::endl;
    }

  // Newton solve: J dz = -r
  scheme.residual(z, r);
  if (shift > 0)
    scheme.solve_shifted_jacobian(z, r, dz, solver, shift);
  else
    scheme.solve_jacobian(z, r, dz, solver);
  scheme.jacobian_vmult(z, dz, jx, shift);
  jx += r;
  const double rel = scheme.residual_norm(jx) / scheme.residual_norm(r);
  Testing::log() << "  |J dz + R| / |R| "
                 << (rel < 1e-6 ? "< 1e-6" : "TOO LARGE") << std::endl;
  if (rel >= 1e-6)
    Testing::log() << "    value " << rel << std::endl;

  if (eta == 0)
    return;
  // gradient of the reduced outer energy: V and P re-solved for every U
  BlockVector y(z);
  y.block(Field::U) = z.block(Field::U);
  scheme.solve_inner_problem(y, solver, 1e-13);
  scheme.residual(y, r);
  const double slope     = r.block(Field::U) * x.block(Field::U);
  const auto   energy_at = [&](const double s) {
    BlockVector trial(y);
    trial.block(Field::U).add(s, x.block(Field::U));
    scheme.solve_inner_problem(trial, solver, 1e-13);
    return scheme.outer_energy(trial);
  };
  const double fd_step = 1e-5;
  const double fd = (energy_at(fd_step) - energy_at(-fd_step)) / (2 * fd_step);
  const double gradient_error = std::abs(fd - slope) / std::abs(slope);
  Testing::log() << "  |d energy/dU x - R_U.x| / |R_U.x| "
                 << (gradient_error < 1e-6 ? "< 1e-6" : "TOO LARGE")
                 << std::endl;
  if (gradient_error >= 1e-6)
    Testing::log() << "    value " << gradient_error << std::endl;
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check<2>(LinearSolverType::direct);
  check<2>(LinearSolverType::direct, 1.);
  check<2>(LinearSolverType::direct, 1., false, 3.);
  check<2>(LinearSolverType::direct, 10., true);
  check<2>(LinearSolverType::direct, 10., true, 3.);
  check<3>(LinearSolverType::direct);
  check<3>(LinearSolverType::iterative);
}
