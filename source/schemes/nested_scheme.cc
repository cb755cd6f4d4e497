#include <cmath>
#include <deal.II/base/conditional_ostream.h>
#include <optional>
#include <phasefield/mesh/operator_backend.h>
#include <phasefield/schemes/nested/constrained_nested_step.h>
#include <phasefield/schemes/nested_scheme.h>
#include <phasefield/solvers/descent_solver.h>
#include <phasefield/solvers/newton_solver.h>

namespace PhaseField
{
  using namespace dealii;

  // ---------------------------------------------------------------------
  // The scheme: Algorithm 3.1, one step per time step, the energy law
  // ---------------------------------------------------------------------

  template <int dim>
  NestedScheme<dim>::NestedScheme(const SchemeSettings      &settings,
                                  const Discretization<dim> &discretization,
                                  const ConditionalOStream  &pcout)
    : settings(settings)
    , discretization(discretization)
    , pcout(pcout)
    , model(settings, discretization)
    , linear_solver(std::make_unique<LinearSolver>(
        settings.solver.type,
        settings.linear_solver.relative_tolerance,
        settings.linear_solver.max_iterations,
        /*symmetric=*/true,
        settings.outer_energy.has_restoration_terms() ?
          full_system_refactorization_threshold :
          LinearSolver::default_refactorization_threshold,
        settings.outer_energy.has_restoration_terms() ?
          full_system_refactorization_threshold :
          0))
    , mesh_matrices(std::make_unique<NestedMatrices<dim>>())
    , constraints(ScalarConstraints::of(settings.outer_energy))
  {
    linear_solver->set_constant_matrix(linear_model());
    // every step passes mesh_matrices, refilled in place; reset_solver()
    // replaces both together
    linear_solver->set_persistent_matrices(true);
  }



  template <int dim>
  bool
  NestedScheme<dim>::linear_model() const
  {
    return !settings.double_well &&
           !settings.outer_energy.has_restoration_terms();
  }



  template <int dim>
  std::string
  NestedScheme<dim>::name() const
  {
    return "nested";
  }



  template <int dim>
  std::vector<std::string>
  NestedScheme<dim>::field_names() const
  {
    return {"U", "V", "P"};
  }



  template <int dim>
  std::string
  NestedScheme<dim>::linear_solver_description() const
  {
    if (linear_solver->type() == LinearSolverType::direct)
      return "direct (MUMPS)";
    return operator_backend(settings.solver.backend).solver_description;
  }



  template <int dim>
  std::vector<std::string>
  NestedScheme<dim>::warnings() const
  {
    return model.warnings();
  }



  template <int dim>
  NestedCoefficients
  NestedScheme<dim>::coefficients(const double tau) const
  {
    return model.coefficients(tau);
  }



  template <int dim>
  void
  NestedScheme<dim>::initialize(BlockVector &state, const double tau)
  {
    model.initialize(state, tau, linear_solver->type());
    if (constraints)
      constraints->set_missing_targets(discretization.get_operators(),
                                       state.block(Field::U));
    first_step_from_initial_data = true;
  }



  template <int dim>
  void
  NestedScheme<dim>::prepare_step(BlockVector &state,
                                  const double state_tau,
                                  const double tau) const
  {
    model.prepare_step(state, state_tau, tau);
  }



  template <int dim>
  StepReport
  NestedScheme<dim>::advance(const BlockVector &old_state,
                             BlockVector       &state,
                             const double       tau)
  {
    const StepReport report = attempt_step(old_state, state, tau);
    // The first step from the initial data ends when it is accepted: its
    // halved attempts keep the descent fallback (the level-8 cube: Newton's
    // method failed at tau and at tau/2)
    if (report.converged)
      first_step_from_initial_data = false;
    return report;
  }



  template <int dim>
  StartExtrapolation
  NestedScheme<dim>::start_extrapolation() const
  {
    return solves_by_descent() ? StartExtrapolation::profile :
                                 StartExtrapolation::linear;
  }



