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



  namespace
  {
    /**
     * Call @p f(index, cell) for every cell of the cell batches
     * [@p first, @p last) of @p data, with index = batch * width + lane.
     */
    template <int dim, typename Number, typename Function>
    void
    for_each_cell(const MatrixFree<dim, Number> &data,
                  const unsigned int             first,
                  const unsigned int             last,
                  const Function                &f)
    {
      constexpr unsigned int width = VectorizedArray<Number>::size();
      for (unsigned int batch = first; batch < last; ++batch)
        for (unsigned int lane = 0;
             lane < data.n_active_entries_per_cell_batch(batch);
             ++lane)
          f(batch * width + lane, batch, lane);
    }



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
  } // namespace



  template <int dim, typename Number>
  void
  reinit_q1_matrix_free(MatrixFree<dim, Number>         &data,
                        const DoFHandler<dim>           &dof_handler,
                        const AffineConstraints<double> &constraints,
                        const unsigned int               mg_level)
  {
    typename MatrixFree<dim, Number>::AdditionalData settings;
    settings.tasks_parallel_scheme =
      MatrixFree<dim, Number>::AdditionalData::none;
    settings.mapping_update_flags = update_gradients;
    settings.mg_level             = mg_level;
    data.reinit(MappingCartesian<dim>(),
                dof_handler,
                constraints,
                QGauss<1>(1),
                settings);
    bool cartesian = true;
    for_each_cell(data,
                  0,
                  data.n_cell_batches(),
                  [&](unsigned int, unsigned int batch, unsigned int lane) {
                    cartesian =
                      cartesian && is_axis_parallel_cube(
                                     data.get_cell_iterator(batch, lane));
                  });
    AssertThrow(Utilities::MPI::min(cartesian ? 1 : 0,
                                    dof_handler.get_communicator()) == 1,
                ExcMessage("The matrix-free stiffness operator needs a mesh "
                           "of axis-parallel cubes."));
  }



  template <int dim>
  Q1LevelCells<dim>::Q1LevelCells(const MatrixFree<dim, float> &data,
                                  const MGConstrainedDoFs &mg_constrained_dofs,
                                  const unsigned int       level)
  {
    constexpr unsigned int n           = Q1CellStiffness<dim, float>::n;
    constexpr unsigned int width       = VectorizedArray<float>::size();
    const auto            &partitioner = *data.get_vector_partitioner();
    const bool boundary = mg_constrained_dofs.have_boundary_indices();
    dofs.assign(data.n_cell_batches() * width * n,
                numbers::invalid_unsigned_int);
    std::vector<types::global_dof_index> indices(n);
    double                               edge      = 0;
    bool                                 same_edge = true;
    for_each_cell(
      data,
      0,
      data.n_cell_batches(),
      [&](const unsigned int index, unsigned int batch, unsigned int lane) {
        const auto cell = data.get_cell_iterator(batch, lane);
        cell->get_mg_dof_indices(indices);
        for (unsigned int i = 0; i < n; ++i)
          if (!boundary ||
              !mg_constrained_dofs.is_boundary_index(level, indices[i]))
            dofs[index * n + i] = partitioner.global_to_local(indices[i]);
        const double h = cell->vertex(1)[0] - cell->vertex(0)[0];
        if (edge == 0)
          edge = h;
        same_edge = same_edge && std::abs(h - edge) <= Constants::roundoff * h;
      });
    AssertThrow(same_edge,
                ExcMessage("The cells of a multigrid level must be cubes of "
                           "one size (a mesh refined from one coarse cube)."));
    scale = std::pow(edge, dim - 2);
  }



  template <int dim>
  std::size_t
  Q1LevelCells<dim>::memory_consumption() const
  {
    return dofs.capacity() * sizeof(unsigned int);
  }



  template <int dim>
  void
  LevelStiffness<dim>::set_coefficients(
    const double                       f,
    const Q1CellStiffness<dim, float> &kernel,
    const Q1LevelCells<dim>           &level_cells,
    const LevelVector                 &l_diagonal,
    const LevelVector                 &d)
  {
    factor             = f;
    cell_stiffness     = &kernel;
    cells              = &level_cells;
    stiffness_diagonal = &l_diagonal;
    diagonal           = &d;
    compute_diagonal();
  }



  template <int dim>
  void
  LevelStiffness<dim>::compute_diagonal()
  {
    this->inverse_diagonal_entries =
      std::make_shared<DiagonalMatrix<LevelVector>>();
    LevelVector &inverse = this->inverse_diagonal_entries->get_vector();
    this->data->initialize_dof_vector(inverse);
    const unsigned int n = inverse.locally_owned_size();
    for (unsigned int i = 0; i < n; ++i)
      inverse.local_element(i) =
        1.f / (factor * stiffness_diagonal->local_element(i) +
               diagonal->local_element(i));
    this->set_constrained_entries_to_one(inverse);
  }



  template <int dim>
  void
  LevelStiffness<dim>::apply_add(LevelVector &dst, const LevelVector &src) const
  {
    this->data->cell_loop(&LevelStiffness::local_apply, this, dst, src);
    const unsigned int n = dst.locally_owned_size();
    for (unsigned int i = 0; i < n; ++i)
      dst.local_element(i) += diagonal->local_element(i) * src.local_element(i);
  }



  template <int dim>
  void
  LevelStiffness<dim>::local_apply(
    const MatrixFree<dim, float>                &data,
    LevelVector                                 &dst,
    const LevelVector                           &src,
    const std::pair<unsigned int, unsigned int> &cell_range) const
  {
    constexpr unsigned int n     = Q1CellStiffness<dim, float>::n;
    constexpr unsigned int none  = numbers::invalid_unsigned_int;
    const float            scale = factor * cells->scale;
    for_each_cell(data,
                  cell_range.first,
                  cell_range.second,
                  [&](const unsigned int cell, unsigned int, unsigned int) {
                    const unsigned int *dofs = cells->dofs.data() + cell * n;
                    float               values[n];
                    for (unsigned int i = 0; i < n; ++i)
                      values[i] =
                        dofs[i] == none ? 0.f : src.local_element(dofs[i]);
                    cell_stiffness->apply(values, scale);
                    for (unsigned int i = 0; i < n; ++i)
                      if (dofs[i] != none)
                        dst.local_element(dofs[i]) += values[i];
                  });
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
    cells.resize(0, n_levels - 1);
    lumped_mass.resize(0, n_levels - 1);
    stiffness_diagonal.resize(0, n_levels - 1);
    for (unsigned int level = 0; level < n_levels; ++level)
      {
        levels[level] = make_level(level);
        cells[level] =
          Q1LevelCells<dim>(*levels[level], mg_constrained_dofs, level);
        compute_level_vectors(level, stiffness_rule(stiffness_quadrature));
      }
    transfer.initialize_constraints(mg_constrained_dofs);
    transfer.build(dof_handler);
  }



  template <int dim>
  std::size_t
  MultigridHierarchy<dim>::memory_consumption() const
  {
    std::size_t bytes = transfer.memory_consumption();
    for (unsigned int level = levels.min_level(); level <= levels.max_level();
         ++level)
      bytes += levels[level]->memory_consumption() +
               cells[level].memory_consumption() +
               lumped_mass[level].memory_consumption() +
               stiffness_diagonal[level].memory_consumption();
    return bytes;
  }



  template <int dim>
  std::shared_ptr<const MatrixFree<dim, float>>
  MultigridHierarchy<dim>::make_level(const unsigned int level) const
  {
    IndexSet relevant;
    DoFTools::extract_locally_relevant_level_dofs(dof_handler, level, relevant);
    AffineConstraints<double> level_constraints;
    level_constraints.reinit(relevant);
    if (mg_constrained_dofs.have_boundary_indices())
      level_constraints.add_lines(
        mg_constrained_dofs.get_boundary_indices(level));
    level_constraints.close();
    auto level_data = std::make_shared<MatrixFree<dim, float>>();
    reinit_q1_matrix_free(*level_data, dof_handler, level_constraints, level);
    return level_data;
  }



  template <int dim>
  void
  MultigridHierarchy<dim>::compute_level_vectors(
    const unsigned int   level,
    const Quadrature<1> &stiffness_rule)
  {
    const MatrixFree<dim, float> &data = *levels[level];
    data.initialize_dof_vector(lumped_mass[level]);
    data.initialize_dof_vector(stiffness_diagonal[level]);
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
              stiffness_diagonal[level](indices[i]) += cell_matrix(i, i);
              lumped_mass[level](indices[i]) += vertex_mass;
            }
        }
    lumped_mass[level].compress(VectorOperation::add);
    stiffness_diagonal[level].compress(VectorOperation::add);
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
        level_diagonal[level].reinit(hierarchy.lumped_mass[level]);
        const unsigned int n = level_diagonal[level].locally_owned_size();
        for (unsigned int i = 0; i < n; ++i)
          level_diagonal[level].local_element(i) =
            hierarchy.lumped_mass[level].local_element(i) *
            level_coefficient[level].local_element(i);
        operators[level].initialize(hierarchy.levels[level],
                                    hierarchy.mg_constrained_dofs,
                                    level);
        operators[level].set_coefficients(factor,
                                          hierarchy.cell_stiffness,
                                          hierarchy.cells[level],
                                          hierarchy.stiffness_diagonal[level],
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
    const LevelVector &mass = hierarchy.lumped_mass[level];
    LevelVector        weighted(mass);
    for (unsigned int i = 0; i < weighted.locally_owned_size(); ++i)
      weighted.local_element(i) *= level_coefficient[level].local_element(i);
    LevelVector sum, weight;
    sum.reinit(hierarchy.lumped_mass[level - 1]);
    weight.reinit(hierarchy.lumped_mass[level - 1]);
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
  template void
  reinit_q1_matrix_free(MatrixFree<2, double> &,
                        const DoFHandler<2> &,
                        const AffineConstraints<double> &,
                        unsigned int);
  template void
  reinit_q1_matrix_free(MatrixFree<3, double> &,
                        const DoFHandler<3> &,
                        const AffineConstraints<double> &,
                        unsigned int);
  template struct Q1LevelCells<2>;
  template struct Q1LevelCells<3>;
  template class LevelStiffness<2>;
  template class LevelStiffness<3>;
  template class MultigridHierarchy<2>;
  template class MultigridHierarchy<3>;
  template class GeometricMultigrid<2>;
  template class GeometricMultigrid<3>;
} // namespace PhaseField
