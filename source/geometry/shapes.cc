#include <algorithm>
#include <cmath>
#include <deal.II/base/function_parser.h>
#include <functional>
#include <phasefield/core/message_text.h>
#include <phasefield/core/parser_messages.h>
#include <phasefield/geometry/shapes.h>
#include <sstream>

namespace PhaseField
{
  namespace Shapes
  {
    using namespace dealii;

    namespace
    {
      template <int dim>
      Point<dim>
      to_point(const std::vector<double> &values,
               const double               default_value,
               const std::string         &parameter_name)
      {
        Point<dim> p;
        if (values.empty())
          {
            for (unsigned int d = 0; d < dim; ++d)
              p[d] = default_value;
            return p;
          }
        if (values.size() != dim)
          throw InputError("The parameter <" + parameter_name + "> has " +
                           std::to_string(values.size()) + " entries, but " +
                           "needs " + std::to_string(dim) +
                           " comma separated entries (one per coordinate "
                           "of <Dimension> = " +
                           std::to_string(dim) + ").");
        for (unsigned int d = 0; d < dim; ++d)
          p[d] = values[d];
        return p;
      }

      /** Sizes with @p n entries; a single entry is repeated. */
      std::vector<double>
      expand_sizes(const std::vector<double> &sizes,
                   const unsigned int         n,
                   const std::string         &shape)
      {
        if (sizes.size() == 1)
          return std::vector<double>(n, sizes[0]);
        if (sizes.size() < n)
          throw InputError("Shape <" + shape + "> needs " + std::to_string(n) +
                           " entries in <Geometry / Sizes>.");
        return std::vector<double>(sizes.begin(), sizes.begin() + n);
      }



      /** Cylinder with axis x_d, Sizes = diameter, thickness. */
      template <int dim>
      std::unique_ptr<Function<dim>>
      disc_distance(const Point<dim> &center, const std::vector<double> &sizes)
      {
        const std::string shape = "disc";
        // cylinder with axis x_d: radius = diameter/2, half thickness
        const std::vector<double> s = expand_sizes(sizes, 2, shape);
        const double radius = 0.5 * s[0], half_thickness = 0.5 * s[1];
        return std::make_unique<FunctionFromCallable<dim>>(
          [center, radius, half_thickness](const Point<dim> &p) {
            const Tensor<1, dim> x    = p - center;
            double               rho2 = 0;
            for (unsigned int d = 0; d + 1 < dim; ++d)
              rho2 += x[d] * x[d];
            Tensor<1, 2> q;
            q[0] = std::sqrt(rho2);
            q[1] = x[dim - 1];
            return box_distance<2>(q, {radius, half_thickness});
          });
      }



      /** Ellipsoid with semi-axes Sizes. */
      template <int dim>
      std::unique_ptr<Function<dim>>
      ellipsoid_distance(const Point<dim>          &center,
                         const std::vector<double> &sizes)
      {
        const std::string shape = "ellipsoid";
        // Quilez's first-order signed distance to an ellipsoid, exact on
        // the surface and along the axes.
        const std::vector<double> a = expand_sizes(sizes, dim, shape);
        return std::make_unique<FunctionFromCallable<dim>>(
          [center, a](const Point<dim> &p) {
            const Tensor<1, dim> x  = p - center;
            double               k0 = 0, k1 = 0;
            for (unsigned int d = 0; d < dim; ++d)
              {
                k0 += std::pow(x[d] / a[d], 2);
                k1 += std::pow(x[d] / (a[d] * a[d]), 2);
              }
            k0 = std::sqrt(k0);
            k1 = std::sqrt(k1);
            if (k1 == 0)
              return -*std::min_element(a.begin(), a.end());
            return k0 * (k0 - 1.) / k1;
          });
      }



