#include <algorithm>
#include <array>
#include <cmath>
#include <deal.II/base/exceptions.h>
#include <deal.II/base/numbers.h>
#include <deal.II/base/tensor.h>
#include <limits>
#include <phasefield/geometry/images.h>
#include <phasefield/geometry/surface_picture.h>

namespace PhaseField
{
  namespace SurfacePicture
  {
    using namespace dealii;

    namespace
    {
      /** Coordinates per triangle: three corners in 3D. */
      constexpr unsigned int triangle_size = 9;

      /** Gray of a surface facing the light, in [0,1]. */
      constexpr double surface_gray = 0.85;
      /** Share of the light that reaches every side (ambient light). */
      constexpr double ambient = 0.25;
      /**
       * The light's direction in the viewer's frame (right, up, towards
       * the viewer): from the upper left, in front of the surface.
       */
      constexpr std::array<double, 3> light_in_view{{-0.4, 0.5, 0.77}};

      /** The viewer's frame: right and up in the picture, towards it. */
      struct Frame
      {
        Tensor<1, 3> right, up, towards_viewer;
      };

      Frame
      frame_of(const View &view)
      {
        const double a = view.azimuth * numbers::PI / 180;
        const double e = view.elevation * numbers::PI / 180;
        Frame        frame;
        frame.towards_viewer = Tensor<1, 3>(
          {std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e)});
        // x_3 up: right = e_3 x d (horizontal), up = d x right
        frame.right = Tensor<1, 3>({-std::sin(a), std::cos(a), 0.});
        frame.up    = cross_product_3d(frame.towards_viewer, frame.right);
        return frame;
      }

      Tensor<1, 3>
      corner(const std::vector<double> &triangles,
             const std::size_t          t,
             const unsigned int         c)
      {
        const double *p = &triangles[t + 3 * c];
        return Tensor<1, 3>({p[0], p[1], p[2]});
      }

      /** The middle of the bounding box and the largest distance to it. */
      std::pair<Tensor<1, 3>, double>
      bounding_sphere(const std::vector<double> &triangles)
      {
        Tensor<1, 3> low, high;
        for (unsigned int k = 0; k < 3; ++k)
          {
            low[k]  = std::numeric_limits<double>::max();
            high[k] = std::numeric_limits<double>::lowest();
          }
        for (std::size_t i = 0; i < triangles.size(); ++i)
          {
            low[i % 3]  = std::min(low[i % 3], triangles[i]);
            high[i % 3] = std::max(high[i % 3], triangles[i]);
          }
        const Tensor<1, 3> centre = 0.5 * (low + high);
        double             radius = 0;
        for (std::size_t i = 0; i < triangles.size(); i += 3)
          radius = std::max(
            radius,
            (Tensor<1, 3>({triangles[i], triangles[i + 1], triangles[i + 2]}) -
             centre)
              .norm());
        return {centre, radius};
      }

      /** A corner in pixel coordinates (x, y) and its depth (larger: nearer).
       */
      struct ScreenPoint
      {
        double x, y, depth;
      };

      /** The depth buffer and the gray of the nearest triangle per pixel. */
      struct Raster
      {
        Raster(const unsigned int width, const unsigned int height)
          : width(width)
          , height(height)
          , depth(std::size_t(width) * height,
                  std::numeric_limits<double>::lowest())
          , gray(depth.size(), -1)
        {}

