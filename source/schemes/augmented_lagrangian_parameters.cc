#include <deal.II/base/mpi.h>
#include <phasefield/core/parameters.h>
#include <phasefield/schemes/augmented_lagrangian_parameters.h>
#include <sstream>

namespace PhaseField
{
  using namespace dealii;

  void
  AugmentedLagrangianParameters::declare_parameters(ParameterHandler &prm)
  {
    const AugmentedLagrangianParameters defaults;
    const auto                          text = [](const auto value) {
      std::ostringstream stream;
      stream << value;
      return stream.str();
    };
    prm.enter_subsection("Augmented Lagrangian");
    prm.declare_entry("Gradient tolerance",
                      text(defaults.gradient_tolerance),
                      Patterns::Double(0),
                      "w*: the outer loop (thesis Algorithm 2.1) stops when "
                      "||grad l_A||_L2 <= w* and ||C||_L2 <= eta*.");
    prm.declare_entry("Constraint tolerance",
                      text(defaults.constraint_tolerance),
                      Patterns::Double(0),
                      "eta*: tolerance of the L2 norm of the constraint "
                      "C(U,V) (the inner Allen-Cahn equation).");
    prm.declare_entry("Initial penalty",
                      text(defaults.initial_penalty),
                      Patterns::Double(0),
                      "lambda0: the penalty of the first step; each later "
                      "step starts from max(lambda_final / <Penalty "
                      "reduction per step>, lambda0). At most 1e16.");
    prm.declare_entry(
      "Penalty reduction per step",
      text(defaults.penalty_reduction),
      Patterns::Double(1),
      "Each step after the first starts from the final penalty of the "
      "previous step divided by this, but not below lambda0 (thesis: "
      "100^2). 10 needs fewer trust-region iterations per step than "
      "100^2 (doc/willmore_flow.md, \"Penalty per step\").");
    prm.declare_entry("Initial multiplier",
                      text(defaults.initial_multiplier),
                      Patterns::Double(),
                      "P0: the multiplier at every node at the start of the "
                      "run (later steps start from the last one).");
    prm.declare_entry("Scaled",
                      defaults.scaled ? "true" : "false",
                      Patterns::Bool(),
                      "true: the outer energy divided by epsilon (thesis "
                      "(7.9)); false: e_out itself.");
    prm.declare_entry("Maximum outer iterations",
                      text(defaults.max_outer_iterations),
                      Patterns::Integer(1),
                      "Multiplier/penalty updates per step before the step "
                      "is halved.");
    prm.declare_entry("Maximum trust-region iterations",
                      text(defaults.max_trust_region_iterations),
                      Patterns::Integer(1),
                      "Trust-region iterations per minimisation of l_A "
                      "before the step is halved.");
    prm.declare_entry(
      "Maximum trust-region iterations per step",
      text(defaults.max_step_trust_region_iterations),
      Patterns::Integer(1),
      "Trust-region iterations of one attempt of a time step, summed over "
      "its outer iterations, before the step is halved. With <Maximum CG "
      "iterations per step> it bounds the work of an attempt, and a step "
      "has at most <Newton / Maximum step halvings> + 1 attempts, so that "
      "every step ends (a step that the augmented Lagrangian cannot take, "
      "e.g. on a mesh far too coarse for epsilon, fails instead of "
      "running for hours).");
    prm.declare_entry(
      "Maximum CG iterations per step",
      text(defaults.max_step_cg_iterations),
      Patterns::Integer(1),
      "Truncated-CG iterations of one attempt of a time step, summed over "
      "its trust-region and outer iterations, before the step is halved "
      "(own trust region only; see Maximum trust-region iterations per "
      "step).");
    prm.declare_entry("Maximum CG iterations",
                      text(defaults.max_cg_iterations),
                      Patterns::Integer(1),
                      "Truncated-CG iterations per trust-region step.");
    prm.declare_entry("Trust-region solver",
                      defaults.rol_trust_region ? "rol" : "own",
                      Patterns::Selection("own|rol"),
                      "own: our Steihaug-Toint trust region "
                      "(solvers/trust_region.h); rol: Trilinos ROL's "
                      "trust-region algorithm with truncated CG, the same "
                      "constants, Hessian products and preconditioner "
                      "(solvers/rol_trust_region.h), for comparison.");
    prm.leave_subsection();
  }



  void
  AugmentedLagrangianParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Augmented Lagrangian");
    gradient_tolerance   = prm.get_double("Gradient tolerance");
    constraint_tolerance = prm.get_double("Constraint tolerance");
    initial_penalty      = prm.get_double("Initial penalty");
    penalty_reduction    = prm.get_double("Penalty reduction per step");
    initial_multiplier   = prm.get_double("Initial multiplier");
    scaled               = prm.get_bool("Scaled");
    max_outer_iterations = prm.get_integer("Maximum outer iterations");
    max_trust_region_iterations =
      prm.get_integer("Maximum trust-region iterations");
    max_step_trust_region_iterations =
      prm.get_integer("Maximum trust-region iterations per step");
    max_step_cg_iterations = prm.get_integer("Maximum CG iterations per step");
    max_cg_iterations      = prm.get_integer("Maximum CG iterations");
    rol_trust_region       = prm.get("Trust-region solver") == "rol";
    prm.leave_subsection();
    if (!(gradient_tolerance > 0) || !(constraint_tolerance > 0))
      throw InputError("<Augmented Lagrangian / Gradient tolerance> and "
                       "<Constraint tolerance> must be positive.");
    if (!(initial_penalty > 0))
      throw InputError(
        "<Augmented Lagrangian / Initial penalty> must be positive.");
    // lambda |C|^2 / 2 against the objective: beyond 1 / round-off the
    // objective drowns in the round-off of the penalty term (and at 1e300
    // the matrices overflow)
    constexpr double largest_initial_penalty = 1e16;
    if (initial_penalty > largest_initial_penalty)
      throw InputError(
        "<Augmented Lagrangian / Initial penalty> = " +
        number_text(initial_penalty) +
        " is above 1e16: the objective would drown in the round-off of the "
        "penalty term, and the matrices of the steps overflow. The penalty "
        "grows by itself where the constraint needs it; start from e.g. 10.");
    // on 2 ranks ROL's trust region does not reach the gradient
    // tolerance of tests/rol_trust_region.cc (not investigated)
    if (rol_trust_region &&
        dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
      throw InputError("<Augmented Lagrangian / Trust-region solver> = rol "
                       "runs on one MPI rank only (a comparison option); "
                       "use <Trust-region solver> = own with several ranks.");
  }
} // namespace PhaseField
