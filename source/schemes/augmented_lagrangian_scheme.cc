#include <algorithm>
#include <cmath>
#include <phasefield/mesh/operator_backend.h>
#include <phasefield/schemes/augmented_lagrangian_scheme.h>
#include <phasefield/schemes/double_well.h>
#include <phasefield/solvers/product_form.h>

namespace PhaseField
{
  using namespace dealii;

  template <int dim>
  AugmentedLagrangianStep<dim>::AugmentedLagrangianStep(
    const Discretization<dim> &discretization,
    const NestedCoefficients  &coefficients,
    const Vector              &old_u,
    const bool                 scaled)
    : discretization(discretization)
    , ops(discretization.get_operators())
    , coeff(coefficients)
    , weights(coefficients)
    , old_u(old_u)
    , f_scale(objective_scale(coefficients, scaled))
    , physics(discretization, coefficients, old_u)
  {}



  template <int dim>
  double
  AugmentedLagrangianStep<dim>::objective_scale(
    const NestedCoefficients &coefficients,
    const bool                scaled)
  {
    return 2 * (scaled ? 1. : coefficients.epsilon);
  }



  template <int dim>
  BlockVector
  AugmentedLagrangianStep<dim>::make_point() const
  {
    return BlockVector(std::vector<IndexSet>(2, ops.locally_owned_dofs),
                       discretization.get_mpi_communicator());
  }



  template <int dim>
  double
  AugmentedLagrangianStep<dim>::objective(const BlockVector &x) const
  {
    // the nested step's outer energy is e_out / (2 eps); x = (U, V) has
    // the block indices of Field::U and Field::V
    return f_scale * physics.outer_energy(x);
  }



  template <int dim>
  void
  AugmentedLagrangianStep<dim>::objective_gradient(const BlockVector &x,
                                                   BlockVector       &g) const
  {
    const double      *m  = ops.lumped_mass.begin();
    const double      *u  = x.block(Field::U).begin();
    const double      *v  = x.block(Field::V).begin();
    const double      *uk = old_u.begin();
    const unsigned int n  = x.block(Field::U).locally_owned_size();
    for (unsigned int i = 0; i < n; ++i)
      {
        const double a_difference = weights.a * m[i] * (v[i] - u[i]);
        g.block(Field::U).begin()[i] =
          f_scale * (m[i] * (u[i] - uk[i]) - a_difference);
        g.block(Field::V).begin()[i] = f_scale * a_difference;
      }
    physics.add_terms_gradient(x.block(Field::U), f_scale, g.block(Field::U));
    physics.zero_fixed_u(g.block(Field::U));
    for (unsigned int b = 0; b < 2; ++b)
      ops.zero_constrained(g.block(b));
  }



  template <int dim>
  void
  AugmentedLagrangianStep<dim>::objective_hessian_vmult(const BlockVector &x,
                                                        const BlockVector &d,
                                                        BlockVector &y) const
  {
    const double      *m  = ops.lumped_mass.begin();
    const double      *du = d.block(Field::U).begin();
    const double      *dv = d.block(Field::V).begin();
    const double       a  = weights.a;
    const unsigned int n  = d.block(Field::U).locally_owned_size();
    for (unsigned int i = 0; i < n; ++i)
      {
        y.block(Field::U).begin()[i] =
          f_scale * m[i] * ((1 + a) * du[i] - a * dv[i]);
        y.block(Field::V).begin()[i] = f_scale * m[i] * a * (dv[i] - du[i]);
      }
    physics.add_terms_hessian_vmult(x.block(Field::U),
                                    d.block(Field::U),
                                    f_scale,
                                    y.block(Field::U));
    physics.zero_fixed_u(y.block(Field::U));
    for (unsigned int b = 0; b < 2; ++b)
      ops.zero_constrained(y.block(b));
  }



  template <int dim>
  void
  AugmentedLagrangianStep<dim>::constraint(const BlockVector &x,
                                           Vector            &c) const
  {
    physics.inner_residual(x.block(Field::U), x.block(Field::V), c);
  }



