#include <cmath>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <map>
#include <phasefield/mesh/matrix_free_stiffness.h>
#include <phasefield/mesh/shifted_product.h>

namespace PhaseField
{
  using namespace dealii;

  template <int dim>
  void
  MatrixFreeStiffness<dim>::reinit(const DoFHandler<dim>           &dofs,
                                   const AffineConstraints<double> &c,
                                   const Vector                    &mass,
                                   const Settings                  &s)
  {
    clear();
    dof_handler = &dofs;
    constraints = &c;
    lumped_mass = &mass;
    settings    = s;

    cells          = Q1Cells<dim>(dofs, c);
    cell_stiffness = std::make_unique<const Q1CellStiffness<dim, double>>(
      stiffness_rule(settings.stiffness_quadrature));
    src_fine.reinit(cells.partitioner);
    dst_fine.reinit(cells.partitioner);
    compute_constrained_diagonal();
  }



  template <int dim>
  std::size_t
  MatrixFreeStiffness<dim>::memory_consumption() const
  {
    return cells.memory_consumption() + src_fine.memory_consumption() +
           dst_fine.memory_consumption() +
           constrained_diagonal.capacity() *
             sizeof(std::pair<unsigned int, double>) +
           multigrid_memory_consumption();
  }



  template <int dim>
  std::size_t
  MatrixFreeStiffness<dim>::multigrid_memory_consumption() const
  {
    return hierarchy ? hierarchy->memory_consumption() : 0;
  }



  template <int dim>
  void
  MatrixFreeStiffness<dim>::clear()
  {
    hierarchy.reset();
    cells = Q1Cells<dim>();
    src_fine.reinit(0);
    dst_fine.reinit(0);
    std::vector<std::pair<unsigned int, double>>().swap(constrained_diagonal);
  }



  template <int dim>
  FineVector
  MatrixFreeStiffness<dim>::assembled_diagonal() const
  {
    const Quadrature<dim> quadrature(
      stiffness_rule(settings.stiffness_quadrature));
    FEValues<dim>      fe_values(dof_handler->get_fe(),
                            quadrature,
                            update_gradients | update_JxW_values);
    const unsigned int n = dof_handler->get_fe().n_dofs_per_cell();
    std::vector<types::global_dof_index> indices(n);
    FullMatrix<double>                   cell_matrix;
    FineVector                           diagonal(cells.partitioner);
    // the weights of every unconstrained DoF j in the cell's shape
    // functions: (C^T A C)_jj = w_j^T A w_j
    std::map<types::global_dof_index, dealii::Vector<double>> weights;
    const auto add_weight = [&](const types::global_dof_index j,
                                const unsigned int            i,
                                const double                  w) {
      auto &wj = weights[j];
      if (wj.size() == 0)
        wj.reinit(n);
      wj(i) += w;
    };
    for (const auto &cell : dof_handler->active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(indices);
          cell_stiffness_matrix(fe_values, cell, cell_matrix);
          weights.clear();
          for (unsigned int i = 0; i < n; ++i)
            if (constraints->is_constrained(indices[i]))
              {
                // the diagonal of
                // AffineConstraints::distribute_local_to_global()
                diagonal(indices[i]) += std::abs(cell_matrix(i, i));
                for (const auto &[master, w] :
                     *constraints->get_constraint_entries(indices[i]))
                  add_weight(master, i, w);
              }
            else
              add_weight(indices[i], i, 1.);
          for (const auto &[j, wj] : weights)
            diagonal(j) += cell_matrix.matrix_norm_square(wj);
        }
    diagonal.compress(VectorOperation::add);
    return diagonal;
  }



  template <int dim>
  void
  MatrixFreeStiffness<dim>::compute_constrained_diagonal()
  {
    const FineVector diagonal = assembled_diagonal();
    const IndexSet  &owned    = dof_handler->locally_owned_dofs();
    for (unsigned int i = 0; i < diagonal.locally_owned_size(); ++i)
      if (constraints->is_constrained(owned.nth_index_in_set(i)))
        constrained_diagonal.emplace_back(i, diagonal.local_element(i));
  }



