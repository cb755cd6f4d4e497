// The registrations of the library's two operator backends
// (mesh/operator_backend.h): the assembled one (TrilinosStiffness) and the
// matrix-free one (MatrixFreeStiffness).

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparsity_tools.h>
#include <phasefield/mesh/matrix_free_stiffness.h>
#include <phasefield/mesh/operator_backend.h>
#include <phasefield/mesh/trilinos_stiffness.h>

namespace PhaseField
{
  using namespace dealii;

  namespace
  {
    /** L assembled into a Trilinos matrix, condensed with the constraints. */
    template <int dim>
    struct AssembledStiffness
    {
      static std::shared_ptr<StiffnessOperator>
      make(const StiffnessSetup<dim> &setup)
      {
        auto stiffness = std::make_shared<TrilinosStiffness>();
        reinit_matrix(setup, stiffness->matrix);
        assemble(setup, stiffness->matrix);
        stiffness->find_diagonal();
        return stiffness;
      }

      /** The sparsity pattern of L on the locally relevant DoFs. */
      static void
      reinit_matrix(const StiffnessSetup<dim>      &setup,
                    TrilinosWrappers::SparseMatrix &matrix)
      {
        const IndexSet &owned = setup.dof_handler.locally_owned_dofs();
        IndexSet        relevant;
        DoFTools::extract_locally_relevant_dofs(setup.dof_handler, relevant);
        DynamicSparsityPattern dsp(relevant);
        DoFTools::make_sparsity_pattern(setup.dof_handler,
                                        dsp,
                                        setup.constraints,
                                        false);
        SparsityTools::distribute_sparsity_pattern(dsp,
                                                   owned,
                                                   setup.mpi_communicator,
                                                   relevant);
        matrix.reinit(owned, owned, dsp, setup.mpi_communicator);
      }

      /** Add the cell matrices of L (with the chosen rule) to @p matrix. */
      static void
      assemble(const StiffnessSetup<dim>      &setup,
               TrilinosWrappers::SparseMatrix &matrix)
      {
        const Quadrature<dim> quadrature =
          setup.stiffness_quadrature == StiffnessQuadrature::gauss_lobatto ?
            Quadrature<dim>(QGaussLobatto<dim>(2)) :
            Quadrature<dim>(QGauss<dim>(2));
        const auto        &fe = setup.dof_handler.get_fe();
        FEValues<dim>      fe_values(fe,
                                quadrature,
                                update_gradients | update_JxW_values);
        const unsigned int dofs_per_cell = fe.n_dofs_per_cell();
        FullMatrix<double> cell_matrix(dofs_per_cell, dofs_per_cell);
        std::vector<types::global_dof_index> dof_indices(dofs_per_cell);
        for (const auto &cell : setup.dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              fe_values.reinit(cell);
              cell_matrix = 0;
              for (unsigned int q = 0; q < quadrature.size(); ++q)
                for (unsigned int i = 0; i < dofs_per_cell; ++i)
                  for (unsigned int j = 0; j < dofs_per_cell; ++j)
                    cell_matrix(i, j) += fe_values.shape_grad(i, q) *
                                         fe_values.shape_grad(j, q) *
                                         fe_values.JxW(q);
              cell->get_dof_indices(dof_indices);
              setup.constraints.distribute_local_to_global(cell_matrix,
                                                           dof_indices,
                                                           matrix);
            }
        matrix.compress(VectorOperation::add);
      }
    };



    /** L cell by cell (the level DoFs must be distributed). */
    template <int dim>
    struct CellByCellStiffness
    {
      static std::shared_ptr<StiffnessOperator>
      make(const StiffnessSetup<dim> &setup)
      {
        auto stiffness = std::make_shared<MatrixFreeStiffness<dim>>();
        stiffness->reinit(setup.dof_handler,
                          setup.constraints,
                          setup.lumped_mass,
                          {setup.stiffness_quadrature, setup.dirichlet});
        return stiffness;
      }
    };



    OperatorBackendEntry
    assembled_entry()
    {
      OperatorBackendEntry entry;
      entry.name = OperatorBackendNames::assembled;
      entry.documentation =
        "CG preconditioned with algebraic multigrid (ML) on the assembled "
        "stiffness matrix (memory linear in the unknowns)";
      entry.solver_description         = "iterative (CG + AMG)";
      entry.preconditioner_description = "algebraic multigrid";
      entry.assembled_matrix           = true;
      entry.set_factory<AssembledStiffness>();
      return entry;
    }



    OperatorBackendEntry
    matrix_free_entry()
    {
      OperatorBackendEntry entry;
      entry.name = OperatorBackendNames::matrix_free;
      entry.documentation =
        "CG with the stiffness operator applied cell by cell and "
        "preconditioned with geometric multigrid (no matrix is stored; the "
        "nested and augmented lagrangian schemes)";
      entry.solver_description = "matrix-free (CG + geometric multigrid)";
      entry.preconditioner_description = "geometric multigrid, no matrix";
      entry.multigrid_levels           = true;
      entry.set_factory<CellByCellStiffness>();
      return entry;
    }



    /** Registers both when the library is loaded, before main(). */
    [[maybe_unused]] const bool registered = [] {
      register_operator_backend(assembled_entry());
      register_operator_backend(matrix_free_entry());
      return true;
    }();
  } // namespace
} // namespace PhaseField
