// One step of the augmented-Lagrangian scheme equals one step of the
// nested Newton scheme: U and V agree to 1e-8 relative in the L2 norm, and
// the step moved U by much more than that (a solver that does nothing
// would fail).
// - 2D, thesis Table 7.2 setting: quarter circle r = 0.4, h = 2^-6
//   uniform, eps = 0.0625, tau = 0.03 h, inner tau = h^2, direct solver
//   (the Schur complement S_V factorised).
// - 3D: octant of a sphere r = 0.35, h = 2^-4 uniform, eps = 2h,
//   tau = 0.03 h, inner tau = h^2, iterative solver (S_V in product form
//   with algebraic multigrid); the trust region must also need fewer than
//   10 CG iterations per iteration on average (block Jacobi, the earlier
//   preconditioner, needed hundreds at large penalties).
// - 3D again with the matrix-free backend (the stiffness operator applied
//   cell by cell, S_V preconditioned with geometric multigrid): the same
//   agreement and the same bound on the CG iterations.
// Both schemes are made by create_time_stepping_scheme() from the same
// SchemeSettings but for the scheme.

#include "tests.h"

#include <cmath>
#include <cstdlib>
#include <deal.II/base/timer.h>
#include <deal.II/numerics/vector_tools.h>
#include <iostream>
#include <phasefield/geometry/shapes.h>
#include <phasefield/schemes/augmented_lagrangian_parameters.h>
#include <phasefield/schemes/nested_scheme.h>
#include <phasefield/schemes/scheme_registry.h>

using namespace dealii;
using namespace PhaseField;
using TBlockVector = TrilinosWrappers::MPI::BlockVector;
using TVector      = TrilinosWrappers::MPI::Vector;

namespace
{
  /** The agreement the issue asks for. */
  constexpr double agreement = 1e-8;

  /** Both tolerances of the augmented Lagrangian in this test. */
  constexpr double al_tolerance = 1e-10;

  /** Bound on the mean CG iterations per trust-region iteration in 3D. */
  constexpr double max_cg_per_trust_region = 10;

  SchemeSettings
  settings(const std::string  &scheme,
           const double        h,
           const double        epsilon,
           const SolverChoice &solver)
  {
    AugmentedLagrangianParameters al;
    al.gradient_tolerance   = al_tolerance;
    al.constraint_tolerance = al_tolerance;
    SchemeSettings s;
    s.scheme                           = {scheme, al};
    s.epsilon                          = epsilon;
    s.inner_tau                        = h * h;
    s.newton.relative_tolerance        = 1e-12;
    s.newton.absolute_tolerance        = 0;
    s.newton.max_iterations            = 30;
    s.newton.max_damping_steps         = 10;
    s.newton.watchdog_factor           = 1;
    s.newton.max_step_halvings         = 0;
    s.solver                           = solver;
    s.linear_solver.relative_tolerance = 1e-13;
    s.linear_solver.max_iterations     = 1000;
    s.verbose                          = std::getenv("AL_VERBOSE") != nullptr;
    return s;
  }



  /**
   * One step of both schemes from the profile of a sphere of @p radius
   * at the origin on the uniform mesh of @p level; logs the comparison.
   */
  template <int dim>
  void
  compare(const unsigned int     level,
          const double           radius,
          const double           epsilon,
          const LinearSolverType solver,
          const std::string     &backend = OperatorBackendNames::assembled)
  {
    const MPI_Comm comm = MPI_COMM_WORLD;
    const double   h    = std::ldexp(1., -int(level));
    const double   tau  = 0.03 * h;
    const bool     root = Utilities::MPI::this_mpi_process(comm) == 0;
    Testing::log() << dim << "D, "
                   << (solver == LinearSolverType::direct ? "direct" : backend)
                   << std::endl;

    typename Discretization<dim>::Settings mesh_settings{};
    mesh_settings.mesh.finest_level = mesh_settings.mesh.coarsest_level = level;
    mesh_settings.mesh.adaptive                                         = false;
    mesh_settings.mesh.stiffness_quadrature = StiffnessQuadrature::gauss;
    mesh_settings.solver                    = {solver, backend};
    Discretization<dim> discretization(mesh_settings, comm);
    discretization.create_mesh(nullptr, 1.);
    const LumpedOperators<dim> &ops = discretization.get_operators();

    const Shapes::SphereDistance<dim>    sphere(Point<dim>(), radius);
    const Shapes::PhaseFieldProfile<dim> profile(sphere, epsilon);

    std::vector<TBlockVector> results;
    TBlockVector              old_state;
    for (const std::string scheme : {"nested", "augmented lagrangian"})
      {
        const ConditionalOStream quiet(std::cout,
                                       std::getenv("AL_VERBOSE") != nullptr &&
                                         root);
        auto                     s = create_time_stepping_scheme<dim>(
          settings(scheme, h, epsilon, discretization.get_settings().solver),
          discretization,
          quiet);
        TBlockVector state;
        discretization.reinit(state, 3);
        discretization.interpolate(profile, state.block(Field::U));
        discretization.distribute_constraints(state);
        s->initialize(state, tau);
        old_state = state;
        Timer            timer;
        const StepReport report = s->advance(old_state, state, tau);
        if (root)
          std::cout << dim << "D " << s->name() << ": converged "
                    << report.converged << ", newton/trust-region "
                    << report.newton_iterations << ", AL "
                    << report.count("al_iterations") << ", linear "
                    << report.linear_iterations << ", " << timer.wall_time()
                    << " s" << std::endl;
        Testing::log() << s->name() << ": converged "
                       << (report.converged ? "yes" : "NO") << std::endl;
        if (dim == 3 && scheme == "augmented lagrangian")
          Testing::log() << "CG iterations per trust-region iteration "
                         << (report.linear_iterations <
                                 max_cg_per_trust_region *
                                   report.count("tr_iterations") ?
                               "< 10" :
                               "TOO MANY")
                         << std::endl;
        results.push_back(state);
      }

    const auto relative = [&](const unsigned int field, const TBlockVector &a) {
      TVector difference(a.block(field));
      difference -= results[0].block(field);
      return std::sqrt(
        ops.mass_product(difference, difference) /
        ops.mass_product(results[0].block(field), results[0].block(field)));
    };
    for (const unsigned int field : {Field::U, Field::V})
      {
        const double rel = relative(field, results[1]);
        Testing::log() << (field == Field::U ? "U" : "V")
                       << ": |AL - nested| / |nested| "
                       << (rel < agreement ? "< 1e-8" : "TOO LARGE")
                       << std::endl;
        if (root)
          std::cout << "field " << field << ": relative difference " << rel
                    << std::endl;
      }
    const double moved = relative(Field::U, old_state);
    Testing::log() << "the step moved U by "
                   << (moved > 1e3 * agreement ? "> 1e-5" : "TOO LITTLE")
                   << " relative" << std::endl;
    if (root)
      std::cout << "step moved U by " << moved << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  compare<2>(6, 0.4, 0.0625, LinearSolverType::direct);
  compare<3>(4, 0.35, 0.125, LinearSolverType::iterative);
  compare<3>(4,
             0.35,
             0.125,
             LinearSolverType::iterative,
             OperatorBackendNames::matrix_free);
}
