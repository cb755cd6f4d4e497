#include <algorithm>
#include <cmath>
#include <limits>
#include <phasefield/geometry/interface_sample.h>

namespace PhaseField
{
  namespace Shapes
  {
    using namespace dealii;

    namespace
    {
      /** Sample points per direction: 512^2 in 2D, 64^3 in 3D. */
      constexpr unsigned int
      points_per_direction(const int dim)
      {
        return dim == 2 ? 512 : 64;
      }

      /** Bands up to this many grid cells wide are scaled, not counted. */
      constexpr double thinnest_counted_band = 2;
    } // namespace



    double
    InterfaceSample::band_volume(const double half_width) const
    {
      const auto share = [this](const double w) {
        const auto in_band =
          std::lower_bound(sorted_distances.begin(), sorted_distances.end(), w);
        return double(in_band - sorted_distances.begin()) /
               sorted_distances.size();
      };
      const double thinnest = thinnest_counted_band * spacing;
      if (half_width >= thinnest)
        return share(half_width);
      return share(thinnest) * half_width / thinnest;
    }



    template <int dim>
    InterfaceSample
    sample_interface(const Function<dim> &signed_distance)
    {
      const unsigned int n = points_per_direction(dim);
      InterfaceSample    sample;
      sample.spacing        = 1. / n;
      sample.half_diagonal  = 0.5 * std::sqrt(double(dim)) * sample.spacing;
      sample.smallest       = std::numeric_limits<double>::infinity();
      sample.largest        = -sample.smallest;
      unsigned int n_points = 1;
      for (int d = 0; d < dim; ++d)
        n_points *= n;
      sample.sorted_distances.reserve(n_points);
      for (unsigned int i = 0; i < n_points; ++i)
        {
          Point<dim>   p;
          unsigned int index = i;
          for (unsigned int d = 0; d < dim; ++d, index /= n)
            p[d] = (index % n + 0.5) * sample.spacing;
          const double value = signed_distance.value(p);
          sample.smallest    = std::min(sample.smallest, value);
          sample.largest     = std::max(sample.largest, value);
          sample.sorted_distances.push_back(std::abs(value));
        }
      std::sort(sample.sorted_distances.begin(), sample.sorted_distances.end());
      return sample;
    }



    template InterfaceSample
    sample_interface<2>(const Function<2> &);
    template InterfaceSample
    sample_interface<3>(const Function<3> &);
  } // namespace Shapes
} // namespace PhaseField
