// Willmore flow of a quarter circle (r0 = 0.4 at the origin) on a small
// adaptive mesh: Newton converges in few iterations, the energies are close
// to the exact ones (quarter of pi/r and of 2 pi r), the radius measured by
// the inside area follows r(t) = (2t + r0^4)^(1/4), its growth since step 0
// is that of the exact flow within 10% (a flow at half speed, a solver that
// does nothing or a Willmore term of the wrong sign fail here), and the
// Willmore energy decreases. The .mpirun=2 variant checks that 2 ranks give
// the same table.

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
  set Tau = 0.03*h
  set Inner tau = h^2
  set Number of steps = 4
end
subsection Output
  set VTU interval = 2
end
)",
                                          header);
  Testing::print_columns(rows, header, Testing::checked_columns());

  Testing::check_quarter_circle(rows, header, 0.4, 0.02, 0.10);
}
