// The exact Jacobian of the semi-implicit Du-Liu-Wang scheme
// (SemiImplicitStep::jacobian_vmult) agrees with central finite
// differences of the residual, and the eliminated Newton solve
// (SemiImplicitStep::solve_jacobian) solves J dZ = -R, in 2D and
// 3D, on an adaptive mesh with hanging nodes, with the direct and the
// iterative (GMRES + AMG) linear solver, and in 2D with the stiffness
// matrix integrated by the Gauss-Lobatto rule (the thesis' 5-point matrix
// on uniform meshes).

#include "adaptive_test_mesh.h"
#include "tests.h"

#include <cmath>
#include <deal.II/base/function_lib.h>
#include <deal.II/base/point.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/numerics/vector_tools.h>
#include <phasefield/geometry/shapes.h>
#include <phasefield/schemes/semi_implicit_scheme.h>

using namespace dealii;
using namespace PhaseField;

template <int dim>
void
check(
  const LinearSolverType    solver_type,
  const StiffnessQuadrature stiffness_quadrature = StiffnessQuadrature::gauss)
{
  const MPI_Comm                       comm = MPI_COMM_WORLD;
  const Testing::AdaptiveTestMesh<dim> mesh(stiffness_quadrature);
  const double                         eps         = mesh.eps;
  const double                         h           = mesh.h;
  const auto                          &dof_handler = mesh.dof_handler;
  const auto                          &constraints = mesh.constraints;
  const auto                          &sphere      = mesh.sphere;
  const LumpedOperators<dim>          &ops         = mesh.operators;

  using BlockVector = TrilinosWrappers::MPI::BlockVector;
  const std::vector<IndexSet> parts(2, ops.locally_owned_dofs);
  BlockVector old_state(parts, comm), z(parts, comm), x(parts, comm),
    r(parts, comm), rp(parts, comm), rm(parts, comm), jx(parts, comm),
    dz(parts, comm);
  const Shapes::PhaseFieldProfile<dim> u0(sphere, eps);
  VectorTools::interpolate(dof_handler,
                           u0,
                           old_state.block(SemiImplicitField::U));
  SemiImplicitStep<dim> scheme(mesh.discretization, eps, 0.03 * h, old_state);
  scheme.initialize_f(old_state);
  LinearSolver solver(solver_type, 1e-12, 2000, /*symmetric=*/false);

  // A generic state and direction: smooth perturbations of both fields.
  Functions::CosineFunction<dim> wave;
  TrilinosWrappers::MPI::Vector  w(ops.locally_owned_dofs, comm);
  VectorTools::interpolate(dof_handler, wave, w);
  z = old_state;
  z.block(SemiImplicitField::U).add(0.05, w);
  z.block(SemiImplicitField::F)
    .add(0.5 * z.block(SemiImplicitField::F).linfty_norm(), w);
  for (unsigned int b = 0; b < 2; ++b)
    {
      x.block(b) = w;
      x.block(b) *= (b + 1.);
      ops.zero_constrained(x.block(b));
    }

  // R_F = 0 after initialize_f
  scheme.residual(old_state, r);
  Testing::log() << dim << "D, " << dof_handler.n_dofs() << " DoFs, "
                 << constraints.n_constraints() << " hanging-node constraints"
                 << (constraints.n_constraints() > 0 ? " (> 0)" : "")
                 << (stiffness_quadrature ==
                         StiffnessQuadrature::gauss_lobatto ?
                       ", Gauss-Lobatto stiffness" :
                       "")
                 << std::endl
                 << "  |R_F(U^0, F^0)| "
                 << (ops.dual_norm(r.block(SemiImplicitField::F)) < 1e-10 ?
                       "< 1e-10" :
                       "TOO LARGE")
                 << std::endl;

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
  for (unsigned int b = 0; b < 2; ++b)
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
  scheme.solve_jacobian(z, r, dz, solver);
  scheme.jacobian_vmult(z, dz, jx);
  jx += r;
  const double rel = scheme.residual_norm(jx) / scheme.residual_norm(r);
  Testing::log() << "  |J dz + R| / |R| "
                 << (rel < 1e-6 ? "< 1e-6" : "TOO LARGE") << std::endl;
  if (rel >= 1e-6)
    Testing::log() << "    value " << rel << std::endl;
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check<2>(LinearSolverType::direct);
  check<2>(LinearSolverType::iterative);
  check<2>(LinearSolverType::direct, StiffnessQuadrature::gauss_lobatto);
  check<3>(LinearSolverType::direct);
}
