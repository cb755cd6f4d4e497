#ifndef phasefield_images_h
#define phasefield_images_h

#include <deal.II/base/function.h>
#include <deal.II/dofs/dof_handler.h>
#include <memory>
#include <phasefield/core/linear_algebra.h>
#include <phasefield/core/parameters.h>
#include <string>
#include <vector>

namespace PhaseField
{
  /** An axis-aligned box [lower[0], upper[0]] x [lower[1], upper[1]]. */
  struct Box2D
  {
    std::vector<double> lower;
    std::vector<double> upper;

    /** Is the box empty (not given)? */
    bool
    empty() const
    {
      return lower.empty();
    }

    /** Is @p p in the open box? */
    bool
    contains(const dealii::Point<2> &p) const
    {
      return p[0] > lower[0] && p[0] < upper[0] && p[1] > lower[1] &&
             p[1] < upper[1];
    }
  };

  /**
   * The input images of edge restoration (thesis section 5.3) as signed
   * distance functions (negative inside) on [0,1]^2: the built-in damaged
   * shapes of Fig. 5.6 and 5.7 and thresholded PNG images.
   */
  namespace Images
  {
    /**
     * The largest image that read_gray_image() accepts, in pixels (width
     * times height; 5000 x 5000): a larger PNG header is refused before
     * any pixel is decoded.
     */
    constexpr unsigned long long max_image_pixels = 25000000;

    /** A gray image: values in [0,1], row by row from the bottom row. */
    struct GrayImage
    {
      unsigned int        nx = 0;
      unsigned int        ny = 0;
      std::vector<double> gray;
    };

    /**
     * Read the PNG image @p filename (gray, gray + alpha: the gray value;
     * RGB(A): the mean of R, G, B). Missing files, files that are not PNG
     * and damaged PNG files (truncated, wrong chunk checksums, undecodable
     * data, less data than the header's size asks for) and images of more
     * than max_image_pixels pixels become an InputError naming the file
     * and @p parameter_name.
     */
    GrayImage
    read_gray_image(const std::string &filename,
                    const std::string &parameter_name);

    /**
     * Signed distance of the (damaged) input shape: `damaged circle`,
     * `cross`, `bar`, `image` (the PNG @p image_file, pixels darker than
     * @p threshold inside), or any shape of willmore_flow, minus the box
     * @p damage if it is not empty. Throws InputError for inconsistent
     * sizes and missing or unreadable image files.
     */
    std::shared_ptr<dealii::Function<2>>
    create_damaged_image(const GeometryParameters &geometry,
                         const std::string        &image_file,
                         const double              threshold,
                         const Box2D              &damage);

    /** Signed distance to the box [lower, upper] (negative inside). */
    double
    box_distance(const dealii::Point<2>    &p,
                 const std::vector<double> &lower,
                 const std::vector<double> &upper);

    /**
     * Signed distance of a thresholded grayscale PNG image: pixels darker
     * than the threshold are inside. The image is mapped onto [0,1]^2 with
     * square pixels (its longer side spans [0,1]); the distance of the
     * pixel centres to the edge (half-way between inside and outside
     * pixels) is computed by an exact Euclidean distance transform and
     * interpolated bilinearly.
     */
    class ImageDistance : public dealii::Function<2>
    {
    public:
      /** Read @p filename (VTK's PNG reader); throws InputError. */
      ImageDistance(const std::string &filename, const double threshold);

      double
      value(const dealii::Point<2> &p,
            const unsigned int      component = 0) const override;

      /** Image size in pixels. */
      unsigned int nx = 0, ny = 0;

    private:
      /** Pixel size on [0,1]^2. */
      double pixel_size = 0;
      /** Signed distance at the pixel centres, row by row from the bottom. */
      std::vector<double> distance;
    };

    /**
     * Write a PNG picture of phase-field values sampled at the centres of
     * an n x n pixel grid on [0,1]^2 (row by row from the bottom): gray
     * from black (U = -1, inside) to white (U = +1), the box @p region
     * outlined in red. Uses VTK's PNG writer; call on one rank only.
     */
    void
    write_picture(const std::vector<double> &values,
                  const unsigned int         n,
                  const Box2D               &region,
                  const std::string         &filename);

    /**
     * Write a PNG picture of phase-field values as write_picture() does
     * (the same gray scale), with the zero level line drawn in red instead
     * of a region: the pixels whose value has the opposite sign of a
     * horizontal or vertical neighbour's and the smaller modulus of the
     * two, a line one pixel wide. Uses VTK's PNG writer; call on one rank
     * only.
     */
    void
    write_picture_with_zero_contour(const std::vector<double> &values,
                                    const unsigned int         n,
                                    const std::string         &filename);

    /**
     * Write the RGB pixels @p rgb (3 bytes per pixel, @p nx x @p ny, row
     * by row from the bottom) as the PNG file @p filename (VTK's PNG
     * writer). Call on one rank only.
     */
    void
    write_rgb_png(const std::vector<unsigned char> &rgb,
                  const unsigned int                nx,
                  const unsigned int                ny,
                  const std::string                &filename);

    /**
     * Sample the Q1 function @p u (locally owned vector on @p dof_handler of
     * an axis-parallel mesh of [0,1]^2) at the centres of an n x n pixel
     * grid, row by row from the bottom. Collective; every rank gets all
     * values.
     */
    std::vector<double>
    sample_on_pixel_grid(const dealii::DoFHandler<2> &dof_handler,
                         const Vector                &u,
                         const unsigned int           n);
  } // namespace Images
} // namespace PhaseField

#endif