        /**
         * Fill the triangle @p p with @p shade where it is nearer than what
         * is there, or as near and brighter. A pixel belongs to the
         * triangle if its centre does (on an edge: to both triangles).
         */
        void
        fill(const std::array<ScreenPoint, 3> &p, const double shade)
        {
          const auto edge = [&](const ScreenPoint &a,
                                const ScreenPoint &b,
                                const double       x,
                                const double       y) {
            return (b.x - a.x) * (y - a.y) - (b.y - a.y) * (x - a.x);
          };
          const double area = edge(p[0], p[1], p[2].x, p[2].y);
          if (area == 0)
            return;
          const auto pixel_range = [](const double       a,
                                      const double       b,
                                      const double       c,
                                      const unsigned int n) {
            const double low  = std::floor(std::min({a, b, c}) - 0.5);
            const double high = std::ceil(std::max({a, b, c}) - 0.5);
            return std::make_pair(
              static_cast<int>(std::clamp(low, 0., double(n))),
              static_cast<int>(std::clamp(high, -1., double(n) - 1)));
          };
          const auto [x0, x1] = pixel_range(p[0].x, p[1].x, p[2].x, width);
          const auto [y0, y1] = pixel_range(p[0].y, p[1].y, p[2].y, height);
          for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x)
              {
                const double cx = x + 0.5, cy = y + 0.5;
                // barycentric coordinates, all >= 0 inside
                const double w0 = edge(p[1], p[2], cx, cy) / area;
                const double w1 = edge(p[2], p[0], cx, cy) / area;
                const double w2 = 1 - w0 - w1;
                if (w0 < 0 || w1 < 0 || w2 < 0)
                  continue;
                const double d =
                  w0 * p[0].depth + w1 * p[1].depth + w2 * p[2].depth;
                const std::size_t i = std::size_t(y) * width + x;
                if (d > depth[i] || (d == depth[i] && shade > gray[i]))
                  {
                    depth[i] = d;
                    gray[i]  = shade;
                  }
              }
        }

        unsigned int        width, height;
        std::vector<double> depth;
        /** Gray in [0,1]; negative where no triangle is. */
        std::vector<double> gray;
      };

      /** Lambert shading of the triangle with the normal @p normal. */
      double
      shade(const Tensor<1, 3> &normal, const Tensor<1, 3> &light)
      {
        const double length = normal.norm();
        const double cosine =
          length > 0 ? std::abs(normal * light) / length : 0;
        return surface_gray * (ambient + (1 - ambient) * cosine);
      }
    } // namespace



    std::vector<unsigned char>
    render(const std::vector<double> &triangles,
           const unsigned int         width,
           const unsigned int         height,
           const View                &view)
    {
      AssertThrow(triangles.size() % triangle_size == 0,
                  ExcMessage("9 coordinates per triangle"));
      const Frame  frame = frame_of(view);
      Tensor<1, 3> light = light_in_view[0] * frame.right +
                           light_in_view[1] * frame.up +
                           light_in_view[2] * frame.towards_viewer;
      light /= light.norm();
      Raster raster(width, height);
      if (!triangles.empty())
        {
          const auto [centre, radius] = bounding_sphere(triangles);
          const double scale =
            radius > 0 ?
              fill_fraction * std::min(width, height) / (2 * radius) :
              0;
          const auto project = [&](const Tensor<1, 3> &p) {
            const Tensor<1, 3> q = p - centre;
            return ScreenPoint{0.5 * width + scale * (q * frame.right),
                               0.5 * height + scale * (q * frame.up),
                               q * frame.towards_viewer};
          };
          for (std::size_t t = 0; t < triangles.size(); t += triangle_size)
            {
              const Tensor<1, 3> p0 = corner(triangles, t, 0),
                                 p1 = corner(triangles, t, 1),
                                 p2 = corner(triangles, t, 2);
              raster.fill({{project(p0), project(p1), project(p2)}},
                          shade(cross_product_3d(p1 - p0, p2 - p0), light));
            }
        }
      std::vector<unsigned char> rgb(3 * raster.gray.size(), 255);
      for (std::size_t i = 0; i < raster.gray.size(); ++i)
        if (raster.gray[i] >= 0)
          std::fill_n(rgb.begin() + 3 * i,
                      3,
                      static_cast<unsigned char>(
                        std::lround(255 * std::clamp(raster.gray[i], 0., 1.))));
      return rgb;
    }



    void
    write(const std::vector<double> &triangles,
          const std::string         &filename,
          const View                &view)
    {
      Images::write_rgb_png(
        render(triangles, default_pixels, default_pixels, view),
        default_pixels,
        default_pixels,
        filename);
    }
  } // namespace SurfacePicture
} // namespace PhaseField
