#include <algorithm>
#include <cctype>
#include <cmath>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/base/utilities.h>
#include <filesystem>
#include <fstream>
#include <phasefield/core/mesh_size.h>
#include <phasefield/core/message_text.h>
#include <phasefield/core/parameters.h>
#include <phasefield/core/parser_messages.h>
#include <sstream>

namespace PhaseField
{
  using namespace dealii;

  std::string
  number_text(const double value)
  {
    std::ostringstream text;
    text << value;
    return text.str();
  }



  double
  evaluate_expression_in_h(const std::string &expression,
                           const double       h,
                           const std::string &parameter_name)
  {
    double              value = std::numeric_limits<double>::quiet_NaN();
    const StderrCapture parser_output;
    try
      {
        FunctionParser<1> parser;
        parser.initialize("h", expression, {});
        value = parser.value(Point<1>(h));
      }
    catch (const ExceptionBase &exc)
      {
        throw InputError(
          "The parameter <" + parameter_name + "> has the value <" +
          abbreviated(expression) +
          ">, which is not a valid expression in h: " +
          abbreviated(parser_message(parser_output.text(), exc)) + ".");
      }
    if (!std::isfinite(value))
      throw InputError(
        "The parameter <" + parameter_name + "> = <" + abbreviated(expression) +
        "> evaluates to a non-finite number at h = " + std::to_string(h) + ".");
    return value;
  }



  std::vector<double>
  parse_double_list(const std::string &text, const std::string &parameter_name)
  {
    std::vector<double> values;
    for (const std::string &entry : Utilities::split_string_list(text, ','))
      {
        std::size_t consumed = 0;
        double      value    = 0;
        try
          {
            value = std::stod(entry, &consumed);
          }
        catch (...)
          {
            consumed = 0;
          }
        if (consumed != entry.size() || entry.empty())
          throw InputError("The parameter <" + parameter_name +
                           "> must be a comma separated list of numbers, "
                           "but contains <" +
                           entry + ">.");
        values.push_back(value);
      }
    return values;
  }



  std::vector<unsigned int>
  parse_integer_list(const std::string &text,
                     const std::string &parameter_name,
                     const unsigned int minimum,
                     const unsigned int maximum,
                     const bool         increasing)
  {
    const std::vector<double> values = parse_double_list(text, parameter_name);
    if (values.empty())
      throw InputError("The parameter <" + parameter_name +
                       "> must list at least one value.");
    std::vector<unsigned int> list;
    for (const double value : values)
      {
        if (value != std::floor(value) || value < minimum || value > maximum)
          throw InputError("The parameter <" + parameter_name +
                           "> must contain integers between " +
                           std::to_string(minimum) + " and " +
                           std::to_string(maximum) + ", but contains " +
                           std::to_string(value) + ".");
        const unsigned int entry = static_cast<unsigned int>(value);
        if (increasing && !list.empty() && entry <= list.back())
          throw InputError("The parameter <" + parameter_name +
                           "> must be strictly increasing, but " +
                           std::to_string(entry) + " follows " +
                           std::to_string(list.back()) + ".");
        list.push_back(entry);
      }
    return list;
  }



  void
  GeometryParameters::declare_parameters(ParameterHandler  &prm,
                                         const std::string &extra_shapes,
                                         const std::string &extra_documentation,
                                         const std::string &subsection,
                                         const std::string &purpose,
                                         const std::string &default_shape)
  {
    prm.enter_subsection(subsection);
    prm.declare_entry(
      "Shape",
      default_shape,
      Patterns::Selection("circle|quarter circle|rectangle|two circles|cube|"
                          "disc|sphere|ellipsoid|torus|function" +
                          (extra_shapes.empty() ? "" : "|" + extra_shapes)),
      purpose +
        ". The phase field is tanh(signed distance / epsilon), "
        "negative inside. circle/sphere: Center, Radius. quarter circle: "
        "circle around Center (default: the origin). rectangle/cube: Center, "
        "Sizes = edge lengths (one value: all edges equal). two circles: "
        "Center, Second center, Radius. disc: Center, Sizes = diameter, "
        "thickness (axis x_d). ellipsoid: Center, Sizes = semi-axes. torus: "
        "Center, Sizes = R, r (axis x_d; in 2D an annulus). function: "
        "Expression." +
        (extra_documentation.empty() ? "" : " " + extra_documentation));
    prm.declare_entry("Center",
                      "",
                      Patterns::Anything(),
                      "Comma separated centre of the shape; empty: the centre "
                      "of the unit cell, the origin for quarter circle and "
                      "(0.35, 0.5) for two circles.");
    prm.declare_entry("Second center",
                      "",
                      Patterns::Anything(),
                      "Centre of the second circle of `two circles`; empty: "
                      "(0.65, 0.5).");
    prm.declare_entry("Radius",
                      "0.13",
                      Patterns::Double(0.),
                      "Radius of circle, quarter circle, two circles, "
                      "sphere.");
    prm.declare_entry("Sizes",
                      "0.4",
                      Patterns::Anything(),
                      "Comma separated sizes: rectangle/cube edge lengths, "
                      "disc diameter and thickness, ellipsoid semi-axes, "
                      "torus R and r.");
    prm.declare_entry("Expression",
                      "sqrt((x-0.5)^2+(y-0.5)^2)-0.25",
                      Patterns::Anything(),
                      "Signed distance (negative inside) as a muParser "
                      "expression in x, y (and z in 3D); used by "
                      "Shape = function.");
    prm.leave_subsection();
  }



