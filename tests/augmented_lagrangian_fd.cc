// The augmented Lagrangian of the augmented-Lagrangian scheme
// (AugmentedLagrangianObjective over an AugmentedLagrangianStep): its
// gradient agrees with central differences of its value, and its
// matrix-free Hessian product with central differences of the gradient,
// in 2D and 3D on an adaptive mesh with hanging nodes, for Willmore flow
// (scaled and unscaled), for the biharmonic model with a forcing and for
// edge restoration (area term, U fixed at every second DoF: the gradient,
// the Hessian products and the preconditioner are 0 there); the
// truncated CG step of the trust region decreases the quadratic model
// and stays inside the radius.

#include "adaptive_test_mesh.h"
#include "tests.h"

#include <cmath>
#include <deal.II/base/function_lib.h>
#include <deal.II/numerics/vector_tools.h>
#include <phasefield/geometry/shapes.h>
#include <phasefield/schemes/augmented_lagrangian_scheme.h>
#include <phasefield/solvers/augmented_lagrangian.h>
#include <phasefield/solvers/trust_region.h>
#include <string>

using namespace dealii;
using namespace PhaseField;
using TBlockVector = TrilinosWrappers::MPI::BlockVector;
using TVector      = TrilinosWrappers::MPI::Vector;

namespace
{
  /** Relative errors below this pass (central differences, step 1e-6). */
  constexpr double fd_tolerance = 1e-6;

  void
  report(const std::string &what, const double relative_error)
  {
    Testing::log() << "  " << what << " "
                   << (relative_error < fd_tolerance ? "< 1e-6" : "TOO LARGE")
                   << std::endl;
    if (!(relative_error < fd_tolerance))
      Testing::log() << "    value " << relative_error << std::endl;
  }
} // namespace

/** Largest |U-entry| of @p x at the DoFs of @p fixed. */
double
max_at_fixed(const TBlockVector &x, const IndexSet &fixed)
{
  double largest = 0;
  for (const auto i : fixed)
    largest = std::max(largest, std::abs(x.block(0)[i]));
  return Utilities::MPI::max(largest, MPI_COMM_WORLD);
}

template <int dim>
void
check(const bool   double_well,
      const bool   scaled,
      const double penalty,
      const bool   restoration = false)
{
  const MPI_Comm comm = MPI_COMM_WORLD;
  (void)comm;
  const Testing::AdaptiveTestMesh<dim> mesh;
  const LumpedOperators<dim>          &ops = mesh.operators;
  const double                         h   = mesh.h;

  // a smooth state and direction: the profile of the test sphere plus
  // cosine waves
  Functions::CosineFunction<dim> wave;
  TVector                        w(ops.locally_owned_dofs, comm);
  VectorTools::interpolate(mesh.dof_handler, wave, w);
  const Shapes::PhaseFieldProfile<dim> profile(mesh.sphere, mesh.eps);
  TVector                              u0(w), forcing(w), p(w);
  VectorTools::interpolate(mesh.dof_handler, profile, u0);

  NestedCoefficients coeff;
  coeff.epsilon     = double_well ? mesh.eps : 1.;
  coeff.tau         = 0.03 * h;
  coeff.inner_tau   = h * h;
  coeff.double_well = double_well;
  if (!double_well)
    {
      forcing = w;
      forcing.scale(ops.lumped_mass);
      coeff.outer.forcing = &forcing;
    }
  // restoration: area weight eta = 4 (the shipped files), U fixed at the
  // locally owned DoFs of even index
  IndexSet fixed(ops.locally_owned_dofs.size());
  if (restoration)
    {
      for (const auto i : ops.locally_owned_dofs)
        if (i % 2 == 0)
          fixed.add_index(i);
      coeff.outer.area_weight = 4;
      coeff.outer.fixed_u     = &fixed;
    }
  TVector old_u(u0);
  old_u.add(0.05, w);
  AugmentedLagrangianStep<dim> step(mesh.discretization, coeff, old_u, scaled);

  TBlockVector x = step.make_point(), d = step.make_point();
  x.block(0) = u0;
  x.block(1) = u0;
  x.block(1).add(0.02, w);
  p = w;
  p *= 0.3;
  p.add(0.1, u0);
  for (unsigned int b = 0; b < 2; ++b)
    {
      d.block(b) = w;
      d.block(b) *= (b + 1.);
      d.block(b).add(0.5 * b, u0);
      ops.zero_constrained(d.block(b));
    }
  // a direction that keeps the fixed values
  for (const auto i : fixed)
    d.block(0)[i] = 0;
  d.compress(VectorOperation::insert);
  mesh.discretization.distribute_constraints(x);

  Testing::log() << dim << "D, "
                 << (restoration ? "restoration" :
                     double_well ? "Willmore" :
                                   "biharmonic")
                 << (scaled ? ", scaled" : ", unscaled") << ", lambda "
                 << penalty << ", " << mesh.constraints.n_constraints()
                 << " hanging-node constraints" << std::endl;

  AugmentedLagrangianObjective objective(step, p, penalty);
  const double                 fd_step = 1e-6;
  TBlockVector                 xp(x), xm(x), g(x), gp(x), gm(x), hd(x);
  xp.add(fd_step, d);
  xm.add(-fd_step, d);
  mesh.discretization.distribute_constraints(xp);
  mesh.discretization.distribute_constraints(xm);
  const double slope_fd =
    (objective.value(xp) - objective.value(xm)) / (2 * fd_step);
  objective.gradient(x, g);
  const double slope = g * d;
  report("|dl_A/dx d - grad.d| / |grad.d|",
         std::abs(slope_fd - slope) / std::abs(slope));

  objective.gradient(xp, gp);
  objective.gradient(xm, gm);
  gp -= gm;
  gp /= 2 * fd_step;
  objective.gradient(x, g);
  objective.hessian_vmult(d, hd);
  gp -= hd;
  report("|H d - FD| / |H d|", step.gradient_norm(gp) / step.gradient_norm(hd));
  if (restoration)
    {
      TBlockVector z(x);
      objective.precondition(g, z);
      Testing::log() << "  at fixed U: gradient, H d, B^-1 gradient "
                     << max_at_fixed(g, fixed) << ", "
                     << max_at_fixed(hd, fixed) << ", "
                     << max_at_fixed(z, fixed) << std::endl;
    }

  // Steihaug-Toint: decrease of the model, inside the B-norm radius
  const double      radius = 1e-3;
  TBlockVector      s(x);
  TruncatedCGResult cg = truncated_cg(objective, g, radius, 1e-12, 500, s);
  objective.hessian_vmult(s, hd);
  const double model = g * s + 0.5 * (s * hd);
  Testing::log() << "  truncated CG: model decrease "
                 << (cg.model_decrease > 0 &&
                         std::abs(cg.model_decrease + model) <=
                           1e-8 * std::abs(model) ?
                       "> 0 and = -m(s)" :
                       "WRONG")
                 << ", step "
                 << (cg.step_norm <= radius * (1 + 1e-12) ? "inside" :
                                                            "OUTSIDE")
                 << " the radius" << std::endl;
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check<2>(true, true, 10.);
  check<2>(true, false, 1e4);
  check<2>(false, true, 10.);
  check<2>(true, true, 1e3, true);
  check<3>(true, true, 10.);
  check<3>(false, true, 1e3);
}
