// U held fixed outside the restoration region (thesis Definition 5.1):
// after a run with re-meshing in every step, U at every unconstrained DoF
// outside the open region equals the input phase field tanh(d/eps) at its
// support point bit for bit, while U inside the region has changed.

#include "tests.h"

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/mapping_q1.h>
#include <map>
#include <phasefield/geometry/images.h>
#include <phasefield/geometry/shapes.h>
#include <phasefield/problems/restoration_problem.h>

int
main(int argc, char **argv)
{
  using namespace dealii;
  using namespace PhaseField;
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  ParameterHandler prm;
  EdgeRestorationParameters::declare_parameters(prm);
  prm.parse_input_from_string(R"(
set Dimension = 2
set Output directory = results
subsection Geometry
  set Shape  = bar
  set Center = 0, 0.5
  set Sizes  = 1, 0.125
end
subsection Restoration
  set Eta    = 0.1
  set Region = 0.25, 0.25, 0.75, 0.75
end
subsection Mesh
  set Finest level = 6
  set Coarsest level = 2
end
subsection Time stepping
  set Tau = 0.03*h
  set Inner tau = h^2
  set Number of steps = 3
end
subsection Output
  set VTU interval = 0
end
)");
  EdgeRestorationParameters parameters;
  parameters.parse_parameters(prm);
  // the problem edge_restoration runs
  RestorationProblem problem(parameters);
  problem.run();

  const Box2D &region      = parameters.restoration.region;
  const auto  &dof_handler = problem.get_discretization().get_dof_handler();
  const auto  &constraints = problem.get_discretization().get_constraints();
  std::map<types::global_dof_index, Point<2>> points;
  DoFTools::map_dofs_to_support_points(MappingQ1<2>(), dof_handler, points);
  const Shapes::PhaseFieldProfile<2> u0(problem.initial_signed_distance(),
                                        parameters.willmore.model.epsilon);
  const auto                        &u = problem.state().block(0);

  unsigned int n_outside = 0, n_changed_outside = 0, n_changed_inside = 0;
  for (const auto &[dof, point] : points)
    if (u.locally_owned_elements().is_element(dof) &&
        !constraints.is_constrained(dof))
      {
        const bool changed = (u[dof] != u0.value(point));
        if (region.contains(point))
          n_changed_inside += changed;
        else
          {
            ++n_outside;
            n_changed_outside += changed;
          }
      }
  const MPI_Comm comm = MPI_COMM_WORLD;
  n_outside           = Utilities::MPI::sum(n_outside, comm);
  n_changed_outside   = Utilities::MPI::sum(n_changed_outside, comm);
  n_changed_inside    = Utilities::MPI::sum(n_changed_inside, comm);
  Testing::log() << "DoFs outside the region: "
                 << (n_outside > 100 ? "> 100" : "TOO FEW") << '\n'
                 << "of them changed: " << n_changed_outside << '\n'
                 << "DoFs inside the region changed: "
                 << (n_changed_inside > 100 ? "> 100" : "TOO FEW") << std::endl;
}
