// The elimination of the monolithic contour step's Jacobian J0 without
// the area term but with the data term H_d in the UU block
// (NestedLinearSystems::solve_without_area_term(): the Schur complement
// S' = S + K M^-1 H_d M^-1 K by CG preconditioned with S^-1). With an
// inner tolerance at round-off it is the exact inverse of J0: for x with
// zero constrained entries, y = J0 x, the elimination applied to y gives
// back x. J0 is the nested step's Jacobian with eta = 0 (no area term),
// the mismatch of Fig. 6.5 as data term (its step model: the
// Gauss-Newton product plus the majoriser's curvature) at a state away
// from U^k, on an adaptive 2D mesh with hanging nodes; for the direct
// (factorised S) and the iterative (product-form S, multigrid
// preconditioner) type, with and without a Levenberg-Marquardt shift.
// Also checked: the data term's share of J0 x is not small (so that an
// elimination without it would not pass).

#include "adaptive_test_mesh.h"
#include "sphere_mismatch.h"
#include "tests.h"

#include <cmath>
#include <phasefield/geometry/huffman_labeling.h>
#include <phasefield/schemes/mismatch_term.h>
#include <phasefield/schemes/nested_scheme.h>

using namespace dealii;
using namespace PhaseField;

namespace
{
  using BlockVector = TrilinosWrappers::MPI::BlockVector;
  using MPIVector   = TrilinosWrappers::MPI::Vector;

  /** The weights of Fig. 6.5. */
  constexpr double gamma_weight    = 10;
  constexpr double willmore_weight = 0.05;
  /** Inner CG tolerance of the exact elimination and its iteration cap. */
  constexpr double       exact_tolerance      = 1e-14;
  constexpr unsigned int exact_max_iterations = 2000;
  /** Relative error of the exact elimination that the test accepts. */
  constexpr double inverse_tolerance = 1e-8;

  template <int dim>
  void
  check(const LinearSolverType solver_type)
  {
    const MPI_Comm                       comm = MPI_COMM_WORLD;
    const Testing::AdaptiveTestMesh<dim> mesh;
    const LumpedOperators<dim>          &ops = mesh.operators;
    const MismatchTerm<dim>              term =
      Testing::sphere_mismatch_term(mesh, gamma_weight);

    NestedCoefficients coeff;
    coeff.epsilon               = mesh.eps;
    coeff.tau                   = 0.03 * mesh.h;
    coeff.inner_tau             = mesh.h * mesh.h;
    coeff.outer.willmore_weight = willmore_weight;
    coeff.outer.area_weight     = 0;
    coeff.outer.data_term       = &term;

    MPIVector old_u(ops.locally_owned_dofs, comm);
    mesh.discretization.interpolate(Shapes::PhaseFieldProfile<dim>(mesh.sphere,
                                                                   mesh.eps),
                                    old_u);
    MPIVector perturbation(old_u);
    Testing::fill_smoothly(perturbation, 0.05, 1.7);
    old_u += perturbation;
    mesh.constraints.distribute(old_u);

    NestedStep<dim> scheme(mesh.discretization, coeff, old_u);
    LinearSolver    solver(solver_type, 1e-12, 2000);
    scheme.set_inner_solver(solver);
    const std::vector<IndexSet> parts(3, ops.locally_owned_dofs);
    BlockVector z(parts, comm), x(parts, comm), y(parts, comm), dz(parts, comm);
    z.block(Field::U) = old_u;
    scheme.initialize_v_and_p(z, solver, 1e-10);
    // a state away from U^k
    MPIVector direction(old_u);
    Testing::fill_smoothly(direction, 0.02, 2.9);
    mesh.constraints.set_zero(direction);
    z.block(Field::U) += direction;
    mesh.constraints.distribute(z.block(Field::U));

    // x: rough, zero at constrained DoFs
    const double frequencies[3] = {2.3, 1.1, 0.7};
    for (unsigned int b = 0; b < 3; ++b)
      {
        Testing::fill_smoothly(x.block(b), 1, frequencies[b]);
        mesh.constraints.set_zero(x.block(b));
      }
    Testing::log() << dim << "D, "
                   << (solver_type == LinearSolverType::direct ? "direct" :
                                                                 "iterative")
                   << ", hanging nodes: "
                   << (mesh.constraints.n_constraints() > 0) << std::endl;

    // the data term's share of J0 x
    NestedCoefficients no_data(coeff);
    no_data.outer.data_term = nullptr;
    const NestedPhysics<dim> physics_without_data(mesh.discretization,
                                                  no_data,
                                                  old_u);
    scheme.jacobian_vmult(z, x, y);
    physics_without_data.jacobian_vmult(z, x, dz);
    dz -= y;
    Testing::log() << "  |H_d x_U| / |J0 x| > 0.1: "
                   << (scheme.residual_norm(dz) > 0.1 * scheme.residual_norm(y))
                   << std::endl;

    NestedLinearSystems<dim> systems(scheme.get_physics());
    for (const double shift : {0., 0.5})
      {
        // the elimination solves J0 dz = -r: r = -J0 x gives dz = x
        scheme.jacobian_vmult(z, x, y, shift);
        y *= -1;
        systems.solve_without_area_term(
          z, y, dz, solver_type, exact_tolerance, exact_max_iterations, shift);
        dz -= x;
        double error = 0, size = 0;
        for (unsigned int b = 0; b < 3; ++b)
          {
            error += ops.mass_product(dz.block(b), dz.block(b));
            size += ops.mass_product(x.block(b), x.block(b));
          }
        Testing::log() << "  shift " << shift
                       << ": |elimination(J0 x) - x| / |x| "
                       << Testing::below(std::sqrt(error / size),
                                         inverse_tolerance)
                       << std::endl;
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check<2>(LinearSolverType::direct);
  check<2>(LinearSolverType::iterative);
}
