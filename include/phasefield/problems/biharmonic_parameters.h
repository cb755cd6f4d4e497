#ifndef phasefield_biharmonic_parameters_h
#define phasefield_biharmonic_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <phasefield/core/parameters.h>
#include <string>
#include <vector>

/**
 * Parameters of the program biharmonic_flow (thesis chapter 4 and section
 * 7.1.3): one struct per subsection with declare_parameters() /
 * parse_parameters(), as in parameters.h.
 */
namespace PhaseField
{
  /** Boundary conditions of the biharmonic heat flow, each with an exact
   * solution. */
  enum class BiharmonicBoundaryConditions
  {
    /** u = Lap u = 0 on the boundary of [0,1]^d, forcing of Lemma 4.5. */
    dirichlet,
    /** Natural conditions d_n u = d_n Lap u = 0, solution of Lemma 7.2. */
    neumann,
    /** Periodic on the unit cell, forced solution (e^{20t}-1) sum cos(2 pi
       x_i). */
    periodic
  };

  /** Subsection `Problem`. */
  struct BiharmonicProblemParameters
  {
    BiharmonicBoundaryConditions boundary_conditions;

    /** The name used in the .prm file. */
    std::string
    boundary_conditions_name() const;

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };

  /** Subsection `Convergence`: the uniform meshes of the study. */
  struct ConvergenceParameters
  {
    /** Strictly increasing refinement levels, h = 2^-level on [0,1]^d. */
    std::vector<unsigned int> levels;

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };

  /**
   * Subsection `Time stepping`. Tau and Inner tau are expressions in the
   * mesh size h, evaluated per level by step_sizes().
   */
  struct BiharmonicTimeParameters
  {
    /**
     * `Scheme` (a scheme that takes a forcing without the double well:
     * nested or augmented lagrangian) and its own parameters, set by
     * BiharmonicParameters::parse_parameters().
     */
    SchemeChoice scheme;
    std::string  tau_expression;
    std::string  inner_tau_expression;
    double       final_time;

    /** Step sizes of one level of the study. */
    struct StepSizes
    {
      /** Tau adjusted to final_time / n_steps (see n_steps). */
      double tau;
      double inner_tau;
      /**
       * ceil(final_time / Tau(h)): the number of uniform steps that end
       * exactly at the final time with a step not larger than Tau(h).
       */
      unsigned int n_steps;
    };

    /**
     * Evaluate Tau and Inner tau at mesh size @p h; throws InputError
     * naming the parameter if one is not positive.
     */
    StepSizes
    step_sizes(const double h) const;

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };

  /** All parameters of biharmonic_flow. */
  struct BiharmonicParameters
  {
    unsigned int                dimension;
    std::string                 output_directory;
    BiharmonicProblemParameters problem;
    ConvergenceParameters       convergence;
    BiharmonicTimeParameters    time;
    /**
     * How the nested scheme's reduced system is solved: direct (one MUMPS
     * factorisation per level) or iterative (CG with the product-form
     * multigrid preconditioner of willmore_flow, memory linear in the
     * unknowns); `auto` is direct in 2D and iterative in 3D.
     */
    LinearSolverParameters linear_solver;

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    /** Parse and validate (every level's step sizes are evaluated once). */
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };
} // namespace PhaseField

#endif
