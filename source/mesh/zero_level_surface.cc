#include <algorithm>
#include <array>
#include <cerrno>
#include <cstdint>
#include <deal.II/base/exceptions.h>
#include <deal.II/base/geometry_info.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/grid/tria.h>
#include <filesystem>
#include <fstream>
#include <phasefield/core/file_io.h>
#include <phasefield/core/statistics.h>
#include <phasefield/geometry/surface_picture.h>
#include <phasefield/mesh/zero_level_surface.h>
#include <vtkCellArray.h>
#include <vtkCleanPolyData.h>
#include <vtkContourFilter.h>
#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkPLYWriter.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSTLWriter.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>

namespace PhaseField
{
  namespace ZeroLevelSurface
  {
    using namespace dealii;

    namespace
    {
      /** Coordinates per triangle: three corners in 3D. */
      constexpr unsigned int triangle_size = 9;

      /**
       * Corners closer than this fraction of the diagonal of the
       * surface's bounding box are one vertex: far above the round-off
       * by which the edge crossings that two cells (or a cell and the
       * constraints of a hanging node) compute for one edge may differ,
       * far below the size of the finest cells.
       */
      constexpr double merge_tolerance = 1e-10;

      /** Bytes of a binary STL file: header, count, 50 per triangle. */
      std::uintmax_t
      stl_file_size(const std::size_t n_triangles)
      {
        constexpr std::uintmax_t header_bytes = 84, triangle_bytes = 50;
        return header_bytes + triangle_bytes * n_triangles;
      }

      /**
       * The trilinear interpolant of the 8 @p corners (deal.II's
       * lexicographic vertex order) at the reference point (@p x, @p y,
       * @p z), interpolated in x, then y, then z with weights (1 - t, t),
       * so that a point on a face depends only on the face's 4 corners.
       */
      template <typename T>
      T
      trilinear(const std::array<T, 8> &corners,
                const double            x,
                const double            y,
                const double            z)
      {
        const auto lerp = [](const T &a, const T &b, const double t) {
          return (1 - t) * a + t * b;
        };
        const T bottom = lerp(lerp(corners[0], corners[1], x),
                              lerp(corners[2], corners[3], x),
                              y);
        const T top    = lerp(lerp(corners[4], corners[5], x),
                           lerp(corners[6], corners[7], x),
                           y);
        return lerp(bottom, top, z);
      }

      /**
       * Add the (@p n + 1)^3 lattice points of the cell with @p vertices
       * and U values @p values to @p grid (points, scalars) and its n^3
       * sub-cells as hexahedra.
       */
      void
      add_sampled_cell(const std::array<Point<3>, 8> &vertices,
                       const std::array<double, 8>   &values,
                       const unsigned int             n,
                       vtkPoints                     &points,
                       vtkDoubleArray                &scalars,
                       vtkUnstructuredGrid           &grid)
      {
        const vtkIdType first = points.GetNumberOfPoints();
        for (unsigned int k = 0; k <= n; ++k)
          for (unsigned int j = 0; j <= n; ++j)
            for (unsigned int i = 0; i <= n; ++i)
              {
                const double x = double(i) / n, y = double(j) / n,
                             z   = double(k) / n;
                const Point<3> p = trilinear(vertices, x, y, z);
                points.InsertNextPoint(p[0], p[1], p[2]);
                scalars.InsertNextValue(trilinear(values, x, y, z));
              }
        const auto id = [&](const unsigned int i,
                            const unsigned int j,
                            const unsigned int k) -> vtkIdType {
          return first + i + (n + 1) * (j + (n + 1) * k);
        };
        for (unsigned int k = 0; k < n; ++k)
          for (unsigned int j = 0; j < n; ++j)
            for (unsigned int i = 0; i < n; ++i)
              {
                // VTK's hexahedron: the bottom face counter-clockwise,
                // then the top face
                const vtkIdType hexahedron[8] = {id(i, j, k),
                                                 id(i + 1, j, k),
                                                 id(i + 1, j + 1, k),
                                                 id(i, j + 1, k),
                                                 id(i, j, k + 1),
                                                 id(i + 1, j, k + 1),
                                                 id(i + 1, j + 1, k + 1),
                                                 id(i, j + 1, k + 1)};
                grid.InsertNextCell(VTK_HEXAHEDRON, 8, hexahedron);
              }
      }