  template <int dim>
  bool
  NestedScheme<dim>::take_extrapolated_start(const BlockVector &old_state,
                                             const BlockVector &last_result,
                                             BlockVector       &extrapolated,
                                             const double       tau) const
  {
    NestedStep<dim> step(discretization,
                         coefficients(tau),
                         old_state.block(Field::U));
    if (solves_by_descent())
      {
        model.solve_inner_problem(extrapolated, tau, linear_solver->type());
        if (settings.verbose)
          pcout << "    descent method: U extrapolated, V and P re-solved"
                << std::endl;
        return true;
      }
    BlockVector residual(last_result);
    const auto  norm_at = [&](const BlockVector &start) {
      step.residual(start, residual);
      return step.residual_norm(residual);
    };
    const double last_norm         = norm_at(last_result);
    const double extrapolated_norm = norm_at(extrapolated);
    if (settings.verbose)
      pcout << "    residual " << extrapolated_norm
            << " at the extrapolated start, " << last_norm
            << " at the last result" << std::endl;
    return extrapolated_norm < last_norm;
  }



  template <int dim>
  bool
  NestedScheme<dim>::solves_by_descent() const
  {
    return settings.outer_energy.fixed_u != nullptr;
  }



  template <int dim>
  StepReport
  NestedScheme<dim>::attempt_step(const BlockVector &old_state,
                                  BlockVector       &state,
                                  const double       tau)
  {
    NestedStep<dim> step(discretization,
                         coefficients(tau),
                         old_state.block(Field::U),
                         mesh_matrices.get());
    NewtonControl   control(settings.newton);
    // a linear system is solved once to the solver's tolerance, not
    // loosely first as inexact Newton does
    control.adapt_linear_tolerance = !linear_model();
    if (linear_model())
      return newton_solve(
        step, state, control, *linear_solver, pcout, settings.verbose);
    if (constraints)
      return constrained_solve(
        step, old_state.block(Field::U), state, tau, control);
    // With U fixed outside a region (edge restoration), and in the first
    // step after initialize() with restoration terms, the descent method
    // directly. Otherwise Newton's method with residual damping first: it
    // needs no inner problems and reaches the same states in less time
    // (doc/benchmarks.md, "Choices in the code").
    const bool first_step  = first_step_from_initial_data;
    const bool restoration = settings.outer_energy.has_restoration_terms();
    if (solves_by_descent() || (first_step && restoration))
      return descent_solve(step, state, control);
    // the start of the step is kept only where the descent method may
    // need it (a block vector: 8 B per DoF at the peak of a step)
    const bool                 descent_fallback = restoration || first_step;
    std::optional<BlockVector> start;
    if (descent_fallback)
      start.emplace(state);
    const StepReport newton = newton_solve(
      step, state, control, *linear_solver, pcout, settings.verbose);
    // Where Newton's method fails, the descent method takes the step from
    // its start before it is halved: the nested step is the minimiser of
    // the outer energy, which every descent iteration lowers (the level-7
    // cube, whose full first step Newton's method could not take). In
    // the Willmore flow only in the first step from the initial data: a
    // later failure means that the flow moves fast, and halving resolves
    // it, where the descent method may find a far lower minimiser (the
    // demo's two circles at step 14: W 25.2 -> 8.9 in one step).
    if (newton.converged || !descent_fallback)
      return newton;
    pcout << "    Newton's method failed: the descent method from the "
             "start of the step"
          << std::endl;
    state = *start;
    NewtonControl descent_control(control);
    descent_control.max_iterations = settings.newton.max_descent_iterations;
    return combine(newton, descent_solve(step, state, descent_control));
  }



  template <int dim>
  bool
  NestedScheme<dim>::energy_law_applies_from(const BlockVector &old_state) const
  {
    if (!constraints)
      return true;
    for (unsigned int j = 0; j < constraints->size(); ++j)
      {
        const double value  = constraints->value(j,
                                                discretization.get_operators(),
                                                old_state.block(Field::U));
        const double target = constraints->target(j);
        if (std::abs(value - target) > feasibility_tolerance * std::abs(target))
          return false;
      }
    return true;
  }