  template <int dim>
  void
  AugmentedLagrangianStep<dim>::constraint_jacobian_vmult(const BlockVector &x,
                                                          const BlockVector &d,
                                                          Vector &jd) const
  {
    // c'(d) = -M d_U + K(V) d_V
    physics.k_vmult(x.block(Field::V), d.block(Field::V), jd);
    const double      *m = ops.lumped_mass.begin();
    const unsigned int n = jd.locally_owned_size();
    for (unsigned int i = 0; i < n; ++i)
      jd.begin()[i] -= m[i] * d.block(Field::U).begin()[i];
  }



  template <int dim>
  void
  AugmentedLagrangianStep<dim>::constraint_jacobian_tvmult(const BlockVector &x,
                                                           const Vector      &y,
                                                           BlockVector &g) const
  {
    // c'^T y = (-M y, K(V) y)
    physics.k_vmult(x.block(Field::V), y, g.block(Field::V));
    g.block(Field::U) = y;
    g.block(Field::U).scale(ops.lumped_mass);
    g.block(Field::U) *= -1;
    physics.zero_fixed_u(g.block(Field::U));
    ops.zero_constrained(g.block(Field::U));
  }



  template <int dim>
  void
  AugmentedLagrangianStep<dim>::constraint_hessian_vmult(const BlockVector &x,
                                                         const Vector      &y,
                                                         const BlockVector &d,
                                                         BlockVector &out) const
  {
    // (0, c M[Psi'''(V) y] d_V)
    out.block(Field::U)  = 0;
    const double      *m = ops.lumped_mass.begin();
    const double      *v = x.block(Field::V).begin();
    const unsigned int n = y.locally_owned_size();
    for (unsigned int i = 0; i < n; ++i)
      out.block(Field::V).begin()[i] =
        m[i] * weights.e(v[i], y.begin()[i]) * d.block(Field::V).begin()[i];
  }



  template <int dim>
  void
  AugmentedLagrangianStep<dim>::riesz(const Vector &c, Vector &out) const
  {
    out = c;
    out.scale(ops.inverse_lumped_mass);
    ops.zero_constrained(out);
  }



  template <int dim>
  double
  AugmentedLagrangianStep<dim>::gradient_norm(const BlockVector &g) const
  {
    return std::sqrt(std::pow(ops.dual_norm(g.block(Field::U)), 2) +
                     std::pow(ops.dual_norm(g.block(Field::V)), 2));
  }



  template <int dim>
  void
  AugmentedLagrangianStep<dim>::setup_preconditioner(const BlockVector &x,
                                                     const Vector &,
                                                     const double penalty)
  {
    // without the double well (the biharmonic model, c = 0) S_V does not
    // depend on the iterate: its factorisation serves all trust-region
    // iterates of one penalty
    if (weights.c == 0 && schur_solver != nullptr && setups > 0 &&
        penalty == schur_penalty)
      return;
    // S_V = w Khat M^-1 Khat + m M, Khat = K - b M (class documentation)
    const double s    = f_scale;
    const double a    = weights.a;
    const double beta = s * (1 + a) + penalty;
    const double w    = penalty * s * (1 + a) / beta;
    const double m    = s * a / beta * (s + penalty / (1 + a));
    ++setups;
    schur_beta    = beta;
    schur_penalty = penalty;
    schur_v       = x.block(Field::V);
    if (schur_solver == nullptr)
      setup_schur_multigrid(a / (1 + a), w, m);
    else
      factorize_schur(a / (1 + a), w, m);
  }



  template <int dim>
  void
  AugmentedLagrangianStep<dim>::setup_schur_multigrid(const double b,
                                                      const double w,
                                                      const double m)
  {
    // the multigrid keeps a reference to G
    schur_multigrid.reset();
    physics.build_schur_factor(schur_v, b, w, m, schur_factor, interface_mode);
    schur_multigrid     = std::make_unique<SchurPreconditioner>(*schur_factor,
                                                            ops.lumped_mass,
                                                            &interface_mode);
    const double gamma  = NestedPhysics<dim>::schur_mass_shift;
    schur_inverse_scale = gamma * gamma / m;
  }