  void
  GeometryParameters::parse_parameters(ParameterHandler  &prm,
                                       const std::string &subsection_name)
  {
    subsection = subsection_name;
    prm.enter_subsection(subsection);
    shape  = prm.get("Shape");
    center = parse_double_list(prm.get("Center"), subsection + " / Center");
    second_center = parse_double_list(prm.get("Second center"),
                                      subsection + " / Second center");
    radius        = prm.get_double("Radius");
    sizes      = parse_double_list(prm.get("Sizes"), subsection + " / Sizes");
    expression = prm.get("Expression");
    prm.leave_subsection();
    const auto check_finite = [&](const std::vector<double> &values,
                                  const std::string         &name) {
      for (const double value : values)
        if (!std::isfinite(value))
          throw InputError("The parameter <" + subsection + " / " + name +
                           "> contains " + std::to_string(value) +
                           ", but must contain finite numbers only.");
    };
    check_finite(center, "Center");
    check_finite(second_center, "Second center");
    check_finite({radius}, "Radius");
    check_finite(sizes, "Sizes");
    for (const double s : sizes)
      if (!(s > 0))
        throw InputError("All entries of <" + subsection +
                         " / Sizes> must be positive.");
  }



  double
  MeshParameters::h() const
  {
    return std::ldexp(1.0, -static_cast<int>(finest_level));
  }



