#include <cmath>
#include <phasefield/core/constants.h>
#include <phasefield/schemes/semi_implicit_scheme.h>
#include <phasefield/solvers/lumped_elimination.h>
#include <phasefield/solvers/newton_solver.h>

namespace PhaseField
{
  using namespace dealii;

  namespace F = SemiImplicitField;

  template <int dim>
  SemiImplicitStep<dim>::SemiImplicitStep(
    const Discretization<dim> &discretization,
    const double               epsilon,
    const double               tau,
    const BlockVector         &old_state)
    : discretization(discretization)
    , ops(discretization.get_operators())
    , epsilon(epsilon)
    , tau(tau)
    , old_state(old_state)
  {}



  template <int dim>
  void
  SemiImplicitStep<dim>::nonlinear_coefficients(const BlockVector &z,
                                                Vector            &G,
                                                Vector            &g) const
  {
    G = z.block(F::F);
    G += old_state.block(F::F);
    const unsigned int n  = G.locally_owned_size();
    const double      *u  = z.block(F::U).begin();
    const double      *uk = old_state.block(F::U).begin();
    g.reinit(G, true);
    for (unsigned int i = 0; i < n; ++i)
      g.begin()[i] = 1 - u[i] * u[i] - u[i] * uk[i] - uk[i] * uk[i];
  }



  template <int dim>
  void
  SemiImplicitStep<dim>::residual(const BlockVector &z, BlockVector &r) const
  {
    Vector G, g;
    nonlinear_coefficients(z, G, g);
    Vector &r_u = r.block(F::U);
    Vector &r_f = r.block(F::F);

    // stiffness parts first
    ops.stiffness_operator().vmult(r_u, G);
    r_u *= -tau / (2 * epsilon);
    ops.stiffness_operator().vmult(r_f, z.block(F::U));
    r_f *= epsilon * epsilon;

    const double       reaction = tau / std::pow(epsilon, 3);
    const unsigned int n        = G.locally_owned_size();
    const double      *m        = ops.lumped_mass.begin();
    const double      *u        = z.block(F::U).begin();
    const double      *f        = z.block(F::F).begin();
    const double      *uk       = old_state.block(F::U).begin();
    for (unsigned int i = 0; i < n; ++i)
      {
        r_u.begin()[i] +=
          m[i] * ((u[i] - uk[i]) + reaction * g.begin()[i] * G.begin()[i]);
        r_f.begin()[i] +=
          m[i] * (epsilon * f[i] - 2 * (1 - u[i] * u[i]) * u[i]);
      }
    ops.zero_constrained(r_u);
    ops.zero_constrained(r_f);
  }



  template <int dim>
  double
  SemiImplicitStep<dim>::residual_norm(const BlockVector &r) const
  {
    return std::sqrt(std::pow(ops.dual_norm(r.block(F::U)), 2) +
                     std::pow(ops.dual_norm(r.block(F::F)), 2));
  }



  template <int dim>
  double
  SemiImplicitStep<dim>::term_scale(const BlockVector &z) const
  {
    Vector G, g, lg;
    nonlinear_coefficients(z, G, g);
    lg.reinit(G, true);
    ops.stiffness_operator().vmult(lg, G);
    ops.zero_constrained(lg);
    const Vector &u = z.block(F::U);
    const Vector &f = z.block(F::F);
    return std::sqrt(ops.mass_product(u, u)) +
           tau / (2 * epsilon) * ops.dual_norm(lg) +
           epsilon * std::sqrt(ops.mass_product(f, f));
  }



  template <int dim>
  unsigned int
  SemiImplicitStep<dim>::solve_jacobian(const BlockVector &z,
                                        const BlockVector &r,
                                        BlockVector       &dz,
                                        LinearSolver      &solver)
  {
    Vector G, g;
    nonlinear_coefficients(z, G, g);
    const double       reaction = tau / std::pow(epsilon, 3);
    const unsigned int n        = G.locally_owned_size();
    const double      *u        = z.block(F::U).begin();
    const double      *uk       = old_state.block(F::U).begin();

    // J_UF = -(tau/(2 eps)) L + reaction M[g],  J_FU = eps^2 L + M[6U^2-2],
    // J_UU = M[1 - reaction (2U + U^k) G], J_FF = eps M
    LumpedTwoFieldMatrix j;
    g *= reaction;
    j.f_uf = -tau / (2 * epsilon);
    j.w_uf = g;
    j.f_fu = epsilon * epsilon;
    j.w_fu.reinit(G, true);
    j.uu.reinit(G, true);
    const double *m = ops.lumped_mass.begin();
    for (unsigned int i = 0; i < n; ++i)
      {
        j.w_fu.begin()[i] = 6 * u[i] * u[i] - 2;
        j.uu.begin()[i] =
          m[i] * (1 - reaction * (2 * u[i] + uk[i]) * G.begin()[i]);
      }
    j.s = epsilon;
    return solve_lumped_elimination(ops, std::move(j), r, dz, solver);
  }