  template <int dim>
  void
  MatrixFreeStiffness<dim>::vmult(FineVector &dst, const FineVector &src) const
  {
    dst = 0.;
    cells.apply_add(*cell_stiffness, 1., src, dst);
    for (const auto &[i, a_ii] : constrained_diagonal)
      dst.local_element(i) = a_ii * src.local_element(i);
  }



  template <int dim>
  void
  MatrixFreeStiffness<dim>::vmult(Vector &dst, const Vector &src) const
  {
    copy_owned(src, src_fine);
    vmult(dst_fine, src_fine);
    copy_owned(dst_fine, dst);
  }



  template <int dim>
  void
  MatrixFreeStiffness<dim>::diagonal(Vector &diagonal) const
  {
    diagonal.reinit(*lumped_mass);
    copy_owned(assembled_diagonal(), diagonal);
  }



  template <int dim>
  void
  MatrixFreeStiffness<dim>::shift(const double                       factor,
                                  Vector                            &diagonal,
                                  std::unique_ptr<ShiftedStiffness> &op) const
  {
    auto *mf_op = dynamic_cast<MatrixFreeShiftedStiffness<dim> *>(op.get());
    if (mf_op == nullptr)
      {
        auto fresh = std::make_unique<MatrixFreeShiftedStiffness<dim>>();
        mf_op      = fresh.get();
        op         = std::move(fresh);
      }
    mf_op->reinit(*this, factor, diagonal);
  }



  template <int dim>
  std::unique_ptr<MultigridCycle>
  MatrixFreeStiffness<dim>::make_multigrid(
    const double       factor,
    const Vector      &diagonal,
    const unsigned int smoother_sweeps) const
  {
    if (!hierarchy)
      hierarchy =
        std::make_unique<MultigridHierarchy<dim>>(*dof_handler,
                                                  settings.stiffness_quadrature,
                                                  settings.dirichlet);
    // the nodal coefficient c of D = M[c], interpolated at hanging nodes
    FineVector         coefficient(cells.partitioner);
    const unsigned int n = coefficient.locally_owned_size();
    for (unsigned int i = 0; i < n; ++i)
      {
        const double m               = lumped_mass->begin()[i];
        coefficient.local_element(i) = m > 0 ? diagonal.begin()[i] / m : 0.;
      }
    constraints->distribute(coefficient);
    coefficient.update_ghost_values();
    // the diagonal entries of the constrained rows of f L + D
    std::vector<std::pair<unsigned int, double>> constrained(
      constrained_diagonal);
    for (auto &[i, a_ii] : constrained)
      a_ii = factor * a_ii + diagonal.begin()[i];
    return std::make_unique<GeometricMultigrid<dim>>(
      *hierarchy, factor, coefficient, smoother_sweeps, std::move(constrained));
  }



  template <int dim>
  void
  MatrixFreeShiftedStiffness<dim>::reinit(const MatrixFreeStiffness<dim> &l,
                                          const double                    f,
                                          Vector &diagonal_entries)
  {
    stiffness = &l;
    factor    = f;
    diagonal.swap(diagonal_entries);
    diagonal_entries.clear();
  }



  template <int dim>
  void
  MatrixFreeShiftedStiffness<dim>::vmult(Vector &dst, const Vector &src) const
  {
    stiffness->vmult(dst, src);
    scale_and_add_diagonal(factor, diagonal, src, dst);
  }



  template <int dim>
  types::global_dof_index
  MatrixFreeShiftedStiffness<dim>::m() const
  {
    return stiffness == nullptr ? 0 : diagonal.size();
  }



  template <int dim>
  std::unique_ptr<MultigridCycle>
  MatrixFreeShiftedStiffness<dim>::make_multigrid(
    const Vector *,
    const unsigned int smoother_sweeps) const
  {
    return stiffness->make_multigrid(factor, diagonal, smoother_sweeps);
  }



  template class MatrixFreeStiffness<2>;
  template class MatrixFreeStiffness<3>;
  template class MatrixFreeShiftedStiffness<2>;
  template class MatrixFreeShiftedStiffness<3>;
} // namespace PhaseField