  template <int dim>
  void
  AugmentedLagrangianStep<dim>::factorize_schur(const double b,
                                                const double w,
                                                const double m)
  {
    // U is eliminated at its free DoFs only: at a fixed one, Khat has no
    // shift b, w = lambda and m = s a (class documentation)
    Vector free(ops.lumped_mass);
    free = 1;
    physics.zero_fixed_u(free);
    const auto nodal = [&](const double at_free, const double at_fixed) {
      Vector values(free);
      values *= at_free - at_fixed;
      values.add(at_fixed);
      return values;
    };
    // S_V = Khat diag(w) Khat + diag(m), Khat = ttau L + M[k(V)] - b M
    Vector shift = nodal(-b, 0.);
    shift.scale(ops.lumped_mass);
    Vector weight = nodal(w, schur_penalty);
    weight.scale(ops.inverse_lumped_mass);
    Vector diagonal = nodal(m, f_scale * weights.a);
    diagonal.scale(ops.lumped_mass);
    schur.assemble(ops,
                   weights.inner_tau,
                   physics.k_weights(schur_v, 0.),
                   shift,
                   weight,
                   diagonal);
    // S_V has the same sparsity pattern at every iterate on one mesh:
    // MUMPS's analysis is kept (half of the time of a trust-region
    // iteration in 2D before)
    schur.factorize(*schur_solver);
  }



  template <int dim>
  void
  AugmentedLagrangianStep<dim>::apply_schur_inverse(const Vector &r,
                                                    Vector       &z) const
  {
    if (schur_solver != nullptr)
      schur.solve(*schur_solver, z, r);
    else
      {
        schur_multigrid->vmult(z, r);
        z *= schur_inverse_scale;
      }
    ops.zero_constrained(z);
  }



  template <int dim>
  void
  AugmentedLagrangianStep<dim>::precondition(const BlockVector &r,
                                             BlockVector       &z) const
  {
    // B z = r: w = (beta M)^-1 r_U, S_V z_V = r_V + (s a M + lambda K) w,
    // z_U = (beta M)^-1 (r_U + (s a M + lambda K) z_V)
    const double s_a      = f_scale * weights.a;
    const auto   coupling = [&](const Vector &in, Vector &out) {
      physics.k_vmult(schur_v, in, out);
      out *= schur_penalty;
      Vector mass_part(in);
      mass_part.scale(ops.lumped_mass);
      out.add(s_a, mass_part);
      ops.zero_constrained(out);
    };
    Vector w(r.block(Field::U)), rhs(w), cz(w);
    w.scale(ops.inverse_lumped_mass);
    w /= schur_beta;
    ops.zero_constrained(w);
    coupling(w, rhs);
    rhs += r.block(Field::V);
    apply_schur_inverse(rhs, z.block(Field::V));
    coupling(z.block(Field::V), cz);
    cz += r.block(Field::U);
    cz.scale(ops.inverse_lumped_mass);
    cz /= schur_beta;
    ops.zero_constrained(cz);
    physics.zero_fixed_u(cz);
    z.block(Field::U) = cz;
  }



  template <int dim>
  void
  AugmentedLagrangianStep<dim>::distribute_constraints(BlockVector &x) const
  {
    discretization.distribute_constraints(x);
  }



  // ---------------------------------------------------------------------
  // The scheme
  // ---------------------------------------------------------------------

  template <int dim>
  AugmentedLagrangianScheme<dim>::AugmentedLagrangianScheme(
    const SchemeSettings      &settings,
    const Discretization<dim> &discretization,
    const ConditionalOStream  &pcout)
    : settings(settings)
    , parameters(settings.own_parameters<AugmentedLagrangianParameters>())
    , discretization(discretization)
    , pcout(pcout)
    , model(settings, discretization)
    , solver_type(settings.solver.type)
    , next_penalty(parameters.initial_penalty)
  {
    if (solver_type == LinearSolverType::direct)
      schur_solver = std::make_unique<LinearSolver>(
        LinearSolverType::direct,
        settings.linear_solver.relative_tolerance,
        settings.linear_solver.max_iterations);
  }



  template <int dim>
  std::string
  AugmentedLagrangianScheme<dim>::name() const
  {
    return "augmented lagrangian";
  }



  template <int dim>
  std::vector<std::string>
  AugmentedLagrangianScheme<dim>::field_names() const
  {
    return {"U", "V", "P"};
  }