  template <int dim>
  void
  SemiImplicitStep<dim>::jacobian_vmult(const BlockVector &z,
                                        const BlockVector &x,
                                        BlockVector       &y) const
  {
    Vector G, g;
    nonlinear_coefficients(z, G, g);
    const double  reaction = tau / std::pow(epsilon, 3);
    const Vector &xu       = x.block(F::U);
    const Vector &xf       = x.block(F::F);
    Vector       &yu       = y.block(F::U);
    Vector       &yf       = y.block(F::F);
    ops.stiffness_operator().vmult(yu, xf);
    yu *= -tau / (2 * epsilon);
    ops.stiffness_operator().vmult(yf, xu);
    yf *= epsilon * epsilon;
    const double      *m  = ops.lumped_mass.begin();
    const double      *u  = z.block(F::U).begin();
    const double      *uk = old_state.block(F::U).begin();
    const unsigned int n  = G.locally_owned_size();
    for (unsigned int i = 0; i < n; ++i)
      {
        yu.begin()[i] +=
          m[i] *
          ((1 - reaction * (2 * u[i] + uk[i]) * G.begin()[i]) * xu.begin()[i] +
           reaction * g.begin()[i] * xf.begin()[i]);
        yf.begin()[i] += m[i] * ((6 * u[i] * u[i] - 2) * xu.begin()[i] +
                                 epsilon * xf.begin()[i]);
      }
    ops.zero_constrained(yu);
    ops.zero_constrained(yf);
  }



  template <int dim>
  void
  SemiImplicitStep<dim>::initialize_f(BlockVector &z) const
  {
    // R_F = 0: F = (eps M)^-1 (2 M[1-U^2] U - eps^2 L U)
    const Vector &u = z.block(F::U);
    Vector       &f = z.block(F::F);
    ops.stiffness_operator().vmult(f, u);
    f *= -epsilon * epsilon;
    const double      *m = ops.lumped_mass.begin();
    const unsigned int n = u.locally_owned_size();
    for (unsigned int i = 0; i < n; ++i)
      {
        const double ui = u.begin()[i];
        f.begin()[i] += m[i] * 2 * (1 - ui * ui) * ui;
      }
    f.scale(ops.inverse_lumped_mass);
    f /= epsilon;
    ops.zero_constrained(f);
  }



  template <int dim>
  void
  SemiImplicitStep<dim>::distribute_constraints(BlockVector &z) const
  {
    discretization.distribute_constraints(z);
  }



  template <int dim>
  SemiImplicitScheme<dim>::SemiImplicitScheme(
    const SchemeSettings      &settings,
    const Discretization<dim> &discretization,
    const ConditionalOStream  &pcout)
    : settings(settings)
    , discretization(discretization)
    , pcout(pcout)
  {
    discretization.require_assembled_operators("The semi-implicit scheme");
    // the Jacobian is not symmetric
    linear_solver =
      std::make_unique<LinearSolver>(settings.solver.type,
                                     settings.linear_solver.relative_tolerance,
                                     settings.linear_solver.max_iterations,
                                     /*symmetric=*/false);
  }



  template <int dim>
  std::string
  SemiImplicitScheme<dim>::name() const
  {
    return "semi-implicit";
  }



  template <int dim>
  std::vector<std::string>
  SemiImplicitScheme<dim>::field_names() const
  {
    return {"U", "F"};
  }



  template <int dim>
  std::string
  SemiImplicitScheme<dim>::linear_solver_description() const
  {
    return linear_solver->type() == LinearSolverType::direct ?
             "direct (MUMPS)" :
             "iterative (GMRES + AMG)";
  }



  template <int dim>
  void
  SemiImplicitScheme<dim>::initialize(BlockVector &state, const double tau)
  {
    SemiImplicitStep<dim>(discretization, settings.epsilon, tau, state)
      .initialize_f(state);
    discretization.distribute_constraints(state);
  }



  template <int dim>
  StepReport
  SemiImplicitScheme<dim>::advance(const BlockVector &old_state,
                                   BlockVector       &state,
                                   const double       tau)
  {
    SemiImplicitStep<dim> step(discretization,
                               settings.epsilon,
                               tau,
                               old_state);
    return newton_solve(step,
                        state,
                        NewtonControl(settings.newton),
                        *linear_solver,
                        pcout,
                        settings.verbose);
  }



  template <int dim>
  void
  SemiImplicitScheme<dim>::reset_solver()
  {
    linear_solver->reset();
  }



  template <int dim>
  void
  SemiImplicitScheme<dim>::before_remesh()
  {
    reset_solver();
  }



  template <int dim>
  void
  SemiImplicitScheme<dim>::after_remesh(BlockVector &state, const double tau)
  {
    reset_solver();
    // F^k enters the next step's residual: it must be f_h(U^k) on the new
    // mesh, not an interpolation from the old one
    initialize(state, tau);
  }


  template <int dim>
  bool
  SemiImplicitScheme<dim>::restores_after_remesh(const unsigned int field) const
  {
    return field == F::F;
  }



  template <int dim>
  Energies
  SemiImplicitScheme<dim>::energies(const BlockVector &state) const
  {
    const LumpedOperators<dim> &ops = discretization.get_operators();
    Energies e = phase_field_energies(ops, state.block(F::U), settings.epsilon);
    // (3/4) (1/(2 eps)) Int F^2
    e.willmore = Constants::geometric_unit * 0.5 / settings.epsilon *
                 ops.mass_product(state.block(F::F), state.block(F::F));
    return e;
  }



  template <int dim>
  void
  SemiImplicitScheme<dim>::curvature(const BlockVector &state,
                                     Vector            &curvature) const
  {
    curvature = state.block(F::F);
    curvature /= -settings.epsilon;
  }



  template class SemiImplicitStep<2>;
  template class SemiImplicitStep<3>;
  template class SemiImplicitScheme<2>;
  template class SemiImplicitScheme<3>;
} // namespace PhaseField
