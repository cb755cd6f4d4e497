#include <cstring>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <deal.II/distributed/p4est_wrappers.h>
#include <deal.II/lac/vector.h>
#include <filesystem>
#include <fstream>
#include <phasefield/core/file_io.h>
#include <phasefield/mesh/saved_files.h>

namespace PhaseField
{
  namespace SavedFiles
  {
    namespace
    {
      namespace fs = std::filesystem;
      using namespace dealii;

      /** p4est aligns the header and the cells of its file to this. */
      constexpr std::uintmax_t p4est_alignment = 32;
      /** Fixed entries of p4est's file header (format, sizes, ranks). */
      constexpr std::uintmax_t p4est_header_entries = 6;
      /** deal.II's version of the `.info` file. */
      const std::string info_version = "4";
      /** The first line of the `.info` file. */
      const std::string info_header =
        "version nproc n_attached_fixed_size_objs "
        "n_attached_variable_size_objs n_coarse_cells";

      std::uintmax_t
      aligned(const std::uintmax_t bytes)
      {
        return (bytes + p4est_alignment - 1) / p4est_alignment *
               p4est_alignment;
      }

      /** The connectivity as p4est_save() writes it (its first bytes). */
      template <int dim>
      std::string
      connectivity_bytes(
        const parallel::distributed::Triangulation<dim> &triangulation)
      {
        const auto *forest = triangulation.get_p4est();
        sc_array_t *buffer = nullptr;
        if constexpr (dim == 2)
          buffer = p4est_connectivity_deflate(forest->connectivity,
                                              P4EST_CONN_ENCODE_NONE);
        else
          buffer = p8est_connectivity_deflate(forest->connectivity,
                                              P8EST_CONN_ENCODE_NONE);
        const std::string bytes(buffer->array,
                                buffer->elem_count * buffer->elem_size);
        sc_array_destroy(buffer);
        return bytes;
      }

      /** The p4est file: connectivity, header, then the cells. */
      template <int dim>
      struct P4estLayout
      {
        std::string                connectivity;
        std::vector<std::uint64_t> header;
        std::uintmax_t             cells_offset   = 0;
        std::uintmax_t             bytes_per_cell = 0;
        std::uintmax_t             size           = 0;
      };

      template <int dim>
      P4estLayout<dim>
      p4est_layout(
        const parallel::distributed::Triangulation<dim> &triangulation)
      {
        const auto      *forest = triangulation.get_p4est();
        P4estLayout<dim> layout;
        layout.connectivity = connectivity_bytes(triangulation);
        // p4est_save() with the partition and without cell data
        layout.header = {dim == 2 ? P4EST_ONDISK_FORMAT : P8EST_ONDISK_FORMAT,
                         sizeof(std::int32_t),
                         dim == 2 ? sizeof(p4est_quadrant_t) :
                                    sizeof(p8est_quadrant_t),
                         0,
                         0,
                         static_cast<std::uint64_t>(forest->mpisize)};
        for (int rank = 0; rank < forest->mpisize; ++rank)
          layout.header.push_back(forest->global_first_quadrant[rank + 1]);
        const std::uintmax_t n_trees  = forest->connectivity->num_trees;
        const std::uintmax_t n_header = layout.header.size() + n_trees;
        layout.cells_offset           = aligned(layout.connectivity.size()) +
                              aligned(n_header * sizeof(std::uint64_t));
        // per cell its coordinates and level as p4est_qcoord_t
        layout.bytes_per_cell = (dim + 1) * sizeof(std::int32_t);
        layout.size           = layout.cells_offset +
                      forest->global_num_quadrants * layout.bytes_per_cell;
        return layout;
      }

      /** This rank's cells as p4est_save() writes them. */
      template <int dim>
      std::string
      local_cell_bytes(
        const parallel::distributed::Triangulation<dim> &triangulation)
      {
        const auto               *forest = triangulation.get_p4est();
        std::vector<std::int32_t> values;
        using Tree     = typename dealii::internal::p4est::types<dim>::tree;
        using Quadrant = typename dealii::internal::p4est::types<dim>::quadrant;
        for (auto tree = forest->first_local_tree;
             tree >= 0 && tree <= forest->last_local_tree;
             ++tree)
          {
            const sc_array_t &quadrants =
              static_cast<const Tree *>(sc_array_index(forest->trees, tree))
                ->quadrants;
            for (std::size_t q = 0; q < quadrants.elem_count; ++q)
              {
                const Quadrant *quadrant = reinterpret_cast<const Quadrant *>(
                  quadrants.array + q * quadrants.elem_size);
                values.push_back(quadrant->x);
                values.push_back(quadrant->y);
                if constexpr (dim == 3)
                  values.push_back(quadrant->z);
                values.push_back(quadrant->level);
              }
          }
        return std::string(reinterpret_cast<const char *>(values.data()),
                           values.size() * sizeof(std::int32_t));
      }