      /** Torus (axis x_d; an annulus in 2D), Sizes = R, r. */
      template <int dim>
      std::unique_ptr<Function<dim>>
      torus_distance(const Point<dim> &center, const std::vector<double> &sizes)
      {
        const std::string         shape = "torus";
        const std::vector<double> s     = expand_sizes(sizes, 2, shape);
        if (s.size() < 2 || sizes.size() < 2)
          throw InputError("Shape <torus> needs <Geometry / Sizes> = R, r.");
        const double R = s[0], rr = s[1];
        return std::make_unique<FunctionFromCallable<dim>>(
          [center, R, rr](const Point<dim> &p) {
            const Tensor<1, dim> x    = p - center;
            double               rho2 = 0;
            for (unsigned int d = 0; d + 1 < dim; ++d)
              rho2 += x[d] * x[d];
            if (dim == 2)
              return std::abs(std::sqrt(rho2 + x[1] * x[1]) - R) - rr;
            return std::sqrt(std::pow(std::sqrt(rho2) - R, 2) +
                             x[dim - 1] * x[dim - 1]) -
                   rr;
          });
      }



      /** Sample points per direction of check_finite_on_grid(). */
      constexpr unsigned int n_check_points = 33;

      /**
       * Throw an InputError naming <Geometry / Expression> if @p distance
       * is not finite at one of n_check_points^dim uniform points of
       * [0,1]^dim (e.g. sqrt(x-0.5)-0.2, NaN for x < 0.5).
       */
      template <int dim>
      void
      check_finite_on_grid(const Function<dim> &distance,
                           const std::string   &expression)
      {
        const unsigned int n_points =
          Utilities::fixed_power<dim>(n_check_points);
        for (unsigned int i = 0; i < n_points; ++i)
          {
            Point<dim>   p;
            unsigned int index = i;
            for (unsigned int d = 0; d < dim; ++d, index /= n_check_points)
              p[d] = double(index % n_check_points) / (n_check_points - 1);
            const double value = distance.value(p);
            if (!std::isfinite(value))
              {
                std::ostringstream where;
                where << p;
                throw InputError("The parameter <Geometry / Expression> = <" +
                                 abbreviated(expression) +
                                 "> is not finite at (" + where.str() +
                                 "): it must be a finite "
                                 "signed distance everywhere in [0,1]^" +
                                 std::to_string(dim) + ".");
              }
          }
      }



      /** Signed distance as a muParser expression in x, y (, z). */
      template <int dim>
      std::unique_ptr<Function<dim>>
      parsed_distance(const std::string &expression)
      {
        auto          parser = std::make_unique<FunctionParser<dim>>();
        StderrCapture parser_output;
        try
          {
            parser->initialize(FunctionParser<dim>::default_variable_names(),
                               expression,
                               {});
            // muParser parses lazily: evaluate once to catch errors here
            const double v = parser->value(Point<dim>());
            (void)v;
          }
        catch (const ExceptionBase &exc)
          {
            throw InputError(
              "The parameter <Geometry / Expression> = <" +
              abbreviated(expression) + "> is not a valid expression in " +
              FunctionParser<dim>::default_variable_names() + ": " +
              abbreviated(parser_message(parser_output.text(), exc)) + ".");
          }
        check_finite_on_grid(*parser, expression);
        return parser;
      }
    } // namespace



    template <int dim>
    double
    box_distance(const Tensor<1, dim> &x, const std::vector<double> &half)
    {
      double outside = 0, inside = -std::numeric_limits<double>::max();
      for (unsigned int d = 0; d < dim; ++d)
        {
          const double q = std::abs(x[d]) - half[d];
          outside += std::pow(std::max(q, 0.), 2);
          inside = std::max(inside, q);
        }
      return std::sqrt(outside) + std::min(inside, 0.);
    }



    template <int dim>
    Point<dim>
    shape_center(const GeometryParameters &geometry)
    {
      Point<dim> center =
        to_point<dim>(geometry.center,
                      geometry.shape == "quarter circle" ? 0.0 : 0.5,
                      "Geometry / Center");
      if (geometry.shape == "two circles" && geometry.center.empty())
        center[0] = 0.35;
      return center;
    }



