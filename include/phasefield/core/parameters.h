#ifndef phasefield_parameters_h
#define phasefield_parameters_h

#include <any>
#include <cmath>
#include <deal.II/base/parameter_handler.h>
#include <string>
#include <vector>

/**
 * Parameter structs of the phase-field programs. Each struct owns one
 * subsection of the .prm file and has the usual pair of
 * declare_parameters() / parse_parameters() functions. Validation that
 * needs more than a pattern (e.g. Finest level >= Coarsest level) is done
 * in parse_parameters() and reported with the name of the parameter.
 */
namespace PhaseField
{
  /**
   * Thrown for invalid user input. The message names the offending
   * parameter; programs print it and exit with a non-zero status.
   */
  class InputError : public std::runtime_error
  {
  public:
    explicit InputError(const std::string &message)
      : std::runtime_error(message)
    {}
  };

  /**
   * Evaluate a muParser expression in the mesh size @p h (e.g. `4*h`,
   * `h^2`, `0.03*h`, `2^-6`). @p parameter_name is used in the error
   * message if the expression is malformed or not finite.
   */
  double
  evaluate_expression_in_h(const std::string &expression,
                           const double       h,
                           const std::string &parameter_name);

  /**
   * @p value as a message shows it: 6 significant digits (1e+30, not 31
   * digits).
   */
  std::string
  number_text(const double value);

  /**
   * Parse a comma separated list of doubles; throws InputError naming
   * @p parameter_name on failure.
   */
  std::vector<double>
  parse_double_list(const std::string &text, const std::string &parameter_name);

  /** Largest mesh level that a parameter may ask for (h = 2^-12). */
  constexpr unsigned int max_mesh_level = 12;

  /**
   * Parse a comma separated list of integers in [@p minimum, @p maximum]
   * (strictly increasing if @p increasing); throws InputError naming
   * @p parameter_name for an empty list or any violation.
   */
  std::vector<unsigned int>
  parse_integer_list(const std::string &text,
                     const std::string &parameter_name,
                     const unsigned int minimum,
                     const unsigned int maximum,
                     const bool         increasing);

  /** Quadrature rule for the cell integrals of the stiffness matrix L. */
  enum class StiffnessQuadrature
  {
    /**
     * 2-point Gauss rule per direction: the exact Q1 stiffness matrix (on a
     * uniform 2D mesh the 9-point stencil (1/3)[-1 -1 -1; -1 8 -1; -1 -1 -1]).
     */
    gauss,
    /**
     * 2-point Gauss-Lobatto rule per direction, i.e. the cell vertices (the
     * rule of the lumped mass). On a uniform mesh this is the 5-point
     * (7-point in 3D) stencil, the stiffness matrix of the P1 elements on
     * the squares cut into right triangles that the thesis uses (section
     * 2.2, Fig. 2.1). Its consistency error for a smooth U,
     * (h^2/12) (d_x^4 + d_y^4) U, is smaller than the Gauss one,
     * (h^2/12) (Lap^2 + 2 d_x^2 d_y^2) U, for every direction of the
     * interface but the axes (where both agree). This matters when h is
     * not small against eps: for the quarter circle at h = eps/2 the
     * semi-implicit Willmore energy of the sampled tanh profile is 5.61
     * instead of 10.98 (exact 1.96; doc/willmore_flow.md, "Known
     * limitations").
     */
    gauss_lobatto
  };

  /** Subsection `Geometry`: the initial shape. */
  struct GeometryParameters
  {
    /** One of the shape names of `--help` (circle, sphere, torus, ...). */
    std::string shape;
    /** Centre; empty means the centre of the unit cell (0.5, ..., 0.5). */
    std::vector<double> center;
    /** Second centre (only used by `two circles`). */
    std::vector<double> second_center;
    double              radius;
    /** Edge lengths, disc diameter/thickness, semi-axes, torus R and r. */
    std::vector<double> sizes;
    /** Signed distance as a muParser expression in x, y (, z). */
    std::string expression;
    /** The subsection the shape was read from (for messages). */
    std::string subsection = "Geometry";

