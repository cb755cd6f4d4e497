#ifndef phasefield_mesh_geometric_multigrid_h
#define phasefield_mesh_geometric_multigrid_h

#include <deal.II/base/mg_level_object.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/diagonal_matrix.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/precondition.h>
#include <deal.II/multigrid/mg_coarse.h>
#include <deal.II/multigrid/mg_constrained_dofs.h>
#include <deal.II/multigrid/mg_matrix.h>
#include <deal.II/multigrid/mg_smoother.h>
#include <deal.II/multigrid/mg_transfer_matrix_free.h>
#include <deal.II/multigrid/multigrid.h>
#include <memory>
#include <phasefield/core/linear_algebra.h>
#include <phasefield/core/parameters.h>
#include <phasefield/mesh/q1_cell_stiffness.h>
#include <phasefield/mesh/q1_cells.h>
#include <phasefield/mesh/stiffness_operator.h>

namespace PhaseField
{
  /**
   * The vectors of the multigrid levels: single precision, since a cycle
   * is only a preconditioner (as in deal.II's step-37); half the memory
   * and memory traffic of double.
   */
  using LevelVector = dealii::LinearAlgebra::distributed::Vector<float>;

  /** The vectors of the matrix-free operators on the active mesh. */
  using FineVector = dealii::LinearAlgebra::distributed::Vector<double>;

  /** The 1D stiffness rule: two points, Gauss or Gauss-Lobatto. */
  dealii::Quadrature<1>
  stiffness_rule(const StiffnessQuadrature stiffness_quadrature);

  /**
   * @p cell_matrix = the stiffness matrix of @p cell (an active or a level
   * cell), integrated with the rule of @p fe_values.
   */
  template <int dim, typename CellIterator>
  void
  cell_stiffness_matrix(dealii::FEValues<dim>      &fe_values,
                        const CellIterator         &cell,
                        dealii::FullMatrix<double> &cell_matrix);



  /**
   * What one level of the mesh hierarchy (local smoothing) holds for the
   * cycles: its cells, its locally owned DoFs on the Dirichlet boundary and
   * on the refinement edge (as local indices), its lumped mass and the
   * diagonal of its stiffness operator L_l.
   */
  template <int dim>
  struct MultigridLevel
  {
    Q1Cells<dim>              cells;
    std::vector<unsigned int> boundary_dofs;
    std::vector<unsigned int> edge_dofs;
    /** Whether the level has a refinement edge on any rank. */
    bool        any_edge = false;
    LevelVector lumped_mass;
    LevelVector stiffness_diagonal;

    /** Bytes of this rank. */
    std::size_t
    memory_consumption() const;
  };



  /**
   * f L_l + D_l on level l of the mesh hierarchy (local smoothing): the
   * stiffness operator of the level's cells times a number f plus a
   * diagonal D_l, the level's lumped mass times the nodal coefficient
   * interpolated from the active mesh. The Dirichlet DoFs and the
   * refinement edge of the level are a homogeneous Dirichlet boundary: the
   * operator is the identity there, and the coupling of the edge to the
   * interior is the interface operator (vmult_interface_down/up), as in
   * deal.II's MatrixFreeOperators::Base, whose semantics this class
   * follows without a MatrixFree object.
   */
  template <int dim>
  class LevelStiffness : public dealii::Subscriptor
  {
  public:
    using value_type = float;

    /**
     * The operator @p factor L_l + diag(@p diagonal) on @p level, with the
     * cell matrix @p cell_stiffness; all three must outlive this object.
     * Computes the inverse diagonal that the smoother uses.
     */
    void
    initialize(const MultigridLevel<dim>         &level,
               const Q1CellStiffness<dim, float> &cell_stiffness,
               const double                       factor,
               const LevelVector                 &diagonal);

    void
    vmult(LevelVector &dst, const LevelVector &src) const;

    void
    vmult_add(LevelVector &dst, const LevelVector &src) const;

    /** The operator is symmetric: Tvmult() is vmult(). */
    void
    Tvmult(LevelVector &dst, const LevelVector &src) const;

    void
    Tvmult_add(LevelVector &dst, const LevelVector &src) const;

