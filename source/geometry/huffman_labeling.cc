#include <array>
#include <cmath>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>
#include <deal.II/lac/vector.h>
#include <phasefield/core/parameters.h>
#include <phasefield/geometry/huffman_labeling.h>

namespace PhaseField
{
  namespace HuffmanLabeling
  {
    using namespace dealii;

    namespace
    {
      /**
       * Corners of a column: the vertices of a cell face normal to x_d.
       * deal.II numbers the vertices of a hypercube lexicographically, so
       * vertex c (c < n_corners) is the bottom corner c and c + n_corners
       * the top corner above it; bit k of c is the side in direction k.
       */
      template <int dim>
      constexpr unsigned int n_corners = 1u << (dim - 1);

      /**
       * (d-1)-linear interpolation weights of the corners at the point
       * @p xi of the unit cube of the image plane.
       */
      template <int dim>
      std::array<double, n_corners<dim>>
      corner_weights(const std::array<double, dim - 1> &xi)
      {
        std::array<double, n_corners<dim>> w;
        for (unsigned int c = 0; c < n_corners<dim>; ++c)
          {
            w[c] = 1;
            for (unsigned int k = 0; k + 1 < dim; ++k)
              w[c] *= ((c >> k) & 1) ? xi[k] : 1 - xi[k];
          }
        return w;
      }

      /** The bottom and top vertex DoFs of a cell (FE_Q(1)). */
      template <int dim>
      using ColumnDofs =
        std::array<types::global_dof_index, 2 * n_corners<dim>>;

      /**
       * Call @p visit(point, weights, dofs) for every point of @p grid
       * under the footprint of every locally owned cell, with the corner
       * weights of the point in the cell and the cell's vertex DoFs; then
       * @p end_cell(dofs) once per cell. The one loop behind the labeling
       * and its derivative.
       */
      template <int dim, typename Visit, typename EndCell>
      void
      for_each_column_point(const DoFHandler<dim>   &dof_handler,
                            const LabelingGrid<dim> &grid,
                            const Visit             &visit,
                            const EndCell           &end_cell)
      {
        const unsigned int         n  = grid.pixels_per_direction();
        const std::vector<double> &s  = grid.unit_points();
        const unsigned int         nq = s.size();
        ColumnDofs<dim>            dofs;
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              for (unsigned int v = 0; v < 2 * n_corners<dim>; ++v)
                dofs[v] = cell->vertex_dof_index(v, 0);
              const Point<dim>   lower = cell->vertex(0);
              const double       size  = cell->vertex(1)[0] - lower[0];
              const unsigned int span  = std::lround(size * n);
              AssertThrow(span >= 1,
                          ExcMessage("A cell is finer than the pixels of "
                                     "the labeling grid."));
              std::array<unsigned int, dim - 1> first;
              for (unsigned int k = 0; k + 1 < dim; ++k)
                first[k] = std::lround(lower[k] * n);
              const unsigned int n_local = Utilities::pow(span, dim - 1);
              for (unsigned int m = 0; m < n_local; ++m)
                {
                  std::array<unsigned int, dim - 1> pixel;
                  unsigned int                      flat = 0, stride = 1;
                  for (unsigned int k = 0, rest = m; k + 1 < dim; ++k)
                    {
                      pixel[k] = first[k] + rest % span;
                      rest /= span;
                      flat += pixel[k] * stride;
                      stride *= n;
                    }
                  for (unsigned int q = 0; q < grid.points_per_pixel(); ++q)
                    {
                      std::array<double, dim - 1> xi;
                      for (unsigned int k = 0, rest = q; k + 1 < dim; ++k)
                        {
                          xi[k] =
                            ((pixel[k] + s[rest % nq]) / n - lower[k]) / size;
                          rest /= nq;
                        }
                      visit(flat * grid.points_per_pixel() + q,
                            corner_weights<dim>(xi),
                            dofs);
                    }
                }
              end_cell(dofs);
            }
      }

      /**
       * The derivative of |s| at the column difference @p s: its sign, 0
       * at the kink.
       */
      inline double
      kink_sign(const double s)
      {
        return (s > 0) - (s < 0);
      }

      /** u(x', top) - u(x', bottom) in a cell, from its vertex values. */
      template <int dim>
      double
      column_difference(const Vector                             &u,
                        const std::array<double, n_corners<dim>> &w,
                        const ColumnDofs<dim>                    &dofs)
      {
        double difference = 0;
        for (unsigned int c = 0; c < n_corners<dim>; ++c)
          difference += w[c] * (u(dofs[c + n_corners<dim>]) - u(dofs[c]));
        return difference;
      }
    } // namespace



