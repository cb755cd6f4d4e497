#include <algorithm>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_cartesian.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/matrix_free/fe_evaluation.h>
#include <deal.II/matrix_free/tools.h>
#include <deal.II/multigrid/mg_tools.h>
#include <phasefield/core/constants.h>
#include <phasefield/mesh/geometric_multigrid.h>

namespace PhaseField
{
  using namespace dealii;

  namespace
  {
    /**
     * Ratio of the largest to the smallest eigenvalue that a smoother
     * damps (deal.II's step-37: the upper part of the spectrum, which the
     * coarser levels cannot represent).
     */
    constexpr double smoothing_range = 15.;

    /** CG iterations of the largest-eigenvalue estimate of a smoother. */
    constexpr unsigned int eigenvalue_iterations = 10;

    /**
     * Relative accuracy of the coarse solve (Chebyshev iteration to this
     * ratio, as in step-37).
     */
    constexpr double multigrid_coarse_accuracy = 1e-3;
  } // namespace



  template <int dim, typename CellIterator>
  void
  cell_stiffness_matrix(FEValues<dim>      &fe_values,
                        const CellIterator &cell,
                        FullMatrix<double> &cell_matrix)
  {
    fe_values.reinit(cell);
    const unsigned int n = fe_values.dofs_per_cell;
    cell_matrix.reinit(n, n);
    for (const unsigned int q : fe_values.quadrature_point_indices())
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = 0; j < n; ++j)
          cell_matrix(i, j) += fe_values.shape_grad(i, q) *
                               fe_values.shape_grad(j, q) * fe_values.JxW(q);
  }



  Quadrature<1>
  stiffness_rule(const StiffnessQuadrature stiffness_quadrature)
  {
    constexpr unsigned int n_points = 2;
    return stiffness_quadrature == StiffnessQuadrature::gauss_lobatto ?
             Quadrature<1>(QGaussLobatto<1>(n_points)) :
             Quadrature<1>(QGauss<1>(n_points));
  }



  void
  copy_owned(const Vector &src, FineVector &dst)
  {
    AssertDimension(src.locally_owned_size(), dst.locally_owned_size());
    std::copy(src.begin(), src.end(), dst.begin());
  }



  void
  copy_owned(const FineVector &src, Vector &dst)
  {
    AssertDimension(src.locally_owned_size(), dst.locally_owned_size());
    std::copy(src.begin(), src.begin() + src.locally_owned_size(), dst.begin());
  }



  template <int dim>
  std::size_t
  MultigridLevel<dim>::memory_consumption() const
  {
    return cells.memory_consumption() +
           (boundary_dofs.capacity() + edge_dofs.capacity()) *
             sizeof(unsigned int) +
           lumped_mass.memory_consumption() +
           stiffness_diagonal.memory_consumption();
  }



  template <int dim>
  void
  LevelStiffness<dim>::initialize(const MultigridLevel<dim>         &l,
                                  const Q1CellStiffness<dim, float> &kernel,
                                  const double                       f,
                                  const LevelVector                 &d)
  {
    level                = &l;
    cell_stiffness       = &kernel;
    factor               = f;
    diagonal             = &d;
    inverse_diagonal     = std::make_shared<DiagonalMatrix<LevelVector>>();
    LevelVector &inverse = inverse_diagonal->get_vector();
    initialize_dof_vector(inverse);
    const unsigned int n = inverse.locally_owned_size();
    for (unsigned int i = 0; i < n; ++i)
      inverse.local_element(i) =
        1.f / (factor * level->stiffness_diagonal.local_element(i) +
               diagonal->local_element(i));
    for (const unsigned int i : level->boundary_dofs)
      inverse.local_element(i) = 1.f;
    for (const unsigned int i : level->edge_dofs)
      inverse.local_element(i) = 1.f;
  }



  template <int dim>
  void
  LevelStiffness<dim>::vmult(LevelVector &dst, const LevelVector &src) const
  {
    adjust_layout(dst);
    dst = 0.f;
    vmult_add(dst, src);
  }



  template <int dim>
  void
  LevelStiffness<dim>::vmult_add(LevelVector &dst, const LevelVector &src) const
  {
    adjust_layout(src);
    adjust_layout(dst);
    // the edge values of src are read as zero; edge and boundary rows are
    // the identity
    auto                    &source   = const_cast<LevelVector &>(src);
    const std::vector<float> edge_src = edge_values(src);
    std::vector<float>       edge_dst = edge_values(dst);
    set_edge_values(source, std::vector<float>(edge_src.size(), 0.f));
    apply_add(dst, src);
    for (const unsigned int i : level->boundary_dofs)
      dst.local_element(i) += src.local_element(i);
    set_edge_values(source, edge_src);
    for (unsigned int k = 0; k < edge_dst.size(); ++k)
      edge_dst[k] += edge_src[k];
    set_edge_values(dst, edge_dst);
  }



  template <int dim>
  void
  LevelStiffness<dim>::Tvmult(LevelVector &dst, const LevelVector &src) const
  {
    vmult(dst, src);
  }



  template <int dim>
  void
  LevelStiffness<dim>::Tvmult_add(LevelVector       &dst,
                                  const LevelVector &src) const
  {
    vmult_add(dst, src);
  }



  template <int dim>
  void
  LevelStiffness<dim>::vmult_interface_down(LevelVector       &dst,
                                            const LevelVector &src) const
  {
    if (!start_interface_product(dst, src))
      return;
    // the columns off the edge, then only the rows on the edge
    auto                    &source   = const_cast<LevelVector &>(src);
    const std::vector<float> edge_src = edge_values(src);
    set_edge_values(source, std::vector<float>(edge_src.size(), 0.f));
    apply_add(dst, src);
    const std::vector<float> edge_dst = edge_values(dst);
    dst                               = 0.f;
    set_edge_values(dst, edge_dst);
    set_edge_values(source, edge_src);
  }



  template <int dim>
  void
  LevelStiffness<dim>::vmult_interface_up(LevelVector       &dst,
                                          const LevelVector &src) const
  {
    if (!start_interface_product(dst, src))
      return;
    // the columns on the edge, then only the rows off the edge
    LevelVector edge_only;
    initialize_dof_vector(edge_only);
    set_edge_values(edge_only, edge_values(src));
    apply_add(dst, edge_only);
    set_edge_values(dst, std::vector<float>(level->edge_dofs.size(), 0.f));
  }



  template <int dim>
  bool
  LevelStiffness<dim>::start_interface_product(LevelVector       &dst,
                                               const LevelVector &src) const
  {
    adjust_layout(src);
    adjust_layout(dst);
    dst = 0.f;
    return level->any_edge;
  }



  template <int dim>
  std::vector<float>
  LevelStiffness<dim>::edge_values(const LevelVector &vector) const
  {
    std::vector<float> values;
    values.reserve(level->edge_dofs.size());
    for (const unsigned int i : level->edge_dofs)
      values.push_back(vector.local_element(i));
    return values;
  }



  template <int dim>
  void
  LevelStiffness<dim>::set_edge_values(LevelVector              &vector,
                                       const std::vector<float> &values) const
  {
    for (unsigned int k = 0; k < values.size(); ++k)
      vector.local_element(level->edge_dofs[k]) = values[k];
  }



  template <int dim>
  types::global_dof_index
  LevelStiffness<dim>::m() const
  {
    return level->cells.partitioner->size();
  }



  template <int dim>
  types::global_dof_index
  LevelStiffness<dim>::n() const
  {
    return m();
  }



  template <int dim>
  void
  LevelStiffness<dim>::initialize_dof_vector(LevelVector &vector) const
  {
    vector.reinit(level->cells.partitioner);
  }



  template <int dim>
  float
  LevelStiffness<dim>::el(const types::global_dof_index row,
                          const types::global_dof_index column) const
  {
    AssertThrow(row == column,
                ExcMessage("LevelStiffness gives its diagonal entries only."));
    return 1.f / inverse_diagonal->get_vector()(row);
  }



  template <int dim>
  const std::shared_ptr<DiagonalMatrix<LevelVector>> &
  LevelStiffness<dim>::get_matrix_diagonal_inverse() const
  {
    return inverse_diagonal;
  }



  template <int dim>
  void
  LevelStiffness<dim>::apply_add(LevelVector &dst, const LevelVector &src) const
  {
    level->cells.apply_add(*cell_stiffness, factor, src, dst);
    const unsigned int n = dst.locally_owned_size();
    for (unsigned int i = 0; i < n; ++i)
      dst.local_element(i) += diagonal->local_element(i) * src.local_element(i);
  }



  template <int dim>
  void
  LevelStiffness<dim>::adjust_layout(const LevelVector &vector) const
  {
    if (vector.get_partitioner().get() == level->cells.partitioner.get())
      return;
    AssertDimension(vector.locally_owned_size(),
                    level->cells.partitioner->locally_owned_size());
    const LevelVector copy(vector);
    auto             &adjusted = const_cast<LevelVector &>(vector);
    initialize_dof_vector(adjusted);
    adjusted.copy_locally_owned_data_from(copy);
  }



  template <int dim>
  void
  LevelInterface<dim>::initialize(const LevelStiffness<dim> &op)
  {
    level_operator = &op;
  }



  template <int dim>
  void
  LevelInterface<dim>::vmult(LevelVector &dst, const LevelVector &src) const
  {
    level_operator->vmult_interface_down(dst, src);
  }



  template <int dim>
  void
  LevelInterface<dim>::Tvmult(LevelVector &dst, const LevelVector &src) const
  {
    level_operator->vmult_interface_up(dst, src);
  }



  template <int dim>
  MultigridHierarchy<dim>::MultigridHierarchy(
    const DoFHandler<dim>    &dof_handler,
    const StiffnessQuadrature stiffness_quadrature,
    const bool                dirichlet)
    : dof_handler(dof_handler)
    , cell_stiffness(stiffness_rule(stiffness_quadrature))
  {
    const unsigned int n_levels =
      dof_handler.get_triangulation().n_global_levels();
    mg_constrained_dofs.initialize(dof_handler);
    if (dirichlet)
      {
        std::set<types::boundary_id> boundary;
        for (unsigned int face = 0; face < 2 * dim; ++face)
          boundary.insert(face);
        mg_constrained_dofs.make_zero_boundary_constraints(dof_handler,
                                                           boundary);
      }
    levels.resize(0, n_levels - 1);
    std::vector<std::shared_ptr<const Utilities::MPI::Partitioner>>
      partitioners;
    for (unsigned int level = 0; level < n_levels; ++level)
      {
        set_up_cells(level);
        compute_level_vectors(level, stiffness_rule(stiffness_quadrature));
        partitioners.push_back(levels[level].cells.partitioner);
      }
    transfer.initialize_constraints(mg_constrained_dofs);
    transfer.build(dof_handler, partitioners);
  }



  template <int dim>
  std::size_t
  MultigridHierarchy<dim>::memory_consumption() const
  {
    std::size_t bytes = transfer.memory_consumption();
    for (unsigned int level = levels.min_level(); level <= levels.max_level();
         ++level)
      bytes += levels[level].memory_consumption();
    return bytes;
  }



  template <int dim>
  void
  MultigridHierarchy<dim>::set_up_cells(const unsigned int level)
  {
    const IndexSet &owned = dof_handler.locally_owned_mg_dofs(level);
    IndexSet        relevant;
    DoFTools::extract_locally_relevant_level_dofs(dof_handler, level, relevant);
    AffineConstraints<double> level_constraints;
    level_constraints.reinit(relevant);
    MultigridLevel<dim> &data = levels[level];
    if (mg_constrained_dofs.have_boundary_indices())
      {
        const IndexSet &boundary =
          mg_constrained_dofs.get_boundary_indices(level);
        level_constraints.add_lines(boundary);
        for (const types::global_dof_index i : boundary)
          if (owned.is_element(i))
            data.boundary_dofs.push_back(owned.index_within_set(i));
      }
    level_constraints.close();
    data.cells = Q1Cells<dim>(dof_handler, level_constraints, level);
    for (const types::global_dof_index i :
         mg_constrained_dofs.get_refinement_edge_indices(level))
      if (owned.is_element(i))
        data.edge_dofs.push_back(owned.index_within_set(i));
    data.any_edge =
      Utilities::MPI::max(static_cast<unsigned int>(data.edge_dofs.size()),
                          dof_handler.get_communicator()) > 0;
  }



  template <int dim>
  void
  MultigridHierarchy<dim>::compute_level_vectors(
    const unsigned int   level,
    const Quadrature<1> &stiffness_rule)
  {
    MultigridLevel<dim> &data = levels[level];
    data.lumped_mass.reinit(data.cells.partitioner);
    data.stiffness_diagonal.reinit(data.cells.partitioner);
    FEValues<dim>                        fe_values(dof_handler.get_fe(),
                            Quadrature<dim>(stiffness_rule),
                            update_gradients | update_JxW_values);
    FullMatrix<double>                   cell_matrix;
    std::vector<types::global_dof_index> indices(
      dof_handler.get_fe().n_dofs_per_cell());
    for (const auto &cell : dof_handler.mg_cell_iterators_on_level(level))
      if (cell->is_locally_owned_on_level())
        {
          cell->get_mg_dof_indices(indices);
          cell_stiffness_matrix(fe_values, cell, cell_matrix);
          // the mass lumped at the vertices: Q1 with Gauss-Lobatto points
          const double vertex_mass = cell->measure() / indices.size();
          for (unsigned int i = 0; i < indices.size(); ++i)
            {
              data.stiffness_diagonal(indices[i]) += cell_matrix(i, i);
              data.lumped_mass(indices[i]) += vertex_mass;
            }
        }
    data.lumped_mass.compress(VectorOperation::add);
    data.stiffness_diagonal.compress(VectorOperation::add);
  }



  template <int dim>
  GeometricMultigrid<dim>::GeometricMultigrid(
    const MultigridHierarchy<dim>               &hierarchy,
    const double                                 factor,
    const FineVector                            &coefficient,
    const unsigned int                           smoother_sweeps,
    std::vector<std::pair<unsigned int, double>> constrained)
    : hierarchy(hierarchy)
    , constrained_diagonal(std::move(constrained))
  {
    setup_levels(factor, coefficient, smoother_sweeps);
    const unsigned int max_level = operators.max_level();
    mg_matrix.initialize(operators);
    mg_interface.initialize(interface_operators);
    coarse.initialize(smoother);
    multigrid = std::make_unique<Multigrid<LevelVector>>(
      mg_matrix, coarse, hierarchy.transfer, smoother, smoother, 0, max_level);
    multigrid->set_edge_matrices(mg_interface, mg_interface);
    preconditioner = std::make_unique<
      PreconditionMG<dim, LevelVector, MGTransferMatrixFree<dim, float>>>(
      hierarchy.dof_handler, *multigrid, hierarchy.transfer);
    src_fine.reinit(coefficient.get_partitioner());
    dst_fine.reinit(coefficient.get_partitioner());
  }



  template <int dim>
  void
  GeometricMultigrid<dim>::setup_levels(const double       factor,
                                        const FineVector  &coefficient,
                                        const unsigned int smoother_sweeps)
  {
    const unsigned int max_level = hierarchy.levels.max_level();
    level_coefficient.resize(0, max_level);
    level_diagonal.resize(0, max_level);
    operators.resize(0, max_level);
    interface_operators.resize(0, max_level);
    hierarchy.transfer.interpolate_to_mg(hierarchy.dof_handler,
                                         level_coefficient,
                                         coefficient);
    for (unsigned int level = max_level; level > 0; --level)
      average_to_coarser(level);

    MGLevelObject<typename Smoother::AdditionalData> smoother_data(0,
                                                                   max_level);
    for (unsigned int level = 0; level <= max_level; ++level)
      {
        level_diagonal[level].reinit(hierarchy.levels[level].lumped_mass);
        const unsigned int n = level_diagonal[level].locally_owned_size();
        for (unsigned int i = 0; i < n; ++i)
          level_diagonal[level].local_element(i) =
            hierarchy.levels[level].lumped_mass.local_element(i) *
            level_coefficient[level].local_element(i);
        // the Dirichlet rows of the level operators are the identity
        for (const unsigned int i : hierarchy.levels[level].boundary_dofs)
          level_diagonal[level].local_element(i) = 0.f;
        operators[level].initialize(hierarchy.levels[level],
                                    hierarchy.cell_stiffness,
                                    factor,
                                    level_diagonal[level]);
        interface_operators[level].initialize(operators[level]);

        auto &data          = smoother_data[level];
        data.preconditioner = operators[level].get_matrix_diagonal_inverse();
        if (level > 0)
          {
            data.smoothing_range     = smoothing_range;
            data.degree              = smoother_sweeps;
            data.eig_cg_n_iterations = eigenvalue_iterations;
          }
        else
          {
            data.smoothing_range     = multigrid_coarse_accuracy;
            data.degree              = numbers::invalid_unsigned_int;
            data.eig_cg_n_iterations = operators[0].m();
          }
      }
    smoother.initialize(operators, smoother_data);
  }



  template <int dim>
  void
  GeometricMultigrid<dim>::average_to_coarser(const unsigned int level)
  {
    const LevelVector &mass = hierarchy.levels[level].lumped_mass;
    LevelVector        weighted(mass);
    for (unsigned int i = 0; i < weighted.locally_owned_size(); ++i)
      weighted.local_element(i) *= level_coefficient[level].local_element(i);
    LevelVector sum, weight;
    sum.reinit(hierarchy.levels[level - 1].lumped_mass);
    weight.reinit(hierarchy.levels[level - 1].lumped_mass);
    hierarchy.transfer.restrict_and_add(level, sum, weighted);
    hierarchy.transfer.restrict_and_add(level, weight, mass);
    LevelVector &coarse = level_coefficient[level - 1];
    for (unsigned int i = 0; i < sum.locally_owned_size(); ++i)
      if (weight.local_element(i) > 0)
        coarse.local_element(i) =
          sum.local_element(i) / weight.local_element(i);
  }



  template <int dim>
  void
  GeometricMultigrid<dim>::vmult(Vector &dst, const Vector &src) const
  {
    copy_owned(src, src_fine);
    for (const auto &[i, a_ii] : constrained_diagonal)
      src_fine.local_element(i) = 0;
    preconditioner->vmult(dst_fine, src_fine);
    copy_owned(dst_fine, dst);
    for (const auto &[i, a_ii] : constrained_diagonal)
      dst.begin()[i] = src.begin()[i] / a_ii;
  }



  template void
  cell_stiffness_matrix(FEValues<2> &,
                        const DoFHandler<2>::active_cell_iterator &,
                        FullMatrix<double> &);
  template void
  cell_stiffness_matrix(FEValues<3> &,
                        const DoFHandler<3>::active_cell_iterator &,
                        FullMatrix<double> &);
  template struct MultigridLevel<2>;
  template struct MultigridLevel<3>;
  template class LevelStiffness<2>;
  template class LevelStiffness<3>;
  template class LevelInterface<2>;
  template class LevelInterface<3>;
  template class MultigridHierarchy<2>;
  template class MultigridHierarchy<3>;
  template class GeometricMultigrid<2>;
  template class GeometricMultigrid<3>;
} // namespace PhaseField
