#include <cmath>
#include <phasefield/core/parameters.h>
#include <phasefield/problems/biharmonic_parameters.h>
#include <phasefield/schemes/scheme_registry.h>

namespace PhaseField
{
  using namespace dealii;

  namespace
  {
    /**
     * Relative slack when counting time steps, so that a final time that
     * is a multiple of Tau up to a printed precision of six digits (the
     * thesis writes 0.00244141 for 10 * 2^-12) is not counted as one step
     * more.
     */
    constexpr double step_count_slack = 1e-4;

    /** Separator of parameter subsection and name in messages. */
    std::string
    parameter_name(const std::string &subsection, const std::string &name)
    {
      return subsection + " / " + name;
    }
  } // namespace



  std::string
  BiharmonicProblemParameters::boundary_conditions_name() const
  {
    switch (boundary_conditions)
      {
        case BiharmonicBoundaryConditions::dirichlet:
          return "dirichlet";
        case BiharmonicBoundaryConditions::neumann:
          return "neumann";
        case BiharmonicBoundaryConditions::periodic:
          return "periodic";
      }
    return "";
  }



  void
  BiharmonicProblemParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Problem");
    prm.declare_entry(
      "Boundary conditions",
      "dirichlet",
      Patterns::Selection("dirichlet|neumann|periodic"),
      "dirichlet: u = Lap u = 0 on the boundary of [0,1]^d (U, V, P vanish "
      "on the boundary) with the forcing and exact solution of thesis "
      "Lemma 4.5, u = (e^{20t}-1) prod_i g(x_i), g(s) = s^4-2s^3+s. "
      "neumann: natural boundary conditions d_n u = d_n Lap u = 0, exact "
      "solution e^{-pi^4 t} sum_i cos(pi x_i) (thesis Lemma 7.2). periodic: "
      "the unit cell, exact solution (e^{20t}-1) sum_i cos(2 pi x_i) with "
      "the forcing f = d_t u + Lap^2 u.");
    prm.leave_subsection();
  }



  void
  BiharmonicProblemParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Problem");
    const std::string bc = prm.get("Boundary conditions");
    boundary_conditions =
      (bc == "dirichlet" ? BiharmonicBoundaryConditions::dirichlet :
       bc == "neumann"   ? BiharmonicBoundaryConditions::neumann :
                           BiharmonicBoundaryConditions::periodic);
    prm.leave_subsection();
  }



  void
  ConvergenceParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Convergence");
    prm.declare_entry("Levels",
                      "3,4,5,6",
                      Patterns::Anything(),
                      "Comma separated, strictly increasing refinement "
                      "levels of the uniform meshes of the study: h = "
                      "2^-level on [0,1]^d.");
    prm.leave_subsection();
  }



  void
  ConvergenceParameters::parse_parameters(ParameterHandler &prm)
  {
    const std::string name = parameter_name("Convergence", "Levels");
    prm.enter_subsection("Convergence");
    levels =
      parse_integer_list(prm.get("Levels"), name, 1, max_mesh_level, true);
    prm.leave_subsection();
  }



  BiharmonicTimeParameters::StepSizes
  BiharmonicTimeParameters::step_sizes(const double h) const
  {
    const std::string tau_name   = parameter_name("Time stepping", "Tau");
    const std::string inner_name = parameter_name("Time stepping", "Inner tau");
    const double      requested_tau =
      evaluate_expression_in_h(tau_expression, h, tau_name);
    StepSizes s;
    s.inner_tau = evaluate_expression_in_h(inner_tau_expression, h, inner_name);
    const auto check_positive = [h](const double       value,
                                    const std::string &name,
                                    const std::string &expression) {
      if (!(value > 0))
        throw InputError("The parameter <" + name + "> = <" + expression +
                         "> evaluates to " + std::to_string(value) +
                         " at h = " + std::to_string(h) +
                         ", but must be positive.");
    };
    check_positive(requested_tau, tau_name, tau_expression);
    check_positive(s.inner_tau, inner_name, inner_tau_expression);

    s.n_steps = static_cast<unsigned int>(
      std::ceil(final_time / requested_tau * (1 - step_count_slack)));
    s.n_steps = std::max(s.n_steps, 1u);
    s.tau     = final_time / s.n_steps;
    return s;
  }



  void
  BiharmonicTimeParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Time stepping");
    prm.declare_entry("Tau",
                      "h^2",
                      Patterns::Anything(),
                      "Outer time step, an expression in the mesh size h "
                      "(e.g. h, h^2). If Final time is not a multiple of "
                      "it, the step is reduced to Final time / "
                      "ceil(Final time / Tau) so that all steps are equal.");
    prm.declare_entry("Inner tau",
                      "h^2",
                      Patterns::Anything(),
                      "Inner time step (approximation of the Laplacian), an "
                      "expression in h.");
    prm.declare_entry("Final time",
                      "0.00244140625",
                      Patterns::Double(0.),
                      "Time at which the errors are measured.");
    prm.leave_subsection();
  }



  void
  BiharmonicTimeParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Time stepping");
    tau_expression       = prm.get("Tau");
    inner_tau_expression = prm.get("Inner tau");
    final_time           = prm.get_double("Final time");
    prm.leave_subsection();
    if (!(final_time > 0))
      throw InputError("The parameter <" +
                       parameter_name("Time stepping", "Final time") +
                       "> must be positive.");
  }



  void
  BiharmonicParameters::declare_parameters(ParameterHandler &prm)
  {
    declare_common_parameters(prm, "Directory for convergence.csv.");
    BiharmonicProblemParameters::declare_parameters(prm);
    ConvergenceParameters::declare_parameters(prm);
    BiharmonicTimeParameters::declare_parameters(prm);
    declare_scheme_parameters(prm);
    LinearSolverParameters::declare_parameters(prm);
  }



  void
  BiharmonicParameters::parse_parameters(ParameterHandler &prm)
  {
    dimension        = prm.get_integer("Dimension");
    output_directory = prm.get("Output directory");
    problem.parse_parameters(prm);
    convergence.parse_parameters(prm);
    time.parse_parameters(prm);
    const ModelTerms needed =
      ModelTerms().with("forcing").with("biharmonic model");
    time.scheme = parse_scheme_parameters(prm, needed, "biharmonic_flow");
    linear_solver.parse_parameters(prm);
    // Validate the step sizes of every level before any computation.
    for (const unsigned int level : convergence.levels)
      time.step_sizes(std::ldexp(1.0, -static_cast<int>(level)));
  }
} // namespace PhaseField
