// Willmore flow of a sphere and a quarter cylinder in 3D with
// `Linear solver / Type = matrix-free` (matrix-free operators, CG +
// geometric multigrid): the checks of sphere_3d (sphere_3d.h), and the same
// energies, volumes and errors as the assembled backend within the Newton
// tolerance (the expected output is sphere_3d's, with the Newton
// iterations of this solver where they differ).

#include "sphere_3d.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  Testing::check_sphere_3d("matrix-free");
}
