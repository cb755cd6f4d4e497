#ifndef phasefield_mesh_geometric_multigrid_h
#define phasefield_mesh_geometric_multigrid_h

#include <deal.II/base/mg_level_object.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/precondition.h>
#include <deal.II/matrix_free/matrix_free.h>
#include <deal.II/matrix_free/operators.h>
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
   * Set up @p data for the Q1CellStiffness kernel on the active cells of
   * @p dof_handler with @p constraints, or on the cells of level
   * @p mg_level: the DoF indices and each cell's Jacobian, from which the
   * kernel reads the cell's edge, and nothing else. The kernel evaluates
   * nothing at quadrature points, so one point per cell and MappingCartesian
   * suffice: with MappingQ1 and two 2-point rules, the setup's transient heap
   * on the level-7 sphere (2 ranks, 983k cells) was 1010 MiB instead of 650
   * (mallinfo2 before and after; most of the rest is deal.II's hanging-node
   * setup in 3D, which 9.4 does not let one switch off). Throws unless every
   * cell is an axis-parallel cube.
   */
  template <int dim, typename Number>
  void
  reinit_q1_matrix_free(
    dealii::MatrixFree<dim, Number>         &data,
    const dealii::DoFHandler<dim>           &dof_handler,
    const dealii::AffineConstraints<double> &constraints,
    const unsigned int mg_level = dealii::numbers::invalid_unsigned_int);

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
   * The cells of one multigrid level as the Q1 kernel reads them, in the
   * order of the cells of the level's matrix-free object (batches, then
   * lanes): per cell its 2^dim DoFs as local indices of the level's
   * vectors, numbers::invalid_unsigned_int for a DoF on the Dirichlet
   * boundary (read as zero and not written, as FEEvaluation does with the
   * level constraints), and the factor h^(dim-2) of the level's cells (all
   * of one edge h). LevelStiffness gathers and scatters through these 32
   * bytes per cell (3D) instead of
   * FEEvaluation, whose generic gather and scatter took most of the time of
   * the level products (doc/scaling.md, "The matrix-free backend").
   */
  template <int dim>
  struct Q1LevelCells
  {
    Q1LevelCells() = default;

    /**
     * The cells of @p data, a matrix-free object of level @p level, with the
     * boundary DoFs of @p mg_constrained_dofs. Throws unless all cells have
     * one edge.
     */
    Q1LevelCells(const dealii::MatrixFree<dim, float> &data,
                 const dealii::MGConstrainedDoFs      &mg_constrained_dofs,
                 const unsigned int                    level);

    /** Bytes of this rank. */
    std::size_t
    memory_consumption() const;

    std::vector<unsigned int> dofs;
    float                     scale = 0;
  };



  /**
   * f L_l + D_l on level l of the mesh hierarchy (local smoothing): the
   * stiffness operator of the level's cells times a number f plus a
   * diagonal D_l, the level's lumped mass times the nodal coefficient
   * interpolated from the active mesh. The refinement edge of the level is
   * a homogeneous Dirichlet boundary (MatrixFreeOperators::Base).
   */
  template <int dim>
  class LevelStiffness
    : public dealii::MatrixFreeOperators::Base<dim, LevelVector>
  {
  public:
    /**
     * The operator @p factor L_l + diag(@p diagonal), with the cell matrices
     * of @p cell_stiffness on the cells @p cells, whose diagonal without the
     * shift is @p stiffness_diagonal (diag L_l); all four must outlive this
     * object. Computes the inverse diagonal that the smoother uses.
     */
    void
    set_coefficients(const double                       factor,
                     const Q1CellStiffness<dim, float> &cell_stiffness,
                     const Q1LevelCells<dim>           &cells,
                     const LevelVector                 &stiffness_diagonal,
                     const LevelVector                 &diagonal);

    void
    compute_diagonal() override;

  private:
    void
    apply_add(LevelVector &dst, const LevelVector &src) const override;

    /** f times the stiffness integral on the cells of @p cell_range. */
    void
    local_apply(const dealii::MatrixFree<dim, float>        &data,
                LevelVector                                 &dst,
                const LevelVector                           &src,
                const std::pair<unsigned int, unsigned int> &cell_range) const;

    float                              factor             = 0;
    const Q1CellStiffness<dim, float> *cell_stiffness     = nullptr;
    const Q1LevelCells<dim>           *cells              = nullptr;
    const LevelVector                 *stiffness_diagonal = nullptr;
    const LevelVector                 *diagonal           = nullptr;
  };



  /**
   * What the geometric multigrid cycles of one mesh share, whatever the
   * operator f L + D: the level DoFs (local smoothing on the refinement
   * levels of the active mesh), the transfer between levels, one
   * matrix-free object per level, and per level the lumped mass and the
   * diagonal of L_l. Built once per mesh, on the first cycle
   * (MatrixFreeStiffness).
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

    const dealii::DoFHandler<dim>           &dof_handler;
    dealii::MGConstrainedDoFs                mg_constrained_dofs;
    dealii::MGTransferMatrixFree<dim, float> transfer;
    dealii::MGLevelObject<std::shared_ptr<const dealii::MatrixFree<dim, float>>>
                                             levels;
    dealii::MGLevelObject<Q1LevelCells<dim>> cells;
    dealii::MGLevelObject<LevelVector>       lumped_mass;
    dealii::MGLevelObject<LevelVector>       stiffness_diagonal;
    /** The cell matrix of every level (the stiffness rule). */
    const Q1CellStiffness<dim, float> cell_stiffness;

  private:
    /** The matrix-free object of @p level. */
    std::shared_ptr<const dealii::MatrixFree<dim, float>>
    make_level(const unsigned int level) const;

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

    const MultigridHierarchy<dim>             &hierarchy;
    dealii::MGLevelObject<LevelVector>         level_coefficient;
    dealii::MGLevelObject<LevelVector>         level_diagonal;
    dealii::MGLevelObject<LevelStiffness<dim>> operators;
    dealii::MGLevelObject<
      dealii::MatrixFreeOperators::MGInterfaceOperator<LevelStiffness<dim>>>
                                                          interface_operators;
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
