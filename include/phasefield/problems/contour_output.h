#ifndef phasefield_problems_contour_output_h
#define phasefield_problems_contour_output_h

#include <deal.II/base/mpi.h>
#include <phasefield/core/linear_algebra.h>
#include <phasefield/geometry/huffman_labeling.h>
#include <phasefield/mesh/discretization.h>
#include <string>
#include <vector>

namespace PhaseField
{
  /**
   * What shape_from_contour writes at the end of every level beyond
   * willmore_flow's output: the labelings as CSV, as VTU and as a picture,
   * in 3D also the picture of the body beside its target labeling.
   */
  namespace ContourOutput
  {
    /** Target and current labeling at the pixel centres of @p grid. */
    template <int dim>
    struct Labelings
    {
      /** A grid with one point per pixel, its centre. */
      const HuffmanLabeling::LabelingGrid<dim> &grid;
      std::vector<double>                       target;
      std::vector<double>                       alpha;
    };

    /**
     * @p filename with the columns x,alpha_target,alpha (2D) or
     * x,y,alpha_target,alpha (3D), one row per pixel centre (x fastest).
     * Written by rank 0; collective.
     */
    template <int dim>
    void
    write_csv(const Labelings<dim> &labelings,
              const std::string    &filename,
              const MPI_Comm        comm);

    /**
     * @p filename: the labelings as a VTU on the image plane, for
     * ParaView: a Q1 mesh whose vertices are the pixel centres, a line in
     * 2D (at y = 0) and a plane in 3D (at z = 0), so that it lies under
     * the domain of solution.pvd, with the point data alpha_target and
     * alpha. Needs one point per pixel. Written by rank 0; collective.
     */
    template <int dim>
    void
    write_vtu(const Labelings<dim> &labelings,
              const std::string    &filename,
              const MPI_Comm        comm);

    /**
     * The PNG picture @p filename (collective; rank 0 writes).
     * 2D, as thesis Fig. 6.5: the phase field @p u on [0,1]^2 (black
     * inside, white outside), and below it alpha* (blue) and alpha[U]
     * (red) over the image line, with gray lines at the even labels.
     * 3D, as thesis Fig. 6.10-6.12: alpha[U] over the image plane (black 0
     * to white at the largest label) with the contour lines of alpha*
     * (blue) and alpha[U] (red) at the labels 1, 3, 5, ... (the apparent
     * contours between the labels 0, 2, 4, ...).
     */
    template <int dim>
    void
    write_picture(const Labelings<dim>      &labelings,
                  const Discretization<dim> &discretization,
                  const Vector              &u,
                  const std::string         &filename);

    /**
     * 3D: the PNG picture @p filename of the body {U < 0}, its surface
     * U = 0 (of @p ghosted_u on @p dof_handler, the hanging nodes on their
     * constraints) seen from the oblique direction of SurfacePicture (the
     * view axis x_3 up) on the left, beside the target labeling alpha* on
     * the right (black 0 to white at the largest label, its contour lines
     * at the labels 1, 3, 5, ... in blue). Collective; rank 0 writes.
     */
    void
    write_body_picture(const Labelings<3>          &labelings,
                       const dealii::DoFHandler<3> &dof_handler,
                       const Vector                &ghosted_u,
                       const std::string           &filename);
  } // namespace ContourOutput
} // namespace PhaseField

#endif
