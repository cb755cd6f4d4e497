#ifndef phasefield_geometry_huffman_labeling_h
#define phasefield_geometry_huffman_labeling_h

#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <phasefield/core/linear_algebra.h>
#include <string>
#include <vector>

namespace PhaseField
{
  /**
   * The phase-field Huffman labeling of thesis chapter 6 (6.1),
   *
   *   alpha[u](x') = (1/2) Int_0^1 |d u / d x_d| dx_d,
   *
   * seen along the last axis e_d onto the image plane x' in [0,1]^{d-1},
   * and its mismatch j[u] = gamma Int (alpha* - alpha[u])^2 dx' (6.2).
   *
   * The labeling lives on a LabelingGrid, a (d-1)-dimensional grid of
   * pixels at the resolution of the finest mesh with a tensor Gauss rule
   * in every pixel. Because the mesh is axis-aligned and Q1, d_d u is
   * constant along x_d on a cell, so the column integral over a cell at x'
   * is |u(x', top) - u(x', bottom)|, the (d-1)-linear interpolation of the
   * differences of the cell's top and bottom vertex values. Every MPI rank
   * adds the contributions of its own cells to the pixels under their
   * footprints (a coarse cell covers several pixels); one sum over the
   * ranks completes the columns. Neither the mesh nor the solution is
   * gathered anywhere; every rank holds the pixel grid.
   */
  namespace HuffmanLabeling
  {
    /**
     * The pixel grid on the image plane [0,1]^{dim-1}: 2^level pixels per
     * direction, numbered lexicographically (x_1 fastest), with the
     * tensor product of a 1D rule of @p n_points points in every pixel.
     * A labeling on the grid is a vector of values at the points, pixel by
     * pixel: index = pixel * points_per_pixel() + point in the pixel.
     */
    template <int dim>
    class LabelingGrid
    {
    public:
      /** The Gauss rule of the labeling: exact for (alpha* - alpha)^2 away
       * from the kinks of |.| for Q1 fields. */
      static constexpr unsigned int gauss_points = 2;

      /**
       * Pixels of size 2^-@p level. @p midpoint: one point per pixel, its
       * centre (for the CSV files and the pictures), else the Gauss rule.
       */
      LabelingGrid(const unsigned int level, const bool midpoint = false);

      unsigned int
      level() const
      {
        return grid_level;
      }

      /** Pixels per direction, 2^level(). */
      unsigned int
      pixels_per_direction() const
      {
        return n_pixels;
      }

      /** Number of pixels, pixels_per_direction()^(dim-1). */
      unsigned int
      n_pixels_total() const;

      /** Points per pixel, n^(dim-1) for n points per direction. */
      unsigned int
      points_per_pixel() const;

      /** Number of points of the grid (the size of a labeling). */
      unsigned int
      size() const
      {
        return n_pixels_total() * points_per_pixel();
      }

      /** The point with index @p i on the image plane. */
      dealii::Point<dim - 1>
      point(const unsigned int i) const;

      /** Quadrature weight of point @p i (the weights sum to 1). */
      double
      weight(const unsigned int i) const;

      /** Int f dx' by the rule of the grid, f given at the points. */
      double
      integrate(const std::vector<double> &f) const;

      /** The 1D rule on [0,1]: points and weights. */
      const std::vector<double> &
      unit_points() const
      {
        return points_1d;
      }

    private:
      unsigned int        grid_level;
      unsigned int        n_pixels;
      std::vector<double> points_1d;
      std::vector<double> weights_1d;
    };

    /**
     * alpha[u] at the points of @p grid, for the Q1 field @p u (ghosted,
     * constraints distributed) on the axis-aligned mesh of [0,1]^dim of
     * @p dof_handler whose cells are not finer than the grid's pixels.
     * Collective; every rank gets all values.
     */
    template <int dim>
    std::vector<double>
    labeling(const dealii::DoFHandler<dim> &dof_handler,
             const Vector                  &u,
             const LabelingGrid<dim>       &grid);