    /**
     * Declare the subsection. A program with shapes of its own (edge
     * restoration's images) adds their names, separated by `|`, in
     * @p extra_shapes and their documentation in @p extra_documentation.
     * A program with a second shape (shape from contour's target)
     * declares it in another @p subsection, with its @p purpose (the first
     * words of the documentation of `Shape`) and @p default_shape.
     */
    static void
    declare_parameters(dealii::ParameterHandler &prm,
                       const std::string        &extra_shapes        = "",
                       const std::string        &extra_documentation = "",
                       const std::string        &subsection = "Geometry",
                       const std::string        &purpose    = "Initial shape",
                       const std::string        &default_shape = "two circles");
    void
    parse_parameters(dealii::ParameterHandler &prm,
                     const std::string        &subsection_name = "Geometry");
  };

  /** Subsection `Mesh`: narrow-band adaptivity on [0,1]^d. */
  struct MeshParameters
  {
    unsigned int finest_level;
    unsigned int coarsest_level;
    bool         adaptive;
    /** Half width of the finest band, in units of epsilon. */
    double band_width;
    /** Check the band every this many time steps. */
    unsigned int refinement_interval;
    /**
     * Re-mesh only when the band of (band_width - band_margin) epsilon is
     * not on the finest level, or finest cells lie outside the
     * (coarsening) band widened by band_margin; 0: whenever a cell would
     * change (Discretization::adapt_to_phase_field()).
     */
    double band_margin = 0;
    /** Quadrature of the stiffness matrix L (see StiffnessQuadrature). */
    StiffnessQuadrature stiffness_quadrature;

    /** Finest mesh size h = 2^-finest_level. */
    double
    h() const;

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };

  /**
   * The value of `Time stepping / Scheme` and the parameters that the
   * chosen scheme owns (its own subsection, e.g. `Augmented Lagrangian`).
   * The scheme registry (schemes/scheme_registry.h) declares, parses and
   * interprets both: core does not know the schemes.
   */
  struct SchemeChoice
  {
    /** A name of the scheme registry, e.g. "nested". */
    std::string name;
    /**
     * The scheme's own parameters as its registry entry parsed them
     * (SchemeSettings::own_parameters() reads them); empty if it has none.
     */
    std::any parameters;
  };

  /** `Time stepping / Step control`. */
  enum class StepControl
  {
    /** The sizes of the schedule: ramp-up, then `Tau` (the thesis). */
    fixed,
    /**
     * The largest size whose local error estimate is below `Tolerance`
     * (AdaptiveStepSizes); `Tau` is the first step.
     */
    adaptive
  };

  /**
   * The step control and the end of a run, in subsection `Time stepping`:
   * `Step control`, `Tolerance`, `Smallest step`, `Largest step` and
   * `End time` where the run counts its steps (not for the levels of
   * shape from contour, which control their own steps), `Stationary
   * tolerance` always.
   */
  struct StepControlParameters
  {
    StepControl control = StepControl::fixed;
    /**
     * The local error per step that the adaptive control allows: the
     * L2 norm over the domain of the estimated error of U after one step
     * (LocalErrorEstimate).
     */
    double      tolerance = 0;
    std::string smallest_step_expression;
    std::string largest_step_expression;
    std::string end_time_expression;
    /**
     * Stop when the relative change of the energy per unit time,
     * |E^{k+1} - E^k| / (tau |E^{k+1}|), falls below this (0: never).
     */
    double stationary_tolerance = 0;

    /** Values after evaluate(); 0: no limit, no end time. */
    double smallest_step = 0;
    double largest_step  = 0;
    double end_time      = 0;

    /** Declare into subsection `Time stepping` (entered by the caller). */
    static void
    declare_parameters(dealii::ParameterHandler &prm,
                       const bool                with_step_counts);
    /** Parse from subsection `Time stepping` (entered by the caller). */
    void
    parse_parameters(dealii::ParameterHandler &prm,
                     const bool                with_step_counts);
    /**
     * Evaluate the expressions at mesh size @p h and check them with the
     * first step size @p tau.
     */
    void
    evaluate(const double h, const double tau);
  };

