// The matrix-free backend of the operator seam (MatrixFreeStiffness,
// `Linear solver / Type = matrix-free`) applies the operators of the
// assembled one to round-off, on the adaptive test mesh (hanging nodes) in
// 2D and 3D, with both stiffness quadratures, natural and homogeneous
// Dirichlet conditions: L x (with arbitrary values at the constrained
// DoFs, where the matrix has only its diagonal), the diagonal of L, and
// f L + M[w] x. The two meshes are the same and so is their numbering of
// the DoFs, which the check requires.

#include "adaptive_test_mesh.h"
#include "tests.h"

#include <cmath>
#include <string>

using namespace dealii;
using namespace PhaseField;
using TVector = TrilinosWrappers::MPI::Vector;

namespace
{
  const char *
  yes(const bool b)
  {
    return b ? "yes" : "NO";
  }

  /** Relative difference of @p a and @p b in the l2 norm. */
  double
  relative_difference(const TVector &a, const TVector &b)
  {
    TVector d(a);
    d -= b;
    return d.l2_norm() / b.l2_norm();
  }

  /**
   * Round-off of a product with L on these meshes: 8 to 27 entries per row
   * of size about 1 (the Q1 Laplacian's entries do not scale with h in 2D
   * and scale with h in 3D), summed in another order.
   */
  constexpr double roundoff = 1e-13;
} // namespace

template <int dim>
void
check(const StiffnessQuadrature quadrature, const BoundaryConditions boundary)
{
  const Testing::AdaptiveTestMesh<dim> assembled(
    quadrature, OperatorBackendNames::assembled, boundary);
  const Testing::AdaptiveTestMesh<dim> matrix_free(
    quadrature, OperatorBackendNames::matrix_free, boundary);
  const LumpedOperators<dim> &a = assembled.operators;
  const LumpedOperators<dim> &m = matrix_free.operators;

  const bool same_dofs = a.locally_owned_dofs == m.locally_owned_dofs &&
                         assembled.constraints.n_constraints() ==
                           matrix_free.constraints.n_constraints() &&
                         assembled.constraints.n_constraints() > 0;

  TVector x(a.lumped_mass), weight(a.lumped_mass);
  Testing::fill_smoothly(x, 1., 7.);
  Testing::fill_smoothly(weight, 0.5, 0.37);
  weight.add(2.);

  TVector lx_a(x), lx_m(x), d_a(x), d_m(x);
  a.stiffness_operator().vmult(lx_a, x);
  m.stiffness_operator().vmult(lx_m, x);
  a.stiffness_operator().diagonal(d_a);
  m.stiffness_operator().diagonal(d_m);

  constexpr double                  factor = 0.25;
  std::unique_ptr<ShiftedStiffness> s_a, s_m;
  a.stiffness_plus_weighted_mass(factor, weight, s_a);
  m.stiffness_plus_weighted_mass(factor, weight, s_m);
  TVector sx_a(x), sx_m(x);
  s_a->vmult(sx_a, x);
  s_m->vmult(sx_m, x);

  Testing::log()
    << dim << "D, "
    << (quadrature == StiffnessQuadrature::gauss ? "Gauss" : "Gauss-Lobatto")
    << ", "
    << (boundary == BoundaryConditions::natural ? "natural" : "Dirichlet")
    << ": same DoFs with hanging nodes: " << yes(same_dofs)
    << ", L x: " << yes(relative_difference(lx_m, lx_a) < roundoff)
    << ", diag L: " << yes(relative_difference(d_m, d_a) < roundoff)
    << ", (f L + M[w]) x: " << yes(relative_difference(sx_m, sx_a) < roundoff)
    << ", size: " << yes(s_m->m() == s_a->m()) << '\n';
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  for (const auto quadrature :
       {StiffnessQuadrature::gauss, StiffnessQuadrature::gauss_lobatto})
    for (const auto boundary :
         {BoundaryConditions::natural, BoundaryConditions::dirichlet})
      {
        check<2>(quadrature, boundary);
        check<3>(quadrature, boundary);
      }
  return 0;
}