    /** @p dst = the rows off the edge of the columns on the edge. */
    void
    vmult_interface_down(LevelVector &dst, const LevelVector &src) const;

    /** @p dst = the transpose of vmult_interface_down(). */
    void
    vmult_interface_up(LevelVector &dst, const LevelVector &src) const;

    dealii::types::global_dof_index
    m() const;

    dealii::types::global_dof_index
    n() const;

    void
    initialize_dof_vector(LevelVector &vector) const;

    /** The diagonal entry of row @p row = @p column (a global index). */
    float
    el(const dealii::types::global_dof_index row,
       const dealii::types::global_dof_index column) const;

    /** The inverse of the diagonal, 1 on the boundary and the edge. */
    const std::shared_ptr<dealii::DiagonalMatrix<LevelVector>> &
    get_matrix_diagonal_inverse() const;

  private:
    /**
     * @p dst += (f L_l + D_l) @p src with the boundary and edge entries of
     * @p src read as zero; the boundary and edge rows of @p dst are not
     * meaningful.
     */
    void
    apply_add(LevelVector &dst, const LevelVector &src) const;

    /**
     * Adjust the layouts of @p dst and @p src and zero @p dst; whether the
     * level has a refinement edge (else the interface products are zero).
     */
    bool
    start_interface_product(LevelVector &dst, const LevelVector &src) const;

    /** The values of @p vector on the refinement edge (owned DoFs). */
    std::vector<float>
    edge_values(const LevelVector &vector) const;

    /** Set the values of @p vector on the refinement edge to @p values. */
    void
    set_edge_values(LevelVector              &vector,
                    const std::vector<float> &values) const;

    /**
     * Give @p vector the layout of the level's cells if it has another one
     * (a vector of the transfer), keeping its owned values.
     */
    void
    adjust_layout(const LevelVector &vector) const;

    const MultigridLevel<dim>         *level          = nullptr;
    const Q1CellStiffness<dim, float> *cell_stiffness = nullptr;
    float                              factor         = 0;
    const LevelVector                 *diagonal       = nullptr;
    std::shared_ptr<dealii::DiagonalMatrix<LevelVector>> inverse_diagonal;
  };



  /**
   * The coupling of the refinement edge to the interior of a level
   * (MGInterfaceOperator without a MatrixFree object): vmult() is
   * LevelStiffness::vmult_interface_down(), Tvmult() vmult_interface_up().
   */
  template <int dim>
  class LevelInterface : public dealii::Subscriptor
  {
  public:
    void
    initialize(const LevelStiffness<dim> &level_operator);

    void
    vmult(LevelVector &dst, const LevelVector &src) const;

    void
    Tvmult(LevelVector &dst, const LevelVector &src) const;

  private:
    const LevelStiffness<dim> *level_operator = nullptr;
  };



  /**
   * What the geometric multigrid cycles of one mesh share, whatever the
   * operator f L + D: the level DoFs (local smoothing on the refinement
   * levels of the active mesh), the transfer between levels and the data
   * of each level (MultigridLevel). Built once per mesh, on the first
   * cycle (MatrixFreeStiffness).
   */
  template <int dim>
  class MultigridHierarchy
  {
  public:
    /**
     * The hierarchy of @p dof_handler, whose triangulation must keep its
     * levels (construct_multigrid_hierarchy) and whose level DoFs must be
     * distributed; with homogeneous Dirichlet conditions on the whole
     * boundary if @p dirichlet. Collective.
     */
    MultigridHierarchy(const dealii::DoFHandler<dim> &dof_handler,
                       const StiffnessQuadrature      stiffness_quadrature,
                       const bool                     dirichlet);

    /** Bytes of the level data, vectors and transfer of this rank. */
    std::size_t
    memory_consumption() const;

    const dealii::DoFHandler<dim>             &dof_handler;
    dealii::MGConstrainedDoFs                  mg_constrained_dofs;
    dealii::MGTransferMatrixFree<dim, float>   transfer;
    dealii::MGLevelObject<MultigridLevel<dim>> levels;
    /** The cell matrix of every level (the stiffness rule). */
    const Q1CellStiffness<dim, float> cell_stiffness;

  private:
    /** The cells and the boundary and edge DoFs of @p level. */
    void
    set_up_cells(const unsigned int level);

