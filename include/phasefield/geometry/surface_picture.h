#ifndef phasefield_geometry_surface_picture_h
#define phasefield_geometry_surface_picture_h

#include <string>
#include <vector>

namespace PhaseField
{
  /**
   * A picture of a triangulated surface in 3D, drawn without OpenGL (VTK's
   * render windows need an X server): the triangles seen from a fixed
   * oblique direction in orthographic projection, each filled in one
   * light gray shaded by its normal (Lambert's law, lit from the upper
   * left of the viewer, both sides alike), hidden parts removed by a depth
   * buffer, on white. The surface is centred and scaled so that its
   * bounding sphere (centre: the middle of its bounding box) fills
   * fill_fraction of the picture's width.
   *
   * The picture depends on the set of triangles only, not on their order:
   * where two triangles reach a pixel at the same depth the brighter one
   * is drawn. So the surface of a parallel run, gathered rank after rank,
   * gives the same picture on any number of ranks.
   */
  namespace SurfacePicture
  {
    /**
     * The direction the surface is seen from, in degrees, as in
     * matplotlib's view_init() and scripts/plot_shape.py: the viewer sits
     * in the direction (cos e cos a, cos e sin a, sin e) from the surface,
     * x_3 points up in the picture.
     */
    struct View
    {
      double azimuth   = -60;
      double elevation = 30;
    };

    /** Share of the picture's width that the bounding sphere fills. */
    constexpr double fill_fraction = 0.9;

    /** Width and height of the pictures that write() draws, in pixels. */
    constexpr unsigned int default_pixels = 512;

    /**
     * RGB pixels (3 bytes each, @p width x @p height, row by row from the
     * bottom, as Images::write_rgb_png() takes them) of the triangles
     * @p triangles (9 coordinates per triangle, its three corners one
     * after the other) seen from @p view. Without triangles the picture
     * is white.
     */
    std::vector<unsigned char>
    render(const std::vector<double> &triangles,
           const unsigned int         width,
           const unsigned int         height,
           const View                &view = View());

    /**
     * Write the picture of @p triangles seen from @p view, default_pixels
     * wide and high, as the PNG file @p filename (Images::write_rgb_png();
     * throws WriteError). Call on one rank only.
     */
    void
    write(const std::vector<double> &triangles,
          const std::string         &filename,
          const View                &view = View());
  } // namespace SurfacePicture
} // namespace PhaseField

#endif
