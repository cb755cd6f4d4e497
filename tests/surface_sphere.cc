// willmore_flow with `Output / Surface format`: the sphere of radius 0.3
// (stationary under Willmore flow) on the adaptive mesh of sphere_3d
// (levels 2 to 5, eps = 2h), one step, run once with STL and once with
// PLY surfaces. The STL run (VTU interval 1) writes surface_00000.stl
// (the initial U) and surface_00001.stl, the PLY run (VTU interval 0)
// only the last step's surface_00001.ply. Each file is read back with
// VTK's readers: closed (no boundary or non-manifold edges, Euler
// characteristic 2), normals outward, area and volume within 1% of
// 4 pi r^2 and 4/3 pi r^3, the same triangles in the STL and the PLY
// file, and the same on 1 and 2 ranks. The area functional A of the
// phase field (area_energy) agrees with the surface's area within 1%
// (the largest difference, at step 0, is 0.44%); the inside measure is
// larger than the volume by the O((eps/r)^2) profile correction (10%),
// so the surface's volume is checked against the sphere's.

#include "surface_check.h"
#include "tests.h"

#include <filesystem>
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

  /** surface_<step>.<format> in @p directory. */
  std::string
  surface_file(const std::string &directory,
               const unsigned int step,
               const std::string &format)
  {
    return directory + "/surface_" + dealii::Utilities::int_to_string(step, 5) +
           "." + format;
  }

  /**
   * Run with `Surface format` @p format and `VTU interval` @p interval
   * and check the surface of each step that has a file; returns the
   * triangles of the last step's surface.
   */
  long
  run(const std::string &format, const unsigned int interval)
  {
    const std::string directory = "results_" + format;
    // no file of an earlier run of the test
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::filesystem::remove_all(directory);
    MPI_Barrier(MPI_COMM_WORLD);
    std::vector<std::string> header;
    const auto               rows =
      Testing::run_willmore(sphere +
                              "subsection Output\n  set VTU interval = " +
                              std::to_string(interval) +
                              "\n  set Surface format = " + format + "\nend\n",
                            header,
                            directory);
    constexpr double r = 0.3, tolerance = 0.01, area_tolerance = 0.01;
    const bool       first_written =
      std::filesystem::exists(surface_file(directory, 0, format));
    Testing::log() << "VTU interval " << interval << ": a surface of step 0: "
                   << (first_written ? "yes" : "no") << std::endl;
    long triangles = 0;
    for (unsigned int step = first_written ? 0 : 1; step < rows.size(); ++step)
      {
        const Testing::SurfaceMeasures m =
          Testing::check_sphere_surface(surface_file(directory, step, format),
                                        r,
                                        tolerance);
        const double a = rows[step][Testing::column(header, "area_energy")];
        Testing::log() << std::setprecision(3)
                       << "  area / area functional of the phase field - 1 = "
                       << m.area / a - 1 << ", |.| "
                       << Testing::below(std::abs(m.area / a - 1),
                                         area_tolerance)
                       << std::setprecision(6) << std::endl;
        triangles = m.triangles;
      }
    return triangles;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  // the output steps and the last one
  const long stl = run("stl", 1);
  // the last step only
  const long ply = run("ply", 0);
  Testing::log() << "the last step's triangles the same in STL and PLY: "
                 << (stl > 0 && stl == ply ? "yes" : "NO") << std::endl;
}