    /**
     * lumped_mass and stiffness_diagonal on @p level, the latter with the
     * 1D rule @p stiffness_rule.
     */
    void
    compute_level_vectors(const unsigned int           level,
                          const dealii::Quadrature<1> &stiffness_rule);
  };



  /**
   * The multigrid cycle of the matrix-free backend for an operator
   * f L + M[c] with a nodal coefficient c: one V-cycle of geometric
   * multigrid with local smoothing on the levels of the adaptive mesh
   * (deal.II's step-37 and step-50), Chebyshev smoothing with the level
   * diagonals, the coarse level solved by Chebyshev iteration to a
   * relative accuracy of multigrid_coarse_accuracy, and level operators
   * f L_l + M_l[c_l] with c_l the nodal coefficient injected level by
   * level (MGTransferMatrixFree::interpolate_to_mg(), as in step-66). The
   * cycle keeps the operators of its set-up: unlike the algebraic
   * multigrid, it does not follow a later refill of the operator.
   */
  template <int dim>
  class GeometricMultigrid : public MultigridCycle
  {
  public:
    /**
     * The cycle for @p factor L + M[@p coefficient] on the levels of
     * @p hierarchy, which must outlive it; @p coefficient is a vector of
     * the active matrix-free object with its constrained entries
     * distributed. @p smoother_sweeps is the Chebyshev degree.
     * @p constrained_diagonal holds (local index, diagonal entry) of the
     * operator's constrained rows, which are decoupled: the cycle solves
     * them exactly and keeps them out of the levels, so that it stays
     * symmetric. Collective.
     */
    GeometricMultigrid(
      const MultigridHierarchy<dim>               &hierarchy,
      const double                                 factor,
      const FineVector                            &coefficient,
      const unsigned int                           smoother_sweeps,
      std::vector<std::pair<unsigned int, double>> constrained_diagonal);

    void
    vmult(Vector &dst, const Vector &src) const override;

  private:
    using Smoother =
      dealii::PreconditionChebyshev<LevelStiffness<dim>, LevelVector>;

    /** The level operators and the Chebyshev smoothers built on them. */
    void
    setup_levels(const double       factor,
                 const FineVector  &coefficient,
                 const unsigned int smoother_sweeps);

    /**
     * The coefficient of level @p level - 1 where level @p level lies
     * below it: the average of the finer level's coefficient weighted with
     * its lumped mass and the prolongation (P^T (m c) / P^T m), so that
     * the coarse mass term M[c] is the row sum of the Galerkin product
     * P^T M[c] P. Injection kept the coefficient of the interface's centre,
     * where Psi''(V) < 0, on coarse cells wider than epsilon: the coarse
     * operators became indefinite and CG failed (level-6 sphere).
     */
    void
    average_to_coarser(const unsigned int level);

    const MultigridHierarchy<dim>                        &hierarchy;
    dealii::MGLevelObject<LevelVector>                    level_coefficient;
    dealii::MGLevelObject<LevelVector>                    level_diagonal;
    dealii::MGLevelObject<LevelStiffness<dim>>            operators;
    dealii::MGLevelObject<LevelInterface<dim>>            interface_operators;
    dealii::mg::Matrix<LevelVector>                       mg_matrix;
    dealii::mg::Matrix<LevelVector>                       mg_interface;
    dealii::mg::SmootherRelaxation<Smoother, LevelVector> smoother;
    dealii::MGCoarseGridApplySmoother<LevelVector>        coarse;
    std::unique_ptr<dealii::Multigrid<LevelVector>>       multigrid;
    std::unique_ptr<
      dealii::PreconditionMG<dim,
                             LevelVector,
                             dealii::MGTransferMatrixFree<dim, float>>>
                                                       preconditioner;
    const std::vector<std::pair<unsigned int, double>> constrained_diagonal;
    mutable FineVector                                 src_fine, dst_fine;
  };



  /** Copy the locally owned values of @p src into @p dst (same layout). */
  void
  copy_owned(const Vector &src, FineVector &dst);

  /** Copy the locally owned values of @p src into @p dst (same layout). */
  void
  copy_owned(const FineVector &src, Vector &dst);
} // namespace PhaseField

#endif
