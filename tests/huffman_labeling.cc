// The phase-field Huffman labeling (thesis (6.1)) of known shapes, viewed
// along the last axis, against values derived independently:
//
// - circle r = 0.2 at (0.5, 0.5) (thesis Fig. 6.4): along a column at
//   distance s < 0.2 from the centre, u = tanh((|x - c| - 0.2)/eps) falls
//   from u(y=0) to its minimum tanh((s-0.2)/eps) at y = 0.5 and rises
//   symmetrically, so alpha(s) = tanh((sqrt(s^2 + 1/4) - 0.2)/eps) -
//   tanh((s - 0.2)/eps); at s = 0: tanh(0.3/eps) + tanh(0.2/eps). For the
//   Q1 interpolant on the uniform grid (nodes at y = 0.5, 0, 1) the
//   column sums are these values at the node columns, and at a pixel
//   centre the mean of the two (every cell is monotone in y on both
//   columns); so the target labeling equals them to round-off.
// - the same circle on the adaptive narrow-band mesh (the column
//   integration of the program): equal to the uniform one up to the
//   coarse cells outside the band (|u| > tanh(4)).
// - on the adaptive mesh at h = eps = 1/64: sphere r = 0.3: 2 in the
//   shadow, 0 outside; torus R = 0.25, r = 0.1 with its axis along
//   the view: 0 in the hole, 2 over the tube; the torus rotated by 90
//   degrees (axis x_1): 4 where a column crosses the tube twice, 2 over
//   the sides, 0 outside, counted by sampling the signed distance along
//   each column. Away from the apparent contour by 3 eps, alpha is within
//   0.02 of these labels (tanh(3) = 0.995).
// - on N MPI ranks the column integration gives the labeling of one rank
//   (a copy of the mesh on MPI_COMM_SELF) to 1e-12.

#include "tests.h"

#include <deal.II/base/function.h>
#include <map>
#include <phasefield/geometry/huffman_labeling.h>
#include <phasefield/geometry/shapes.h>
#include <phasefield/mesh/discretization.h>

using namespace dealii;
using namespace PhaseField;
using HuffmanLabeling::LabelingGrid;

namespace
{
  /** The labeling of @p distance's phase field on an adaptive mesh. */
  template <int dim>
  std::vector<double>
  adaptive_labeling(const Function<dim>     &distance,
                    const double             eps,
                    const LabelingGrid<dim> &grid,
                    const MPI_Comm           comm)
  {
    typename Discretization<dim>::Settings settings{};
    settings.mesh.coarsest_level = 2;
    settings.mesh.finest_level   = grid.level();
    settings.mesh.adaptive       = true;
    settings.mesh.band_width     = 4;
    Discretization<dim> discretization(settings, comm);
    discretization.create_mesh(&distance, eps);
    TrilinosWrappers::MPI::BlockVector u;
    discretization.reinit(u, 1);
    discretization.interpolate(Shapes::PhaseFieldProfile<dim>(distance, eps),
                               u.block(0));
    const auto &ops = discretization.get_operators();
    TrilinosWrappers::MPI::Vector ghosted(ops.locally_owned_dofs,
                                          ops.locally_relevant_dofs,
                                          comm);
    ghosted = u.block(0);
    return HuffmanLabeling::labeling(discretization.get_dof_handler(),
                                     ghosted,
                                     grid);
  }

  double
  max_difference(const std::vector<double> &a, const std::vector<double> &b)
  {
    double d = 0;
    for (unsigned int i = 0; i < a.size(); ++i)
      d = std::max(d, std::abs(a[i] - b[i]));
    return d;
  }

  void
  check_circle()
  {
    const double                  eps = 1. / 32, r = 0.2;
    const LabelingGrid<2>         grid(7, true);
    const double                  h = 1. / grid.pixels_per_direction();
    const Shapes::SphereDistance<2> circle(Point<2>(0.5, 0.5), r);
    const std::vector<double>       uniform =
      HuffmanLabeling::labeling_of_function(
        Shapes::PhaseFieldProfile<2>(circle, eps), grid, MPI_COMM_WORLD);
    const auto exact = [&](const double x) {
      const double s = std::abs(x - 0.5);
      return std::tanh((std::sqrt(s * s + 0.25) - r) / eps) -
             std::tanh((s - r) / eps);
    };
    double error = 0;
    for (unsigned int i = 0; i < grid.size(); ++i)
      {
        const double x = grid.point(i)[0];
        if (std::abs(x - 0.5) < r)
          error = std::max(error,
                           std::abs(uniform[i] - 0.5 * (exact(x - 0.5 * h) +
                                                        exact(x + 0.5 * h))));
      }
    Testing::log() << "circle r = 0.2, eps = 1/32, 128 pixels: |alpha - "
                      "exact node mean| < 1e-12 over the shadow: "
                   << (error < 1e-12) << std::endl;
    const unsigned int centre = grid.pixels_per_direction() / 2;
    Testing::log() << "  alpha at x = 0.5 - h/2: " << std::setprecision(10)
                   << uniform[centre - 1]
                   << ", tanh(0.3/eps) + tanh(0.2/eps) = "
                   << std::tanh(0.3 / eps) + std::tanh(0.2 / eps)
                   << std::setprecision(6) << std::endl;
    Testing::log() << "  alpha at x = h/2 < 1e-6: " << (uniform[0] < 1e-6)
                   << std::endl;

    const std::vector<double> adaptive =
      adaptive_labeling<2>(circle, eps, grid, MPI_COMM_WORLD);
    Testing::log() << "  adaptive mesh: |alpha - uniform alpha| < 2e-3: "
                   << (max_difference(adaptive, uniform) < 2e-3) << std::endl;
    const std::vector<double> one_rank =
      adaptive_labeling<2>(circle, eps, grid, MPI_COMM_SELF);
    Testing::log() << "  all ranks vs one rank: difference < 1e-12: "
                   << (max_difference(adaptive, one_rank) < 1e-12)
                   << std::endl;
  }

