// A step whose interface leaves the band of finest cells is repeated on
// the mesh refined there (TimeLoop::advance_on_resolving_mesh()), so that
// an adaptive step is the step of a mesh that resolves its result. The
// damaged circle of parameter_files/edge_restoration/damaged_circle.prm at
// level 7 with a narrow band (Band width 2, margin 0.5): step 1 fills the
// gap of the arc, where the band of the input has coarse cells. The
// weighted energies of steps 1-3 are compared with those on the uniform
// level-7 mesh, measured with
//   mpirun -np 2 build/edge_restoration damaged_circle.prm
//     --set "Mesh/Finest level=7" --set "Mesh/Adaptive=false"
//     --set "Time stepping/Number of steps=3"
// (2026-11-27): 20.895, 20.495, 20.428. Without the repetition the
// adaptive steps gave 22.275, 20.735, 20.503 (6.6%, 1.2%, 0.4% above; the
// re-meshing after step 1 then raised 22.275 to 27.333); with it, 20.947,
// 20.535, 20.469 (0.25%, 0.20%, 0.20% above: the band ends 2 epsilon from
// the interface, the uniform mesh has no such end).
// Step 3 starts from the extrapolation of steps 1 and 2 (doc/willmore_flow.md,
// "Extrapolated start"; 2026-11-28): the same step, reached more closely.
// From the last result the descent method ends stationary to round-off at
// the residual 6.07e-7 (W = 14.83341576, the same with Newton / Tolerance
// 1e-11), from the extrapolation at 2.18e-8 (W = 14.83341557, likewise):
// the expected step-3 values are now the latter.

#include "tests.h"

#include <cmath>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::vector<std::string>                 header;
  const auto                               rows =
    Testing::run_restoration(Testing::damaged_circle_restoration + R"(
subsection Restoration
  set Eta = 4
end
subsection Mesh
  set Finest level = 7
  set Coarsest level = 3
  set Band width = 2
  set Band margin = 0.5
end
subsection Phase field
  set Epsilon = 4*h
end
subsection Time stepping
  set Tau = 0.03*h
  set Inner tau = h^2
  set Number of steps = 3
end
subsection Newton
  set Maximum iterations = 200
end
subsection Output
  set VTU interval = 0
end
)",
                             header);
  Testing::check_restoration_table(rows, header);

  // the uniform mesh's energies (above); 1% lies between the measured
  // deviations with (0.25%) and without (6.6% in step 1) the repetition
  const std::vector<double> uniform_mesh = {20.895, 20.495, 20.428};
  constexpr double          tolerance    = 0.01;
  const int                 energy = Testing::column(header, "weighted_energy");
  bool                      close  = rows.size() == uniform_mesh.size() + 1;
  for (unsigned int i = 0; close && i < uniform_mesh.size(); ++i)
    close = std::abs(rows[i + 1][energy] - uniform_mesh[i]) <=
            tolerance * uniform_mesh[i];
  Testing::log() << "steps 1-3 within 1% of the uniform mesh's weighted "
                    "energy: "
                 << (close ? "yes" : "NO") << std::endl;
}
