// The adaptive test mesh of the Jacobian tests: a Discretization with a
// narrow band around a sphere of radius 0.3 at (0.45, ...), hanging nodes,
// Q1 DoFs, their constraints and the lumped operators on them.
#ifndef phasefield_tests_adaptive_test_mesh_h
#define phasefield_tests_adaptive_test_mesh_h

#include <cmath>
#include <deal.II/base/mpi.h>
#include <phasefield/core/parameters.h>
#include <phasefield/geometry/shapes.h>
#include <phasefield/mesh/discretization.h>

namespace Testing
{
  template <int dim>
  struct AdaptiveTestMesh
  {
    /** Interface width used for the band. */
    static constexpr double eps = 1. / 16;
    /** Finest mesh size of the band. */
    static constexpr double h = 1. / (dim == 2 ? 32 : 16);

    /**
     * The mesh, with L integrated by the rule @p stiffness_quadrature and
     * represented by @p backend, with the boundary conditions @p boundary.
     */
    explicit AdaptiveTestMesh(
      const PhaseField::StiffnessQuadrature stiffness_quadrature =
        PhaseField::StiffnessQuadrature::gauss,
      const std::string &backend = PhaseField::OperatorBackendNames::assembled,
      const PhaseField::BoundaryConditions boundary =
        PhaseField::BoundaryConditions::natural)
      : sphere(center(), 0.3)
      , discretization(settings(stiffness_quadrature, backend, boundary),
                       MPI_COMM_WORLD)
      , dof_handler(discretization.get_dof_handler())
      , constraints(discretization.get_constraints())
      , operators(discretization.get_operators())
    {
      discretization.create_mesh(&sphere, eps);
    }

    static dealii::Point<dim>
    center()
    {
      dealii::Point<dim> c;
      for (unsigned int d = 0; d < dim; ++d)
        c[d] = 0.45;
      return c;
    }

    /** Levels 2 to 5 (2D) or 4 (3D), band of 1.5 eps. */
    static typename PhaseField::Discretization<dim>::Settings
    settings(const PhaseField::StiffnessQuadrature stiffness_quadrature,
             const std::string                    &backend,
             const PhaseField::BoundaryConditions  boundary)
    {
      typename PhaseField::Discretization<dim>::Settings s{};
      s.solver.type               = PhaseField::LinearSolverType::iterative;
      s.solver.backend            = backend;
      s.boundary_conditions       = boundary;
      s.mesh.coarsest_level       = 2;
      s.mesh.finest_level         = dim == 2 ? 5 : 4;
      s.mesh.adaptive             = true;
      s.mesh.band_width           = 1.5;
      s.mesh.stiffness_quadrature = stiffness_quadrature;
      return s;
    }

    const PhaseField::Shapes::SphereDistance<dim> sphere;
    PhaseField::Discretization<dim>               discretization;
    const dealii::DoFHandler<dim>                &dof_handler;
    const dealii::AffineConstraints<double>      &constraints;
    const PhaseField::LumpedOperators<dim>       &operators;
  };
  /**
   * v_i = amplitude sin(frequency i + 0.3) at every locally owned DoF i: a
   * smooth deterministic field, the same on every number of ranks.
   */
  inline void
  fill_smoothly(dealii::TrilinosWrappers::MPI::Vector &v,
                const double                           amplitude,
                const double                           frequency)
  {
    for (const auto i : v.locally_owned_elements())
      v(i) = amplitude * std::sin(frequency * i + 0.3);
    v.compress(dealii::VectorOperation::insert);
  }
} // namespace Testing

#endif