    template <int dim>
    LabelingGrid<dim>::LabelingGrid(const unsigned int level,
                                    const bool         midpoint)
      : grid_level(level)
      , n_pixels(1u << level)
    {
      const Quadrature<1> rule =
        midpoint ? Quadrature<1>(QMidpoint<1>()) : QGauss<1>(gauss_points);
      for (unsigned int q = 0; q < rule.size(); ++q)
        {
          points_1d.push_back(rule.point(q)[0]);
          weights_1d.push_back(rule.weight(q));
        }
    }



    template <int dim>
    unsigned int
    LabelingGrid<dim>::n_pixels_total() const
    {
      return Utilities::pow(n_pixels, dim - 1);
    }



    template <int dim>
    unsigned int
    LabelingGrid<dim>::points_per_pixel() const
    {
      return Utilities::pow(static_cast<unsigned int>(points_1d.size()),
                            dim - 1);
    }



    template <int dim>
    Point<dim - 1>
    LabelingGrid<dim>::point(const unsigned int i) const
    {
      const unsigned int nq    = points_1d.size();
      unsigned int       pixel = i / points_per_pixel();
      unsigned int       q     = i % points_per_pixel();
      Point<dim - 1>     p;
      for (unsigned int k = 0; k + 1 < dim; ++k)
        {
          p[k] = (pixel % n_pixels + points_1d[q % nq]) / n_pixels;
          pixel /= n_pixels;
          q /= nq;
        }
      return p;
    }



    template <int dim>
    double
    LabelingGrid<dim>::weight(const unsigned int i) const
    {
      const unsigned int nq = points_1d.size();
      double             w  = 1;
      for (unsigned int k = 0, q = i % points_per_pixel(); k + 1 < dim; ++k)
        {
          w *= weights_1d[q % nq] / n_pixels;
          q /= nq;
        }
      return w;
    }



    template <int dim>
    double
    LabelingGrid<dim>::integrate(const std::vector<double> &f) const
    {
      AssertDimension(f.size(), size());
      double sum = 0;
      for (unsigned int i = 0; i < size(); ++i)
        sum += weight(i) * f[i];
      return sum;
    }



    template <int dim>
    std::vector<double>
    labeling(const DoFHandler<dim>   &dof_handler,
             const Vector            &u,
             const LabelingGrid<dim> &grid)
    {
      std::vector<double> alpha(grid.size(), 0.);
      for_each_column_point(
        dof_handler,
        grid,
        [&](const unsigned int                        i,
            const std::array<double, n_corners<dim>> &w,
            const ColumnDofs<dim>                    &dofs) {
          alpha[i] += 0.5 * std::abs(column_difference<dim>(u, w, dofs));
        },
        [](const ColumnDofs<dim> &) {});
      Utilities::MPI::sum(alpha, u.get_mpi_communicator(), alpha);
      return alpha;
    }



    namespace
    {
      /**
       * @p result += sum over the column points i and cells of
       * factor(i, w, dofs) times the derivative of the cell's column
       * difference at the point with respect to the DoF values, through
       * @p constraints: the transposed column integrals behind
       * add_labeling_derivative() and add_kink_curvature_product().
       * Collective (compresses @p result).
       */
      template <int dim, typename Factor>
      void
      add_column_gradients(const DoFHandler<dim>           &dof_handler,
                           const AffineConstraints<double> &constraints,
                           const LabelingGrid<dim>         &grid,
                           const Factor                    &factor,
                           Vector                          &result)
      {
        constexpr unsigned int               nc = n_corners<dim>;
        dealii::Vector<double>               local(2 * nc);
        std::vector<types::global_dof_index> local_dofs(2 * nc);
        for_each_column_point(
          dof_handler,
          grid,
          [&](const unsigned int            i,
              const std::array<double, nc> &w,
              const ColumnDofs<dim>        &dofs) {
            const double f = factor(i, w, dofs);
            for (unsigned int c = 0; c < nc; ++c)
              {
                local[c + nc] += f * w[c];
                local[c] -= f * w[c];
              }
          },
          [&](const ColumnDofs<dim> &dofs) {
            std::copy(dofs.begin(), dofs.end(), local_dofs.begin());
            constraints.distribute_local_to_global(local, local_dofs, result);
            local = 0;
          });
        result.compress(VectorOperation::add);
      }
    } // namespace



