#ifndef phasefield_shapes_h
#define phasefield_shapes_h

#include <deal.II/base/function.h>
#include <deal.II/base/tensor.h>
#include <functional>
#include <memory>
#include <phasefield/core/parameters.h>
#include <vector>

namespace PhaseField
{
  /**
   * Signed distance functions of the shapes of `Geometry / Shape`
   * (negative inside) and the phase field tanh(d/epsilon) built on them.
   */
  namespace Shapes
  {
    /** A scalar Function<dim> given by a callable, e.g. a lambda. */
    template <int dim>
    class FunctionFromCallable : public dealii::Function<dim>
    {
    public:
      explicit FunctionFromCallable(
        std::function<double(const dealii::Point<dim> &)> f)
        : f(std::move(f))
      {}

      double
      value(const dealii::Point<dim> &p, const unsigned int = 0) const override
      {
        return f(p);
      }

    private:
      const std::function<double(const dealii::Point<dim> &)> f;
    };

    /**
     * Exact signed distance of the point @p x (relative to the centre of
     * the box) to the axis-parallel box with half edge lengths @p half.
     */
    template <int dim>
    double
    box_distance(const dealii::Tensor<1, dim> &x,
                 const std::vector<double>    &half);

    /**
     * Create the signed distance function of the shape described by
     * @p geometry. Throws InputError for inconsistent sizes or a malformed
     * expression.
     */
    template <int dim>
    std::unique_ptr<dealii::Function<dim>>
    create_signed_distance(const GeometryParameters &geometry);

    /**
     * The centre of the shape: `Geometry / Center`, or if that is empty the
     * centre of the unit cell, the origin for `quarter circle` and
     * (0.35, 0.5, ...) for `two circles`.
     */
    template <int dim>
    dealii::Point<dim>
    shape_center(const GeometryParameters &geometry);

    /**
     * The radius of the exact evolution at time @p t if one is known:
     * circles (and quarter circles) in 2D grow as r(t) = (2t + r0^4)^(1/4)
     * under Willmore flow, spheres in 3D are stationary. Returns a negative
     * number if no exact evolution is known for the shape.
     */
    double
    exact_radius(const GeometryParameters &geometry,
                 const unsigned int        dim,
                 const double              t);

    /**
     * The function x -> tanh(d(x)/epsilon) for a given signed distance d.
     */
    template <int dim>
    class PhaseFieldProfile : public dealii::Function<dim>
    {
    public:
      PhaseFieldProfile(const dealii::Function<dim> &signed_distance,
                        const double                 epsilon);

      double
      value(const dealii::Point<dim> &p,
            const unsigned int        component = 0) const override;

    private:
      const dealii::Function<dim> &signed_distance;
      const double                 epsilon;
    };

    /** Signed distance to the sphere of radius @p radius around @p center. */
    template <int dim>
    class SphereDistance : public dealii::Function<dim>
    {
    public:
      SphereDistance(const dealii::Point<dim> &center, const double radius);

      double
      value(const dealii::Point<dim> &p,
            const unsigned int        component = 0) const override;

    private:
      const dealii::Point<dim> center;
      const double             radius;
    };
  } // namespace Shapes
} // namespace PhaseField

#endif
