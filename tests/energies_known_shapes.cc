// Energies of a circle (r = 0.25) at eps = r/10 and h = eps/12.8 (finest
// level 9 in the narrow band): Willmore energy pi/r and length 2 pi r
// within 5%, inside measure pi r^2 within 1%. Also the total lumped mass
// (inside + outside measure) equals the area of the unit square.

#include "tests.h"

#include <cmath>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::vector<std::string> header;
  const auto               rows = Testing::run_willmore(R"(
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
)",
                                               header);
  const double pi = M_PI, r = 0.25;
  const auto & row = rows[0];
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
}