      /**
       * The corners of the triangles of @p surface, 9 coordinates per
       * triangle, in the order of @p surface (reversed if @p reverse).
       */
      std::vector<double>
      corner_coordinates(vtkPolyData &surface, const bool reverse = false)
      {
        std::vector<double> coordinates;
        vtkCellArray       *polygons = surface.GetPolys();
        coordinates.reserve(triangle_size * polygons->GetNumberOfCells());
        vtkIdType        n_corners;
        const vtkIdType *corners;
        for (polygons->InitTraversal();
             polygons->GetNextCell(n_corners, corners) != 0;)
          {
            Assert(n_corners == 3, ExcInternalError());
            for (const int c : reverse ? std::array<int, 3>{{0, 2, 1}} :
                                         std::array<int, 3>{{0, 1, 2}})
              {
                double p[3];
                surface.GetPoint(corners[c], p);
                coordinates.insert(coordinates.end(), p, p + 3);
              }
          }
        return coordinates;
      }



      /**
       * All ranks' @p local triangles on rank 0, one rank after the other
       * (empty on the other ranks). Collective.
       */
      std::vector<double>
      gather_on_root(const std::vector<double> &local,
                     const MPI_Comm             mpi_communicator)
      {
        const int              n_local = static_cast<int>(local.size());
        const std::vector<int> counts =
          Utilities::MPI::gather(mpi_communicator, n_local, 0);
        std::vector<int> offsets(counts.size(), 0);
        for (unsigned int r = 1; r < counts.size(); ++r)
          offsets[r] = offsets[r - 1] + counts[r - 1];
        std::vector<double> all(
          counts.empty() ? 0 : std::size_t(offsets.back()) + counts.back());
        const int error = MPI_Gatherv(local.data(),
                                      n_local,
                                      MPI_DOUBLE,
                                      all.data(),
                                      counts.data(),
                                      offsets.data(),
                                      MPI_DOUBLE,
                                      0,
                                      mpi_communicator);
        AssertThrowMPI(error);
        return all;
      }

      /**
       * The surface of the triangles @p coordinates (9 per triangle) with
       * their common corners merged and degenerate triangles removed.
       */
      vtkSmartPointer<vtkPolyData>
      merged_surface(const std::vector<double> &coordinates)
      {
        vtkNew<vtkPoints> points;
        points->SetDataTypeToDouble();
        vtkNew<vtkCellArray> triangles;
        for (std::size_t t = 0; t < coordinates.size(); t += triangle_size)
          {
            vtkIdType corners[3];
            for (unsigned int c = 0; c < 3; ++c)
              corners[c] = points->InsertNextPoint(&coordinates[t + 3 * c]);
            triangles->InsertNextCell(3, corners);
          }
        vtkNew<vtkPolyData> soup;
        soup->SetPoints(points);
        soup->SetPolys(triangles);
        vtkNew<vtkCleanPolyData> clean;
        clean->SetInputData(soup);
        clean->PointMergingOn();
        clean->SetTolerance(merge_tolerance);
        // a triangle that merging collapses is dropped, not made a line
        clean->ConvertPolysToLinesOff();
        clean->Update();
        return clean->GetOutput();
      }

      /**
       * Numbers of @p surface's triangles and vertices, its area and the
       * volume it encloses (sum of the signed volumes of the tetrahedra
       * of the origin and each triangle).
       */
      Summary
      summarize(vtkPolyData &surface)
      {
        Summary summary;
        summary.n_triangles                   = surface.GetNumberOfPolys();
        summary.n_vertices                    = surface.GetNumberOfPoints();
        const std::vector<double> coordinates = corner_coordinates(surface);
        for (std::size_t t = 0; t < coordinates.size(); t += triangle_size)
          {
            const Tensor<1, 3> p0(
              {coordinates[t], coordinates[t + 1], coordinates[t + 2]});
            const Tensor<1, 3> p1(
              {coordinates[t + 3], coordinates[t + 4], coordinates[t + 5]});
            const Tensor<1, 3> p2(
              {coordinates[t + 6], coordinates[t + 7], coordinates[t + 8]});
            const Tensor<1, 3> normal = cross_product_3d(p1 - p0, p2 - p0);
            summary.area += 0.5 * normal.norm();
            summary.volume += p0 * cross_product_3d(p1, p2) / 6;
          }
        return summary;
      }



