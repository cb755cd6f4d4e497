#ifndef phasefield_images_h
#define phasefield_images_h

#include <deal.II/base/function.h>
#include <memory>
#include <phasefield/parameters.h>
#include <phasefield/restoration_parameters.h>
#include <string>
#include <vector>

namespace PhaseField
{
  /**
   * The input images of edge restoration (thesis section 5.3) as signed
   * distance functions (negative inside) on [0,1]^2: the built-in damaged
   * shapes of Fig. 5.6 and 5.7 and thresholded PNG images.
   */
  namespace Images
  {
    /**
     * Signed distance of the (damaged) input shape: `damaged circle`,
     * `cross`, `bar`, `image`, or any shape of willmore_flow, minus the box
     * `Restoration / Damage` if one is given. Throws InputError for
     * inconsistent sizes and missing or unreadable image files.
     */
    std::shared_ptr<dealii::Function<2>>
    create_damaged_image(const GeometryParameters    &geometry,
                         const RestorationParameters &restoration);

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
  } // namespace Images
} // namespace PhaseField

#endif