    template <int dim>
    void
    add_labeling_derivative(const DoFHandler<dim>           &dof_handler,
                            const AffineConstraints<double> &constraints,
                            const Vector                    &u,
                            const LabelingGrid<dim>         &grid,
                            const std::vector<double>       &r,
                            Vector                          &gradient)
    {
      AssertDimension(r.size(), grid.size());
      add_column_gradients(
        dof_handler,
        constraints,
        grid,
        [&](const unsigned int                        i,
            const std::array<double, n_corners<dim>> &w,
            const ColumnDofs<dim>                    &dofs) {
          // d/du (1/2)|difference|; zero where the sign has a kink
          return 0.5 * r[i] * kink_sign(column_difference<dim>(u, w, dofs));
        },
        gradient);
    }



    template <int dim>
    void
    add_kink_curvature_product(const DoFHandler<dim>           &dof_handler,
                               const AffineConstraints<double> &constraints,
                               const Vector                    &u0,
                               const Vector                    &d,
                               const LabelingGrid<dim>         &grid,
                               const std::vector<double>       &c,
                               const double                     floor,
                               Vector                          &y)
    {
      AssertDimension(c.size(), grid.size());
      add_column_gradients(
        dof_handler,
        constraints,
        grid,
        [&](const unsigned int                        i,
            const std::array<double, n_corners<dim>> &w,
            const ColumnDofs<dim>                    &dofs) {
          const double s0 = column_difference<dim>(u0, w, dofs);
          return c[i] * column_difference<dim>(d, w, dofs) /
                 std::max(std::abs(s0), floor);
        },
        y);
    }



    template <int dim>
    std::vector<double>
    labeling_derivative(const DoFHandler<dim>   &dof_handler,
                        const Vector            &u,
                        const Vector            &d,
                        const LabelingGrid<dim> &grid)
    {
      std::vector<double> jd(grid.size(), 0.);
      for_each_column_point(
        dof_handler,
        grid,
        [&](const unsigned int                        i,
            const std::array<double, n_corners<dim>> &w,
            const ColumnDofs<dim>                    &dofs) {
          const double difference = column_difference<dim>(u, w, dofs);
          // d/du (1/2)|difference|; zero where the sign has a kink
          jd[i] +=
            0.5 * kink_sign(difference) * column_difference<dim>(d, w, dofs);
        },
        [](const ColumnDofs<dim> &) {});
      Utilities::MPI::sum(jd, u.get_mpi_communicator(), jd);
      return jd;
    }



    template <int dim>
    std::vector<double>
    labeling_of_function(const Function<dim>     &phase_field,
                         const LabelingGrid<dim> &grid,
                         const MPI_Comm           comm)
    {
      constexpr unsigned int nc = n_corners<dim>;
      const unsigned int     n  = grid.pixels_per_direction();
      // a node row: the node columns at one position in the last image
      // direction (in 2D one column), each with the n+1 nodes along x_d
      const unsigned int columns_per_row = Utilities::pow(n + 1, dim - 2);
      const auto         node_row        = [&](const unsigned int row) {
        std::vector<double> values(columns_per_row * (n + 1));
        Point<dim>          p;
        for (unsigned int column = 0; column < columns_per_row; ++column)
          {
            for (unsigned int k = 0, rest = column; k + 2 < dim; ++k)
              {
                p[k] = double(rest % (n + 1)) / n;
                rest /= n + 1;
              }
            p[dim - 2] = double(row) / n;
            for (unsigned int z = 0; z <= n; ++z)
              {
                p[dim - 1]                   = double(z) / n;
                values[column * (n + 1) + z] = phase_field.value(p);
              }
          }
        return values;
      };

      const unsigned int         pixels_per_row = Utilities::pow(n, dim - 2);
      const std::vector<double> &s              = grid.unit_points();
      const unsigned int         nq             = s.size();
      std::vector<double>        alpha(grid.size(), 0.);
      const IndexSet             rows =
        Utilities::MPI::create_evenly_distributed_partitioning(comm, n);
      std::array<std::vector<double>, 2> pair; // node rows row, row + 1
      for (const auto row : rows)
        {
          pair[0] = row == *rows.begin() ? node_row(row) : std::move(pair[1]);
          pair[1] = node_row(row + 1);
          for (unsigned int m = 0; m < pixels_per_row; ++m)
            for (unsigned int q = 0; q < grid.points_per_pixel(); ++q)
              {
                std::array<double, dim - 1> xi;
                for (unsigned int k = 0, rest = q; k + 1 < dim; ++k)
                  {
                    xi[k] = s[rest % nq];
                    rest /= nq;
                  }
                const auto                     w = corner_weights<dim>(xi);
                std::array<const double *, nc> corner;
                for (unsigned int c = 0; c < nc; ++c)
                  {
                    // column of corner c within its node row (3D: x_1)
                    const unsigned int column = dim == 3 ? m + (c & 1) : 0;
                    corner[c] =
                      pair[(c >> (dim - 2)) & 1].data() + column * (n + 1);
                  }
                double sum = 0;
                for (unsigned int z = 0; z < n; ++z)
                  {
                    double difference = 0;
                    for (unsigned int c = 0; c < nc; ++c)
                      difference += w[c] * (corner[c][z + 1] - corner[c][z]);
                    sum += std::abs(difference);
                  }
                const unsigned int pixel = m + row * pixels_per_row;
                alpha[pixel * grid.points_per_pixel() + q] = 0.5 * sum;
              }
        }
      Utilities::MPI::sum(alpha, comm, alpha);
      return alpha;
    }



