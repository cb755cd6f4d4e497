#ifndef phasefield_problems_restoration_problem_h
#define phasefield_problems_restoration_problem_h

#include <deal.II/base/index_set.h>
#include <deal.II/lac/trilinos_vector.h>
#include <phasefield/problems/phase_field_problem.h>
#include <phasefield/problems/restoration_parameters.h>
#include <string>
#include <vector>

namespace PhaseField
{
  /**
   * Edge restoration (thesis section 5.3, Definition 5.1): Willmore flow
   * plus the area term eta a_eps[U] in the outer energy, with U held at
   * the (damaged) input image outside the restoration region (V and P
   * stay free). What it adds to PhaseFieldProblem: the fixed values (kept
   * on every new mesh), the columns `weighted_energy` (W + eta A, the
   * energy that decreases) and `fixed_u_deviation`, and the pictures
   * initial.png and restored.png of the phase field with the region
   * outlined.
   */
  class RestorationProblem : public PhaseFieldProblem<2>
  {
  public:
    explicit RestorationProblem(const EdgeRestorationParameters &parameters);

    /** Run the flow, then write the pictures. */
    void
    run() override;

    /** The input phase field's signed distance (damaged image). */
    const dealii::Function<2> &
    initial_signed_distance() const
    {
      return *setup.signed_distance;
    }

    std::vector<std::string>
    extra_columns() const override;
    std::vector<double>
    extra_values(const BlockVector &state,
                 const Energies    &energies) const override;
    /** The fixed values on the new mesh. */
    void
    after_remesh(BlockVector &state) override;
    /** The fixed DoFs and values on the loaded mesh. */
    void
    after_load(BlockVector               &state,
               const std::vector<double> &problem_data) override;

  protected:
    /**
     * The parameters that give the state its meaning, beyond
     * willmore_flow's: `Restoration / Eta` (the weight of the area term),
     * `Region` and `Damage`, and the input image (`Geometry / Shape` with
     * its numbers, or `Image file` and `Threshold`): the fixed values
     * outside the region are those of the input.
     */
    Checkpoint::Parameters
    own_checkpoint_parameters() const override;

  private:
    void
    initialize_fields() override;
    /**
     * Collect the DoFs with fixed U (outside the region) and the input
     * data U^0 on the current mesh.
     */
    void
    setup_fixed_u();
    /** U = input data at the fixed DoFs. */
    void
    reset_fixed_u(BlockVector &state) const;
    /** max |U - input data| over the fixed DoFs. */
    double
    fixed_u_deviation(const BlockVector &state) const;
    /** The pictures of the input and the restored phase field. */
    void
    write_pictures() const;

    const RestorationParameters &restoration;
    /** DoFs with fixed U (locally relevant); OuterEnergy::fixed_u. */
    dealii::IndexSet fixed_u_dofs;
    /** The input data U^0 on the current mesh. */
    Vector initial_u;
  };
} // namespace PhaseField

#endif
