#include <algorithm>
#include <array>
#include <cmath>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/data_out.h>
#include <fstream>
#include <iomanip>
#include <phasefield/core/file_io.h>
#include <phasefield/core/statistics.h>
#include <phasefield/geometry/images.h>
#include <phasefield/geometry/surface_picture.h>
#include <phasefield/mesh/zero_level_surface.h>
#include <phasefield/problems/contour_output.h>

namespace PhaseField
{
  namespace ContourOutput
  {
    using namespace dealii;

    namespace
    {
      /** Pictures are at least this many pixels wide. */
      constexpr unsigned int min_picture_width = 512;

      using Colour = std::array<unsigned char, 3>;
      constexpr Colour white{{255, 255, 255}};
      constexpr Colour grid_gray{{200, 200, 200}};
      constexpr Colour target_blue{{0, 60, 255}};
      constexpr Colour current_red{{230, 0, 0}};

      /**
       * The index i_0 + n i_1 of the pixel (of @p n per direction of
       * [0,1]) whose centre is @p p.
       */
      template <int d>
      unsigned int
      pixel_index(const Point<d> &p, const unsigned int n)
      {
        unsigned int index = 0, stride = 1;
        for (unsigned int k = 0; k < d; ++k, stride *= n)
          index += stride * static_cast<unsigned int>(std::floor(p[k] * n));
        return index;
      }

      /** An RGB canvas with rows from the bottom. */
      struct Canvas
      {
        Canvas(const unsigned int nx, const unsigned int ny)
          : nx(nx)
          , ny(ny)
          , rgb(3 * nx * ny, 255)
        {}

        void
        set(const unsigned int x, const unsigned int y, const Colour &c)
        {
          std::copy(c.begin(), c.end(), rgb.begin() + 3 * (y * nx + x));
        }

        unsigned int               nx, ny;
        std::vector<unsigned char> rgb;
      };

      /** Gray value of @p t in [0,1] (0 black). */
      Colour
      gray(const double t)
      {
        const auto g =
          static_cast<unsigned char>(std::lround(255 * std::clamp(t, 0., 1.)));
        return {{g, g, g}};
      }

      /**
       * How far a value may exceed an even label and still be shown at it:
       * alpha[U] overshoots its labels slightly (by 0.017 over label 2 on
       * the torus at level 8), which must not double the gray scale.
       */
      constexpr double label_overshoot = 0.5;

      /** The largest label to show: even, at least 2. */
      template <int dim>
      double
      top_label(const Labelings<dim> &labelings)
      {
        double top = 2;
        for (const auto *values : {&labelings.target, &labelings.alpha})
          for (const double a : *values)
            top = std::max(top, 2 * std::ceil((a - label_overshoot) / 2));
        return top;
      }

      /** Magnification of the pixel grid in the picture. */
      unsigned int
      magnification(const unsigned int n)
      {
        return std::max(1u, min_picture_width / n);
      }

      /**
       * 2D: the phase field sampled at @p width x @p width pixels above a
       * plot of both labelings over the image line.
       */
      void
      draw_2d(const Labelings<2>        &labelings,
              const std::vector<double> &u,
              const unsigned int         width,
              const std::string         &filename)
      {
        const unsigned int n      = labelings.grid.pixels_per_direction();
        const unsigned int scale  = width / n;
        const unsigned int height = width / 2;
        Canvas             canvas(width, height + width);
        for (unsigned int y = 0; y < width; ++y)
          for (unsigned int x = 0; x < width; ++x)
            canvas.set(x, height + y, gray(0.5 * (u[y * width + x] + 1)));
        const double top = top_label(labelings);
        const auto   row = [&](const double a) {
          const long r = std::lround(a / top * (height - 1));
          return static_cast<int>(std::clamp<long>(r, 0, height - 1));
        };
        for (unsigned int label = 0; label <= top; label += 2)
          for (unsigned int x = 0; x < width; ++x)
            canvas.set(x, row(label), grid_gray);
        for (const auto &[values, colour] :
             {std::make_pair(&labelings.target, target_blue),
              std::make_pair(&labelings.alpha, current_red)})
          for (unsigned int x = 0; x < width; ++x)
            {
              // a vertical segment joins the value to that of the last pixel
              const int now  = row((*values)[x / scale]);
              const int last = x == 0 ? now : row((*values)[(x - 1) / scale]);
              for (int y = std::min(now, last); y <= std::max(now, last); ++y)
                canvas.set(x, y, colour);
            }
        Images::write_rgb_png(canvas.rgb, canvas.nx, canvas.ny, filename);
      }

