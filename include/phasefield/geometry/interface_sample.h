#ifndef phasefield_geometry_interface_sample_h
#define phasefield_geometry_interface_sample_h

#include <deal.II/base/function.h>
#include <vector>

namespace PhaseField
{
  namespace Shapes
  {
    /**
     * A signed distance sampled at the centres of a uniform grid of the
     * unit cell [0,1]^dim (512^2 points in 2D, 64^3 in 3D): where the
     * interface d = 0 is, before any mesh exists. For a true signed
     * distance (1-Lipschitz) a grid cell whose centre has |d| above half
     * its diagonal does not meet the interface, and the volume of the band
     * |d| < w is about 2 w times the measure of the interface.
     */
    struct InterfaceSample
    {
      /** Edge length of the grid cells. */
      double spacing = 0;
      /** Half the diagonal of a grid cell. */
      double half_diagonal = 0;
      /** Smallest and largest value of d at the sample points. */
      double smallest = 0;
      double largest  = 0;
      /** |d| at the sample points, sorted. */
      std::vector<double> sorted_distances;

      /**
       * The volume of the band {x in [0,1]^dim : |d(x)| < @p half_width}:
       * the share of the sample points in it, for bands wider than two
       * grid cells; for thinner ones that of the band of two grid cells
       * scaled by @p half_width (the band's volume is linear in its width
       * while it is thin against the curvature radii).
       */
      double
      band_volume(const double half_width) const;
    };

    /** Sample @p signed_distance (see InterfaceSample). */
    template <int dim>
    InterfaceSample
    sample_interface(const dealii::Function<dim> &signed_distance);
  } // namespace Shapes
} // namespace PhaseField

#endif
