#ifndef phasefield_problems_contour_parameters_h
#define phasefield_problems_contour_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <phasefield/core/parameters.h>
#include <string>
#include <vector>

namespace PhaseField
{
  /**
   * Subsection `Target`: the shape whose Huffman labeling alpha* is given
   * (every Geometry shape; its labeling is computed on each level's pixel
   * grid, as the thesis does), or `image`: a gray PNG over the image
   * plane with alpha* = `Maximum label` * gray value.
   */
  struct TargetParameters
  {
    /** The target shape, read from subsection `Target`. */
    GeometryParameters shape;
    /** Shape = image: the PNG file. */
    std::string image_file;
    /** Shape = image: the label of a white pixel. */
    double maximum_label;

    /** Is the labeling given as an image? */
    bool
    is_image() const
    {
      return shape.shape == "image";
    }

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };

  /**
   * Subsection `Model`: the weights of thesis (6.3), acting on the energies
   * as printed there (without the 3/4 of geometric units):
   * e = eta a_eps[u] + mu (eps/2) ||(v-u)/ttau||^2 + gamma ||alpha* -
   * alpha[u]||^2.
   */
  struct ContourModelParameters
  {
    /** mu > 0 (the nested scheme needs a Willmore term). */
    double willmore_weight;
    /** eta >= 0. */
    double area_weight;
    /** gamma >= 0. */
    double mismatch_weight;

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };

  /** When the multilevel schedule moves on to the next level. */
  enum class LevelTransition
  {
    /** After `Steps per level` steps. */
    fixed,
    /**
     * When the transition criterion has stopped decreasing (see
     * MultilevelParameters::window), at most `Steps per level` steps.
     */
    automatic
  };

  /** What the automatic transition watches (`Transition criterion`). */
  enum class TransitionCriterion
  {
    /** The total energy (thesis (6.3)), the functional the steps lower. */
    total_energy,
    /** The labeling error Int |alpha* - alpha[U]| dx'. */
    labeling_error
  };

  /** Subsection `Multilevel`: coarse to fine levels (thesis 6.4). */
  struct MultilevelParameters
  {
    /** Finest mesh level of each stage, strictly increasing. */
    std::vector<unsigned int> levels;
    /** Steps (of Algorithm 6.1) on each level; the maximum if automatic. */
    std::vector<unsigned int> steps_per_level;
    LevelTransition           transition;
    /**
     * Automatic transition: move on once the criterion's value E has
     * decreased by less than `tolerance` * |E| over the last `window` steps.
     */
    TransitionCriterion criterion;
    unsigned int        window;
    double              tolerance;
    /**
     * Map U to the finer epsilon's profile at each level transition
     * (ContourProblem::move_to_level()).
     */
    bool sharpen;

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    /**
     * Parse and validate (@p finest_level, @p coarsest_level: `Mesh /
     * Finest level`, the one level if `Levels` is empty, and `Mesh /
     * Coarsest level`).
     */
    void
    parse_parameters(dealii::ParameterHandler &prm,
                     const unsigned int        finest_level,
                     const unsigned int        coarsest_level);
  };

  /** How a step couples the mismatch with the nested step. */
  enum class ContourCoupling
  {
    /**
     * Thesis Algorithm 6.1: nested step with tau/2, explicit mismatch step
     * with tau, nested step with tau/2.
     */
    split,
    /**
     * One nested step whose outer energy holds the mismatch j
     * (OuterEnergy::data_term): the minimiser of eps ||u-u^k||^2 +
     * 2 tau (e_reg + j), with the energy law of the whole step.
     */
    monolithic
  };

  /**
   * The entries of subsection `Time stepping` of shape_from_contour beyond
   * willmore_flow's: the coupling and the step-size control
   * (ContourProblem::next_step_size()).
   */
  struct ContourTimeSteppingParameters
  {
    ContourCoupling coupling;
    /** Grow and shrink tau (ContourProblem::step_accepted()). */
    bool step_size_control;
    /** The largest tau as a multiple of the level's Tau. */
    double largest_tau_factor;
    /** A step with at most this many Newton iterations converged easily. */
    unsigned int easy_iterations;

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };

  /** All parameters of shape_from_contour. */
  struct ContourParameters
  {
    /**
     * The parameters shared with willmore_flow (`Geometry` is the initial
     * shape); its finest level and step count are those of the level
     * being computed (for_level()).
     */
    WillmoreParameters            willmore;
    TargetParameters              target;
    ContourModelParameters        model;
    MultilevelParameters          multilevel;
    ContourTimeSteppingParameters time_stepping;

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /**
     * The Willmore-flow parameters of level number @p index of the
     * schedule: its finest level, the expressions in h evaluated at its h,
     * its number of steps.
     */
    WillmoreParameters
    for_level(const unsigned int index) const;
  };
} // namespace PhaseField

#endif
