#ifndef phasefield_problems_willmore_problem_h
#define phasefield_problems_willmore_problem_h

#include <phasefield/core/linear_algebra.h>
#include <phasefield/core/parameters.h>
#include <phasefield/problems/phase_field_problem.h>

namespace PhaseField
{
  /**
   * All parameters of willmore_flow: those of WillmoreParameters and the
   * choice of `Time stepping / Scheme` with the schemes' own subsections
   * (declare_scheme_parameters(), parse_scheme_parameters()).
   */
  struct WillmoreFlowParameters : public WillmoreParameters
  {
    /** Subsection `Constraints`: fixed volume and area (vesicles). */
    ConstraintParameters constraints;

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };

  /**
   * The problem of willmore_flow: Willmore flow (Willmore weight 1, no
   * area term) of the `Geometry` shape on a narrow-band mesh of [0,1]^dim
   * with the scheme of `Time stepping / Scheme`. What it adds to
   * PhaseFieldProblem is the exact evolution where one is known (circles
   * grow as r(t) = (2t + r0^4)^(1/4), spheres are stationary) for the
   * `l2_error` column, and the volume and area constraints of `Constraints`
   * (ScalarConstraints, which the nested scheme holds by Lagrange
   * multipliers).
   */
  template <int dim>
  class WillmoreProblem : public PhaseFieldProblem<dim>
  {
  public:
    /** The flow of @p parameters with the constraints @p constraints. */
    explicit WillmoreProblem(const WillmoreParameters   &parameters,
                             const ConstraintParameters &constraints = {});

    /** ||U - tanh(d_exact(t)/eps)||_L2, NaN without an exact solution. */
    double
    l2_error(const BlockVector &state, const double time) const override;

    /**
     * PhaseFieldProblem::run(), then in 2D the picture phase_field.png of
     * the final U with its zero level line in the output directory
     * (Images::write_picture_with_zero_contour(), picture_pixels per side),
     * in 3D the picture surface.png of the final surface U = 0
     * (ZeroLevelSurface::write_picture()).
     */
    void
    run() override;

    /** Pixels per side of phase_field.png. */
    static constexpr unsigned int picture_pixels = 512;

  protected:
    /**
     * The parameters of `Constraints`: a resume with other constraints is
     * refused.
     */
    Checkpoint::Parameters
    own_checkpoint_parameters() const override;

  private:
    const ConstraintParameters constraints;
  };
} // namespace PhaseField

#endif
