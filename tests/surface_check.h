// Reading a surface file (STL or PLY) back with VTK's readers and
// measuring it independently of the code that wrote it: triangles,
// area and volume (vtkMassProperties), the signed volume (positive for
// outward normals), boundary and non-manifold edges (vtkFeatureEdges) and
// the Euler characteristic V - E + F.
#ifndef phasefield_tests_surface_check_h
#define phasefield_tests_surface_check_h

#include "tests.h"

#include <filesystem>
#include <set>
#include <string>
#include <utility>
#include <vtkCellArray.h>
#include <vtkFeatureEdges.h>
#include <vtkMassProperties.h>
#include <vtkNew.h>
#include <vtkPLYReader.h>
#include <vtkPolyData.h>
#include <vtkSTLReader.h>
#include <vtkSmartPointer.h>

namespace Testing
{
  /** What the test measures of a surface file. */
  struct SurfaceMeasures
  {
    long   triangles            = 0;
    long   vertices             = 0;
    double area                 = 0;
    double volume               = 0;
    double signed_volume        = 0;
    long   boundary_edges       = 0;
    long   non_manifold_edges   = 0;
    long   euler_characteristic = 0;
  };

  /** The surface in @p filename (.stl or .ply), read by VTK. */
  inline vtkSmartPointer<vtkPolyData>
  read_surface(const std::string &filename)
  {
    if (std::filesystem::path(filename).extension() == ".stl")
      {
        vtkNew<vtkSTLReader> reader;
        reader->SetFileName(filename.c_str());
        reader->Update();
        return reader->GetOutput();
      }
    vtkNew<vtkPLYReader> reader;
    reader->SetFileName(filename.c_str());
    reader->Update();
    return reader->GetOutput();
  }

  /** Sum of the signed volumes of the tetrahedra (origin, triangle). */
  inline double
  signed_volume(vtkPolyData &surface)
  {
    double           volume = 0;
    vtkIdType        n;
    const vtkIdType *ids;
    vtkCellArray    *polygons = surface.GetPolys();
    for (polygons->InitTraversal(); polygons->GetNextCell(n, ids) != 0;)
      {
        double p[3][3];
        for (unsigned int c = 0; c < 3; ++c)
          surface.GetPoint(ids[c], p[c]);
        volume += (p[0][0] * (p[1][1] * p[2][2] - p[1][2] * p[2][1]) -
                   p[0][1] * (p[1][0] * p[2][2] - p[1][2] * p[2][0]) +
                   p[0][2] * (p[1][0] * p[2][1] - p[1][1] * p[2][0])) /
                  6;
      }
    return volume;
  }

  /** Number of distinct edges of the triangles of @p surface. */
  inline long
  count_edges(vtkPolyData &surface)
  {
    std::set<std::pair<vtkIdType, vtkIdType>> edges;
    vtkIdType                                 n;
    const vtkIdType                          *ids;
    vtkCellArray                             *polygons = surface.GetPolys();
    for (polygons->InitTraversal(); polygons->GetNextCell(n, ids) != 0;)
      for (vtkIdType c = 0; c < n; ++c)
        edges.insert(std::minmax(ids[c], ids[(c + 1) % n]));
    return edges.size();
  }

  /**
   * Number of boundary edges (in one triangle; @p boundary) or
   * non-manifold edges (in more than two) of @p surface.
   */
  inline long
  count_feature_edges(vtkPolyData &surface, const bool boundary)
  {
    vtkNew<vtkFeatureEdges> edges;
    edges->SetInputData(&surface);
    edges->FeatureEdgesOff();
    edges->ManifoldEdgesOff();
    edges->SetBoundaryEdges(boundary);
    edges->SetNonManifoldEdges(!boundary);
    edges->Update();
    return edges->GetOutput()->GetNumberOfLines();
  }

  /** The measures of the surface file @p filename. */
  inline SurfaceMeasures
  measure_surface(const std::string &filename)
  {
    const vtkSmartPointer<vtkPolyData> surface = read_surface(filename);
    SurfaceMeasures                    m;
    m.triangles = surface->GetNumberOfPolys();
    m.vertices  = surface->GetNumberOfPoints();
    if (m.triangles == 0)
      return m;
    vtkNew<vtkMassProperties> mass;
    mass->SetInputData(surface);
    mass->Update();
    m.area                 = mass->GetSurfaceArea();
    m.volume               = mass->GetVolume();
    m.signed_volume        = signed_volume(*surface);
    m.boundary_edges       = count_feature_edges(*surface, true);
    m.non_manifold_edges   = count_feature_edges(*surface, false);
    m.euler_characteristic = m.vertices - count_edges(*surface) + m.triangles;
    return m;
  }

  /**
   * Log the measures of @p filename and whether it is a closed sphere of
   * radius @p r: no boundary or non-manifold edges, Euler characteristic
   * 2, outward normals, area and volume within @p tolerance (relative)
   * of 4 pi r^2 and 4/3 pi r^3.
   */
  inline SurfaceMeasures
  check_sphere_surface(const std::string &filename,
                       const double       r,
                       const double       tolerance)
  {
    const SurfaceMeasures m      = measure_surface(filename);
    const double          area   = 4 * M_PI * r * r;
    const double          volume = 4 * M_PI * r * r * r / 3;
    log() << std::filesystem::path(filename).filename().string() << ": "
          << m.triangles << " triangles, " << m.vertices << " vertices\n"
          << "  closed (boundary edges " << m.boundary_edges
          << ", non-manifold edges " << m.non_manifold_edges
          << ", Euler characteristic " << m.euler_characteristic << "): "
          << (m.boundary_edges == 0 && m.non_manifold_edges == 0 &&
                  m.euler_characteristic == 2 ?
                "yes" :
                "NO")
          << "\n  normals outward (signed volume = volume): "
          << (std::abs(m.signed_volume - m.volume) < 1e-9 * volume ? "yes" :
                                                                     "NO")
          << std::setprecision(3)
          << "\n  area / (4 pi r^2) - 1 = " << m.area / area - 1 << ", |.| "
          << below(std::abs(m.area / area - 1), tolerance)
          << "\n  volume / (4/3 pi r^3) - 1 = " << m.volume / volume - 1
          << ", |.| " << below(std::abs(m.volume / volume - 1), tolerance)
          << std::setprecision(6) << std::endl;
    return m;
  }
} // namespace Testing

#endif
