// edge_restoration of the damaged circle (thesis Fig. 5.6) on a small
// adaptive mesh: the weighted energy W + eta A decreases at every step, U
// outside the restoration region stays at the input image, and the
// restored phase field is close to the intact circle's, tanh(d/eps) of the
// circle before the damage: its L2 distance to it is below a quarter of
// the damaged input's (a solver that does nothing keeps the whole
// distance). The .mpirun=2 variant checks that 2 ranks give the same table.

#include <deal.II/numerics/vector_tools.h>

#include <phasefield/geometry/shapes.h>

#include "tests.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  dealii::ParameterHandler prm;
  PhaseField::EdgeRestorationParameters::declare_parameters(prm);
  prm.parse_input_from_string(R"(
set Dimension = 2
subsection Geometry
  set Shape  = damaged circle
  set Center = 0.5, 0
  set Radius = 0.45
end
subsection Restoration
  set Eta    = 1
  set Region = 0.25, 0.25, 0.75, 0.75
  set Damage = 0.375, 0.3, 0.625, 0.6
  set Picture resolution = 64
end
subsection Mesh
  set Finest level = 6
  set Coarsest level = 3
end
subsection Phase field
  set Epsilon = 4*h
end
subsection Time stepping
  set Tau = 0.03*h
  set Inner tau = h^2
  set Number of steps = 2
end
subsection Output
  set VTU interval = 0
end
set Output directory = results
)");
  PhaseField::EdgeRestorationParameters parameters;
  parameters.parse_parameters(prm);
  PhaseField::RestorationProblem problem(parameters);
  problem.run();
  std::vector<std::string> header;
  const auto rows = Testing::read_csv("results/statistics.csv", header);
  Testing::check_restoration_table(rows, header);

  // distance to the intact circle, of the input and of the restored field
  const double eps    = parameters.willmore.model.epsilon;
  const auto  &disc   = problem.get_discretization();
  const auto  &geometry = parameters.willmore.geometry;
  const PhaseField::Shapes::SphereDistance<2> intact(
    PhaseField::Shapes::shape_center<2>(geometry), geometry.radius);
  const PhaseField::Shapes::PhaseFieldProfile<2> intact_u(intact, eps);
  const PhaseField::Shapes::PhaseFieldProfile<2> damaged_u(
    problem.initial_signed_distance(), eps);
  dealii::TrilinosWrappers::MPI::Vector input(problem.state().block(0));
  disc.interpolate(damaged_u, input);
  disc.get_constraints().distribute(input);
  const double before =
    disc.error(input, intact_u, dealii::VectorTools::L2_norm);
  const double after = disc.error(problem.state().block(0),
                                  intact_u,
                                  dealii::VectorTools::L2_norm);
  Testing::log() << "L2 distance to the intact circle below 1/4 of the "
                    "input's: "
                 << (after < 0.25 * before ? "yes" : "NO") << std::endl;
  Testing::log() << "restored.png written: "
                 << (std::ifstream("results/restored.png") ? "yes" : "NO")
                 << std::endl;
}
