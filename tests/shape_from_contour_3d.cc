// shape_from_contour in 3D on 2 MPI ranks (thesis Fig. 6.10 setting on
// the coarse level 5): the labeling of a sphere of radius 0.3 seen along
// x_3, from an ellipsoid with semi-axes 0.15, 0.23, 0.23 (mu = 0.0625,
// eta = 0, gamma = 6, tau = inner tau = h^2, eps = 4h). The ellipsoid's
// shadow is too narrow in x_1 (0.15 against 0.3), so the mismatch step
// must widen it: the mismatch falls by a factor 2 in three steps (measured:
// 1.15 -> 0.015), the labeling error falls and the inside measure grows.
// A do-nothing step and a mismatch gradient of the wrong sign fail these.

#include "tests.h"

int
main(int argc, char **argv)
{
  using namespace Testing;
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::vector<std::string>                 header;
  const auto                               rows = run_contour(R"(
set Dimension = 3
subsection Geometry
  set Shape  = ellipsoid
  set Center = 0.5, 0.5, 0.5
  set Sizes  = 0.15, 0.23, 0.23
end
subsection Target
  set Shape  = sphere
  set Radius = 0.3
end
subsection Model
  set Willmore weight = 0.0625
  set Area weight     = 0
  set Mismatch weight = 6
end
subsection Time stepping
  set Tau = h^2
end
subsection Output
  set VTU interval = 0
end
subsection Multilevel
  set Levels          = 5
  set Steps per level = 3
end
)",
                                header);
  const auto get = [&](const unsigned int row, const std::string &name) {
    return rows[row][column(header, name)];
  };
  log() << "rows: " << rows.size() << std::endl;
  log() << "j(step 3) < j(0) / 2: "
        << (get(3, "mismatch_energy") < get(0, "mismatch_energy") / 2)
        << std::endl;
  log() << "inside measure grows: "
        << (get(3, "inside_measure") > get(0, "inside_measure")) << std::endl;
  log() << "labeling error falls: "
        << (get(3, "labeling_error") < get(0, "labeling_error")) << std::endl;
}
