#ifndef phasefield_mesh_matrix_free_stiffness_h
#define phasefield_mesh_matrix_free_stiffness_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <memory>
#include <phasefield/core/linear_algebra.h>
#include <phasefield/core/parameters.h>
#include <phasefield/mesh/geometric_multigrid.h>
#include <phasefield/mesh/q1_cells.h>
#include <phasefield/mesh/stiffness_operator.h>
#include <utility>
#include <vector>

namespace PhaseField
{
  /**
   * The stiffness operator L applied cell by cell without a matrix (as in
   * deal.II's step-37, with the Q1 cube kernel Q1CellStiffness on the
   * cell table Q1Cells instead of MatrixFree and FEEvaluation): the
   * matrix-free backend of the operator seam. It applies the same operator
   * as TrilinosStiffness, the Q1 Laplacian condensed with the constraints:
   * on unconstrained rows C^T A C, on a constrained row only the diagonal
   * entry that AffineConstraints::distribute_local_to_global() puts there
   * (the sum of |a_ii| over the cells of the DoF). Its shifted operators
   * f L + D are MatrixFreeShiftedStiffness, preconditioned by
   * GeometricMultigrid. What it keeps per DoF: the cell table (DoF indices
   * and the level of each cell) and two vectors; no matrix.
   */
  template <int dim>
  class MatrixFreeStiffness : public StiffnessOperator
  {
  public:
    /** How the backend is built. */
    struct Settings
    {
      StiffnessQuadrature stiffness_quadrature = StiffnessQuadrature::gauss;
      /** Homogeneous Dirichlet conditions on the whole boundary. */
      bool dirichlet = false;
    };

    /**
     * Set up on @p dof_handler (scalar Q1, level DoFs distributed) with
     * @p constraints (hanging nodes and boundary conditions) and the lumped
     * mass @p lumped_mass; all three must outlive this object until
     * clear(). Collective.
     */
    void
    reinit(const dealii::DoFHandler<dim>           &dof_handler,
           const dealii::AffineConstraints<double> &constraints,
           const Vector                            &lumped_mass,
           const Settings                          &settings);

    /** Free everything (before the mesh changes). */
    void
    clear();

    void
    vmult(Vector &dst, const Vector &src) const override;

    void
    diagonal(Vector &diagonal) const override;

    /** @p op becomes (or is refilled as) a MatrixFreeShiftedStiffness. */
    void
    shift(const double                       factor,
          Vector                            &diagonal,
          std::unique_ptr<ShiftedStiffness> &op) const override;

    /**
     * A geometric multigrid cycle for @p factor L + diag(@p diagonal), with
     * the diagonal read as the lumped mass times a nodal coefficient.
     * Collective.
     */
    std::unique_ptr<MultigridCycle>
    make_multigrid(const double       factor,
                   const Vector      &diagonal,
                   const unsigned int smoother_sweeps) const;

    /** The cell data, two vectors and the multigrid levels, if built. */
    std::size_t
    memory_consumption() const override;

    /** Bytes of the multigrid levels (0 before the first cycle). */
    std::size_t
    multigrid_memory_consumption() const;

    /** @p dst = L @p src on vectors of the matrix-free object. */
    void
    vmult(FineVector &dst, const FineVector &src) const;

  private:
    /**
     * The diagonal of the assembled matrix, cell by cell: w_j^T A_K w_j on
     * an unconstrained row j, with w_j the weights of j in the cell's shape
     * functions, and the sum of |a_ii| on a constrained row i. Collective.
     */
    FineVector
    assembled_diagonal() const;

    /**
     * The diagonal entries of the constrained rows of the assembled
     * matrix, as (local index, value) of the locally owned ones.
     */
    void
    compute_constrained_diagonal();

    Q1Cells<dim>                                        cells;
    std::unique_ptr<const Q1CellStiffness<dim, double>> cell_stiffness;
    const dealii::DoFHandler<dim>                      *dof_handler = nullptr;
    const dealii::AffineConstraints<double>            *constraints = nullptr;
    const Vector                                       *lumped_mass = nullptr;
    Settings                                            settings;
    std::vector<std::pair<unsigned int, double>>        constrained_diagonal;
    mutable FineVector                                  src_fine, dst_fine;
    /** The level data of the multigrid cycles, built on the first one. */
    mutable std::unique_ptr<MultigridHierarchy<dim>> hierarchy;
  };



  /**
   * f L + D with the matrix-free L of MatrixFreeStiffness (which must
   * outlive it): one vector for D, no matrix.
   */
  template <int dim>
  class MatrixFreeShiftedStiffness : public ShiftedStiffness
  {
  public:
    /** The operator @p factor L + diag(@p diagonal), taking @p diagonal. */
    void
    reinit(const MatrixFreeStiffness<dim> &stiffness,
           const double                    factor,
           Vector                         &diagonal);

    void
    vmult(Vector &dst, const Vector &src) const override;

    dealii::types::global_dof_index
    m() const override;

    /**
     * GeometricMultigrid for this operator; @p slow_mode is not needed (the
     * geometric coarse levels represent the smooth modes) and ignored.
     */
    std::unique_ptr<MultigridCycle>
    make_multigrid(const Vector      *slow_mode,
                   const unsigned int smoother_sweeps) const override;

  private:
    const MatrixFreeStiffness<dim> *stiffness = nullptr;
    double                          factor    = 0;
    Vector                          diagonal;
  };
} // namespace PhaseField

#endif
