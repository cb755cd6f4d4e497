// ZeroLevelSurface on the adaptive test mesh (levels 2 to 4 in a band
// around a sphere of radius 0.3 at (0.45, 0.45, 0.45)), for the nodal
// interpolant (hanging-node constraints applied) of two signed distances:
// - the band's own sphere: cut by cells of the finest level only;
// - a sphere of radius 0.3 at (0.6, 0.45, 0.45): it leaves the band, so
//   cells of all three levels cut it and it crosses faces with hanging
//   nodes.
// Each surface is written as STL and PLY, read back with VTK's readers
// and must be closed (no boundary or non-manifold edges, Euler
// characteristic 2), with outward normals and the same triangles in both
// files, on 1 and 2 ranks alike. Without the sampling of coarse cells on
// the finest lattice the second surface has holes at the hanging faces.
// Area and volume: within 1% of the sphere's where h = 1/16 (r/h = 4.8),
// within 5% where cells of h = 1/4 cut it.

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
    return Utilities::MPI::sum(counts, MPI_COMM_WORLD);
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
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  Testing::AdaptiveTestMesh<3>     mesh;
  const double                     r = 0.3;
  check(mesh, Testing::AdaptiveTestMesh<3>::center(), r, 0.01, "band_sphere");
  check(mesh, Point<3>(0.6, 0.45, 0.45), r, 0.05, "shifted_sphere");
}
