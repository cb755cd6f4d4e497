#ifndef phasefield_core_mesh_size_h
#define phasefield_core_mesh_size_h

#include <deal.II/base/mpi.h>
#include <string>

namespace PhaseField
{
  /**
   * Whether a mesh fits: the limits against which the size of a uniform
   * mesh (WillmoreParameters::check_uniform_mesh_size()) and the estimate
   * of a narrow-band mesh (problems/mesh_estimate.h) are checked before
   * any mesh exists, so that a run that cannot fit stops with an input
   * error instead of an allocation failure deep inside p4est or MUMPS.
   */
  namespace MeshSize
  {
    /**
     * Determine the memory one MPI rank of @p mpi_communicator may use:
     * the smallest over the ranks of the physical memory (or the cgroup's
     * memory limit, if smaller) divided by the ranks on that node, and the
     * address space that the process's limit (`ulimit -v`) leaves. The
     * same value on every rank. Collective; run_program() calls it once.
     */
    void
    determine_memory_per_rank(const MPI_Comm mpi_communicator);

    /**
     * The memory per rank of determine_memory_per_rank() in bytes;
     * infinity if it was not called (a test that makes a problem
     * directly: then only the number of cells per rank limits).
     */
    double
    memory_per_rank();

    /**
     * The memory a run needs per cell of its mesh in @p dim dimensions:
     * 8 KB in 2D (direct solver), 1.5 KB in 3D (matrix-free solver); the
     * runs behind them: doc/willmore_flow.md, "Input checks".
     */
    double
    bytes_per_cell(const unsigned int dim);

    /**
     * Throw an InputError if @p n_cells cells on @p n_ranks ranks are more
     * than WillmoreParameters::max_uniform_cells_per_rank (2^24) per rank,
     * or need more than memory_per_rank() at bytes_per_cell(@p dim). The
     * message is @p what (which
     * names the parameters and ends with "of"), the number of cells, the
     * memory per rank, the limit, and @p remedy. Not collective: the same
     * on every rank for the same arguments.
     */
    void
    check_mesh_fits(const double       n_cells,
                    const unsigned int dim,
                    const unsigned int n_ranks,
                    const std::string &what,
                    const std::string &remedy);
  } // namespace MeshSize
} // namespace PhaseField

#endif