  /**
   * Check that alpha is within 0.02 of @p expected(x') wherever that
   * returns a label (a negative value: near the contour, not checked).
   */
  template <typename Expected>
  void
  check_labels(const std::string         &name,
               const std::vector<double> &alpha,
               const LabelingGrid<3>     &grid,
               const Expected            &expected)
  {
    std::map<int, unsigned int> n_checked;
    double                      error = 0;
    for (unsigned int i = 0; i < grid.size(); ++i)
      {
        const double label = expected(grid.point(i));
        if (label < 0)
          continue;
        ++n_checked[static_cast<int>(label)];
        error = std::max(error, std::abs(alpha[i] - label));
      }
    Testing::log() << name << ": |alpha - label| < 0.02 away from the "
                   << "contour: " << (error < 0.02) << "; labels checked:";
    for (const auto &[label, n] : n_checked)
      Testing::log() << ' ' << label << " (" << (n > 10) << ')';
    Testing::log() << std::endl;
  }

  /**
   * The sharp label of the column over @p p: the number of sign changes of
   * @p distance along it (sampled finely); -1 if the diffuse labeling
   * need not be within 0.02 of it: |distance| < @p margin farther than
   * 2 @p margin from every crossing (the column grazes the surface) or at
   * an end of the column, or below @p margin between two crossings.
   */
  double
  sampled_label(const Function<3> &distance,
                const Point<2>    &p,
                const double       margin)
  {
    constexpr unsigned int n_samples = 4000;
    std::vector<double>    d(n_samples + 1);
    for (unsigned int k = 0; k <= n_samples; ++k)
      d[k] = distance.value(Point<3>(p[0], p[1], double(k) / n_samples));
    std::vector<double> crossings;
    for (unsigned int k = 1; k <= n_samples; ++k)
      if ((d[k] < 0) != (d[k - 1] < 0))
        crossings.push_back(double(k) / n_samples);
    for (unsigned int k = 0; k <= n_samples; ++k)
      if (std::abs(d[k]) < margin)
        {
          const double z    = double(k) / n_samples;
          bool         near = false;
          for (const double c : crossings)
            near = near || std::abs(z - c) < 2 * margin;
          if (!near || k == 0 || k == n_samples)
            return -1;
        }
    // between two crossings (and at the ends) u must reach +-tanh(3)
    double largest = 0;
    for (unsigned int k = 0; k <= n_samples; ++k)
      {
        if (k > 0 && (d[k] < 0) != (d[k - 1] < 0))
          {
            if (largest < margin)
              return -1;
            largest = 0;
          }
        largest = std::max(largest, std::abs(d[k]));
      }
    return crossings.size();
  }



  void
  check_3d()
  {
    const LabelingGrid<3> grid(6, true);
    const double          eps    = 1. / 64;
    const double          margin = 3 * eps;
    const Point<3>        c(0.5, 0.5, 0.5);
    const auto            s = [&](const Point<2> &p) {
      return std::hypot(p[0] - c[0], p[1] - c[1]);
    };

    const Shapes::SphereDistance<3> sphere(c, 0.3);
    const std::vector<double>       alpha_sphere =
      adaptive_labeling<3>(sphere, eps, grid, MPI_COMM_WORLD);
    check_labels("sphere r = 0.3", alpha_sphere, grid, [&](const Point<2> &p) {
      return s(p) < 0.3 - margin ? 2. : s(p) > 0.3 + margin ? 0. : -1.;
    });
    const std::vector<double> one_rank =
      adaptive_labeling<3>(sphere, eps, grid, MPI_COMM_SELF);
    Testing::log() << "  all ranks vs one rank: difference < 1e-12: "
                   << (max_difference(alpha_sphere, one_rank) < 1e-12)
                   << std::endl;

    const double R = 0.25, r = 0.1;
    const Shapes::FunctionFromCallable<3> torus([&](const Point<3> &p) {
      return std::hypot(std::hypot(p[0] - c[0], p[1] - c[1]) - R, p[2] - c[2]) -
             r;
    });
    check_labels("torus, axis along the view",
                 adaptive_labeling<3>(torus, eps, grid, MPI_COMM_WORLD),
                 grid,
                 [&](const Point<2> &p) {
                   const double d = std::abs(s(p) - R);
                   return d < r - margin ? 2. : d > r + margin ? 0. : -1.;
                 });

    const Shapes::FunctionFromCallable<3> rotated([&](const Point<3> &p) {
      return std::hypot(std::hypot(p[1] - c[1], p[2] - c[2]) - R, p[0] - c[0]) -
             r;
    });
    check_labels("torus, axis x_1",
                 adaptive_labeling<3>(rotated, eps, grid, MPI_COMM_WORLD),
                 grid,
                 [&](const Point<2> &p) {
                   return sampled_label(rotated, p, margin);
                 });
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check_circle();
  check_3d();
}