      /**
       * Is pixel @p i on the contour of @p f at level @p c: does f - c
       * change sign to its right or upper neighbour?
       */
      bool
      on_contour(const std::vector<double> &f,
                 const unsigned int         n,
                 const unsigned int         i,
                 const double               c)
      {
        const unsigned int x = i % n, y = i / n;
        const bool         below = f[i] < c;
        return (x + 1 < n && (f[i + 1] < c) != below) ||
               (y + 1 < n && (f[i + n] < c) != below);
      }

      /**
       * 3D: @p shown (a labeling at the pixel centres) in gray with the
       * odd-level contours of alpha* (blue) and, if @p with_current, of
       * alpha[U] (red).
       */
      Canvas
      labeling_canvas(const Labelings<3>        &labelings,
                      const std::vector<double> &shown,
                      const bool                 with_current)
      {
        const unsigned int n     = labelings.grid.pixels_per_direction();
        const unsigned int scale = magnification(n);
        const double       top   = top_label(labelings);
        Canvas             canvas(n * scale, n * scale);
        for (unsigned int y = 0; y < canvas.ny; ++y)
          for (unsigned int x = 0; x < canvas.nx; ++x)
            {
              const unsigned int i = (y / scale) * n + x / scale;
              Colour             c = gray(shown[i] / top);
              // the line at the upper/right edge of the pixel block
              const bool edge =
                (x + 1) % scale == 0 || (y + 1) % scale == 0 || scale == 1;
              for (double level = 1; level < top; level += 2)
                {
                  if (with_current && edge &&
                      on_contour(labelings.alpha, n, i, level))
                    c = current_red;
                  if (edge && on_contour(labelings.target, n, i, level))
                    c = target_blue;
                }
              canvas.set(x, y, c);
            }
        return canvas;
      }

      /** 3D: alpha[U] in gray with the odd-level contours of both. */
      void
      draw_3d(const Labelings<3> &labelings, const std::string &filename)
      {
        const Canvas canvas = labeling_canvas(labelings, labelings.alpha, true);
        Images::write_rgb_png(canvas.rgb, canvas.nx, canvas.ny, filename);
      }

      /**
       * The picture of the @p triangles of the body (left) beside the
       * target labeling (right), both as high as the labeling's canvas.
       */
      void
      draw_body(const Labelings<3>        &labelings,
                const std::vector<double> &triangles,
                const std::string         &filename)
      {
        const Canvas target =
          labeling_canvas(labelings, labelings.target, false);
        const std::vector<unsigned char> body =
          SurfacePicture::render(triangles, target.nx, target.ny);
        Canvas            both(2 * target.nx, target.ny);
        const std::size_t row = 3 * std::size_t(target.nx);
        for (unsigned int y = 0; y < target.ny; ++y)
          {
            auto out = both.rgb.begin() + 2 * row * y;
            std::copy_n(body.begin() + row * y, row, out);
            std::copy_n(target.rgb.begin() + row * y, row, out + row);
          }
        Images::write_rgb_png(both.rgb, both.nx, both.ny, filename);
      }
    } // namespace



    template <int dim>
    void
    write_csv(const Labelings<dim> &labelings,
              const std::string    &filename,
              const MPI_Comm        comm)
    {
      run_on_root(comm, [&]() {
        write_checked(filename, [&](std::ostream &file) {
          file << (dim == 2 ? "x," : "x,y,") << "alpha_target,alpha\n"
               << std::setprecision(10);
          for (unsigned int i = 0; i < labelings.grid.size(); ++i)
            {
              const Point<dim - 1> p = labelings.grid.point(i);
              for (unsigned int k = 0; k + 1 < dim; ++k)
                file << p[k] << ',';
              file << labelings.target[i] << ',' << labelings.alpha[i] << '\n';
            }
        });
      });
    }



