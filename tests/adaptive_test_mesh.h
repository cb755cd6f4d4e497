// The adaptive test mesh of the Jacobian tests: a narrow band around a
// sphere of radius 0.3 at (0.45, ...) with hanging nodes, Q1 DoFs, their
// hanging-node constraints and the lumped operators on them.
#ifndef phasefield_adaptive_test_mesh_h
#define phasefield_adaptive_test_mesh_h

#include <deal.II/distributed/tria.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_q.h>

#include <deal.II/grid/grid_generator.h>

#include <deal.II/lac/affine_constraints.h>

#include <phasefield/lumped_operators.h>
#include <phasefield/narrow_band.h>
#include <phasefield/shapes.h>

namespace Testing
{
  template <int dim>
  struct AdaptiveTestMesh
  {
    /** Interface width used for the band. */
    static constexpr double eps = 1. / 16;
    /** Finest mesh size of the band. */
    static constexpr double h = 1. / (dim == 2 ? 32 : 16);

    /** The mesh, with L integrated by the rule @p stiffness_quadrature. */
    explicit AdaptiveTestMesh(
      const PhaseField::StiffnessQuadrature stiffness_quadrature =
        PhaseField::StiffnessQuadrature::gauss)
      : triangulation(MPI_COMM_WORLD)
      , fe(1)
      , dof_handler(triangulation)
      , sphere(center(), 0.3)
    {
      dealii::GridGenerator::hyper_cube(triangulation, 0., 1.);
      triangulation.refine_global(2);
      PhaseField::NarrowBand::refine_around_zero_level_set(
        triangulation, sphere, 1.5, eps, dim == 2 ? 5 : 4);
      dof_handler.distribute_dofs(fe);
      dealii::IndexSet relevant;
      dealii::DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
      constraints.reinit(relevant);
      dealii::DoFTools::make_hanging_node_constraints(dof_handler,
                                                      constraints);
      constraints.close();
      operators.reinit(dof_handler,
                       constraints,
                       MPI_COMM_WORLD,
                       stiffness_quadrature);
    }

    static dealii::Point<dim>
    center()
    {
      dealii::Point<dim> c;
      for (unsigned int d = 0; d < dim; ++d)
        c[d] = 0.45;
      return c;
    }

    dealii::parallel::distributed::Triangulation<dim> triangulation;
    dealii::FE_Q<dim>                                 fe;
    dealii::DoFHandler<dim>                           dof_handler;
    dealii::AffineConstraints<double>                 constraints;
    const PhaseField::Shapes::SphereDistance<dim>     sphere;
    PhaseField::LumpedOperators<dim>                  operators;
  };
} // namespace Testing

#endif