      /** The `.info` file of deal.II's save(). */
      template <int dim>
      std::string
      info_text(const parallel::distributed::Triangulation<dim> &triangulation)
      {
        // one fixed-size SolutionTransfer, no variable-size data
        return info_header + "\n" + info_version + " " +
               std::to_string(Utilities::MPI::n_mpi_processes(
                 triangulation.get_communicator())) +
               " 1 0 " + std::to_string(triangulation.n_cells(0)) + "\n";
      }

      /**
       * The header of `_fixed.data`: the cumulative sizes per cell of the
       * cell status and the fields (SolutionTransfer writes the values
       * of all fields at the cell's DoFs one after the other).
       */
      template <int dim>
      std::vector<unsigned int>
      fixed_data_header(const unsigned int dofs_per_cell,
                        const unsigned int n_fields)
      {
        const std::size_t status =
          sizeof(typename dealii::Triangulation<dim>::CellStatus);
        return {static_cast<unsigned int>(status),
                static_cast<unsigned int>(status + std::size_t(n_fields) *
                                                     dofs_per_cell *
                                                     sizeof(double))};
      }

      /** @p length bytes of @p filename from @p offset (fewer at its end). */
      std::string
      read_bytes(const std::string   &filename,
                 const std::uintmax_t offset,
                 const std::uintmax_t length)
      {
        std::ifstream in(filename, std::ios::binary);
        std::string   bytes(length, '\0');
        in.seekg(offset);
        in.read(bytes.data(), length);
        bytes.resize(in ? length : std::max<std::streamsize>(in.gcount(), 0));
        return bytes;
      }

      [[noreturn]] void
      fail(const std::string &filename, const std::string &problem)
      {
        throw WriteError(
          "The checkpoint file <" + filename + "> " + problem +
          " after it was written (a file size limit (ulimit -f), a quota or "
          "a full disk?). The run stops here: statistics.csv and the output "
          "are complete up to this step, the incomplete checkpoint is "
          "removed, and the last complete checkpoint (if any) is intact.");
      }

      /** Rank 0's part of check(): sizes and the headers. */
      template <int dim>
      void
      check_on_root(
        const std::string                               &filename_base,
        const parallel::distributed::Triangulation<dim> &triangulation,
        const unsigned int                               dofs_per_cell,
        const unsigned int                               n_fields)
      {
        for (const ExpectedFile &file : expected_files(
               filename_base, triangulation, dofs_per_cell, n_fields))
          {
            std::error_code      error;
            const std::uintmax_t found = fs::file_size(file.filename, error);
            if (error)
              fail(file.filename, "is missing");
            if (found != file.size)
              fail(file.filename,
                   "has " + std::to_string(found) + " bytes instead of " +
                     std::to_string(file.size) +
                     (found < file.size ? " (cut short)" : ""));
          }
        const std::string info = filename_base + ".info";
        if (read_bytes(info, 0, info_text(triangulation).size()) !=
            info_text(triangulation))
          fail(info, "does not hold what deal.II writes for this mesh");
        const P4estLayout<dim> layout = p4est_layout(triangulation);
        const std::string      header_bytes(
          reinterpret_cast<const char *>(layout.header.data()),
          layout.header.size() * sizeof(std::uint64_t));
        if (read_bytes(filename_base, 0, layout.connectivity.size()) !=
              layout.connectivity ||
            read_bytes(filename_base,
                       aligned(layout.connectivity.size()),
                       header_bytes.size()) != header_bytes)
          fail(filename_base,
               "does not hold the coarse mesh and header of this mesh");
        const std::vector<unsigned int> fixed =
          fixed_data_header<dim>(dofs_per_cell, n_fields);
        const std::string fixed_file = filename_base + "_fixed.data";
        if (read_bytes(fixed_file, 0, fixed.size() * sizeof(unsigned int)) !=
            std::string(reinterpret_cast<const char *>(fixed.data()),
                        fixed.size() * sizeof(unsigned int)))
          fail(fixed_file,
               "does not have the header of " + std::to_string(n_fields) +
                 " fields per cell");
      }
    } // namespace



