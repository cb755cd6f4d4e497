// Energies of a circle (r = 0.25) at eps = r/10 and h = eps/12.8 (finest
// level 9 in the narrow band): Willmore energy pi/r and length 2 pi r
// within 5%, inside measure pi r^2 within 1%. Also the total lumped mass
// on the adaptive mesh with hanging nodes, i.e. inside measure
// Int (1-U)/2 plus outside measure Int (1+U)/2, equals the area 1 of the
// unit square to round-off.

#include "tests.h"

#include <cmath>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  dealii::ParameterHandler                 prm;
  PhaseField::WillmoreFlowParameters::declare_parameters(prm);
  prm.parse_input_from_string(R"(
set Dimension = 2
subsection Geometry
  set Shape = circle
  set Radius = 0.25
end
subsection Mesh
  set Finest level = 9
  set Coarsest level = 4
end
subsection Phase field
  set Epsilon = 0.025
end
subsection Time stepping
  set Tau = h^2
  set Inner tau = h^2
  set Number of steps = 0
end
subsection Output
  set VTU interval = 0
end
set Output directory = results
)");
  PhaseField::WillmoreFlowParameters parameters;
  parameters.parse_parameters(prm);
  PhaseField::WillmoreProblem<2> problem(parameters);
  problem.run();
  std::vector<std::string> header;
  const auto   rows = Testing::read_csv("results/statistics.csv", header);
  const double pi = M_PI, r = 0.25;
  const auto  &row = rows[0];
  const double w   = row[Testing::column(header, "willmore_energy")];
  const double a   = row[Testing::column(header, "area_energy")];
  const double m   = row[Testing::column(header, "inside_measure")];
  Testing::log() << "Willmore energy / (pi/r) = " << w / (pi / r)
                 << (std::abs(w / (pi / r) - 1) < 0.05 ? " (within 5%)" :
                                                         " (NOT within 5%)")
                 << "\nlength / (2 pi r) = " << a / (2 * pi * r)
                 << (std::abs(a / (2 * pi * r) - 1) < 0.05 ? " (within 5%)" :
                                                             " (NOT within 5%)")
                 << "\ninside / (pi r^2) = " << m / (pi * r * r)
                 << (std::abs(m / (pi * r * r) - 1) < 0.01 ? " (within 1%)" :
                                                             " (NOT within 1%)")
                 << std::endl;

  // total lumped mass = inside + outside measure = area of [0,1]^2
  const auto  &mass  = problem.get_discretization().get_operators().lumped_mass;
  const double total = mass.l1_norm();
  Testing::log() << "total lumped mass - 1 "
                 << (std::abs(total - 1) < 1e-12 ? "< 1e-12" : "TOO LARGE")
                 << std::endl;
}
