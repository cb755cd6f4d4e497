#include <cmath>
#include <phasefield/geometry/shapes.h>
#include <phasefield/problems/contour_parameters.h>
#include <phasefield/schemes/scheme_registry.h>

namespace PhaseField
{
  using namespace dealii;

  void
  TargetParameters::declare_parameters(ParameterHandler &prm)
  {
    GeometryParameters::declare_parameters(
      prm,
      "image",
      "image: the labeling is the gray PNG <Image file> (alpha* = Maximum "
      "label * gray value in [0,1]).",
      "Target",
      "The shape whose Huffman labeling (view along the last axis x_d) is "
      "given; its labeling is computed on each level's pixel grid from the "
      "Q1 interpolant of its phase field on the uniform mesh of the level, "
      "as the thesis does (section 6.4)",
      "circle");
    prm.enter_subsection("Target");
    prm.set("Radius", "0.25");
    prm.declare_entry("Image file",
                      "",
                      Patterns::Anything(),
                      "Shape = image: grayscale PNG of the labeling over the "
                      "image plane [0,1]^(d-1), rows from top (y = 1) to "
                      "bottom (y = 0). 2D: an image of one row; 3D: a square "
                      "image. Any size; each point of the pixel grid takes "
                      "the image pixel it lies in.");
    prm.declare_entry("Maximum label",
                      "2",
                      Patterns::Double(0.),
                      "Shape = image: the label of a white pixel (gray "
                      "value 255); black is 0.");
    prm.leave_subsection();
  }



  void
  TargetParameters::parse_parameters(ParameterHandler &prm)
  {
    shape.parse_parameters(prm, "Target");
    prm.enter_subsection("Target");
    image_file    = prm.get("Image file");
    maximum_label = prm.get_double("Maximum label");
    prm.leave_subsection();
    if (is_image() && image_file.empty())
      throw InputError("<Target / Shape> = image needs <Target / Image "
                       "file>.");
  }



