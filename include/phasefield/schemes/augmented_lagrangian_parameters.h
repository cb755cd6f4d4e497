#ifndef phasefield_schemes_augmented_lagrangian_parameters_h
#define phasefield_schemes_augmented_lagrangian_parameters_h

#include <deal.II/base/parameter_handler.h>

namespace PhaseField
{
  /**
   * Subsection `Augmented Lagrangian`, the parameters that the augmented
   * Lagrangian scheme owns (thesis Algorithm 2.1, chapter 7; its entry in
   * the scheme registry declares and parses them): the tolerances of the outer
   * loop, its start values and the limits of the trust-region inner solver.
   */
  struct AugmentedLagrangianParameters
  {
    /** w*: ||grad l_A||_L2 at which the outer loop may stop. */
    double gradient_tolerance = 1e-8;
    /** eta*: ||C||_L2 at which the outer loop may stop. */
    double constraint_tolerance = 1e-8;
    /** lambda0: the penalty of the first step (later steps: see scheme). */
    double initial_penalty = 10;
    /**
     * Each later step starts from max(lambda_final / this, lambda0)
     * (thesis: 100^2).
     */
    double penalty_reduction = 1e4;
    /** P0: the multiplier at every node at the start of the run. */
    double initial_multiplier = 0.1;
    /** true: the outer energy divided by epsilon (thesis (7.9)). */
    bool scaled = true;
    /** Limit of the outer (multiplier / penalty) iterations per step. */
    unsigned int max_outer_iterations = 30;
    /** Limit of the trust-region iterations per inner minimisation. */
    unsigned int max_trust_region_iterations = 200;
    /**
     * Limit of the trust-region iterations of one attempt of a step, over
     * all its outer iterations: with max_cg_iterations it bounds the work
     * of a step.
     */
    unsigned int max_step_trust_region_iterations = 1000;
    /** Limit of the CG iterations of one attempt of a step, likewise. */
    unsigned int max_step_cg_iterations = 20000;
    /** Limit of the truncated-CG iterations per trust-region step. */
    unsigned int max_cg_iterations = 2000;
    /** The inner trust-region solver: ours (false) or Trilinos ROL's. */
    bool rol_trust_region = false;

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };
} // namespace PhaseField

#endif
