#include <algorithm>
#include <cmath>
#include <deal.II/dofs/dof_tools.h>
#include <phasefield/core/constants.h>
#include <phasefield/mesh/q1_cells.h>
#include <unordered_map>

namespace PhaseField
{
  using namespace dealii;

  namespace
  {
    /** Whether the vertices of @p cell are those of an axis-parallel cube. */
    template <typename CellIterator>
    bool
    is_axis_parallel_cube(const CellIterator &cell)
    {
      constexpr int dim       = CellIterator::AccessorType::dimension;
      const auto   &origin    = cell->vertex(0);
      const double  h         = cell->vertex(1)[0] - origin[0];
      const double  tolerance = Constants::roundoff * h;
      for (const unsigned int v : cell->vertex_indices())
        for (unsigned int d = 0; d < dim; ++d)
          if (std::abs(cell->vertex(v)[d] - origin[d] - ((v >> d) & 1) * h) >
              tolerance)
            return false;
      return true;
    }
    /**
     * The partitioner of the DoFs of @p dof_handler on the multigrid level
     * @p mg_level (numbers::invalid_unsigned_int: the active mesh): the
     * locally owned ones and the locally relevant ones as ghosts.
     */
    template <int dim>
    std::shared_ptr<const Utilities::MPI::Partitioner>
    make_partitioner(const DoFHandler<dim> &dof_handler,
                     const unsigned int     mg_level)
    {
      const bool on_level = mg_level != numbers::invalid_unsigned_int;
      IndexSet   relevant;
      if (on_level)
        DoFTools::extract_locally_relevant_level_dofs(dof_handler,
                                                      mg_level,
                                                      relevant);
      else
        DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
      return std::make_shared<const Utilities::MPI::Partitioner>(
        on_level ? dof_handler.locally_owned_mg_dofs(mg_level) :
                   dof_handler.locally_owned_dofs(),
        relevant,
        dof_handler.get_communicator());
    }
  } // namespace



  template <int dim>
  Q1Cells<dim>::Q1Cells(const DoFHandler<dim>           &dof_handler,
                        const AffineConstraints<double> &constraints,
                        const unsigned int               mg_level)
  {
    const bool     on_level = mg_level != numbers::invalid_unsigned_int;
    const MPI_Comm comm     = dof_handler.get_communicator();
    partitioner             = make_partitioner(dof_handler, mg_level);

    // the constraint number of every constrained DoF met so far
    std::unordered_map<types::global_dof_index, unsigned int> numbered;
    const auto entry = [&](const types::global_dof_index dof) {
      if (!constraints.is_constrained(dof))
        return partitioner->global_to_local(dof);
      const auto [it, fresh] = numbered.emplace(dof, numbered.size());
      if (fresh)
        {
          for (const auto &[master, weight] :
               *constraints.get_constraint_entries(dof))
            constraint_entries.emplace_back(
              partitioner->global_to_local(master), weight);
          constraint_start.push_back(constraint_entries.size());
        }
      return constrained_mark | it->second;
    };

    // every cell is a cube whose edge is that of a level-0 cell halved
    // level times: coarse_edge = h 2^level within round-off
    bool                                 cubes      = true;
    double                               coarse_min = 1e300, coarse_max = 0;
    std::vector<types::global_dof_index> indices(n);
    const auto                           add_cell = [&](const auto &cell) {
      if (on_level)
        cell->get_mg_dof_indices(indices);
      else
        cell->get_dof_indices(indices);
      for (const types::global_dof_index dof : indices)
        dofs.push_back(entry(dof));
      cell_level.push_back(cell->level());
      const double coarse_edge =
        std::ldexp(cell->vertex(1)[0] - cell->vertex(0)[0], cell->level());
      coarse_min = std::min(coarse_min, coarse_edge);
      coarse_max = std::max(coarse_max, coarse_edge);
      cubes = cubes && is_axis_parallel_cube(cell);
    };
    // every owned cell once, counted first so that the tables are
    // allocated once (growing them would take up to three times their size)
    const auto for_each_owned_cell = [&](const auto &action) {
      if (on_level)
        {
          for (const auto &cell :
               dof_handler.mg_cell_iterators_on_level(mg_level))
            if (cell->is_locally_owned_on_level())
              action(cell);
        }
      else
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            action(cell);
    };
    std::size_t n_cells = 0;
    for_each_owned_cell([&](const auto &) { ++n_cells; });
    dofs.reserve(n_cells * n);
    cell_level.reserve(n_cells);
    for_each_owned_cell(add_cell);

    coarse_min = Utilities::MPI::min(coarse_min, comm);
    coarse_max = Utilities::MPI::max(coarse_max, comm);
    AssertThrow(Utilities::MPI::min(cubes ? 1 : 0, comm) == 1 &&
                  coarse_max - coarse_min <= Constants::roundoff * coarse_max,
                ExcMessage("The matrix-free stiffness operator needs a mesh "
                           "of axis-parallel cubes refined from coarse cubes "
                           "of one size."));
    const unsigned int n_levels =
      dof_handler.get_triangulation().n_global_levels();
    for (unsigned int level = 0; level < n_levels; ++level)
      level_scale.push_back(
        std::pow(std::ldexp(coarse_max, -static_cast<int>(level)), dim - 2));
  }