  void
  MeshParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh");
    prm.declare_entry("Finest level",
                      "7",
                      Patterns::Integer(1, 12),
                      "Finest refinement level: h = 2^-level on [0,1]^d.");
    prm.declare_entry("Coarsest level",
                      "3",
                      Patterns::Integer(0, 12),
                      "Level of the cells far from the interface.");
    prm.declare_entry("Adaptive",
                      "true",
                      Patterns::Bool(),
                      "true: narrow band of finest cells around the "
                      "interface; false: uniform mesh at Finest level, "
                      "2^(d Finest level) cells. A mesh of more than 2^24 "
                      "cells per MPI rank, or of more than the memory of a "
                      "rank at 8 KB (2D) or 1.5 KB (3D) per cell (the "
                      "machine's memory shared "
                      "by the ranks on a node, or `ulimit -v`), is "
                      "rejected before the run; for a narrow band, the "
                      "finest cells of the band around the initial "
                      "interface are estimated (a lower bound).");
    prm.declare_entry("Band width",
                      "4",
                      Patterns::Double(0.5),
                      "Cells closer to the interface than Band width * "
                      "epsilon (measured through the phase field, "
                      "|U| < tanh(Band width)) are on the finest level.");
    prm.declare_entry(
      "Refinement interval",
      "1",
      Patterns::Integer(1),
      "Check the narrow band every this many time steps (the band is "
      "wide enough for the interface to move a few epsilon in between); "
      "whether the mesh is then adapted, see Band margin.");
    prm.declare_entry(
      "Band margin",
      "1",
      Patterns::Double(0),
      "Re-mesh (at a check, see Refinement interval) only when a cell "
      "closer than (Band width - Band margin) * epsilon to the interface "
      "is not on the finest level, or a group of finest sibling cells lies "
      "farther than (Band width + Band margin) * epsilon from it; the new "
      "mesh has the full Band width again. The interface can so move Band "
      "margin * epsilon before the mesh (and a direct solver's "
      "factorisation) changes. 0: re-mesh whenever any cell would be "
      "refined or coarsened. Must be smaller than Band width.");
    prm.declare_entry(
      "Stiffness quadrature",
      "Gauss",
      Patterns::Selection("Gauss|Gauss-Lobatto"),
      "Quadrature of the stiffness matrix L. Gauss: the exact Q1 matrix "
      "(9-point stencil on a uniform 2D mesh). Gauss-Lobatto: the vertices, "
      "as for the lumped mass; on a uniform mesh the 5-point (3D: 7-point) "
      "stencil, i.e. the P1 matrix on right triangles that the thesis uses, "
      "with a smaller consistency error for the tanh profile when h is not "
      "small against epsilon (thesis Fig. 5.1 / Table 5.1 files).");
    prm.leave_subsection();
  }



  void
  MeshParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh");
    finest_level         = prm.get_integer("Finest level");
    coarsest_level       = prm.get_integer("Coarsest level");
    adaptive             = prm.get_bool("Adaptive");
    band_width           = prm.get_double("Band width");
    refinement_interval  = prm.get_integer("Refinement interval");
    band_margin          = prm.get_double("Band margin");
    stiffness_quadrature = prm.get("Stiffness quadrature") == "Gauss-Lobatto" ?
                             StiffnessQuadrature::gauss_lobatto :
                             StiffnessQuadrature::gauss;
    prm.leave_subsection();
    if (band_margin >= band_width)
      throw InputError("<Mesh / Band margin> (" + std::to_string(band_margin) +
                       ") must be smaller than <Mesh / Band width> (" +
                       std::to_string(band_width) + ").");
    if (finest_level < coarsest_level)
      throw InputError("<Mesh / Finest level> (" +
                       std::to_string(finest_level) +
                       ") must not be smaller than <Mesh / Coarsest level> (" +
                       std::to_string(coarsest_level) + ").");
  }



  void
  ModelParameters::declare_parameters(ParameterHandler &prm,
                                      const bool        with_step_counts)
  {
    prm.enter_subsection("Phase field");
    prm.declare_entry("Epsilon",
                      "4*h",
                      Patterns::Anything(),
                      "Interface width epsilon, an expression in the finest "
                      "mesh size h, e.g. 4*h or 2^-6. At least h/2 (below h "
                      "a warning: the mesh hardly resolves the interface), "
                      "and below the largest distance of a point of the "
                      "domain to the initial interface.");
    prm.leave_subsection();

    prm.enter_subsection("Time stepping");
    prm.declare_entry("Tau",
                      "h^2",
                      Patterns::Anything(),
                      "Outer (Willmore) time step, an expression in h; at "
                      "most 1.");
    prm.declare_entry("Inner tau",
                      "h^2",
                      Patterns::Anything(),
                      "Inner (mean curvature) time step, an expression in h. "
                      "Inner tau < epsilon^2/2 keeps the inner problem "
                      "convex.");
    prm.declare_entry(
      "Largest inside change factor",
      "4",
      Patterns::Double(0),
      "A step whose result has an inside measure Int (1-U)/2 more than this "
      "factor larger or smaller than before the step is rejected and "
      "retried with half the time step (see Newton / Maximum step "
      "halvings): a flow moves the interface continuously, and such a "
      "result is another branch of solutions of the step's problem (the "
      "augmented lagrangian scheme let the level-6 cube vanish in one "
      "step, inside measure 0.072 -> 0.00045, while the first step of the "
      "small quarter circle at level 5 legitimately doubles it). A step "
      "that breaks the energy law of the nested and augmented lagrangian "
      "schemes (energy + dissipation above the energy before the step) is "
      "rejected likewise. 0: no limit; otherwise at least 1.");
    if (with_step_counts)
      declare_step_counts(prm);
    StepControlParameters::declare_parameters(prm, with_step_counts);
    prm.leave_subsection();
  }



  void
  ModelParameters::declare_step_counts(ParameterHandler &prm)
  {
    prm.declare_entry("Number of steps",
                      "15",
                      Patterns::Integer(0),
                      "Number of outer time steps.");
    prm.declare_entry("Ramp-up steps",
                      "0",
                      Patterns::Integer(0, max_ramp_steps),
                      "Start-up from rough initial data: this many extra "
                      "steps come first, of sizes Tau/2^n, ..., Tau/4, "
                      "Tau/2 (n = Ramp-up steps, at most 30, so that "
                      "Tau/2^n stays far from underflow), then Number of "
                      "steps "
                      "steps of size Tau. With Tau much larger than "
                      "Inner tau^2 the first step from non-smooth data is "
                      "a hard nonlinear problem whatever its size (halving "
                      "Tau after a failure does not help); small first "
                      "steps smooth the data so that Newton converges.");
    prm.declare_entry(
      "Coarse start level",
      "0",
      Patterns::Integer(0),
      "Nested iteration for the first step. 0: Newton's method of step 1 "
      "starts from the initial data. A level l below Mesh / Finest level: "
      "step 1 is first computed on the narrow-band meshes of levels l, "
      "l+1, ..., Finest level - 1, each with Epsilon, Tau and Inner tau "
      "evaluated at its own h, from the initial data at that resolution "
      "and starting from the result of the level below with its profile "
      "sharpened to the finer epsilon; Newton's method of step 1 on "
      "Finest level then starts from the sharpened result of Finest "
      "level - 1. The step solved is the same, only the start of its "
      "iteration changes: it pays where step 1 is a long minimisation "
      "(edge restoration, where the interface crosses the damage). Level "
      "l must resolve what step 1 does (its epsilon well below the size "
      "of the damage), or the coarse steps find another critical point. "
      "l >= Finest level: no coarse start. Needs Mesh / Adaptive = true "
      "and l >= Mesh / Coarsest level; not used on resume from a "
      "checkpoint.");
    prm.declare_entry(
      "Extrapolated start",
      "true",
      Patterns::Bool(),
      "Start the iteration of a step of the nested scheme from the last "
      "result plus theta times the last change, theta = |dU_n| / "
      "|dU_(n-1)| at most 1 (the changes of the last two steps), instead "
      "of from the last result, where the residual of the step is smaller "
      "there. Only after two steps of the same size on the same mesh; "
      "re-meshing and checkpoints start the history anew. "
      "The step solved is the same, only the start of its iteration "
      "changes: nearly stationary steps need fewer iterations.");
  }



  void
  ModelParameters::parse_parameters(ParameterHandler &prm,
                                    const bool        with_step_counts)
  {
    prm.enter_subsection("Phase field");
    epsilon_expression = prm.get("Epsilon");
    prm.leave_subsection();
    prm.enter_subsection("Time stepping");
    tau_expression           = prm.get("Tau");
    inner_tau_expression     = prm.get("Inner tau");
    max_inside_change_factor = prm.get_double("Largest inside change factor");
    if (max_inside_change_factor > 0 && max_inside_change_factor < 1)
      throw InputError("<Time stepping / Largest inside change factor> = " +
                       prm.get("Largest inside change factor") +
                       " is below 1: every step would be rejected. Use a "
                       "factor of at least 1, or 0 for no limit.");
    n_steps      = with_step_counts ? prm.get_integer("Number of steps") : 0;
    n_ramp_steps = with_step_counts ? prm.get_integer("Ramp-up steps") : 0;
    coarse_start_level =
      with_step_counts ? prm.get_integer("Coarse start level") : 0;
    extrapolated_start =
      with_step_counts ? prm.get_bool("Extrapolated start") : false;
    step_control.parse_parameters(prm, with_step_counts);
    prm.leave_subsection();
  }



  void
  ModelParameters::evaluate(const double h)
  {
    epsilon =
      evaluate_expression_in_h(epsilon_expression, h, "Phase field / Epsilon");
    tau = evaluate_expression_in_h(tau_expression, h, "Time stepping / Tau");
    inner_tau                 = evaluate_expression_in_h(inner_tau_expression,
                                         h,
                                         "Time stepping / Inner tau");
    const auto check_positive = [](const double       value,
                                   const std::string &name,
                                   const std::string &expression) {
      if (!(value > 0))
        throw InputError("The parameter <" + name + "> = <" +
                         abbreviated(expression) + "> evaluates to " +
                         std::to_string(value) + ", but must be positive.");
    };
    check_positive(epsilon, "Phase field / Epsilon", epsilon_expression);
    check_positive(tau, "Time stepping / Tau", tau_expression);
    check_positive(inner_tau,
                   "Time stepping / Inner tau",
                   inner_tau_expression);
    step_control.evaluate(h, step_size(1));
    // Willmore flow moves a circle of radius r0 to (2 t + r0^4)^(1/4):
    // in a time of 1 every shape of the unit cell grows out of it
    constexpr double largest_tau = 1;
    if (tau > largest_tau)
      throw InputError("The parameter <Time stepping / Tau> = <" +
                       abbreviated(tau_expression) + "> evaluates to " +
                       number_text(tau) +
                       ", but must be at most 1: in a time of 1 Willmore "
                       "flow changes every shape in the unit cell beyond "
                       "recognition (a circle of radius r0 grows to (2 t + "
                       "r0^4)^(1/4) > 1), so one such step destroys the "
                       "interface. Use e.g. h^2 or 0.03*h.");
    // tanh(d / eps) on cells of size h: below h/2 the interface is a jump
    // between two nodes, and its energies are noise (W 1e-18 at 0.2 h)
    constexpr double smallest_epsilon_per_h = 0.5;
    if (epsilon < smallest_epsilon_per_h * h)
      throw InputError("The parameter <Phase field / Epsilon> = <" +
                       abbreviated(epsilon_expression) + "> evaluates to " +
                       std::to_string(epsilon) + " (" +
                       std::to_string(epsilon / h) +
                       " h at h = " + std::to_string(h) +
                       "), but must be at least h/2: the mesh cannot "
                       "resolve a thinner interface. Use e.g. 4*h.");
    // V - U is of the size inner tau / h^2: below this bound it is within
    // 10^4 of the round-off of U, and the curvature (U - V) / inner tau
    // is noise (or not finite: 1e-300 overflowed the inner problem)
    constexpr double smallest_inner_tau_per_h2 = 1e-12;
    if (inner_tau < smallest_inner_tau_per_h2 * h * h)
      throw InputError("The parameter <Time stepping / Inner tau> = <" +
                       abbreviated(inner_tau_expression) + "> evaluates to " +
                       std::to_string(inner_tau) + " (" +
                       std::to_string(inner_tau / (h * h)) +
                       " h^2), but must be at least 1e-12 h^2: V - U is of the "
                       "size inner tau / h^2 and would drown in round-off, "
                       "and the residuals of the steps would not be finite.");
  }



  void
  StepControlParameters::declare_parameters(ParameterHandler &prm,
                                            const bool        with_step_counts)
  {
    prm.declare_entry(
      "Stationary tolerance",
      "0",
      Patterns::Double(0),
      "0: off. > 0: the run (for shape from contour: the level) ends after "
      "the first step in which the relative change of the energy per unit "
      "time, |E(k+1) - E(k)| / (tau |E(k+1)|), is below this value, E the "
      "energy of the scheme's energy law (mu W + eta A; shape from "
      "contour: the merit function, mismatch included). Needs a scheme "
      "with an energy law (nested, augmented lagrangian).");
    if (!with_step_counts)
      return;
    prm.declare_entry(
      "Step control",
      "fixed",
      Patterns::Selection("fixed|adaptive"),
      "fixed: the steps of the schedule (Ramp-up steps, then Tau), as in "
      "the thesis. adaptive: each step size is chosen so that the "
      "estimated local error of the step stays below Tolerance (the "
      "difference of the step to the linear extrapolation of the last two "
      "steps, scaled to the error of the step; a PI controller chooses the "
      "next size from it, a step above Tolerance is retried with half the "
      "size); Tau (or the first ramp-up size) is the first step.");
    prm.declare_entry(
      "Tolerance",
      "1e-4",
      Patterns::Double(0),
      "adaptive: the local error one step may make, in the L2 norm of U "
      "over the domain (U = +-1 away from the interface, so an error e "
      "moves an interface of length L by about e^2 / (2 L) in the mean).");
    prm.declare_entry("Smallest step",
                      "0",
                      Patterns::Anything(),
                      "adaptive: the smallest step the control chooses "
                      "(an expression in h like Tau; 0: no limit). A "
                      "step at this size is not rejected for its error.");
    prm.declare_entry("Largest step",
                      "0",
                      Patterns::Anything(),
                      "adaptive: the largest step the control chooses (an "
                      "expression in h like Tau; 0: no limit).");
    prm.declare_entry(
      "End time",
      "0",
      Patterns::Anything(),
      "0: Number of steps (and Ramp-up steps) decide how long the run is. "
      "> 0: the run ends at this time (an expression in h like Tau), its "
      "last step shortened to reach it exactly; Number of steps is not "
      "used.");
  }



  void
  StepControlParameters::parse_parameters(ParameterHandler &prm,
                                          const bool        with_step_counts)
  {
    stationary_tolerance = prm.get_double("Stationary tolerance");
    if (!with_step_counts)
      return;
    control   = prm.get("Step control") == "adaptive" ? StepControl::adaptive :
                                                        StepControl::fixed;
    tolerance = prm.get_double("Tolerance");
    if (control == StepControl::adaptive && !(tolerance > 0))
      throw InputError("<Time stepping / Step control> = adaptive needs a "
                       "positive <Time stepping / Tolerance>; it is " +
                       prm.get("Tolerance") + ".");
    smallest_step_expression = prm.get("Smallest step");
    largest_step_expression  = prm.get("Largest step");
    end_time_expression      = prm.get("End time");
  }



  void
  StepControlParameters::evaluate(const double h, const double tau)
  {
    const auto evaluate_non_negative = [h](const std::string &expression,
                                           const std::string &name) {
      if (expression.empty())
        return 0.;
      const double value =
        evaluate_expression_in_h(expression, h, "Time stepping / " + name);
      if (value < 0)
        throw InputError(
          "The parameter <Time stepping / " + name + "> = <" +
          abbreviated(expression) + "> evaluates to " + std::to_string(value) +
          ", but must be positive (or 0: " +
          (name == "End time" ? "no end time" : "no limit") + ").");
      return value;
    };
    smallest_step =
      evaluate_non_negative(smallest_step_expression, "Smallest step");
    largest_step =
      evaluate_non_negative(largest_step_expression, "Largest step");
    end_time = evaluate_non_negative(end_time_expression, "End time");
    if (largest_step > 0 && smallest_step > largest_step)
      throw InputError("<Time stepping / Smallest step> = <" +
                       abbreviated(smallest_step_expression) +
                       "> = " + std::to_string(smallest_step) +
                       " is larger than <Time stepping / Largest step> = <" +
                       abbreviated(largest_step_expression) +
                       "> = " + std::to_string(largest_step) + ".");
    if (control == StepControl::adaptive &&
        (tau < smallest_step || (largest_step > 0 && tau > largest_step)))
      throw InputError(
        "With <Time stepping / Step control> = adaptive, <Time stepping / "
        "Tau> is the first step, " +
        std::to_string(tau) +
        ", but it lies outside [<Smallest step>, "
        "<Largest step>] = [" +
        std::to_string(smallest_step) + ", " + std::to_string(largest_step) +
        "].");
  }



  void
  NewtonParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Newton");
    prm.declare_entry("Tolerance",
                      "1e-8",
                      Patterns::Double(0.),
                      "Relative tolerance: stop when the residual norm "
                      "(the L2 norm of the residual functions, "
                      "sqrt(R.M^-1 R)) has dropped by this factor in the "
                      "current time step.");
    prm.declare_entry("Absolute tolerance",
                      "1e-10",
                      Patterns::Double(0.),
                      "Also stop when sqrt(R.M^-1 R) is below this value "
                      "times the size of the terms that cancel in R (for "
                      "the nested scheme |U| + a |V-U| + |P| in the mass "
                      "norm): a tolerance relative to the scale of R, "
                      "which ends the Newton iteration of a step in which "
                      "the solution hardly changes (doc/benchmarks.md, "
                      "\"Eisenstat-Walker forcing terms; Newton "
                      "tolerances of nearly stationary steps\").");
    prm.declare_entry("Maximum iterations",
                      "30",
                      Patterns::Integer(1),
                      "Newton iterations per time step before the step is "
                      "retried with half the time step (or first taken by "
                      "the descent method where doc/willmore_flow.md, "
                      "\"Newton's method\", says so). A first step from "
                      "sharp data may need 15-25 damped iterations "
                      "(doc/benchmarks.md, \"The default Newton limit\").");
    prm.declare_entry("Maximum damping steps",
                      "8",
                      Patterns::Integer(0),
                      "How often one Newton update may be halved when it "
                      "does not reduce the residual.");
    prm.declare_entry("Watchdog factor",
                      "100",
                      Patterns::Double(1.),
                      "A full Newton update that increases the residual "
                      "norm by less than this factor is taken anyway (the "
                      "watchdog's relaxed step); if the next " +
                        std::to_string(NewtonParameters::watchdog_iterations) +
                        " iterations do not bring the norm below its value "
                        "before, Newton returns there, damps that update "
                        "and relaxes no more in this solve. Any other update "
                        "that does not decrease the norm is damped. 1: "
                        "always monotone.");
    prm.declare_entry("Maximum step halvings",
                      "4",
                      Patterns::Integer(0),
                      "How often a failed time step is retried with half "
                      "the outer step before the program stops.");
    prm.declare_entry(
      "Regrow step size",
      "false",
      Patterns::Bool(),
      "false: every step first tries its scheduled size (Tau, or the "
      "ramp-up size), the thesis's time grid. true: after a step that "
      "needed halvings, the next step starts from the size that "
      "converged, and each step taken without halving lets the next one "
      "double, up to the scheduled size. Where the scheduled size fails "
      "in many consecutive steps, this saves one failed attempt (up to "
      "Maximum iterations Newton iterations) per step; Number of steps "
      "then covers a shorter time.");
    prm.declare_entry(
      "Maximum descent iterations",
      "60",
      Patterns::Integer(1),
      "Nested scheme: where Newton's method fails in the first step from "
      "the initial data, the descent method (Newton's method on the outer "
      "energy, every iterate lowering it) takes the step again from its "
      "start, with at most this many iterations, before the step is "
      "halved. Edge restoration, which takes every step with the descent "
      "method, uses Maximum iterations.");
    prm.leave_subsection();
  }



  void
  NewtonParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Newton");
    relative_tolerance     = prm.get_double("Tolerance");
    absolute_tolerance     = prm.get_double("Absolute tolerance");
    max_iterations         = prm.get_integer("Maximum iterations");
    max_damping_steps      = prm.get_integer("Maximum damping steps");
    max_step_halvings      = prm.get_integer("Maximum step halvings");
    regrow_step_size       = prm.get_bool("Regrow step size");
    watchdog_factor        = prm.get_double("Watchdog factor");
    max_descent_iterations = prm.get_integer("Maximum descent iterations");
    prm.leave_subsection();
  }



  std::vector<LinearSolverTypeValue> &
  linear_solver_type_values()
  {
    static std::vector<LinearSolverTypeValue> values;
    return values;
  }



  void
  LinearSolverParameters::declare_parameters(ParameterHandler &prm)
  {
    std::string names = "auto|direct";
    std::string documentation =
      "How the reduced Newton system in V is solved. direct: MUMPS "
      "(through Trilinos Amesos);";
    for (const LinearSolverTypeValue &value : linear_solver_type_values())
      {
        names += "|" + value.name;
        documentation += " " + value.name + ": " + value.documentation + ";";
      }
    documentation +=
      " auto: direct in 2D; in 3D matrix-free for the schemes that run on "
      "it (iterative for the semi-implicit scheme and for periodic "
      "boundary conditions).";
    prm.enter_subsection("Linear solver");
    prm.declare_entry("Type",
                      "auto",
                      Patterns::Selection(names),
                      documentation);
    prm.declare_entry("Tolerance",
                      "1e-10",
                      Patterns::Double(0.),
                      "Relative residual reduction of the iterative solver.");
    prm.declare_entry("Maximum iterations",
                      "1000",
                      Patterns::Integer(1),
                      "Iterations of the iterative solver.");
    prm.leave_subsection();
  }



  void
  LinearSolverParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Linear solver");
    type               = prm.get("Type");
    relative_tolerance = prm.get_double("Tolerance");
    max_iterations     = prm.get_integer("Maximum iterations");
    prm.leave_subsection();
  }



  void
  OutputParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    prm.declare_entry("VTU interval",
                      "5",
                      Patterns::Integer(0),
                      "Write VTU/PVTU output every this many steps (0: no "
                      "VTU output). statistics.csv is always written.");
    prm.declare_entry("Verbose",
                      "false",
                      Patterns::Bool(),
                      "Print every Newton iteration and, for the nested "
                      "scheme, the energy check of every step (energy + "
                      "dissipation - energy before the step) and the "
                      "energy change at every re-meshing.");
    prm.declare_entry(
      "Surface format",
      "none",
      Patterns::Selection("none|stl|ply"),
      "3D runs: write the surface U = 0 (marching cubes on the Q1 field, "
      "every cell that the surface cuts sampled on the finest level's "
      "lattice) as surface_<step>.stl (binary STL) or surface_<step>.ply "
      "(binary PLY with shared vertices) into the output directory, at "
      "every VTU output step and at the last step (also with VTU interval "
      "= 0): one file of all ranks' triangles, to open in ParaView, "
      "MeshLab, Blender or a slicer. 2D runs write no surface files. none: "
      "no surface files.");
    prm.leave_subsection();
  }



  void
  OutputParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    vtu_interval             = prm.get_integer("VTU interval");
    verbose                  = prm.get_bool("Verbose");
    const std::string format = prm.get("Surface format");
    surface_format           = format == "stl" ? SurfaceFormat::stl :
                               format == "ply" ? SurfaceFormat::ply :
                                                 SurfaceFormat::none;
    prm.leave_subsection();
  }



  void
  ConstraintParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Constraints");
    prm.declare_entry(
      "Volume",
      "free",
      Patterns::Selection("free|fixed"),
      "fixed: every step holds the inside measure Int (1-U)/2 (the "
      "inside_measure column) at its value (Volume value) by a Lagrange "
      "multiplier, the pressure (statistics column pressure). Nested "
      "scheme only.");
    prm.declare_entry(
      "Area",
      "free",
      Patterns::Selection("free|fixed"),
      "fixed: every step holds the area functional (3/4) a_eps[U] (the "
      "area_energy column) at its value (Area value) by a Lagrange "
      "multiplier, the tension (statistics column tension). Nested scheme "
      "only.");
    prm.declare_entry("Volume value",
                      "0",
                      Patterns::Double(0),
                      "The inside measure that Volume = fixed holds; 0: "
                      "that of the initial phase field.");
    prm.declare_entry("Area value",
                      "0",
                      Patterns::Double(0),
                      "The area functional that Area = fixed holds; 0: "
                      "that of the initial phase field.");
    prm.declare_entry(
      "Reduced volume",
      "0",
      Patterns::Double(0, 1),
      "With Volume = Area = fixed: hold the inside measure V at the value of "
      "this reduced volume for the area A that Area = fixed holds: 3D "
      "v = 6 sqrt(pi) V / A^(3/2), 2D nu = 4 pi V / A^2 (1 for the "
      "sphere and the circle). 0: Volume value decides.");
    prm.leave_subsection();
  }



  void
  ConstraintParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Constraints");
    volume         = prm.get("Volume") == "fixed";
    area           = prm.get("Area") == "fixed";
    volume_value   = prm.get_double("Volume value");
    area_value     = prm.get_double("Area value");
    reduced_volume = prm.get_double("Reduced volume");
    prm.leave_subsection();
    if (reduced_volume != 0 && !(volume && area))
      throw InputError(
        "Constraints / Reduced volume = " + number_text(reduced_volume) +
        " needs Volume = fixed and Area = fixed.");
    if (reduced_volume != 0 && volume_value != 0)
      throw InputError("Constraints / Reduced volume and Volume value both "
                       "set the volume: set one of them to 0.");
  }



  void
  CheckpointParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Checkpoint");
    prm.declare_entry(
      "Interval",
      "0",
      Patterns::Integer(0),
      "Write a checkpoint (mesh, fields and time-stepping state, in the "
      "directory checkpoint-<step> of the output directory) after every "
      "step that is a multiple of this number, after the re-meshing of "
      "that step; it replaces the previous checkpoint. The linear solver "
      "forgets its factorisations at every checkpoint, so that a resumed "
      "run computes the same steps as an uninterrupted one. 0: no "
      "checkpoints.");
    prm.declare_entry(
      "Resume",
      "false",
      Patterns::Bool(),
      "true: continue from the last checkpoint in the output directory "
      "(on any number of MPI ranks) up to Number of steps, appending to "
      "statistics.csv and solution.pvd. The other parameters must be those "
      "of the run that wrote the checkpoint (Number of steps may be "
      "larger). false: start from the initial shape; checkpoints of an "
      "earlier run in the output directory are deleted. A resume verifies "
      "the checksums of the checkpoint's files and compares the "
      "parameters recorded in it (program, Dimension, levels, Epsilon, "
      "scheme, ...) with this run's: a damaged checkpoint or another "
      "value is refused (exit status 2).");
    prm.declare_entry(
      "Allow parameter change",
      "",
      Patterns::Anything(),
      "Comma separated names (Subsection / Name, as in the message of a "
      "refused resume, e.g. Mesh / Finest level) of parameters recorded in "
      "the checkpoint that may have another value on resume; each "
      "difference is then printed as a warning. Empty: none.");
    prm.leave_subsection();
  }



  void
  CheckpointParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Checkpoint");
    interval = prm.get_integer("Interval");
    resume   = prm.get_bool("Resume");
    allowed_changes.clear();
    for (const std::string &name :
         Utilities::split_string_list(prm.get("Allow parameter change"), ','))
      {
        // "Mesh/Finest level" and "Mesh / Finest level" name the same one
        std::string normalized;
        for (const std::string &part : Utilities::split_string_list(name, '/'))
          normalized += (normalized.empty() ? "" : " / ") + part;
        if (!normalized.empty())
          allowed_changes.push_back(normalized);
      }
    prm.leave_subsection();
  }



  void
  WillmoreParameters::declare_parameters(ParameterHandler  &prm,
                                         const std::string &extra_shapes,
                                         const std::string &extra_documentation,
                                         const bool         multilevel)
  {
    declare_common_parameters(
      prm, "Directory for statistics.csv and the VTU/PVD files.");
    GeometryParameters::declare_parameters(prm,
                                           extra_shapes,
                                           extra_documentation);
    MeshParameters::declare_parameters(prm);
    ModelParameters::declare_parameters(prm, !multilevel);
    NewtonParameters::declare_parameters(prm);
    LinearSolverParameters::declare_parameters(prm);
    OutputParameters::declare_parameters(prm);
    CheckpointParameters::declare_parameters(prm);
  }



  void
  WillmoreParameters::parse_parameters(ParameterHandler &prm,
                                       const bool        multilevel)
  {
    dimension        = prm.get_integer("Dimension");
    output_directory = prm.get("Output directory");
    geometry.parse_parameters(prm);
    mesh.parse_parameters(prm);
    model.parse_parameters(prm, !multilevel);
    newton.parse_parameters(prm);
    linear_solver.parse_parameters(prm);
    output.parse_parameters(prm);
    checkpoint.parse_parameters(prm);
    if (!multilevel)
      set_finest_level(mesh.finest_level);
    check_coarse_start_level();
  }



  void
  WillmoreParameters::check_coarse_start_level() const
  {
    if (start_level() == mesh.finest_level)
      return;
    const std::string name = "<Time stepping / Coarse start level> = " +
                             std::to_string(model.coarse_start_level);
    if (!mesh.adaptive)
      throw InputError(name + " needs <Mesh / Adaptive> = true: the coarse "
                              "levels are narrow-band meshes.");
    if (model.coarse_start_level < mesh.coarsest_level)
      throw InputError(name + " is below <Mesh / Coarsest level> = " +
                       std::to_string(mesh.coarsest_level) +
                       "; 0 switches the coarse start off.");
  }



  unsigned int
  WillmoreParameters::start_level() const
  {
    const unsigned int level = model.coarse_start_level;
    return level == 0 || level >= mesh.finest_level ? mesh.finest_level : level;
  }



  void
  WillmoreParameters::set_finest_level(const unsigned int level)
  {
    mesh.finest_level = level;
    model.evaluate(mesh.h());
    check_uniform_mesh_size();
  }



  WillmoreParameters
  WillmoreParameters::for_finest_level(const unsigned int level) const
  {
    WillmoreParameters parameters = *this;
    parameters.set_finest_level(level);
    return parameters;
  }



  void
  WillmoreParameters::check_uniform_mesh_size() const
  {
    if (mesh.adaptive)
      return;
    MeshSize::check_mesh_fits(
      std::ldexp(1.0, dimension * mesh.finest_level),
      dimension,
      Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD),
      "<Mesh / Finest level> = " + std::to_string(mesh.finest_level) +
        " with <Mesh / Adaptive> = false is a uniform mesh of",
      "Use a smaller level, Adaptive = true, or more ranks.");
  }



  void
  declare_common_parameters(ParameterHandler  &prm,
                            const std::string &output_description)
  {
    prm.declare_entry("Dimension",
                      "2",
                      Patterns::Integer(2, 3),
                      "Space dimension, 2 or 3.");
    prm.declare_entry("Output directory",
                      "output",
                      Patterns::Anything(),
                      output_description);
  }
} // namespace PhaseField
