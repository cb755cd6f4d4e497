// ZeroLevelSurface on the adaptive test mesh (levels 2 to 4 in a band
// around a sphere of radius 0.3 at (0.45, 0.45, 0.45)), for the nodal
// interpolant (hanging-node constraints applied) of two signed distances:
// - the band's own sphere: cut by cells of the finest level only;
// - a sphere of radius 0.3 at (0.6, 0.45, 0.45) and one of radius 0.2 at
//   (0.75, 0.75, 0.75): they leave the band, so cells of levels 3 and 4
//   cut them, across faces with hanging nodes.
// Each surface is written as STL and PLY, read back with VTK's readers
// and must be closed (no boundary or non-manifold edges, Euler
// characteristic 2), with outward normals and the same triangles in both
// files, on 1 and 2 ranks alike. Without the sampling of coarse cells on
// the finest lattice the second surface has holes at the hanging faces.
// The nodal interpolant of a distance cuts inside the sphere by O(h^2):
// area and volume within 5% of the sphere's for the spheres of radius 0.3
// (h = 1/16 where they are cut), within 25% for the corner sphere of
// radius 0.2 at (0.75, 0.75, 0.75), cut by cells of h = 1/8 and 1/16 (a
// surface without a rank's half is 50% off). Last, a field without zero
// writes files without triangles.

#include "adaptive_test_mesh.h"
#include "surface_check.h"
#include "tests.h"

#include <deal.II/base/mpi.h>
#include <filesystem>
#include <phasefield/geometry/shapes.h>
#include <phasefield/mesh/zero_level_surface.h>

namespace
{
  using namespace dealii;

  /** Cut cells per level (all ranks): U changes sign on their vertices. */
  std::vector<unsigned int>
  cut_cells_per_level(const DoFHandler<3>      &dof_handler,
                      const PhaseField::Vector &ghosted_u)
  {
    std::vector<unsigned int> counts(
      dof_handler.get_triangulation().n_global_levels(), 0);
    Vector<double> values(dof_handler.get_fe().n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_values(ghosted_u, values);
          if (*std::min_element(values.begin(), values.end()) <= 0 &&
              *std::max_element(values.begin(), values.end()) >= 0)
            ++counts[cell->level()];
        }
    const int error = MPI_Allreduce(MPI_IN_PLACE,
                                    counts.data(),
                                    counts.size(),
                                    MPI_UNSIGNED,
                                    MPI_SUM,
                                    MPI_COMM_WORLD);
    AssertThrowMPI(error);
    return counts;
  }

  /**
   * Write and check the surface of the distance to the sphere (@p center,
   * @p r) on @p mesh as STL and PLY.
   */
  void
  check(Testing::AdaptiveTestMesh<3> &mesh,
        const Point<3>               &center,
        const double                  r,
        const double                  tolerance,
        const std::string            &name)
  {
    const PhaseField::Shapes::SphereDistance<3> distance(center, r);
    PhaseField::Vector u(mesh.discretization.get_operators().locally_owned_dofs,
                         MPI_COMM_WORLD);
    mesh.discretization.interpolate(distance, u);
    mesh.constraints.distribute(u);
    const PhaseField::Vector ghosted = mesh.discretization.ghosted_copy(u);
    const std::vector<unsigned int> cut =
      cut_cells_per_level(mesh.dof_handler, ghosted);
    Testing::log() << name << ": cut cells per level";
    for (unsigned int level = 0; level < cut.size(); ++level)
      Testing::log() << ' ' << cut[level];
    Testing::log() << std::endl;
    std::filesystem::create_directories("results");
    long triangles[2];
    for (const auto format :
         {PhaseField::SurfaceFormat::stl, PhaseField::SurfaceFormat::ply})
      {
        const std::string filename =
          "results/" + name + "." +
          PhaseField::ZeroLevelSurface::extension(format);
        const PhaseField::ZeroLevelSurface::Summary written =
          PhaseField::ZeroLevelSurface::write(mesh.dof_handler,
                                              ghosted,
                                              format,
                                              filename);
        MPI_Barrier(MPI_COMM_WORLD);
        const Testing::SurfaceMeasures read =
          Testing::check_sphere_surface(filename, r, tolerance);
        triangles[format == PhaseField::SurfaceFormat::ply] = read.triangles;
        Testing::log() << "  as written: " << written.n_triangles
                       << " triangles, area and volume those read back: "
                       << (written.n_triangles == read.triangles &&
                               std::abs(written.area / read.area - 1) < 1e-6 &&
                               std::abs(written.volume / read.volume - 1) <
                                 1e-6 ?
                             "yes" :
                             "NO")
                       << std::endl;
      }
    Testing::log() << "STL and PLY: the same triangles: "
                   << (triangles[0] == triangles[1] ? "yes" : "NO")
                   << std::endl;
  }

  /**
   * A field without zero (U < 0 everywhere: the inside of a sphere that
   * holds the domain) writes files without triangles.
   */
  void
  check_empty(Testing::AdaptiveTestMesh<3> &mesh)
  {
    const PhaseField::Shapes::SphereDistance<3> distance(
      Point<3>(0.5, 0.5, 0.5), 2);
    PhaseField::Vector u(mesh.discretization.get_operators().locally_owned_dofs,
                         MPI_COMM_WORLD);
    mesh.discretization.interpolate(distance, u);
    const PhaseField::Vector ghosted = mesh.discretization.ghosted_copy(u);
    for (const auto format :
         {PhaseField::SurfaceFormat::stl, PhaseField::SurfaceFormat::ply})
      {
        const std::string filename =
          "results/empty." + PhaseField::ZeroLevelSurface::extension(format);
        const PhaseField::ZeroLevelSurface::Summary written =
          PhaseField::ZeroLevelSurface::write(mesh.dof_handler,
                                              ghosted,
                                              format,
                                              filename);
        MPI_Barrier(MPI_COMM_WORLD);
        Testing::log() << filename << " without triangles: "
                       << (written.n_triangles == 0 &&
                               std::filesystem::exists(filename) &&
                               Testing::measure_surface(filename).triangles ==
                                 0 ?
                             "yes" :
                             "NO")
                       << std::endl;
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  Testing::AdaptiveTestMesh<3>     mesh;
  const double                     r = 0.3;
  check(mesh, Testing::AdaptiveTestMesh<3>::center(), r, 0.05, "band_sphere");
  check(mesh, Point<3>(0.6, 0.45, 0.45), r, 0.05, "shifted_sphere");
  check(mesh, Point<3>(0.75, 0.75, 0.75), 0.2, 0.25, "corner_sphere");
  check_empty(mesh);
}
