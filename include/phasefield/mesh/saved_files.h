#ifndef phasefield_mesh_saved_files_h
#define phasefield_mesh_saved_files_h

#include <cstdint>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <phasefield/core/linear_algebra.h>
#include <string>
#include <vector>

namespace PhaseField
{
  /**
   * What Discretization::save() must have written, so that a file that a
   * file size limit, a quota or a full disk cut short is found right after
   * the save instead of when a resume reads it: deal.II's and p4est's
   * writers do not report every failed write (MPI-IO and buffered stdio
   * writes of a file that reaches `ulimit -f` end short without an error
   * that reaches the program).
   *
   * The sizes follow the file formats of deal.II 9.4's
   * parallel::distributed::Triangulation::save() with one fixed-size
   * SolutionTransfer and of p4est 2.x's p4est_save(): a change of either
   * format makes every checkpoint write fail with a message naming the
   * file, never a checkpoint accepted unchecked.
   */
  namespace SavedFiles
  {
    /** A file of a save() and the number of bytes it must have. */
    struct ExpectedFile
    {
      std::string    filename;
      std::uintmax_t size = 0;
    };

    /**
     * The files that save(@p filename_base, fields) writes for the mesh
     * @p triangulation with @p n_fields fields of @p dofs_per_cell values
     * per cell: `<base>` (p4est), `<base>.info`, `<base>_fixed.data`,
     * with their sizes. Not collective.
     */
    template <int dim>
    std::vector<ExpectedFile>
    expected_files(
      const std::string                                       &filename_base,
      const dealii::parallel::distributed::Triangulation<dim> &triangulation,
      const unsigned int                                       dofs_per_cell,
      const unsigned int                                       n_fields);

    /**
     * Check the files of a save(@p filename_base) of @p triangulation
     * with @p n_fields fields: each must have its expected size; the
     * `.info` file must hold what deal.II writes for this mesh and number
     * of ranks, the p4est file the connectivity, the header and this
     * rank's cells of @p triangulation, and `_fixed.data` the header of
     * @p n_fields fields per cell. Throws a WriteError naming the first
     * file that differs on every rank. Collective.
     */
    template <int dim>
    void
    check(
      const std::string                                       &filename_base,
      const dealii::parallel::distributed::Triangulation<dim> &triangulation,
      const unsigned int                                       dofs_per_cell,
      const unsigned int                                       n_fields);

    /**
     * A 64-bit checksum of the values of @p fields at the vertices of the
     * mesh of @p dof_handler (Q1): the sum over all DoFs of a hash of the
     * DoF's vertex coordinates and values (all bits), so that it does not
     * depend on the numbering of the DoFs or on the partition. A mesh and
     * fields read back by Discretization::load() have the checksum of
     * the ones saved. Collective.
     */
    template <int dim>
    std::uint64_t
    field_checksum(const dealii::DoFHandler<dim> &dof_handler,
                   const BlockVector             &fields);
  } // namespace SavedFiles
} // namespace PhaseField

#endif