  template <int dim>
  StepReport
  NestedScheme<dim>::constrained_solve(NestedStep<dim>     &step,
                                       const Vector        &old_u,
                                       BlockVector         &state,
                                       const double         tau,
                                       const NewtonControl &control)
  {
    constraints->set_missing_targets(discretization.get_operators(), old_u);
    ConstrainedNestedStep<dim> system(step, *constraints, discretization);
    std::vector<double>        lambda(constraints->size());
    for (unsigned int j = 0; j < lambda.size(); ++j)
      lambda[j] =
        constraints->to_residual_units(tau) * constraints->multiplier(j);
    BlockVector      z = system.extended_state(state, lambda);
    const StepReport report =
      newton_solve(system, z, control, *linear_solver, pcout, settings.verbose);
    ConstrainedNestedStep<dim>::copy_nested_state(z, state);
    if (report.converged)
      {
        lambda = system.multipliers(z);
        for (unsigned int j = 0; j < lambda.size(); ++j)
          constraints->set_multiplier(j,
                                      lambda[j] /
                                        constraints->to_residual_units(tau));
      }
    return report;
  }



  template <int dim>
  StepReport
  NestedScheme<dim>::descent_solve(NestedStep<dim>     &step,
                                   BlockVector         &state,
                                   const NewtonControl &control)
  {
    // Minimise the outer energy over U with V, P re-solved for every
    // trial U, so that the energy decreases at every iteration (for edge
    // restoration, Newton's method alone converged to critical points
    // that are not minimisers). The inner problem is convex; its own
    // solver keeps the factorisation of K(V).
    const std::unique_ptr<LinearSolver> inner_solver =
      model.make_solver(linear_solver->type());
    step.set_inner_solver(*inner_solver);
    return minimizing_newton_solve(
      step, state, control, *linear_solver, pcout, settings.verbose);
  }



  template <int dim>
  void
  NestedScheme<dim>::reset_solver()
  {
    linear_solver->reset();
    mesh_matrices = std::make_unique<NestedMatrices<dim>>();
  }



  template <int dim>
  void
  NestedScheme<dim>::before_remesh()
  {
    reset_solver();
  }



  template <int dim>
  void
  NestedScheme<dim>::after_remesh(BlockVector &state, const double tau)
  {
    reset_solver();
    // V and P are not carried by the transfer (an interpolated V would
    // not be the inner minimiser on the new mesh, and with restoration
    // terms the energy of the state not the one the next step decreases):
    // solved for U, with U as the start of the inner Newton iteration
    state.block(Field::V) = state.block(Field::U);
    model.solve_inner_problem(state, tau, linear_solver->type());
  }



  template <int dim>
  bool
  NestedScheme<dim>::restores_after_remesh(const unsigned int field) const
  {
    return field != Field::U;
  }



  template <int dim>
  Energies
  NestedScheme<dim>::energies(const BlockVector &state) const
  {
    return model.energies(state);
  }



  template <int dim>
  void
  NestedScheme<dim>::curvature(const BlockVector &state,
                               Vector            &curvature) const
  {
    model.curvature(state, curvature);
  }



  template <int dim>
  double
  NestedScheme<dim>::energy_law_energy(const Energies &energies) const
  {
    return model.energy_law_energy(energies);
  }



  template <int dim>
  double
  NestedScheme<dim>::energy_law_tolerance() const
  {
    return settings.outer_energy.data_term != nullptr ?
             data_term_energy_law_tolerance :
             TimeSteppingScheme<dim>::energy_law_tolerance();
  }



  template <int dim>
  double
  NestedScheme<dim>::dissipation(const BlockVector &old_state,
                                 const BlockVector &state,
                                 const double       tau) const
  {
    return model.dissipation(old_state, state, tau);
  }



  template class NestedScheme<2>;
  template class NestedScheme<3>;
} // namespace PhaseField
