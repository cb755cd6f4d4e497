#include <algorithm>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <phasefield/mesh/lumped_operators.h>
#include <phasefield/mesh/operator_backend.h>

namespace PhaseField
{
  using namespace dealii;

  template <int dim>
  void
  LumpedOperators<dim>::reinit(const DoFHandler<dim>           &dof_handler,
                               const AffineConstraints<double> &constraints,
                               const MPI_Comm            mpi_communicator,
                               const StiffnessQuadrature stiffness_quadrature)
  {
    Settings settings;
    settings.stiffness_quadrature = stiffness_quadrature;
    reinit(dof_handler, constraints, mpi_communicator, settings);
  }



  template <int dim>
  void
  LumpedOperators<dim>::reinit(const DoFHandler<dim>           &dof_handler,
                               const AffineConstraints<double> &constraints,
                               const MPI_Comm  mpi_communicator,
                               const Settings &settings)
  {
    locally_owned_dofs = dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dof_handler, locally_relevant_dofs);
    lumped_mass.reinit(locally_owned_dofs, mpi_communicator);

    const double min_cell_mass = assemble_mass(dof_handler, constraints);
    set_inverse_lumped_mass(constraints,
                            Utilities::MPI::min(min_cell_mass,
                                                mpi_communicator));
    stiffness =
      operator_backend(settings.backend)
        .template make_stiffness<dim>()({dof_handler,
                                         constraints,
                                         lumped_mass,
                                         settings.stiffness_quadrature,
                                         settings.dirichlet,
                                         mpi_communicator});
  }



  template <int dim>
  const StiffnessOperator &
  LumpedOperators<dim>::stiffness_operator() const
  {
    Assert(stiffness, ExcInternalError());
    return *stiffness;
  }



  template <int dim>
  const TrilinosStiffness &
  LumpedOperators<dim>::assembled_stiffness() const
  {
    const auto *assembled =
      dynamic_cast<const TrilinosStiffness *>(stiffness.get());
    AssertThrow(assembled != nullptr,
                ExcMessage(
                  "This solver needs the assembled stiffness matrix, which "
                  "`Linear solver / Type = matrix-free` does not store. Use "
                  "`Linear solver / Type = iterative` or `direct`."));
    return *assembled;
  }



  template <int dim>
  const TrilinosWrappers::SparseMatrix &
  LumpedOperators<dim>::stiffness_matrix() const
  {
    return assembled_stiffness().matrix;
  }



  template <int dim>
  void
  LumpedOperators<dim>::release()
  {
    stiffness.reset();
    lumped_mass.clear();
    inverse_lumped_mass.clear();
    std::vector<unsigned int>().swap(constrained_local_indices);
  }



  template <int dim>
  double
  LumpedOperators<dim>::assemble_mass(
    const DoFHandler<dim>           &dof_handler,
    const AffineConstraints<double> &constraints)
  {
    // Gauss-Lobatto points of Q1 are the vertices: the mass is lumped.
    const QGaussLobatto<dim> lumping_quadrature(2);
    const auto              &fe = dof_handler.get_fe();
    FEValues<dim>            fe_lumped(fe,
                            lumping_quadrature,
                            update_values | update_JxW_values);

    const unsigned int                   dofs_per_cell = fe.n_dofs_per_cell();
    dealii::Vector<double>               cell_mass(dofs_per_cell);
    std::vector<types::global_dof_index> dof_indices(dofs_per_cell);
    double min_cell_mass = std::numeric_limits<double>::max();

    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_lumped.reinit(cell);
          cell_mass = 0;
          for (unsigned int q = 0; q < lumping_quadrature.size(); ++q)
            for (unsigned int i = 0; i < dofs_per_cell; ++i)
              cell_mass(i) += fe_lumped.shape_value(i, q) * fe_lumped.JxW(q);
          min_cell_mass = std::min(min_cell_mass, cell_mass.linfty_norm());

          cell->get_dof_indices(dof_indices);
          constraints.distribute_local_to_global(cell_mass,
                                                 dof_indices,
                                                 lumped_mass);
        }
    lumped_mass.compress(VectorOperation::add);
    return min_cell_mass;
  }



  template <int dim>
  void
  LumpedOperators<dim>::set_inverse_lumped_mass(
    const AffineConstraints<double> &constraints,
    const double                     min_cell_mass)
  {
    inverse_lumped_mass.reinit(lumped_mass);
    constrained_local_indices.clear();
    const unsigned int n_local = lumped_mass.locally_owned_size();
    for (unsigned int i = 0; i < n_local; ++i)
      {
        const types::global_dof_index g =
          locally_owned_dofs.nth_index_in_set(i);
        if (constraints.is_constrained(g))
          {
            constrained_local_indices.push_back(i);
            inverse_lumped_mass.begin()[i] = 1. / min_cell_mass;
          }
        else
          inverse_lumped_mass.begin()[i] = 1. / lumped_mass.begin()[i];
      }
  }



  template <int dim>
  void
  LumpedOperators<dim>::stiffness_plus_weighted_mass(
    const double                    stiffness_factor,
    const Vector                   &nodal_weight,
    TrilinosWrappers::SparseMatrix &matrix) const
  {
    const TrilinosStiffness &assembled = assembled_stiffness();
    if (!share_pattern(matrix, assembled.matrix))
      matrix.copy_from(assembled.matrix);
    const CompressedRows l   = compressed_rows(assembled.matrix);
    const CompressedRows out = compressed_rows(matrix);
    const unsigned int   n   = nodal_weight.locally_owned_size();
    for (int k = 0; k < l.offsets[n]; ++k)
      out.values[k] = stiffness_factor * l.values[k];
    for (unsigned int i = 0; i < n; ++i)
      out.values[assembled.diagonal_positions[i]] +=
        lumped_mass.begin()[i] * nodal_weight.begin()[i];
  }



  template <int dim>
  void
  LumpedOperators<dim>::stiffness_plus_weighted_mass(
    const double                       stiffness_factor,
    const Vector                      &nodal_weight,
    std::unique_ptr<ShiftedStiffness> &op) const
  {
    Vector             diagonal(lumped_mass);
    const unsigned int n = nodal_weight.locally_owned_size();
    for (unsigned int i = 0; i < n; ++i)
      diagonal.begin()[i] *= nodal_weight.begin()[i];
    stiffness_operator().shift(stiffness_factor, diagonal, op);
  }



  template <int dim>
  void
  LumpedOperators<dim>::add_to_diagonal(
    const Vector                   &values,
    TrilinosWrappers::SparseMatrix &matrix) const
  {
    const unsigned int n = values.locally_owned_size();
    for (unsigned int i = 0; i < n; ++i)
      {
        const types::global_dof_index g =
          locally_owned_dofs.nth_index_in_set(i);
        matrix.add(g, g, values.begin()[i]);
      }
    matrix.compress(VectorOperation::add);
  }



  template <int dim>
  void
  LumpedOperators<dim>::zero_constrained(Vector &vector) const
  {
    for (const unsigned int i : constrained_local_indices)
      vector.begin()[i] = 0;
  }



  template <int dim>
  double
  LumpedOperators<dim>::mass_product(const Vector &x, const Vector &y) const
  {
    const unsigned int n = x.locally_owned_size();
    const double      *m = lumped_mass.begin();
    double             s = 0;
    for (unsigned int i = 0; i < n; ++i)
      s += m[i] * x.begin()[i] * y.begin()[i];
    return Utilities::MPI::sum(s, lumped_mass.get_mpi_communicator());
  }



  template <int dim>
  double
  LumpedOperators<dim>::stiffness_product(const Vector &x) const
  {
    Vector y(x), Ly(x);
    zero_constrained(y);
    stiffness_operator().vmult(Ly, y);
    return y * Ly;
  }



  template <int dim>
  double
  LumpedOperators<dim>::dual_norm(const Vector &r) const
  {
    const unsigned int n     = r.locally_owned_size();
    const double      *m_inv = inverse_lumped_mass.begin();
    double             s     = 0;
    for (unsigned int i = 0; i < n; ++i)
      s += m_inv[i] * r.begin()[i] * r.begin()[i];
    return std::sqrt(
      Utilities::MPI::sum(s, lumped_mass.get_mpi_communicator()));
  }



  CompressedRows
  compressed_rows(const TrilinosWrappers::SparseMatrix &matrix)
  {
    CompressedRows rows;
    const int      error =
      matrix.trilinos_matrix().ExtractCrsDataPointers(rows.offsets,
                                                      rows.columns,
                                                      rows.values);
    AssertThrow(error == 0,
                ExcMessage("The matrix is not compressed with optimised "
                           "storage."));
    return rows;
  }



  bool
  share_pattern(const TrilinosWrappers::SparseMatrix &a,
                const TrilinosWrappers::SparseMatrix &b)
  {
    CompressedRows rows_a, rows_b;
    return a.trilinos_matrix().ExtractCrsDataPointers(rows_a.offsets,
                                                      rows_a.columns,
                                                      rows_a.values) == 0 &&
           b.trilinos_matrix().ExtractCrsDataPointers(rows_b.offsets,
                                                      rows_b.columns,
                                                      rows_b.values) == 0 &&
           rows_a.columns == rows_b.columns && rows_a.offsets == rows_b.offsets;
  }



  template class LumpedOperators<2>;
  template class LumpedOperators<3>;
} // namespace PhaseField
