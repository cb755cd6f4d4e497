// MismatchTerm, the contour mismatch j[U] = gamma Int (alpha* - alpha[U])^2
// dx' as a term of the energy-term list: its value is the discrete j, its
// gradient agrees with central finite differences of the value, and its
// Gauss-Newton product e.(H d) equals sum_i 2 gamma w_i (J e)_i (J d)_i
// with J, the linearised labeling, from central finite differences of the
// discrete labeling alpha[U] (away from its kinks: U is the phase field of
// a sphere plus a smooth perturbation, so no column difference is exactly
// zero). The product is symmetric and positive on these directions. On an
// adaptive mesh with hanging nodes, 2D and 3D.

#include "adaptive_test_mesh.h"
#include "sphere_mismatch.h"
#include "tests.h"

#include <cmath>
#include <phasefield/geometry/huffman_labeling.h>
#include <phasefield/problems/mismatch_term.h>

using namespace dealii;
using namespace PhaseField;

namespace
{
  constexpr double gamma_weight = 10;
  constexpr double step         = 1e-6;

  template <int dim>
  void
  check()
  {
    const Testing::AdaptiveTestMesh<dim> mesh;
    const auto                          &ops  = mesh.operators;
    const MPI_Comm                       comm = MPI_COMM_WORLD;
    const std::vector<double> target = Testing::sphere_target_labeling(mesh);
    const MismatchTerm<dim>   term(
      mesh.discretization,
      mesh.discretization.get_settings().mesh.finest_level,
      target,
      gamma_weight);
    const HuffmanLabeling::LabelingGrid<dim> &grid = term.grid();

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
    const auto direction = [&](const double frequency) {
      TrilinosWrappers::MPI::Vector d(u);
      Testing::fill_smoothly(d, 1, frequency);
      mesh.constraints.set_zero(d);
      mesh.constraints.distribute(d);
      return d;
    };
    // J d from central differences of the labeling
    const auto linearised = [&](const TrilinosWrappers::MPI::Vector &d) {
      TrilinosWrappers::MPI::Vector plus(u), minus(u);
      plus.add(step, d);
      minus.add(-step, d);
      std::vector<double>       jd    = alpha_of(plus);
      const std::vector<double> lower = alpha_of(minus);
      for (unsigned int i = 0; i < grid.size(); ++i)
        jd[i] = (jd[i] - lower[i]) / (2 * step);
      return jd;
    };

    const std::vector<double> alpha = alpha_of(u);
    std::vector<double>       squared(grid.size());
    for (unsigned int i = 0; i < grid.size(); ++i)
      squared[i] = std::pow(alpha[i] - target[i], 2);
    const double j = gamma_weight * grid.integrate(squared);
    Testing::log() << dim << "D, pixel grid " << grid.pixels_per_direction()
                   << "^" << dim - 1 << ", value = j: "
                   << (std::abs(term.value(u) - j) <= 1e-14 * j)
                   << ", j > 0.5: " << (j > 0.5) << std::endl;

    TrilinosWrappers::MPI::Vector gradient(u);
    gradient = 0;
    term.add_gradient(u, 1., gradient);
    const TrilinosWrappers::MPI::Vector e = direction(0.37);
    const TrilinosWrappers::MPI::Vector d = direction(2.9);
    {
      TrilinosWrappers::MPI::Vector plus(u), minus(u);
      plus.add(step, d);
      minus.add(-step, d);
      const double fd    = (term.value(plus) - term.value(minus)) / (2 * step);
      const double exact = gradient * d;
      Testing::log() << "  gradient: |G.d - FD| / |G.d| < 1e-6: "
                     << (std::abs(exact - fd) < 1e-6 * std::abs(exact))
                     << ", G.d != 0: " << (std::abs(exact) > 1e-3) << std::endl;
    }

    TrilinosWrappers::MPI::Vector hd(u), he(u);
    hd = 0;
    he = 0;
    term.add_hessian_vmult(u, d, 1., hd);
    term.add_hessian_vmult(u, e, 1., he);
    const std::vector<double> jd = linearised(d), je = linearised(e);
    double                    fd_product = 0, fd_dd = 0;
    for (unsigned int i = 0; i < grid.size(); ++i)
      {
        fd_product += 2 * gamma_weight * grid.weight(i) * je[i] * jd[i];
        fd_dd += 2 * gamma_weight * grid.weight(i) * jd[i] * jd[i];
      }
    const double product = e * hd;
    Testing::log() << "  Gauss-Newton: |e.Hd - (Je)^T 2 gamma W (Jd)| < 1e-6 "
                      "relative: "
                   << (std::abs(product - fd_product) <
                       1e-6 * std::abs(fd_product))
                   << ", d.Hd: " << (std::abs(d * hd - fd_dd) < 1e-6 * fd_dd)
                   << ", symmetric: "
                   << (std::abs(product - d * he) < 1e-12 * std::abs(product))
                   << ", d.Hd > 0: " << (d * hd > 0) << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check<2>();
  check<3>();
}