    template <int dim>
    std::vector<double>
    labeling_of_image(const std::vector<double> &gray,
                      const unsigned int         nx,
                      const unsigned int         ny,
                      const double               maximum_label,
                      const LabelingGrid<dim>   &grid,
                      const std::string         &parameter_name)
    {
      const std::string size =
        std::to_string(nx) + " x " + std::to_string(ny) + " pixels";
      if (dim == 2 && ny != 1)
        throw InputError("The image <" + parameter_name + "> has " + size +
                         ", but the labeling of a 2D shape is a line: the "
                         "image must have exactly one row.");
      if (dim == 3 && nx != ny)
        throw InputError("The image <" + parameter_name + "> has " + size +
                         ", but the image plane [0,1]^2 is square: the "
                         "image must be square.");
      std::vector<double> alpha(grid.size());
      for (unsigned int i = 0; i < grid.size(); ++i)
        {
          const Point<dim - 1> p     = grid.point(i);
          unsigned int         pixel = 0, stride = 1;
          for (unsigned int k = 0; k + 1 < dim; ++k)
            {
              pixel += std::min<unsigned int>(p[k] * nx, nx - 1) * stride;
              stride *= nx;
            }
          alpha[i] = maximum_label * gray[pixel];
        }
      return alpha;
    }



    template class LabelingGrid<2>;
    template class LabelingGrid<3>;
#define INSTANTIATE(dim)                                                                  \
  template std::vector<double> labeling(const DoFHandler<dim> &,                          \
                                        const Vector &,                                   \
                                        const LabelingGrid<dim> &);                       \
  template std::vector<double> labeling_derivative(const DoFHandler<dim> &,               \
                                                   const Vector &,                        \
                                                   const Vector &,                        \
                                                   const LabelingGrid<dim> &);            \
  template void                add_labeling_derivative(const DoFHandler<dim> &,           \
                                                       const AffineConstraints<double> &, \
                                                       const Vector &,                    \
                                                       const LabelingGrid<dim> &,         \
                                                       const std::vector<double> &,       \
                                                       Vector &);                         \
  template void add_kink_curvature_product(const DoFHandler<dim> &,                       \
                                           const AffineConstraints<double> &,             \
                                           const Vector &,                                \
                                           const Vector &,                                \
                                           const LabelingGrid<dim> &,                     \
                                           const std::vector<double> &,                   \
                                           const double,                                  \
                                           Vector &);                                     \
  template std::vector<double> labeling_of_function(const Function<dim> &,                \
                                                    const LabelingGrid<dim> &,            \
                                                    const MPI_Comm);                      \
  template std::vector<double> labeling_of_image(const std::vector<double> &,             \
                                                 const unsigned int,                      \
                                                 const unsigned int,                      \
                                                 const double,                            \
                                                 const LabelingGrid<dim> &,               \
                                                 const std::string &);
    INSTANTIATE(2)
    INSTANTIATE(3)
#undef INSTANTIATE
  } // namespace HuffmanLabeling
} // namespace PhaseField
