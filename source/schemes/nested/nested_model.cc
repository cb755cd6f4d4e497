#include <cmath>
#include <phasefield/core/constants.h>
#include <phasefield/schemes/energy_term_registry.h>
#include <phasefield/schemes/nested/nested_model.h>
#include <phasefield/schemes/nested/nested_step.h>

namespace PhaseField
{
  template <int dim>
  NestedModel<dim>::NestedModel(const SchemeSettings      &settings,
                                const Discretization<dim> &discretization)
    : settings(settings)
    , discretization(discretization)
  {}



  template <int dim>
  NestedCoefficients
  NestedModel<dim>::coefficients(const double tau) const
  {
    NestedCoefficients c;
    c.epsilon     = settings.epsilon;
    c.tau         = tau;
    c.inner_tau   = settings.inner_tau;
    c.double_well = settings.double_well;
    c.outer       = settings.outer_energy;
    return c;
  }



  template <int dim>
  std::vector<std::string>
  NestedModel<dim>::warnings() const
  {
    if (settings.double_well &&
        settings.inner_tau >= 0.5 * std::pow(settings.epsilon, 2))
      return {"Inner tau >= epsilon^2/2; the inner (Allen-Cahn) energy is "
              "then not convex and Newton may fail."};
    return {};
  }



  template <int dim>
  std::unique_ptr<LinearSolver>
  NestedModel<dim>::make_solver(const LinearSolverType type) const
  {
    return std::make_unique<LinearSolver>(
      type,
      settings.linear_solver.relative_tolerance,
      settings.linear_solver.max_iterations);
  }



  template <int dim>
  void
  NestedModel<dim>::initialize(BlockVector           &state,
                               const double           tau,
                               const LinearSolverType type) const
  {
    const NestedStep<dim> step(discretization,
                               coefficients(tau),
                               state.block(Field::U));
    // its own solver: the factorisations of K are no use for S later
    const std::unique_ptr<LinearSolver> solver = make_solver(type);
    constexpr double                    initialization_tolerance = 1e-10;
    step.initialize_v_and_p(state, *solver, initialization_tolerance);
    discretization.distribute_constraints(state);
  }



  template <int dim>
  void
  NestedModel<dim>::solve_inner_problem(BlockVector           &state,
                                        const double           tau,
                                        const LinearSolverType type) const
  {
    const std::unique_ptr<LinearSolver> solver = make_solver(type);
    NestedStep<dim>(discretization, coefficients(tau), state.block(Field::U))
      .solve_inner_problem(state, *solver, NestedStep<dim>::inner_tolerance);
  }



  template <int dim>
  void
  NestedModel<dim>::prepare_step(BlockVector &state,
                                 const double state_tau,
                                 const double tau) const
  {
    if (tau != state_tau)
      state.block(Field::P) *= tau / state_tau;
  }



  template <int dim>
  Energies
  NestedModel<dim>::energies(const BlockVector &state) const
  {
    const LumpedOperators<dim> &ops = discretization.get_operators();
    Vector                      curvature_field(state.block(Field::U));
    curvature(state, curvature_field);
    Energies e =
      phase_field_energies(ops, state.block(Field::U), settings.epsilon);
    e.willmore = Constants::geometric_unit * 0.5 * settings.epsilon *
                 ops.mass_product(curvature_field, curvature_field);
    if (settings.outer_energy.data_term != nullptr)
      e.data_term =
        settings.outer_energy.data_term->value(state.block(Field::U));
    e.registered_terms = registered_terms_energy(settings.outer_energy,
                                                 ops,
                                                 state.block(Field::U));
    return e;
  }



  template <int dim>
  void
  NestedModel<dim>::curvature(const BlockVector &state, Vector &curvature) const
  {
    curvature = state.block(Field::U);
    curvature -= state.block(Field::V);
    curvature /= settings.inner_tau;
  }



  template <int dim>
  double
  NestedModel<dim>::energy_law_energy(const Energies &energies) const
  {
    // the data term and the registered terms enter the step's energy as
    // mu W and eta A do in thesis units, so in geometric units with the
    // factor 3/4
    return weighted_regularisation(settings.outer_energy, energies) +
           Constants::geometric_unit * energies.data_term +
           Constants::geometric_unit * energies.registered_terms;
  }



  template <int dim>
  double
  NestedModel<dim>::dissipation(const BlockVector &old_state,
                                const BlockVector &state,
                                const double       tau) const
  {
    Vector difference(state.block(Field::U));
    difference -= old_state.block(Field::U);
    return Constants::geometric_unit * settings.epsilon / (2 * tau) *
           discretization.get_operators().mass_product(difference, difference);
  }



  template class NestedModel<2>;
  template class NestedModel<3>;
} // namespace PhaseField
