#ifndef phasefield_lumped_operators_h
#define phasefield_lumped_operators_h

#include <deal.II/base/index_set.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_index_access.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <memory>
#include <phasefield/core/linear_algebra.h>
#include <phasefield/core/parameters.h>
#include <phasefield/mesh/stiffness_operator.h>
#include <phasefield/mesh/trilinos_stiffness.h>
#include <string>
#include <vector>

namespace PhaseField
{
  /**
   * The two mesh-dependent operators of every scheme in this library, for
   * one scalar Q1 space with hanging-node constraints:
   *
   * - the lumped mass matrix M (Gauss-Lobatto quadrature on the cell
   *   vertices), stored as the vector of its diagonal. Cell contributions
   *   at hanging vertices are distributed to their parents, so M is the
   *   diagonal of a positive weighted nodal inner product on the
   *   conforming space; its entries are zero at constrained DoFs;
   * - the stiffness matrix L, condensed with the constraints, integrated
   *   with the rule chosen by StiffnessQuadrature (exact by default).
   *
   * Nonlinear terms such as M[Psi''(V)] are then nodal: their assembly
   * costs one loop over the locally owned entries of a vector.
   */
  template <int dim>
  class LumpedOperators
  {
  public:
    /** How L is represented. */
    struct Settings
    {
      StiffnessQuadrature stiffness_quadrature = StiffnessQuadrature::gauss;
      /**
       * The name of the registered operator backend whose factory makes L
       * (mesh/operator_backend.h); the matrix-free one needs the level DoFs
       * of the DoF handler distributed.
       */
      std::string backend = OperatorBackendNames::assembled;
      /** Homogeneous Dirichlet conditions on the whole boundary. */
      bool dirichlet = false;
    };

    /**
     * Assemble M and set up L on @p dof_handler (scalar Q1) as
     * @p settings say. @p dof_handler and @p constraints must outlive the
     * operators until release().
     */
    void
    reinit(const dealii::DoFHandler<dim>           &dof_handler,
           const dealii::AffineConstraints<double> &constraints,
           const MPI_Comm                           mpi_communicator,
           const Settings                          &settings);

    /**
     * reinit() with the assembled backend (TrilinosStiffness), L with the
     * rule
     * @p stiffness_quadrature.
     */
    void
    reinit(const dealii::DoFHandler<dim>           &dof_handler,
           const dealii::AffineConstraints<double> &constraints,
           const MPI_Comm                           mpi_communicator,
           const StiffnessQuadrature                stiffness_quadrature =
             StiffnessQuadrature::gauss);

    /**
     * Free L, M and the per-row data (the index sets stay): called before
     * the mesh changes, whose operators reinit() builds anew, so that the
     * old ones are not held through the refinement's transfer buffers
     * (Discretization::execute_with_transfer()).
     */
    void
    release();

    /** Diagonal of the lumped mass matrix (zero at constrained DoFs). */
    Vector lumped_mass;

    /**
     * Inverse of the lumped mass. At constrained DoFs, where the mass is
     * zero, it holds the inverse of a typical cell mass so that the
     * reduced systems stay regular; all residual entries there are zero.
     */
    Vector inverse_lumped_mass;

    /** Local indices (into the locally owned range) of constrained DoFs. */
    std::vector<unsigned int> constrained_local_indices;

    dealii::IndexSet locally_owned_dofs;
    dealii::IndexSet locally_relevant_dofs;

    /**
     * @p matrix = @p stiffness_factor L + M[@p nodal_weight], i.e. the
     * stiffness matrix plus the lumped mass weighted nodally. If @p matrix
     * shares the pattern of L (an earlier result), only its values are
     * written.
     */
    void
    stiffness_plus_weighted_mass(
      const double                            stiffness_factor,
      const Vector                           &nodal_weight,
      dealii::TrilinosWrappers::SparseMatrix &matrix) const;

    /**
     * The same operator as an @p op that applies L
     * (StiffnessOperator::shift(): refilled in place if @p op holds one
     * already) instead of storing the matrix.
     */
    void
    stiffness_plus_weighted_mass(const double  stiffness_factor,
                                 const Vector &nodal_weight,
                                 std::unique_ptr<ShiftedStiffness> &op) const;