      /**
       * Bytes of the binary PLY file @p filename of @p n_vertices vertices
       * and @p n_triangles triangles as vtkPLYWriter writes it: its header
       * (up to `end_header`), 3 floats per vertex, a count byte and 3
       * indices per triangle. 0 if the file has no complete header.
       */
      std::uintmax_t
      ply_file_size(const std::string &filename,
                    const std::size_t  n_vertices,
                    const std::size_t  n_triangles)
      {
        constexpr std::size_t header_limit = 4096;
        std::ifstream         in(filename, std::ios::binary);
        std::string           header(header_limit, '\0');
        in.read(header.data(), header_limit);
        header.resize(in.gcount());
        const std::string end_of_header = "end_header\n";
        const std::size_t position      = header.find(end_of_header);
        if (position == std::string::npos)
          return 0;
        constexpr std::uintmax_t vertex_bytes   = 3 * sizeof(float);
        constexpr std::uintmax_t triangle_bytes = 1 + 3 * sizeof(std::int32_t);
        return position + end_of_header.size() + vertex_bytes * n_vertices +
               triangle_bytes * n_triangles;
      }

      /**
       * Write @p surface to @p filename by @p writer (a vtkSTLWriter or
       * vtkPLYWriter, binary) and check that the file has the
       * @p expected_size (a function of the file name); throws WriteError
       * otherwise, after removing the file.
       */
      template <typename Writer, typename Size>
      void
      write_checked_by(Writer            &writer,
                       vtkPolyData       &surface,
                       const std::string &filename,
                       const Size        &expected_size)
      {
        writer.SetInputData(&surface);
        writer.SetFileName(filename.c_str());
        writer.SetFileTypeToBinary();
        errno = 0;
        writer.Write();
        const int error = errno;
        // VTK does not report every failed write (a full disk): the file
        // must have all its bytes
        std::error_code size_error;
        const auto      size = std::filesystem::file_size(filename, size_error);
        if (writer.GetErrorCode() != 0 || size_error ||
            size != expected_size(filename))
          {
            std::filesystem::remove(filename, size_error);
            throw WriteError(write_failure_message(filename, error));
          }
      }

      /**
       * Write a surface without triangles to @p filename in @p format
       * (VTK's writers refuse empty data): an ASCII STL file of 0
       * triangles (the binary one the readers take for ASCII) or a PLY
       * file of 0 vertices and 0 faces.
       */
      void
      write_empty_surface(const SurfaceFormat format,
                          const std::string  &filename)
      {
        write_checked(filename, [&](std::ostream &out) {
          if (format == SurfaceFormat::stl)
            out << "solid surface\nendsolid surface\n";
          else
            out << "ply\nformat binary_little_endian 1.0\n"
                << "element vertex 0\nproperty float x\nproperty float y\n"
                << "property float z\nelement face 0\n"
                << "property list uchar int vertex_indices\nend_header\n";
        });
      }

      /** Write @p surface to @p filename in @p format. */
      void
      write_surface(vtkPolyData        &surface,
                    const SurfaceFormat format,
                    const std::string  &filename)
      {
        const std::size_t n_triangles = surface.GetNumberOfPolys();
        const std::size_t n_vertices  = surface.GetNumberOfPoints();
        if (n_triangles == 0)
          write_empty_surface(format, filename);
        else if (format == SurfaceFormat::stl)
          {
            vtkNew<vtkSTLWriter> writer;
            write_checked_by(*writer, surface, filename, [&](const auto &) {
              return stl_file_size(n_triangles);
            });
          }
        else
          {
            vtkNew<vtkPLYWriter> writer;
            writer->SetDataByteOrderToLittleEndian();
            write_checked_by(*writer, surface, filename, [&](const auto &name) {
              return ply_file_size(name, n_vertices, n_triangles);
            });
          }
      }
    } // namespace



