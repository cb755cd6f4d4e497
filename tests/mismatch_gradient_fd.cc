// The gradient of the discrete mismatch j[U] = gamma Int (alpha* -
// alpha[U])^2 dx' (thesis (6.2), Gauss quadrature on the pixel grid) that
// the mismatch step of shape_from_contour uses
// (HuffmanLabeling::add_labeling_derivative) is the exact derivative of
// the discrete j: it agrees with central finite differences in random
// directions of the constrained Q1 space, on an adaptive mesh with hanging
// nodes, in 2D and 3D. U is the phase field of a sphere plus a smooth
// perturbation (so no column difference is exactly zero: j has kinks
// there); the target is the labeling of another sphere.

#include "adaptive_test_mesh.h"
#include "tests.h"

#include <cmath>
#include <phasefield/geometry/huffman_labeling.h>

using namespace dealii;
using namespace PhaseField;

namespace
{
  constexpr double gamma_weight = 10;

  template <int dim>
  void
  check()
  {
    const Testing::AdaptiveTestMesh<dim>     mesh;
    const auto                              &ops  = mesh.operators;
    const MPI_Comm                           comm = MPI_COMM_WORLD;
    const HuffmanLabeling::LabelingGrid<dim> grid(
      mesh.discretization.get_settings().mesh.finest_level);
    Point<dim> c;
    for (unsigned int d = 0; d < dim; ++d)
      c[d] = 0.5;
    const Shapes::SphereDistance<dim> target_sphere(c, 0.25);
    const std::vector<double> target = HuffmanLabeling::labeling_of_function(
      Shapes::PhaseFieldProfile<dim>(target_sphere, mesh.eps), grid, comm);

    TrilinosWrappers::MPI::Vector u(ops.locally_owned_dofs, comm);
    mesh.discretization.interpolate(Shapes::PhaseFieldProfile<dim>(mesh.sphere,
                                                                   mesh.eps),
                                    u);
    TrilinosWrappers::MPI::Vector perturbation(u);
    Testing::fill_smoothly(perturbation, 0.05, 1.7);
    u += perturbation;
    mesh.constraints.distribute(u);

    TrilinosWrappers::MPI::Vector ghosted(ops.locally_owned_dofs,
                                          ops.locally_relevant_dofs,
                                          comm);
    const auto alpha_of = [&](const TrilinosWrappers::MPI::Vector &v) {
      ghosted = v;
      return HuffmanLabeling::labeling(mesh.dof_handler, ghosted, grid);
    };
    const auto j = [&](const TrilinosWrappers::MPI::Vector &v) {
      const std::vector<double> alpha = alpha_of(v);
      std::vector<double>       squared(grid.size());
      for (unsigned int i = 0; i < grid.size(); ++i)
        squared[i] = std::pow(alpha[i] - target[i], 2);
      return gamma_weight * grid.integrate(squared);
    };

    const std::vector<double> alpha = alpha_of(u);
    std::vector<double>       r(grid.size());
    for (unsigned int i = 0; i < grid.size(); ++i)
      r[i] = 2 * gamma_weight * grid.weight(i) * (alpha[i] - target[i]);
    TrilinosWrappers::MPI::Vector gradient(u);
    gradient = 0;
    ghosted  = u;
    HuffmanLabeling::add_labeling_derivative(
      mesh.dof_handler, mesh.constraints, ghosted, grid, r, gradient);

    // (the narrow band, so the DoF count, can differ with the partition)
    Testing::log() << dim << "D, pixel grid " << grid.pixels_per_direction()
                   << "^" << dim - 1 << ", hanging nodes: "
                   << (mesh.constraints.n_constraints() > 0)
                   << ", j > 0.5: " << (j(u) > 0.5) << std::endl;
    for (const double frequency : {0.37, 2.9})
      {
        TrilinosWrappers::MPI::Vector direction(u);
        Testing::fill_smoothly(direction, 1, frequency);
        mesh.constraints.set_zero(direction);
        mesh.constraints.distribute(direction);
        constexpr double              step = 1e-6;
        TrilinosWrappers::MPI::Vector plus(u), minus(u);
        plus.add(step, direction);
        minus.add(-step, direction);
        const double fd    = (j(plus) - j(minus)) / (2 * step);
        const double exact = gradient * direction;
        Testing::log() << "  direction " << frequency
                       << ": |G.d - FD| / |G.d| < 1e-6: "
                       << (std::abs(exact - fd) < 1e-6 * std::abs(exact))
                       << ", G.d != 0: " << (std::abs(exact) > 1e-3)
                       << std::endl;
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check<2>();
  check<3>();
}