  template <int dim>
  std::string
  AugmentedLagrangianScheme<dim>::linear_solver_description() const
  {
    const std::string krylov =
      "trust region, Steihaug-Toint truncated CG with matrix-free Hessian "
      "products, Schur-complement preconditioner ";
    if (schur_solver)
      return krylov + "(MUMPS)";
    return krylov + "in product form (" +
           operator_backend(settings.solver.backend)
             .preconditioner_description +
           ")";
  }



  template <int dim>
  std::vector<std::string>
  AugmentedLagrangianScheme<dim>::warnings() const
  {
    return model.warnings();
  }



  template <int dim>
  void
  AugmentedLagrangianScheme<dim>::initialize(BlockVector &state,
                                             const double tau)
  {
    // V from the inner problem (Algorithm 3.1), P = P0 at every node
    model.initialize(state, tau, solver_type);
    state.block(Field::P) = parameters.initial_multiplier;
    discretization.distribute_constraints(state);
    next_penalty = parameters.initial_penalty;
  }



  template <int dim>
  void
  AugmentedLagrangianScheme<dim>::prepare_step(BlockVector &state,
                                               const double state_tau,
                                               const double tau) const
  {
    // P is proportional to tau, as in the nested scheme
    model.prepare_step(state, state_tau, tau);
  }



  template <int dim>
  AugmentedLagrangianControl
  AugmentedLagrangianScheme<dim>::control() const
  {
    AugmentedLagrangianControl c;
    c.gradient_tolerance          = parameters.gradient_tolerance;
    c.constraint_tolerance        = parameters.constraint_tolerance;
    c.initial_penalty             = next_penalty;
    c.max_outer_iterations        = parameters.max_outer_iterations;
    c.trust_region.max_iterations = parameters.max_trust_region_iterations;
    c.max_total_trust_region_iterations =
      parameters.max_step_trust_region_iterations;
    c.max_total_cg_iterations        = parameters.max_step_cg_iterations;
    c.trust_region.max_cg_iterations = parameters.max_cg_iterations;
    c.rol_trust_region               = parameters.rol_trust_region;
    return c;
  }



  template <int dim>
  StepReport
  AugmentedLagrangianScheme<dim>::advance(const BlockVector &old_state,
                                          BlockVector       &state,
                                          const double       tau)
  {
    AugmentedLagrangianStep<dim> step(discretization,
                                      model.coefficients(tau),
                                      old_state.block(Field::U),
                                      parameters.scaled);
    if (schur_solver)
      step.set_schur_solver(*schur_solver);
    BlockVector start        = step.make_point();
    start.block(0)           = state.block(Field::U);
    start.block(1)           = state.block(Field::V);
    const double start_value = step.objective(start);

    // Algorithm 2.1 is not monotone: at a small penalty the first
    // subproblems may leave the constraint set and the outer loop return
    // to a critical point of higher outer energy. Then the step is
    // repeated from the same start with a penalty penalty_growth times
    // larger, which keeps the iterates nearer the constraint set.
    StepReport                 report;
    BlockVector                x(start);
    Vector                     p(state.block(Field::P));
    AugmentedLagrangianControl control_now = control();
    for (unsigned int attempt = 0;; ++attempt)
      {
        if (attempt > 0)
          {
            x = start;
            p = state.block(Field::P);
          }
        const AugmentedLagrangianReport al = augmented_lagrangian_minimize(
          step, x, p, control_now, pcout, settings.verbose);
        add_to_report(al, report);
        const double end_value = al.converged ? step.objective(x) : 0.;
        const bool   rises =
          al.converged &&
          end_value - start_value >
            AugmentedLagrangian::monotonicity_tolerance * std::abs(start_value);
        if (!al.converged || !rises)
          {
            report.converged = al.converged;
            if (al.converged)
              next_penalty =
                std::max(al.final_penalty / parameters.penalty_reduction,
                         parameters.initial_penalty);
            else
              report_failure(al);
            break;
          }
        if (attempt == AugmentedLagrangian::max_monotonicity_retries)
          {
            pcout << "  augmented Lagrangian: the step ends above the outer "
                     "energy of its start also with the penalty "
                  << control_now.initial_penalty << "; the step is halved."
                  << std::endl;
            report.converged = false;
            break;
          }
        control_now.initial_penalty *= AugmentedLagrangian::penalty_growth;
        if (settings.verbose)
          pcout << "    the outer energy rose from " << start_value << " to "
                << end_value << ": step repeated with lambda0 = "
                << control_now.initial_penalty << std::endl;
      }
    state.block(Field::U) = x.block(0);
    state.block(Field::V) = x.block(1);
    state.block(Field::P) = p;
    preconditioner_setups += step.n_setups();
    return report;
  }