    /**
     * The stiffness operator L: what schemes apply (the seam to the
     * linear-algebra backend).
     */
    const StiffnessOperator &
    stiffness_operator() const;

    /**
     * The assembled stiffness matrix, for what needs its entries: the
     * direct solvers' matrices (StiffnessSquare, the 3-field Jacobian).
     * Throws unless the backend's L is a TrilinosStiffness
     * (OperatorBackendEntry::assembled_matrix).
     */
    const dealii::TrilinosWrappers::SparseMatrix &
    stiffness_matrix() const;

    /**
     * Add @p values (one per locally owned DoF) to the diagonal of
     * @p matrix, whose sparsity pattern contains the diagonal, and compress.
     */
    void
    add_to_diagonal(const Vector                           &values,
                    dealii::TrilinosWrappers::SparseMatrix &matrix) const;

    /** Set all constrained entries of @p vector to zero. */
    void
    zero_constrained(Vector &vector) const;

    /** (x, y)_M = sum_i m_i x_i y_i. */
    double
    mass_product(const Vector &x, const Vector &y) const;

    /** x^T L x over the unconstrained DoFs, i.e. Int |grad x_h|^2. */
    double
    stiffness_product(const Vector &x) const;

    /** sqrt(r^T M^-1 r): the L2 norm of the function that r represents. */
    double
    dual_norm(const Vector &r) const;

  private:
    /**
     * Assemble M into the reinitialised vector; returns the smallest cell
     * mass of this rank.
     */
    double
    assemble_mass(const dealii::DoFHandler<dim>           &dof_handler,
                  const dealii::AffineConstraints<double> &constraints);

    /** The assembled L; throws unless L is one. */
    const TrilinosStiffness &
    assembled_stiffness() const;

    /**
     * inverse_lumped_mass and constrained_local_indices, with
     * 1/@p min_cell_mass at the constrained DoFs.
     */
    void
    set_inverse_lumped_mass(
      const dealii::AffineConstraints<double> &constraints,
      const double                             min_cell_mass);

    /** L, made by the backend's factory (null before reinit()). */
    std::shared_ptr<StiffnessOperator> stiffness;
  };
  /**
   * Epetra's compressed row storage of the locally owned rows of a
   * compressed matrix: the entries of local row i are offsets[i], ...,
   * offsets[i+1] - 1, with local column indices and values. Writing to
   * values changes the matrix (no compress() needed).
   */
  struct CompressedRows
  {
    int    *offsets = nullptr;
    int    *columns = nullptr;
    double *values  = nullptr;
  };

  /**
   * The compressed rows of @p matrix, which must be compressed with
   * optimised storage (as deal.II compresses).
   */
  CompressedRows
  compressed_rows(const dealii::TrilinosWrappers::SparseMatrix &matrix);

  /**
   * Do @p a and @p b share one sparsity pattern (one Epetra graph, as after
   * a.copy_from(b) with a different pattern before)? Then their values
   * correspond entry by entry.
   */
  bool
  share_pattern(const dealii::TrilinosWrappers::SparseMatrix &a,
                const dealii::TrilinosWrappers::SparseMatrix &b);

  /**
   * Call @p f(column, value) for every stored entry of the locally owned
   * row @p row of @p matrix (global indices), through Epetra's view of the
   * row. deal.II's row iterators copy the row at every end(), which made
   * assembling the 3-field Jacobian from L cost more than factorising it.
   */
  template <typename Function>
  void
  for_each_entry_in_row(const dealii::TrilinosWrappers::SparseMatrix &matrix,
                        const dealii::types::global_dof_index         row,
                        const Function                               &f)
  {
    const Epetra_CrsMatrix &m         = matrix.trilinos_matrix();
    int                     n_entries = 0;
    double                 *values    = nullptr;
    int                    *columns   = nullptr;
    m.ExtractMyRowView(
      m.LRID(static_cast<dealii::TrilinosWrappers::types::int_type>(row)),
      n_entries,
      values,
      columns);
    for (int k = 0; k < n_entries; ++k)
      f(static_cast<dealii::types::global_dof_index>(
          dealii::TrilinosWrappers::global_column_index(m, columns[k])),
        values[k]);
  }
} // namespace PhaseField

#endif