    template <int dim>
    std::vector<ExpectedFile>
    expected_files(
      const std::string                               &filename_base,
      const parallel::distributed::Triangulation<dim> &triangulation,
      const unsigned int                               dofs_per_cell,
      const unsigned int                               n_fields)
    {
      const std::vector<unsigned int> fixed =
        fixed_data_header<dim>(dofs_per_cell, n_fields);
      const std::uintmax_t fixed_size =
        fixed.size() * sizeof(unsigned int) +
        static_cast<std::uintmax_t>(triangulation.n_global_active_cells()) *
          fixed.back();
      return {{filename_base, p4est_layout(triangulation).size},
              {filename_base + ".info", info_text(triangulation).size()},
              {filename_base + "_fixed.data", fixed_size}};
    }



    template <int dim>
    void
    check(const std::string                               &filename_base,
          const parallel::distributed::Triangulation<dim> &triangulation,
          const unsigned int                               dofs_per_cell,
          const unsigned int                               n_fields)
    {
      const MPI_Comm comm = triangulation.get_communicator();
      run_on_every_rank(comm, [&]() {
        if (Utilities::MPI::this_mpi_process(comm) == 0)
          check_on_root(filename_base, triangulation, dofs_per_cell, n_fields);
      });
      // every rank reads back its own cells of the p4est file
      run_on_every_rank(comm, [&]() {
        const auto            *forest = triangulation.get_p4est();
        const P4estLayout<dim> layout = p4est_layout(triangulation);
        const std::string      cells  = local_cell_bytes(triangulation);
        const std::uintmax_t   offset =
          layout.cells_offset + forest->global_first_quadrant[forest->mpirank] *
                                  layout.bytes_per_cell;
        if (read_bytes(filename_base, offset, cells.size()) != cells)
          fail(filename_base,
               "does not hold the cells of rank " +
                 std::to_string(forest->mpirank));
      });
    }



    template <int dim>
    std::uint64_t
    field_checksum(const DoFHandler<dim> &dof_handler,
                   const BlockVector     &fields)
    {
      constexpr std::uint64_t offset_basis = 14695981039346656037ull;
      constexpr std::uint64_t prime        = 1099511628211ull;
      const auto              mix = [&](std::uint64_t &hash, const double x) {
        unsigned char bytes[sizeof(double)];
        std::memcpy(bytes, &x, sizeof(double));
        for (const unsigned char byte : bytes)
          hash = (hash ^ byte) * prime;
      };
      const IndexSet   &owned = dof_handler.locally_owned_dofs();
      std::vector<bool> seen(owned.n_elements(), false);
      std::uint64_t     sum = 0;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const unsigned int v : cell->vertex_indices())
            {
              const types::global_dof_index dof = cell->vertex_dof_index(v, 0);
              if (!owned.is_element(dof) || seen[owned.index_within_set(dof)])
                continue;
              seen[owned.index_within_set(dof)] = true;
              std::uint64_t hash                = offset_basis;
              for (unsigned int d = 0; d < dim; ++d)
                mix(hash, cell->vertex(v)[d]);
              for (unsigned int b = 0; b < fields.n_blocks(); ++b)
                mix(hash, fields.block(b)[dof]);
              // a sum does not depend on the order of the DoFs
              sum += hash;
            }
      return Utilities::MPI::sum(sum, dof_handler.get_communicator());
    }



    template std::vector<ExpectedFile>
    expected_files<2>(const std::string &,
                      const parallel::distributed::Triangulation<2> &,
                      const unsigned int,
                      const unsigned int);
    template std::vector<ExpectedFile>
    expected_files<3>(const std::string &,
                      const parallel::distributed::Triangulation<3> &,
                      const unsigned int,
                      const unsigned int);
    template void
    check<2>(const std::string &,
             const parallel::distributed::Triangulation<2> &,
             const unsigned int,
             const unsigned int);
    template void
    check<3>(const std::string &,
             const parallel::distributed::Triangulation<3> &,
             const unsigned int,
             const unsigned int);
    template std::uint64_t
    field_checksum<2>(const DoFHandler<2> &, const BlockVector &);
    template std::uint64_t
    field_checksum<3>(const DoFHandler<3> &, const BlockVector &);
  } // namespace SavedFiles
} // namespace PhaseField
