#ifndef phasefield_mesh_zero_level_surface_h
#define phasefield_mesh_zero_level_surface_h

#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_handler.h>
#include <phasefield/core/linear_algebra.h>
#include <phasefield/core/parameters.h>
#include <string>
#include <vector>

namespace PhaseField
{
  /**
   * The zero level set of the Q1 phase field U of a 3D run as a
   * triangulated surface, and its STL and PLY files (`Output / Surface
   * format`).
   *
   * Each locally owned cell that U changes sign on is sampled on the
   * lattice of the finest level of the mesh (2^(finest level - cell level)
   * sub-cells per direction, the values those of the cell's trilinear
   * interpolant), and VTK's contour filter (marching cubes on hexahedra)
   * cuts the sub-cells at U = 0. Because every cut cell is sampled on the
   * same lattice, two cells that share a face, of one level or across a
   * face with hanging nodes (whose values the constraints of the
   * continuous Q1 field interpolate from the coarse face), cut it along
   * the same edges at the same points: the triangles of all cells join
   * without seams, and a surface that does not meet the boundary of the
   * domain is closed. Each cell belongs to one rank, so no triangle is
   * written twice; rank 0 gathers the triangles of all ranks, merges
   * their common corners (VTK's vtkCleanPolyData) and writes one file.
   *
   * The triangles are oriented with their normals towards U > 0 (out of
   * the inside phase U = -1).
   */
  namespace ZeroLevelSurface
  {
    /** The surface of all ranks, as written (rank 0's summary). */
    struct Summary
    {
      unsigned int n_triangles = 0;
      unsigned int n_vertices  = 0;
      /** Area of the triangles. */
      double area = 0;
      /**
       * Volume enclosed by the triangles (the divergence theorem with the
       * outward normals; the inside measure where the surface is closed).
       */
      double volume = 0;
    };

    /**
     * The triangles of U = 0 on the locally owned cells of
     * @p dof_handler (Q1) for the field @p ghosted_u (with the ghost
     * entries of the locally relevant DoFs, satisfying the hanging-node
     * constraints, or the surface has holes there): 9 coordinates per triangle,
     * its three corners one after the other. Not collective.
     */
    std::vector<double>
    local_triangles(const dealii::DoFHandler<3> &dof_handler,
                    const Vector                &ghosted_u);

    /**
     * The triangles of local_triangles() of all ranks on rank 0 (9
     * coordinates per triangle, one rank after the other; empty on the
     * other ranks). Collective.
     */
    std::vector<double>
    gathered_triangles(const dealii::DoFHandler<3> &dof_handler,
                       const Vector                &ghosted_u);

    /**
     * Write a picture of the surface U = 0 of @p ghosted_u on
     * @p dof_handler as the PNG file @p filename (SurfacePicture::write():
     * seen from the default oblique direction, light gray on white; the
     * same picture on any number of ranks). Rank 0 writes; throws
     * WriteError on every rank if it cannot. Collective.
     */
    void
    write_picture(const dealii::DoFHandler<3> &dof_handler,
                  const Vector                &ghosted_u,
                  const std::string           &filename);

    /** The file name extension of @p format (`stl`, `ply`). */
    std::string
    extension(const SurfaceFormat format);

    /**
     * Write the surface U = 0 of @p ghosted_u on @p dof_handler to
     * @p filename in @p format (not none): binary STL, or binary PLY with
     * shared vertices. Throws WriteError on every rank if the file cannot
     * be written completely. Returns the summary of the written surface
     * on every rank. Collective.
     */
    Summary
    write(const dealii::DoFHandler<3> &dof_handler,
          const Vector                &ghosted_u,
          const SurfaceFormat          format,
          const std::string           &filename);
  } // namespace ZeroLevelSurface
} // namespace PhaseField

#endif