  template <int dim>
  template <typename Number>
  Number
  Q1Cells<dim>::read(
    const unsigned int                                dof,
    const LinearAlgebra::distributed::Vector<Number> &src) const
  {
    if ((dof & constrained_mark) == 0)
      return src.local_element(dof);
    const unsigned int k     = dof & ~constrained_mark;
    Number             value = 0;
    for (unsigned int e = constraint_start[k]; e < constraint_start[k + 1]; ++e)
      value += static_cast<Number>(constraint_entries[e].second) *
               src.local_element(constraint_entries[e].first);
    return value;
  }



  template <int dim>
  template <typename Number>
  void
  Q1Cells<dim>::add(const unsigned int                          dof,
                    const Number                                value,
                    LinearAlgebra::distributed::Vector<Number> &dst) const
  {
    if ((dof & constrained_mark) == 0)
      {
        dst.local_element(dof) += value;
        return;
      }
    const unsigned int k = dof & ~constrained_mark;
    for (unsigned int e = constraint_start[k]; e < constraint_start[k + 1]; ++e)
      dst.local_element(constraint_entries[e].first) +=
        static_cast<Number>(constraint_entries[e].second) * value;
  }



  template <int dim>
  template <typename Number>
  void
  Q1Cells<dim>::apply_add(const Q1CellStiffness<dim, Number> &kernel,
                          const Number                        factor,
                          const LinearAlgebra::distributed::Vector<Number> &src,
                          LinearAlgebra::distributed::Vector<Number> &dst) const
  {
    Assert(src.get_partitioner()->ghost_indices() ==
               partitioner->ghost_indices() &&
             dst.get_partitioner()->ghost_indices() ==
               partitioner->ghost_indices(),
           ExcMessage("The vectors do not have the layout of the cells."));
    const bool had_ghosts = src.has_ghost_elements();
    src.update_ghost_values();
    dst.zero_out_ghost_values();
    std::vector<Number> scale(level_scale.size());
    for (unsigned int level = 0; level < scale.size(); ++level)
      scale[level] = factor * level_scale[level];

    const std::size_t n_cells = cell_level.size();
    for (std::size_t cell = 0; cell < n_cells; ++cell)
      {
        const unsigned int *cell_dofs = dofs.data() + cell * n;
        Number              values[n];
        for (unsigned int i = 0; i < n; ++i)
          values[i] = read(cell_dofs[i], src);
        kernel.apply(values, scale[cell_level[cell]]);
        for (unsigned int i = 0; i < n; ++i)
          add(cell_dofs[i], values[i], dst);
      }

    dst.compress(VectorOperation::add);
    if (!had_ghosts)
      src.zero_out_ghost_values();
  }



  template <int dim>
  std::size_t
  Q1Cells<dim>::memory_consumption() const
  {
    return dofs.capacity() * sizeof(unsigned int) + cell_level.capacity() +
           constraint_start.capacity() * sizeof(unsigned int) +
           constraint_entries.capacity() *
             sizeof(std::pair<unsigned int, double>) +
           (partitioner ? partitioner->memory_consumption() : 0);
  }



  template class Q1Cells<2>;
  template class Q1Cells<3>;
  template void
  Q1Cells<2>::apply_add(const Q1CellStiffness<2, float> &,
                        const float,
                        const LinearAlgebra::distributed::Vector<float> &,
                        LinearAlgebra::distributed::Vector<float> &) const;
  template void
  Q1Cells<3>::apply_add(const Q1CellStiffness<3, float> &,
                        const float,
                        const LinearAlgebra::distributed::Vector<float> &,
                        LinearAlgebra::distributed::Vector<float> &) const;
  template void
  Q1Cells<2>::apply_add(const Q1CellStiffness<2, double> &,
                        const double,
                        const LinearAlgebra::distributed::Vector<double> &,
                        LinearAlgebra::distributed::Vector<double> &) const;
  template void
  Q1Cells<3>::apply_add(const Q1CellStiffness<3, double> &,
                        const double,
                        const LinearAlgebra::distributed::Vector<double> &,
                        LinearAlgebra::distributed::Vector<double> &) const;
} // namespace PhaseField
