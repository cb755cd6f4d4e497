// The semi-implicit Du-Liu-Wang scheme on the quarter circle (r0 = 0.4 at
// the origin) on a small adaptive mesh, with re-meshing after every step:
// Newton converges, the Willmore energy (3/4) w_eps is within 10% of the
// exact pi/(4r) and decreases (w_eps is evaluated through the discrete
// Laplacian in F, whose consistency error is O(h^2/eps^2): 6.7% at
// h = eps/4, where the nested scheme's energy is within 2%), and the radius
// measured by the inside area follows r(t) = (2t + r0^4)^(1/4). The .mpirun=2
// variant checks that 2 ranks give the same table.

#include "tests.h"


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::vector<std::string>                 header;
  const auto                               rows = Testing::run_willmore(R"(
set Dimension = 2
subsection Geometry
  set Shape = quarter circle
  set Radius = 0.4
end
subsection Mesh
  set Finest level = 7
  set Coarsest level = 3
end
subsection Phase field
  set Epsilon = 4*h
end
subsection Time stepping
  set Scheme = semi-implicit
  set Tau = h^2
  set Number of steps = 4
end
subsection Output
  set VTU interval = 2
end
)",
                                          header);
  Testing::print_columns(rows, header, Testing::checked_columns());

  Testing::check_quarter_circle(rows, header, 0.4, 0.10, 0.10);
}