    namespace
    {
      /**
       * The locally owned cells of @p dof_handler on which @p ghosted_u
       * has a zero, each sampled on the lattice of the finest level, as
       * hexahedra with the values of U at their points.
       */
      vtkSmartPointer<vtkUnstructuredGrid>
      sampled_cut_cells(const DoFHandler<3> &dof_handler,
                        const Vector        &ghosted_u)
      {
        AssertDimension(dof_handler.get_fe().n_dofs_per_cell(),
                        GeometryInfo<3>::vertices_per_cell);
        const unsigned int finest_level =
          dof_handler.get_triangulation().n_global_levels() - 1;
        vtkNew<vtkPoints> points;
        points->SetDataTypeToDouble();
        vtkNew<vtkDoubleArray> scalars;
        scalars->SetName("U");
        auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
        grid->AllocateEstimate(0, GeometryInfo<3>::vertices_per_cell);
        dealii::Vector<double>  dof_values(GeometryInfo<3>::vertices_per_cell);
        std::array<double, 8>   values;
        std::array<Point<3>, 8> vertices;
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              // Q1: the cell's DoFs are the values at its vertices
              cell->get_dof_values(ghosted_u, dof_values);
              for (unsigned int v = 0; v < 8; ++v)
                {
                  values[v]   = dof_values[v];
                  vertices[v] = cell->vertex(v);
                }
              const auto [minimum, maximum] =
                std::minmax_element(values.begin(), values.end());
              if (*minimum > 0 || *maximum < 0)
                continue;
              add_sampled_cell(vertices,
                               values,
                               1U << (finest_level - cell->level()),
                               *points,
                               *scalars,
                               *grid);
            }
        grid->SetPoints(points);
        grid->GetPointData()->SetScalars(scalars);
        return grid;
      }
    } // namespace



    std::vector<double>
    local_triangles(const DoFHandler<3> &dof_handler, const Vector &ghosted_u)
    {
      const vtkSmartPointer<vtkUnstructuredGrid> grid =
        sampled_cut_cells(dof_handler, ghosted_u);
      if (grid->GetNumberOfCells() == 0)
        return {};
      vtkNew<vtkContourFilter> contour;
      contour->SetInputData(grid);
      contour->SetValue(0, 0.);
      contour->ComputeScalarsOff();
      contour->ComputeNormalsOff();
      contour->GenerateTrianglesOn();
      contour->Update();
      // VTK's marching cubes orients the triangles towards decreasing U
      return corner_coordinates(*contour->GetOutput(), true);
    }



    std::vector<double>
    gathered_triangles(const DoFHandler<3> &dof_handler,
                       const Vector        &ghosted_u)
    {
      return gather_on_root(local_triangles(dof_handler, ghosted_u),
                            ghosted_u.get_mpi_communicator());
    }



    void
    write_picture(const DoFHandler<3> &dof_handler,
                  const Vector        &ghosted_u,
                  const std::string   &filename)
    {
      const std::vector<double> all =
        gathered_triangles(dof_handler, ghosted_u);
      run_on_root(ghosted_u.get_mpi_communicator(),
                  [&]() { SurfacePicture::write(all, filename); });
    }



    std::string
    extension(const SurfaceFormat format)
    {
      Assert(format != SurfaceFormat::none, ExcInternalError());
      return format == SurfaceFormat::stl ? "stl" : "ply";
    }



    Summary
    write(const DoFHandler<3> &dof_handler,
          const Vector        &ghosted_u,
          const SurfaceFormat  format,
          const std::string   &filename)
    {
      const MPI_Comm mpi_communicator = ghosted_u.get_mpi_communicator();
      const std::vector<double> all =
        gathered_triangles(dof_handler, ghosted_u);
      Summary summary;
      run_on_root(mpi_communicator, [&]() {
        const vtkSmartPointer<vtkPolyData> surface = merged_surface(all);
        summary                                    = summarize(*surface);
        write_surface(*surface, format, filename);
      });
      std::array<double, 4> numbers = {{double(summary.n_triangles),
                                        double(summary.n_vertices),
                                        summary.area,
                                        summary.volume}};
      numbers = Utilities::MPI::broadcast(mpi_communicator, numbers, 0);
      return {static_cast<unsigned int>(numbers[0]),
              static_cast<unsigned int>(numbers[1]),
              numbers[2],
              numbers[3]};
    }
  } // namespace ZeroLevelSurface
} // namespace PhaseField