  /**
   * Subsections `Phase field` and `Time stepping`. The raw expressions are
   * kept so that they can be evaluated once h is known (see evaluate()).
   */
  struct ModelParameters
  {
    /**
     * `Time stepping / Scheme` and the scheme's own parameters: set by
     * parse_scheme_parameters() (schemes/scheme_registry.h), not by
     * parse_parameters(), which does not know the schemes.
     */
    SchemeChoice scheme;
    std::string  epsilon_expression;
    std::string  tau_expression;
    std::string  inner_tau_expression;
    unsigned int n_steps;
    /**
     * Start-up: this many extra steps before the n_steps steps of size
     * tau, of sizes tau / 2^n_ramp_steps, ..., tau / 4, tau / 2.
     */
    unsigned int n_ramp_steps;
    /**
     * Nested iteration for the first step: Newton's method of step 1
     * starts from that step computed on the narrow-band meshes of this
     * level up to the finest level - 1
     * (PhaseFieldProblem::coarse_start_value()); 0: from the initial data.
     * See WillmoreParameters::start_level().
     */
    unsigned int coarse_start_level;
    /**
     * Start each step of the nested scheme from the start value
     * extrapolated from the last two steps (StartValuePredictor).
     */
    bool extrapolated_start;
    /**
     * `Time stepping / Largest inside change factor`: a step whose result
     * has an inside measure more than this factor larger or smaller than
     * before the step is rejected and halved (StepAttempt::rejection()); 0:
     * no limit.
     */
    double max_inside_change_factor;
    /** Step control, end time and stationarity. */
    StepControlParameters step_control;

    /** Size of time step @p step (1-based), see n_ramp_steps. */
    double
    step_size(const unsigned int step) const
    {
      return step <= n_ramp_steps ?
               std::ldexp(tau, -static_cast<int>(n_ramp_steps - step + 1)) :
               tau;
    }

    /** Values after evaluate(). */
    double epsilon   = 0;
    double tau       = 0;
    double inner_tau = 0;

    /**
     * Without @p with_step_counts (shape from contour, whose multilevel
     * schedule counts the steps) `Number of steps`, `Ramp-up steps` and
     * `Coarse start level` are not declared and are 0.
     */
    static void
    declare_parameters(dealii::ParameterHandler &prm,
                       const bool                with_step_counts = true);
    void
    parse_parameters(dealii::ParameterHandler &prm,
                     const bool                with_step_counts = true);
    /** Evaluate the expressions at mesh size @p h and validate them. */
    void
    evaluate(const double h);

  private:
    /**
     * `Number of steps`, `Ramp-up steps` and `Coarse start level` in
     * `Time stepping`.
     */
    static void
    declare_step_counts(dealii::ParameterHandler &prm);
  };

  /** Subsection `Newton`. */
  struct NewtonParameters
  {
    /** Stop when ||R||_{M^-1} <= tolerance * ||R_0||_{M^-1} ... */
    double relative_tolerance;
    /** ... or when ||R||_{M^-1} <= absolute tolerance. */
    double       absolute_tolerance;
    unsigned int max_iterations;
    /** Backtracking halvings of one Newton update before giving up. */
    unsigned int max_damping_steps;
    /**
     * A full update that increases the residual norm by less than this
     * factor is taken anyway, the watchdog's relaxed step (1: always
     * monotone; see watchdog_iterations).
     */
    double watchdog_factor;
    /**
     * Iterations after a relaxed step in which the residual norm must fall
     * below its value before that step; otherwise Newton's method returns
     * there, damps the update and relaxes no more in the solve. On the
     * level-8 cube's first step (doc/benchmarks.md, "The watchdog with a
     * return") a relaxed step that raised the norm 25-fold needed 6, and 4
     * were not enough.
     */
    static constexpr unsigned int watchdog_iterations = 8;
    /** How often a failed time step may be retried with half the step. */
    unsigned int max_step_halvings;
    /**
     * `Regrow step size`: after a step that needed halvings, the next
     * steps start from the reduced size and double after each step taken
     * without halving, up to the scheduled size (false: every step starts
     * from the scheduled size, the thesis's fixed grid).
     */
    bool regrow_step_size;
    /**
     * Iterations of the descent method that takes a step from its start
     * where Newton's method failed (nested scheme without fixed U).
     */
    unsigned int max_descent_iterations;

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };

  /** How the reduced (Schur complement) system is solved. */
  enum class LinearSolverType
  {
    direct,
    iterative
  };

  /**
   * The names (`Linear solver / Type` values) of the two operator backends
   * of the library, which source/mesh/operator_backends.cc registers.
   */
  namespace OperatorBackendNames
  {
    /** TrilinosStiffness: the assembled matrix, algebraic multigrid. */
    inline constexpr char assembled[] = "iterative";
    /** MatrixFreeStiffness: cell by cell, geometric multigrid. */
    inline constexpr char matrix_free[] = "matrix-free";
  } // namespace OperatorBackendNames

  /**
   * What `Linear solver / Type` chooses for one run: the solver of the
   * reduced system and the operator backend that applies (and
   * preconditions) the stiffness operator L. resolve_solver_choice() in
   * schemes/scheme_registry.h makes it from the parameters; the problems
   * hand it to the mesh (Discretization::Settings) and to the schemes
   * (SchemeSettings).
   */
  struct SolverChoice
  {
    LinearSolverType type = LinearSolverType::direct;
    /**
     * The name of a registered operator backend
     * (mesh/operator_backend.h): the `Type` value that selects it with
     * the iterative solver. The direct solver needs the assembled one.
     */
    std::string backend = OperatorBackendNames::assembled;
  };

  /**
   * A value of `Linear solver / Type` besides auto and direct: the name of
   * an operator backend and its documentation, which become part of the
   * parameter's pattern and of its `--help` text.
   * register_operator_backend() (mesh/operator_backend.h) adds them.
   */
  struct LinearSolverTypeValue
  {
    std::string name;
    std::string documentation;
  };

  /** The registered values, in the order of registration. */
  std::vector<LinearSolverTypeValue> &
  linear_solver_type_values();

  /** Subsection `Linear solver`. */
  struct LinearSolverParameters
  {
    /**
     * `Type`: auto, direct, or the name of an operator backend (iterative:
     * CG with algebraic multigrid on the assembled L; matrix-free: CG on
     * the matrix-free backend), as written; resolve_solver_choice() makes
     * the SolverChoice of a run from it.
     */
    std::string  type = "auto";
    double       relative_tolerance;
    unsigned int max_iterations;

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };

  /**
   * File format of the zero level set of U as a triangulated surface
   * (`Output / Surface format`; mesh/zero_level_surface.h).
   */
  enum class SurfaceFormat
  {
    /** No surface files. */
    none,
    /** Binary STL (a triangle soup, 50 bytes per triangle). */
    stl,
    /** Binary PLY (shared vertices and triangles). */
    ply
  };

  /** Subsection `Output`. */
  struct OutputParameters
  {
    /** Write VTU every this many steps (0: never). */
    unsigned int vtu_interval;
    bool         verbose;
    /**
     * Write the surface U = 0 of a 3D run in this format at the VTU
     * output steps and at the last step (nothing in 2D).
     */
    SurfaceFormat surface_format;

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };

  /**
   * Subsection `Constraints` (willmore_flow): the inside measure
   * Int (1-U)/2 (`Volume`) and the area functional (3/4) a_eps[U]
   * (`Area`, the `area_energy` column) held fixed in every step by
   * Lagrange multipliers (ScalarConstraints, schemes/constraints.h).
   */
  struct ConstraintParameters
  {
    /** Hold the inside measure fixed? */
    bool volume = false;
    /** Hold the area functional fixed? */
    bool area = false;
    /** The value to hold the inside measure at; 0: the initial one. */
    double volume_value = 0;
    /** The value to hold the area functional at; 0: the initial one. */
    double area_value = 0;
    /**
     * With both fixed: hold the inside measure at the value that gives this
     * reduced volume with the area's target; 0: Volume value decides.
     */
    double reduced_volume = 0;

    /** Is any constraint fixed? */
    bool
    any() const
    {
      return volume || area;
    }

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };

  /**
   * Subsection `Checkpoint`: checkpoint and resume of the time-dependent
   * programs (willmore_flow, edge_restoration; see TimeLoop).
   */
  struct CheckpointParameters
  {
    /** Write a checkpoint every this many time steps (0: never). */
    unsigned int interval;
    /**
     * Continue from the last checkpoint in the output directory instead of
     * starting from the initial shape.
     */
    bool resume;
    /**
     * The parameters (as `Subsection / Name`) that may differ from those
     * recorded in the checkpoint on resume (a warning is printed for
     * each); any other difference refuses the resume.
     */
    std::vector<std::string> allowed_changes;

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };

  /** Largest value of `Time stepping / Ramp-up steps`. */
  constexpr unsigned int max_ramp_steps = 30;

  /**
   * The parameters of willmore_flow that core owns. `Time stepping /
   * Scheme` and the schemes' own subsections are declared and parsed by
   * the scheme registry (declare_scheme_parameters() and
   * parse_scheme_parameters() in schemes/scheme_registry.h), which a
   * program calls besides declare_parameters() and parse_parameters()
   * (WillmoreFlowParameters, EdgeRestorationParameters, ...).
   */
  struct WillmoreParameters
  {
    /**
     * Largest uniform mesh (`Mesh / Adaptive = false`) per MPI rank:
     * 2^24 cells, about 16 GB at bytes_per_cell.
     */
    static constexpr double max_uniform_cells_per_rank = 16777216.;
    /** Memory estimate per cell of a run (matrices, vectors, mesh). */
    static constexpr double bytes_per_cell = 1024.;

    unsigned int           dimension;
    std::string            output_directory;
    GeometryParameters     geometry;
    MeshParameters         mesh;
    ModelParameters        model;
    NewtonParameters       newton;
    LinearSolverParameters linear_solver;
    OutputParameters       output;
    CheckpointParameters   checkpoint;

    /**
     * @p extra_shapes, @p extra_documentation: see GeometryParameters.
     * @p multilevel: without `Time stepping / Number of steps` and
     * `Ramp-up steps` (shape from contour, whose multilevel schedule sets
     * them and the finest level; parse_parameters() then leaves the
     * expressions in h unevaluated until set_finest_level()).
     */
    static void
    declare_parameters(dealii::ParameterHandler &prm,
                       const std::string        &extra_shapes        = "",
                       const std::string        &extra_documentation = "",
                       const bool                multilevel          = false);
    void
    parse_parameters(dealii::ParameterHandler &prm,
                     const bool                multilevel = false);

    /**
     * Set the finest level, evaluate the expressions in h there and check
     * the size of a uniform mesh.
     */
    void
    set_finest_level(const unsigned int level);

    /**
     * Throw an InputError giving the number of cells and the memory
     * estimate if a uniform mesh has more than max_uniform_cells_per_rank
     * cells per MPI rank (of MPI_COMM_WORLD).
     */
    void
    check_uniform_mesh_size() const;

    /**
     * Throw an InputError if `Time stepping / Coarse start level` is below
     * `Mesh / Coarsest level` (and not 0) or set for a uniform mesh.
     */
    void
    check_coarse_start_level() const;

    /**
     * The finest level of the mesh step 1 starts on: `Time stepping /
     * Coarse start level` if it is below the finest level (and not 0),
     * else the finest level (no coarse start).
     */
    unsigned int
    start_level() const;

    /** These parameters with @p level as the finest level. */
    WillmoreParameters
    for_finest_level(const unsigned int level) const;
  };

  /**
   * Read @p filename into @p prm. Missing files, directories and other
   * files that are not regular files, unknown parameters and
   * values that violate their pattern become an InputError with a message
   * that names the file and the parameter.
   */
  void
  read_parameter_file(dealii::ParameterHandler &prm,
                      const std::string        &filename);

  /**
   * Declare the top-level entries that every program has: `Dimension` (2 or 3)
   * and `Output directory`, documented by
   * @p output_description.
   */
  void
  declare_common_parameters(dealii::ParameterHandler &prm,
                            const std::string        &output_description);
} // namespace PhaseField

#endif
