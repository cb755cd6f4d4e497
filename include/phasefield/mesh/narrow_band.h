#ifndef phasefield_narrow_band_h
#define phasefield_narrow_band_h

#include <deal.II/base/function.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <phasefield/core/linear_algebra.h>

namespace PhaseField
{
  /**
   * Narrow-band mesh adaptation: cells near the diffuse interface are kept
   * on the finest level, all others are coarsened down to the coarsest
   * level; p4est's 2:1 balance grades the transition.
   */
  namespace NarrowBand
  {
    /**
     * Refine, up to @p finest_level, every cell whose centre is closer to
     * the zero level set of @p signed_distance than
     * band_width * epsilon + half the cell diameter. Repeats until no cell
     * is flagged, so the band ends up on the finest level.
     */
    template <int dim>
    void
    refine_around_zero_level_set(
      dealii::parallel::distributed::Triangulation<dim> &triangulation,
      const dealii::Function<dim>                       &signed_distance,
      const double                                       band_width,
      const double                                       epsilon,
      const unsigned int                                 finest_level);

    /**
     * Set refinement and coarsening flags from the phase field @p u
     * (ghosted): a cell is in the band if one of its vertices has
     * |u| < tanh(band_width) or u changes sign on it. Cells in the band
     * are flagged for refinement up to @p finest_level. Cells outside the
     * wider band of @p coarsening_band_width (>= band_width; by default
     * the same) are flagged for coarsening down to @p coarsest_level, the
     * cells in between keep their level. Returns true if any flag was set
     * on any rank (a collective operation).
     */
    template <int dim>
    bool
    flag_cells_from_phase_field(const dealii::DoFHandler<dim> &dof_handler,
                                const Vector                  &u,
                                const double                   band_width,
                                const unsigned int             finest_level,
                                const unsigned int             coarsest_level,
                                const double coarsening_band_width = 0);

    /**
     * Whether the mesh fits the band of the phase field @p u (ghosted)
     * within a margin, on all ranks (a collective operation): every cell
     * of the band of @p inner_width (as in flag_cells_from_phase_field():
     * a vertex with |u| < tanh(inner_width) or a sign change) is on
     * @p finest_level, and no group of sibling cells on @p finest_level
     * lies wholly outside the band of @p outer_width (such a group would
     * be coarsened; not checked if @p outer_width is infinite).
     */
    template <int dim>
    bool
    band_fits(const dealii::DoFHandler<dim> &dof_handler,
              const Vector                  &u,
              const double                   inner_width,
              const double                   outer_width,
              const unsigned int             finest_level);
  } // namespace NarrowBand
} // namespace PhaseField

#endif