  void
  ContourModelParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Model");
    prm.declare_entry("Willmore weight",
                      "0.05",
                      Patterns::Anything(),
                      "mu > 0: weight of the Willmore term (mu/2) Int eps "
                      "((v-u)/inner tau)^2 of thesis (6.3), which is mu/0.75 "
                      "times the willmore_energy column (geometric units).");
    prm.declare_entry("Area weight",
                      "0.05",
                      Patterns::Anything(),
                      "eta >= 0: weight of the area term (eta/2) Int "
                      "Psi(u)/eps + eps |grad u|^2 of (6.3), which is "
                      "eta/0.75 times the area_energy column.");
    prm.declare_entry("Mismatch weight",
                      "10",
                      Patterns::Anything(),
                      "gamma >= 0: weight of the mismatch Int (alpha* - "
                      "alpha[u])^2 dx' of (6.2), (6.3).");
    prm.leave_subsection();
  }



  void
  ContourModelParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Model");
    const auto weight = [&](const std::string &name, const bool positive) {
      const std::string full = "Model / " + name;
      const double value     = evaluate_expression_in_h(prm.get(name), 1, full);
      if (positive ? !(value > 0) : !(value >= 0))
        throw InputError("The parameter <" + full + "> must be " +
                         (positive ? "positive (the nested scheme needs a "
                                     "Willmore term)" :
                                     "non-negative") +
                         ", but is " + prm.get(name) + ".");
      return value;
    };
    willmore_weight = weight("Willmore weight", true);
    area_weight     = weight("Area weight", false);
    mismatch_weight = weight("Mismatch weight", false);
    prm.leave_subsection();
  }



  void
  MultilevelParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Multilevel");
    prm.declare_entry("Levels",
                      "5, 6",
                      Patterns::Anything(),
                      "Comma separated, strictly increasing finest mesh "
                      "levels (h = 2^-level), coarse to fine; empty: the "
                      "one level <Mesh / Finest level>. Epsilon, Tau "
                      "and Inner tau are evaluated at each level's h; U, V, "
                      "P are transferred to the finer band and the target "
                      "labeling is recomputed on the finer pixel grid.");
    prm.declare_entry("Steps per level",
                      "20, 5",
                      Patterns::Anything(),
                      "Comma separated steps of Algorithm 6.1 on each level "
                      "(as many as Levels); with Transition = automatic the "
                      "largest number of steps.");
    prm.declare_entry("Transition",
                      "fixed",
                      Patterns::Selection("fixed|automatic"),
                      "fixed: Steps per level steps on each level. "
                      "automatic: move on to the next level as soon as the "
                      "Transition criterion has decreased by less "
                      "than Transition tolerance times its value over the "
                      "last Transition window steps (at most Steps per "
                      "level steps).");
    prm.declare_entry("Transition criterion",
                      "total energy",
                      Patterns::Selection("total energy|labeling error"),
                      "Automatic transition: the quantity that must have "
                      "stopped decreasing. total energy: thesis (6.3), the "
                      "functional the steps lower (the level's shape has "
                      "converged). labeling error: Int |alpha* - "
                      "alpha[U]| dx' (the labeling has stopped improving; "
                      "on a coarse level it can rise again while the total "
                      "energy still falls).");
    prm.declare_entry("Transition window",
                      "10",
                      Patterns::Integer(1),
                      "Automatic transition: the number of steps over which "
                      "the relative decrease of the Transition criterion is "
                      "measured.");
    prm.declare_entry("Transition tolerance",
                      "0.01",
                      Patterns::Double(0.),
                      "Automatic transition: move on when the Transition "
                      "criterion decreased by less than this fraction of "
                      "its value over the window.");
    prm.declare_entry("Sharpen interface",
                      "false",
                      Patterns::Bool(),
                      "At each level transition, map the transferred U to "
                      "the profile of the finer epsilon, U <- tanh((eps_old "
                      "/ eps_new) artanh(U)) at every node (U = tanh(d/eps) "
                      "has the width of the coarse level otherwise), before "
                      "V and P are solved again; the transition then refines "
                      "only the band of the finer profile.");
    prm.leave_subsection();
  }



  void
  MultilevelParameters::parse_parameters(ParameterHandler  &prm,
                                         const unsigned int finest_level,
                                         const unsigned int coarsest_level)
  {
    prm.enter_subsection("Multilevel");
    levels          = prm.get("Levels").empty() ?
                        std::vector<unsigned int>{finest_level} :
                        parse_integer_list(prm.get("Levels"),
                                  "Multilevel / Levels",
                                  1,
                                  max_mesh_level,
                                  true);
    steps_per_level = parse_integer_list(prm.get("Steps per level"),
                                         "Multilevel / Steps per level",
                                         0,
                                         std::numeric_limits<int>::max(),
                                         false);
    transition      = prm.get("Transition") == "automatic" ?
                        LevelTransition::automatic :
                        LevelTransition::fixed;
    criterion       = prm.get("Transition criterion") == "labeling error" ?
                        TransitionCriterion::labeling_error :
                        TransitionCriterion::total_energy;
    window          = prm.get_integer("Transition window");
    tolerance       = prm.get_double("Transition tolerance");
    sharpen         = prm.get_bool("Sharpen interface");
    prm.leave_subsection();
    if (levels.size() != steps_per_level.size())
      throw InputError("<Multilevel / Levels> has " +
                       std::to_string(levels.size()) +
                       " entries, but <Multilevel / Steps per level> has " +
                       std::to_string(steps_per_level.size()) +
                       ": they must have the same length.");
    if (levels.front() < coarsest_level)
      throw InputError("The first of <Multilevel / Levels> (" +
                       std::to_string(levels.front()) +
                       ") is below <Mesh / Coarsest level> (" +
                       std::to_string(coarsest_level) + ").");
  }



  void
  ContourTimeSteppingParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Time stepping");
    prm.declare_entry(
      "Contour coupling",
      "split",
      Patterns::Selection("split|monolithic"),
      "How a step couples the mismatch j with the nested step of the "
      "regularisation. split: thesis Algorithm 6.1 (nested step with "
      "tau/2, explicit mismatch step eps M (U - U') = -tau j'(U'), nested "
      "step with tau/2). monolithic: one nested step that minimises eps "
      "||u - u^k||^2 + 2 tau (e_reg[u] + j[u]) (thesis 6.5, 7.3), solved by "
      "Newton's method with the Gauss-Newton Hessian J^T 2 gamma W J of j "
      "(the descent method on that energy where Newton fails) and accepted "
      "if the energy law of the whole step holds: mu W + eta A + (3/4) j + "
      "dissipation must not exceed its value before the step (otherwise "
      "the step is halved). Only with <Time stepping / Scheme> = nested.");
    prm.declare_entry(
      "Step size control",
      "false",
      Patterns::Bool(),
      "Grow and shrink tau (doc/shape_from_contour.md, \"Step-size "
      "control\"): after an accepted step that took at most <Easy Newton "
      "iterations> Newton iterations at the size it tried and decreased "
      "the energy by at least twice its dissipation (what the minimiser of "
      "a convex step energy does), the next step tries twice the size, at "
      "most <Largest tau factor> times Tau; after a halved step it tries "
      "the halved size. false: every step tries Tau.");
    prm.declare_entry("Largest tau factor",
                      "16",
                      Patterns::Anything(),
                      "Step size control: the largest step size as a "
                      "multiple of the level's Tau (>= 1).");
    prm.declare_entry("Easy Newton iterations",
                      "5",
                      Patterns::Anything(),
                      "Step size control: a step with at most this many "
                      "Newton iterations (both half steps of the split "
                      "coupling together) converged easily (>= 1).");
    prm.leave_subsection();
  }



  void
  ContourTimeSteppingParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Time stepping");
    coupling                 = prm.get("Contour coupling") == "monolithic" ?
                                 ContourCoupling::monolithic :
                                 ContourCoupling::split;
    step_size_control        = prm.get_bool("Step size control");
    const std::string factor = prm.get("Largest tau factor");
    const std::string easy   = prm.get("Easy Newton iterations");
    prm.leave_subsection();
    largest_tau_factor =
      evaluate_expression_in_h(factor, 1, "Time stepping / Largest tau factor");
    if (!(largest_tau_factor >= 1))
      throw InputError("The parameter <Time stepping / Largest tau factor> "
                       "must be at least 1, but is " +
                       factor + ".");
    const double iterations =
      evaluate_expression_in_h(easy,
                               1,
                               "Time stepping / Easy Newton iterations");
    if (!(iterations >= 1) || iterations != std::floor(iterations))
      throw InputError("The parameter <Time stepping / Easy Newton "
                       "iterations> must be a positive integer, but is " +
                       easy + ".");
    easy_iterations = static_cast<unsigned int>(iterations);
  }



  void
  ContourParameters::declare_parameters(ParameterHandler &prm)
  {
    WillmoreParameters::declare_parameters(prm, "", "", true);
    declare_scheme_parameters(prm);
    prm.enter_subsection("Geometry");
    prm.set("Shape", "circle");
    prm.leave_subsection();
    prm.enter_subsection("Time stepping");
    prm.set("Tau", "0.03*h");
    prm.leave_subsection();
    prm.enter_subsection("Output");
    prm.set("VTU interval", "25");
    prm.leave_subsection();
    TargetParameters::declare_parameters(prm);
    ContourModelParameters::declare_parameters(prm);
    MultilevelParameters::declare_parameters(prm);
    ContourTimeSteppingParameters::declare_parameters(prm);
  }



  void
  ContourParameters::parse_parameters(ParameterHandler &prm)
  {
    willmore.parse_parameters(prm, true);
    target.parse_parameters(prm);
    model.parse_parameters(prm);
    multilevel.parse_parameters(prm,
                                willmore.mesh.finest_level,
                                willmore.mesh.coarsest_level);
    time_stepping.parse_parameters(prm);
    const ModelTerms needed = ModelTerms()
                                .with("area term")
                                .with("Willmore weight")
                                .with("mismatch term");
    willmore.model.scheme =
      parse_scheme_parameters(prm, needed, "shape_from_contour");
    // a target shape that cannot be made is a mistake in the file: say so
    // before any mesh exists
    if (!target.is_image())
      {
        if (willmore.dimension == 2)
          Shapes::create_signed_distance<2>(target.shape);
        else
          Shapes::create_signed_distance<3>(target.shape);
      }
    // evaluate and check the expressions in h on every level now
    for (unsigned int i = 0; i < multilevel.levels.size(); ++i)
      for_level(i);
    willmore = for_level(0);
  }



  WillmoreParameters
  ContourParameters::for_level(const unsigned int index) const
  {
    WillmoreParameters level = willmore;
    level.set_finest_level(multilevel.levels[index]);
    level.model.n_steps = multilevel.steps_per_level[index];
    return level;
  }
} // namespace PhaseField