    namespace
    {
      /** create_signed_distance() with messages about `Geometry`. */
      template <int dim>
      std::unique_ptr<Function<dim>>
      create_shape_distance(const GeometryParameters &geometry)
      {
        const std::string &shape  = geometry.shape;
        const Point<dim>   center = shape_center<dim>(geometry);
        const double       r      = geometry.radius;
        if (!(r > 0) && (shape == "circle" || shape == "quarter circle" ||
                         shape == "sphere" || shape == "two circles"))
          throw InputError("<Geometry / Radius> must be positive.");

        if (shape == "circle" || shape == "quarter circle" || shape == "sphere")
          return std::make_unique<SphereDistance<dim>>(center, r);

        if (shape == "two circles")
          {
            Point<dim> second = to_point<dim>(geometry.second_center,
                                              0.5,
                                              "Geometry / Second center");
            if (geometry.second_center.empty())
              second[0] = 0.65;
            return std::make_unique<FunctionFromCallable<dim>>(
              [center, second, r](const Point<dim> &p) {
                return std::min(p.distance(center), p.distance(second)) - r;
              });
          }

        if (shape == "rectangle" || shape == "cube")
          {
            std::vector<double> half = expand_sizes(geometry.sizes, dim, shape);
            for (double &s : half)
              s *= 0.5;
            return std::make_unique<FunctionFromCallable<dim>>(
              [center, half](const Point<dim> &p) {
                return box_distance<dim>(p - center, half);
              });
          }

        if (shape == "disc")
          return disc_distance<dim>(center, geometry.sizes);

        if (shape == "ellipsoid")
          return ellipsoid_distance<dim>(center, geometry.sizes);

        if (shape == "torus")
          return torus_distance<dim>(center, geometry.sizes);

        if (shape == "function")
          return parsed_distance<dim>(geometry.expression);

        throw InputError("Unknown <Geometry / Shape> = <" + shape + ">.");
      }
    } // namespace



    template <int dim>
    std::unique_ptr<Function<dim>>
    create_signed_distance(const GeometryParameters &geometry)
    {
      try
        {
          return create_shape_distance<dim>(geometry);
        }
      catch (const InputError &error)
        {
          // the messages name <Geometry / ...>: say where the shape was
          std::string       message = error.what();
          const std::string from    = "<Geometry / ",
                            to      = "<" + geometry.subsection + " / ";
          for (std::size_t at = message.find(from); at != std::string::npos;
               at             = message.find(from, at + to.size()))
            message.replace(at, from.size(), to);
          throw InputError(message);
        }
    }



    double
    exact_radius(const GeometryParameters &geometry,
                 const unsigned int        dim,
                 const double              t)
    {
      const std::string &shape = geometry.shape;
      if (shape != "circle" && shape != "quarter circle" && shape != "sphere")
        return -1;
      const double r0 = geometry.radius;
      if (dim == 2)
        return std::pow(2 * t + std::pow(r0, 4), 0.25);
      if (dim == 3)
        return r0;
      return -1;
    }



    template <int dim>
    PhaseFieldProfile<dim>::PhaseFieldProfile(
      const Function<dim> &signed_distance,
      const double         epsilon)
      : signed_distance(signed_distance)
      , epsilon(epsilon)
    {}



    template <int dim>
    double
    PhaseFieldProfile<dim>::value(const Point<dim> &p, const unsigned int) const
    {
      return std::tanh(signed_distance.value(p) / epsilon);
    }



    template <int dim>
    SphereDistance<dim>::SphereDistance(const Point<dim> &center,
                                        const double      radius)
      : center(center)
      , radius(radius)
    {}



    template <int dim>
    double
    SphereDistance<dim>::value(const Point<dim> &p, const unsigned int) const
    {
      return p.distance(center) - radius;
    }



    template std::unique_ptr<Function<2>>
    create_signed_distance<2>(const GeometryParameters &);
    template std::unique_ptr<Function<3>>
    create_signed_distance<3>(const GeometryParameters &);
    template Point<2>
    shape_center<2>(const GeometryParameters &);
    template Point<3>
    shape_center<3>(const GeometryParameters &);
    template class PhaseFieldProfile<2>;
    template class PhaseFieldProfile<3>;
    template double
    box_distance<2>(const Tensor<1, 2> &, const std::vector<double> &);
    template double
    box_distance<3>(const Tensor<1, 3> &, const std::vector<double> &);
    template class SphereDistance<2>;
    template class SphereDistance<3>;
  } // namespace Shapes
} // namespace PhaseField