    /**
     * The derivative of sum_q r_q alpha[u](x'_q) with respect to the DoF
     * values of u, for nodal values @p r_q at the points of @p grid:
     * added into the locally owned vector @p gradient, through
     * @p constraints (hanging nodes pass their derivative to their
     * masters). With r_q = 2 gamma w_q (alpha[u] - alpha*)(x'_q) this is
     * the exact derivative of the discrete mismatch j[u], wherever no
     * column difference u(x', top) - u(x', bottom) is zero. Collective
     * (compresses @p gradient).
     */
    template <int dim>
    void
    add_labeling_derivative(
      const dealii::DoFHandler<dim>           &dof_handler,
      const dealii::AffineConstraints<double> &constraints,
      const Vector                            &u,
      const LabelingGrid<dim>                 &grid,
      const std::vector<double>               &r,
      Vector                                  &gradient);

    /**
     * The curvature of the labeling's quadratic majoriser at @p u0 applied
     * to @p d: each column difference s of a cell at a point is bounded by
     * |s| <= (s^2 + s0^2) / (2 |s0|) (equal at s0, the majoriser of
     * iteratively reweighted least squares), whose second derivative is
     * 1 / |s0|. Adds to @p y the sum over the points q and the cells above
     * them of @p c_q s(d) / max(|s0|, @p floor) times the derivative of s
     * with respect to the DoF values, through @p constraints. With
     * c_q = gamma w_q max(alpha_q - alpha*_q, 0) this is the part of the
     * Hessian of the majorised mismatch beyond J^T 2 gamma W J (the
     * MismatchModel). @p u0 and @p d ghosted, @p d with its constraints
     * distributed. Collective (compresses @p y).
     */
    template <int dim>
    void
    add_kink_curvature_product(
      const dealii::DoFHandler<dim>           &dof_handler,
      const dealii::AffineConstraints<double> &constraints,
      const Vector                            &u0,
      const Vector                            &d,
      const LabelingGrid<dim>                 &grid,
      const std::vector<double>               &c,
      const double                             floor,
      Vector                                  &y);

    /**
     * The linearised labeling J d = alpha'[@p u](@p d) at every point of
     * @p grid: (1/2) Int sign(d_d u) d_d d dx_d by the same column
     * integrals as labeling() (zero where the sign has a kink), so that
     * add_labeling_derivative() with r is J^T r. @p u and @p d ghosted,
     * @p d with its constraints distributed. Collective.
     */
    template <int dim>
    std::vector<double>
    labeling_derivative(const dealii::DoFHandler<dim> &dof_handler,
                        const Vector                  &u,
                        const Vector                  &d,
                        const LabelingGrid<dim>       &grid);

    /**
     * The labeling, at the points of @p grid, of the Q1 interpolant of
     * @p phase_field on the uniform mesh of [0,1]^dim at the grid's level:
     * the discrete labeling that the thesis takes as given (6.4). The
     * pixel rows are shared among the ranks of @p comm; every rank gets
     * all values.
     */
    template <int dim>
    std::vector<double>
    labeling_of_function(const dealii::Function<dim> &phase_field,
                         const LabelingGrid<dim>     &grid,
                         const MPI_Comm               comm);

    /**
     * A labeling given as a gray image: alpha* = @p maximum_label * g at
     * every point of @p grid, with g in [0,1] the gray value of the image
     * pixel (of @p nx x @p ny, rows from the bottom) that contains it. The
     * image spans the image plane: in 2D it must have one row, in 3D it
     * must be square; otherwise an InputError names @p parameter_name.
     */
    template <int dim>
    std::vector<double>
    labeling_of_image(const std::vector<double> &gray,
                      const unsigned int         nx,
                      const unsigned int         ny,
                      const double               maximum_label,
                      const LabelingGrid<dim>   &grid,
                      const std::string         &parameter_name);
  } // namespace HuffmanLabeling
} // namespace PhaseField

#endif
