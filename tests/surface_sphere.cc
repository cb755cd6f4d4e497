// willmore_flow with `Output / Surface format`: the sphere of radius 0.3
// (stationary under Willmore flow) on the adaptive mesh of sphere_3d
// (levels 2 to 5, eps = 2h), one step, run once with STL and once with
// PLY surfaces. Each run writes surface_00000 (the initial U) and
// surface_00001 (the last step; VTU interval 0), which are read back with
// VTK's readers: closed (no boundary or non-manifold edges, Euler
// characteristic 2), normals outward, area and volume within 1% of
// 4 pi r^2 and 4/3 pi r^3, the same triangles in the STL and the PLY
// file, and the same on 1 and 2 ranks. The area functional A of the
// phase field (area_energy) agrees with the surface's area within 5% at
// this eps (sphere_3d); the inside measure is larger than the volume by
// the O((eps/r)^2) profile correction (10%), so the surface's volume is
// checked against the sphere's.

#include "surface_check.h"
#include "tests.h"

#include <string>

namespace
{
  const std::string sphere = R"(
set Dimension = 3
subsection Geometry
  set Shape = sphere
  set Radius = 0.3
end
subsection Mesh
  set Finest level = 5
  set Coarsest level = 2
  set Band width = 3
end
subsection Phase field
  set Epsilon = 2*h
end
subsection Time stepping
  set Tau = h^2
  set Inner tau = h^2/4
  set Number of steps = 1
end
subsection Linear solver
  set Maximum iterations = 200
end
)";

  /** The files of a run with surface format @p format. */
  std::vector<long>
  run(const std::string &format)
  {
    const std::string        directory = "results_" + format;
    std::vector<std::string> header;
    const auto               rows =
      Testing::run_willmore(sphere +
                              "subsection Output\n  set VTU interval = 0\n"
                              "  set Surface format = " +
                              format + "\nend\n",
                            header,
                            directory);
    constexpr double  r = 0.3, tolerance = 0.01, area_tolerance = 0.05;
    std::vector<long> triangles;
    for (unsigned int step = 0; step < rows.size(); ++step)
      {
        const Testing::SurfaceMeasures m = Testing::check_sphere_surface(
          directory + "/surface_" + dealii::Utilities::int_to_string(step, 5) +
            "." + format,
          r,
          tolerance);
        const double a = rows[step][Testing::column(header, "area_energy")];
        Testing::log() << "  area / area functional of the phase field - 1: "
                       << Testing::below(std::abs(m.area / a - 1),
                                         area_tolerance)
                       << std::endl;
        triangles.push_back(m.triangles);
      }
    return triangles;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::vector<long>                  stl = run("stl");
  const std::vector<long>                  ply = run("ply");
  Testing::log() << "two surfaces per run, the same triangles in STL and "
                    "PLY: "
                 << (stl.size() == 2 && stl == ply ? "yes" : "NO") << std::endl;
}
