#ifndef phasefield_problems_initial_shape_check_h
#define phasefield_problems_initial_shape_check_h

#include <deal.II/base/function.h>
#include <phasefield/core/parameters.h>
#include <string>

namespace PhaseField
{
  /**
   * The checks of a run's initial shape against the domain and the mesh,
   * before any mesh exists (PhaseFieldProblem::run()), from a sample of
   * its signed distance (Shapes::sample_interface()). Throws an
   * InputError, the same on every rank, if
   * - the shape lies entirely outside the domain [0,1]^dim, or contains
   *   it: there is no interface;
   * - no point of the domain is farther than `Phase field / Epsilon`
   *   (of @p first) from the interface: U = tanh(d / epsilon) has no bulk
   *   phase;
   * - `Mesh / Adaptive` = true and the finest cells of the narrow band
   *   alone (|d| < `Band width` epsilon on the level of @p finest) do not
   *   fit (MeshSize::check_mesh_fits()): their number is estimated as the
   *   band's volume over h^dim, a lower bound of the mesh's cells, which
   *   also has the coarser cells around the band.
   * @p first: the parameters of the first level (shape from contour's
   * first level, the others' only one), @p finest: those of the finest
   * level of the run.
   */
  template <int dim>
  void
  check_initial_shape(const dealii::Function<dim> &signed_distance,
                      const WillmoreParameters    &first,
                      const WillmoreParameters    &finest);

  /**
   * The warning about an interface that the mesh hardly resolves
   * (`Phase field / Epsilon` below h; below h/2 it is refused by
   * ModelParameters::evaluate()), or "" if there is none.
   */
  std::string
  epsilon_resolution_warning(const WillmoreParameters &parameters);
} // namespace PhaseField

#endif