  template <int dim>
  void
  AugmentedLagrangianScheme<dim>::add_to_report(
    const AugmentedLagrangianReport &al,
    StepReport                      &report)
  {
    report.newton_iterations += al.tr_iterations;
    report.linear_iterations += al.cg_iterations;
    report.add_count("al_iterations", al.outer_iterations);
    report.add_count("tr_iterations", al.tr_iterations);
    if (report.initial_residual_norm == 0)
      report.initial_residual_norm =
        std::max(al.initial_gradient_norm, al.initial_constraint_norm);
    report.final_residual_norm = std::max(al.gradient_norm, al.constraint_norm);
  }



  template <int dim>
  void
  AugmentedLagrangianScheme<dim>::report_failure(
    const AugmentedLagrangianReport &al) const
  {
    pcout << "  augmented Lagrangian: no convergence after "
          << al.outer_iterations << " outer, " << al.tr_iterations
          << " trust-region and " << al.cg_iterations
          << " CG iterations (|grad l_A| = " << al.gradient_norm
          << ", |C| = " << al.constraint_norm
          << "); raise <Augmented Lagrangian / Maximum outer iterations>, "
             "<Maximum trust-region iterations>, <Maximum CG iterations> "
             "(or their limits per step) or lower <Time stepping / Tau>."
          << std::endl;
  }



  template <int dim>
  void
  AugmentedLagrangianScheme<dim>::before_remesh()
  {
    // the penalty carries over re-meshing, and the Schur preconditioner
    // is set up anew in every trust-region iteration; a direct solver
    // forgets the factorisation (and analysis) of the old mesh
    if (schur_solver)
      schur_solver->reset();
  }



  template <int dim>
  void
  AugmentedLagrangianScheme<dim>::after_remesh(BlockVector &state,
                                               const double tau)
  {
    if (!settings.outer_energy.has_restoration_terms())
      return;
    // V and its adjoint P solved for the new mesh (as the nested scheme
    // does, from V = U); the multiplier of the augmented Lagrangian is -2s
    // times that P
    state.block(Field::V) = state.block(Field::U);
    model.solve_inner_problem(state, tau, solver_type);
    state.block(Field::P) *=
      -AugmentedLagrangianStep<dim>::objective_scale(model.coefficients(tau),
                                                     parameters.scaled);
  }


  template <int dim>
  bool
  AugmentedLagrangianScheme<dim>::restores_after_remesh(
    const unsigned int field) const
  {
    return field != Field::U && settings.outer_energy.has_restoration_terms();
  }



  template <int dim>
  void
  AugmentedLagrangianScheme<dim>::reset_solver()
  {
    next_penalty = parameters.initial_penalty;
    if (schur_solver)
      schur_solver->reset();
  }



  template <int dim>
  Energies
  AugmentedLagrangianScheme<dim>::energies(const BlockVector &state) const
  {
    return model.energies(state);
  }



  template <int dim>
  void
  AugmentedLagrangianScheme<dim>::curvature(const BlockVector &state,
                                            Vector            &curvature) const
  {
    model.curvature(state, curvature);
  }



  template <int dim>
  double
  AugmentedLagrangianScheme<dim>::energy_law_energy(
    const Energies &energies) const
  {
    return model.energy_law_energy(energies);
  }



  template <int dim>
  double
  AugmentedLagrangianScheme<dim>::dissipation(const BlockVector &old_state,
                                              const BlockVector &state,
                                              const double       tau) const
  {
    return model.dissipation(old_state, state, tau);
  }



  template class AugmentedLagrangianStep<2>;
  template class AugmentedLagrangianStep<3>;
  template class AugmentedLagrangianScheme<2>;
  template class AugmentedLagrangianScheme<3>;
} // namespace PhaseField
