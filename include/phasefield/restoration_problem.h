#ifndef phasefield_restoration_problem_h
#define phasefield_restoration_problem_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/trilinos_vector.h>
#include <phasefield/restoration_parameters.h>
#include <vector>

namespace PhaseField
{
  /**
   * Edge restoration (thesis section 5.3, Definition 5.1): the Willmore
   * problem with the area term eta a_eps[U] in the outer energy and U held
   * at the (damaged) input image outside the restoration region. Runs
   * WillmoreProblem<2> with WillmoreProblemOptions and writes, besides its
   * output, the pictures initial.png and restored.png of the phase field
   * with the region outlined.
   */
  class RestorationProblem
  {
  public:
    explicit RestorationProblem(const EdgeRestorationParameters &parameters);

    /** Run the whole simulation. Throws on failure. */
    void
    run();

  private:
    const EdgeRestorationParameters &prm;
  };

  /**
   * Sample the Q1 function @p u (locally owned vector on @p dof_handler of
   * an axis-parallel mesh of [0,1]^2) at the centres of an n x n pixel
   * grid, row by row from the bottom. Collective; every rank gets all
   * values.
   */
  std::vector<double>
  sample_on_pixel_grid(const dealii::DoFHandler<2>                 &dof_handler,
                       const dealii::TrilinosWrappers::MPI::Vector &u,
                       const unsigned int                           n);
} // namespace PhaseField

#endif
