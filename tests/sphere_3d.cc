// Willmore flow of a sphere and a quarter cylinder in 3D with the
// iterative solver on the assembled stiffness matrix (CG + AMG); the
// checks are in sphere_3d.h.

#include "sphere_3d.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  Testing::check_sphere_3d("iterative");
}