    template <int dim>
    void
    write_vtu(const Labelings<dim> &labelings,
              const std::string    &filename,
              const MPI_Comm        comm)
    {
      const HuffmanLabeling::LabelingGrid<dim> &grid = labelings.grid;
      const unsigned int                        n = grid.pixels_per_direction();
      AssertThrow(n > 1 && grid.size() == grid.n_pixels_total(),
                  ExcMessage("The labeling VTU needs one point per pixel "
                             "and at least two pixels per direction."));
      run_on_root(comm, [&]() {
        // the pixel centres as the vertices of a Q1 mesh of the image
        // plane, embedded in the domain's space at x_dim = 0
        const double   h = 1.0 / n;
        Point<dim - 1> first, last;
        for (unsigned int k = 0; k + 1 < dim; ++k)
          {
            first[k] = 0.5 * h;
            last[k]  = 1 - 0.5 * h;
          }
        Triangulation<dim - 1, dim> plane;
        GridGenerator::subdivided_hyper_rectangle(
          plane, std::vector<unsigned int>(dim - 1, n - 1), first, last);
        const FE_Q<dim - 1, dim> fe(1);
        DoFHandler<dim - 1, dim> dof_handler(plane);
        dof_handler.distribute_dofs(fe);
        // pixel (i_0, i_1) has the point index i_0 + n i_1 (x fastest)
        std::vector<unsigned int> point_of_pixel(grid.size());
        for (unsigned int i = 0; i < grid.size(); ++i)
          point_of_pixel[pixel_index(grid.point(i), n)] = i;
        dealii::Vector<double> target(dof_handler.n_dofs()),
          alpha(target.size());
        for (const auto &cell : dof_handler.active_cell_iterators())
          for (const unsigned int v : cell->vertex_indices())
            {
              Point<dim - 1> p;
              for (unsigned int k = 0; k + 1 < dim; ++k)
                p[k] = cell->vertex(v)[k];
              const unsigned int i   = point_of_pixel[pixel_index(p, n)];
              const auto         dof = cell->vertex_dof_index(v, 0);
              target[dof]            = labelings.target[i];
              alpha[dof]             = labelings.alpha[i];
            }
        DataOut<dim - 1, dim> data_out;
        data_out.attach_dof_handler(dof_handler);
        data_out.add_data_vector(target, "alpha_target");
        data_out.add_data_vector(alpha, "alpha");
        data_out.build_patches();
        write_checked(filename,
                      [&](std::ostream &file) { data_out.write_vtu(file); });
      });
    }



    template <int dim>
    void
    write_picture(const Labelings<dim>      &labelings,
                  const Discretization<dim> &discretization,
                  const Vector              &u,
                  const std::string         &filename)
    {
      const MPI_Comm comm = discretization.get_mpi_communicator();
      if constexpr (dim == 2)
        {
          const unsigned int width =
            labelings.grid.pixels_per_direction() *
            magnification(labelings.grid.pixels_per_direction());
          const std::vector<double> samples =
            Images::sample_on_pixel_grid(discretization.get_dof_handler(),
                                         u,
                                         width);
          run_on_root(comm,
                      [&]() { draw_2d(labelings, samples, width, filename); });
        }
      else
        {
          (void)u;
          run_on_root(comm, [&]() { draw_3d(labelings, filename); });
        }
    }



    void
    write_body_picture(const Labelings<3>  &labelings,
                       const DoFHandler<3> &dof_handler,
                       const Vector        &ghosted_u,
                       const std::string   &filename)
    {
      const std::vector<double> triangles =
        ZeroLevelSurface::gathered_triangles(dof_handler, ghosted_u);
      run_on_root(ghosted_u.get_mpi_communicator(),
                  [&]() { draw_body(labelings, triangles, filename); });
    }



    template void
    write_csv(const Labelings<2> &, const std::string &, const MPI_Comm);
    template void
    write_csv(const Labelings<3> &, const std::string &, const MPI_Comm);
    template void
    write_vtu(const Labelings<2> &, const std::string &, const MPI_Comm);
    template void
    write_vtu(const Labelings<3> &, const std::string &, const MPI_Comm);
    template void
    write_picture(const Labelings<2> &,
                  const Discretization<2> &,
                  const Vector &,
                  const std::string &);
    template void
    write_picture(const Labelings<3> &,
                  const Discretization<3> &,
                  const Vector &,
                  const std::string &);
  } // namespace ContourOutput
} // namespace PhaseField
