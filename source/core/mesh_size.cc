#include <algorithm>
#include <cmath>
#include <deal.II/base/utilities.h>
#include <fstream>
#include <limits>
#include <phasefield/core/mesh_size.h>
#include <phasefield/core/parameters.h>
#include <sys/resource.h>
#include <unistd.h>

namespace PhaseField
{
  namespace MeshSize
  {
    namespace
    {
      constexpr double unlimited = std::numeric_limits<double>::infinity();

      /** The value of determine_memory_per_rank(). */
      double determined_memory_per_rank = unlimited;

      /** The number in the file @p filename, or unlimited (none, "max"). */
      double
      limit_in_file(const char *filename)
      {
        std::ifstream in(filename);
        double        value = 0;
        if (in >> value && value > 0)
          return value;
        return unlimited;
      }

      /** Physical memory of this node, or its cgroup's limit if smaller. */
      double
      node_memory()
      {
        const double physical =
          double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGESIZE));
        return std::min(
          {physical > 0 ? physical : unlimited,
           limit_in_file("/sys/fs/cgroup/memory.max"),
           limit_in_file("/sys/fs/cgroup/memory/memory.limit_in_bytes")});
      }

      /** The address space that `ulimit -v` leaves this process. */
      double
      address_space_left()
      {
        rlimit limit{};
        if (getrlimit(RLIMIT_AS, &limit) != 0 ||
            limit.rlim_cur == RLIM_INFINITY)
          return unlimited;
        dealii::Utilities::System::MemoryStats memory;
        dealii::Utilities::System::get_memory_stats(memory);
        constexpr double bytes_per_kib = 1024.;
        return std::max(0.,
                        double(limit.rlim_cur) - memory.VmSize * bytes_per_kib);
      }

      /** The number of ranks of @p mpi_communicator on this node. */
      unsigned int
      ranks_on_node(const MPI_Comm mpi_communicator)
      {
        MPI_Comm node;
        MPI_Comm_split_type(
          mpi_communicator, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
        const unsigned int n = dealii::Utilities::MPI::n_mpi_processes(node);
        MPI_Comm_free(&node);
        return n;
      }

      /** @p bytes in GB, rounded up, as text. */
      std::string
      gigabytes(const double bytes)
      {
        constexpr double bytes_per_gb = 1e9;
        return std::to_string(
          static_cast<long long>(std::ceil(bytes / bytes_per_gb)));
      }
    } // namespace



    void
    determine_memory_per_rank(const MPI_Comm mpi_communicator)
    {
      const double local =
        std::min(node_memory() / ranks_on_node(mpi_communicator),
                 address_space_left());
      determined_memory_per_rank =
        dealii::Utilities::MPI::min(local, mpi_communicator);
    }



    double
    memory_per_rank()
    {
      return determined_memory_per_rank;
    }



    double
    bytes_per_cell(const unsigned int dim)
    {
      constexpr double bytes_per_kb = 1024;
      return (dim == 2 ? 8 : 1.5) * bytes_per_kb;
    }



    void
    check_mesh_fits(const double       n_cells,
                    const unsigned int dim,
                    const unsigned int n_ranks,
                    const std::string &what,
                    const std::string &remedy)
    {
      const double per_rank = n_cells / n_ranks;
      const double bytes    = per_rank * bytes_per_cell(dim);
      const bool   too_many =
        per_rank > WillmoreParameters::max_uniform_cells_per_rank;
      if (!too_many && bytes <= memory_per_rank())
        return;
      const std::string limit =
        too_many ? "the limit is 2^24 cells per rank" :
                   "this machine has about " + gigabytes(memory_per_rank()) +
                     " GB per rank (its memory, or the limit of `ulimit -v`, "
                     "shared by the ranks on a node)";
      throw InputError(
        what + " " + std::to_string(static_cast<unsigned long long>(n_cells)) +
        " cells (" + std::to_string(static_cast<unsigned long long>(per_rank)) +
        " per rank on " + std::to_string(n_ranks) + " rank(s), about " +
        gigabytes(bytes) + " GB per rank at " +
        (dim == 2 ? std::string("8") : std::string("1.5")) + " KB per cell); " +
        limit + ". " + remedy);
    }
  } // namespace MeshSize
} // namespace PhaseField
