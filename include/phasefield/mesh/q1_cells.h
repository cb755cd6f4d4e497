#ifndef phasefield_mesh_q1_cells_h
#define phasefield_mesh_q1_cells_h

#include <deal.II/base/partitioner.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <memory>
#include <phasefield/mesh/q1_cell_stiffness.h>
#include <utility>
#include <vector>

namespace PhaseField
{
  /**
   * The locally owned cells of one mesh of axis-parallel cubes as the Q1
   * kernel reads them: the active cells of a DoFHandler, or the cells of
   * one of its multigrid levels. This table is all that the matrix-free
   * products keep of the mesh, in place of a deal.II MatrixFree object:
   * - per cell its 2^dim DoFs as local indices of vectors with
   *   #partitioner (lexicographic, FE_Q's order of the vertices), where a
   *   constrained DoF is marked and names its constraint instead;
   * - per cell its refinement level, which gives h^(dim-2), the factor of
   *   the cell matrix h^(dim-2) A_ref;
   * - the constraints of the marked DoFs as (local index, weight) lists:
   *   hanging nodes, and none for a DoF on a homogeneous Dirichlet boundary
   *   (read as zero, never written).
   *
   * apply_add() reads the constrained values C x, applies the cell matrices
   * and adds C^T of the result, as FEEvaluation::read_dof_values() and
   * distribute_local_to_global() do. 33 bytes per cell (3D) and the
   * constraints, less than the MatrixFree objects they replace
   * (doc/benchmarks.md, "Choices in the code").
   */
  template <int dim>
  class Q1Cells
  {
  public:
    /** Q1 DoFs of a cell. */
    static constexpr unsigned int n = Q1CellStiffness<dim, double>::n;

    Q1Cells() = default;

    /**
     * The locally owned active cells of @p dof_handler (scalar Q1), or its
     * locally owned cells of level @p mg_level, with the constraints
     * @p constraints (homogeneous; on a level: the Dirichlet DoFs of the
     * level). Vectors of these cells have the locally relevant DoFs as
     * ghosts. Throws unless every cell is an axis-parallel cube and all
     * cells of one level have one edge.
     */
    Q1Cells(
      const dealii::DoFHandler<dim>           &dof_handler,
      const dealii::AffineConstraints<double> &constraints,
      const unsigned int mg_level = dealii::numbers::invalid_unsigned_int);

    /**
     * @p dst += @p factor times the condensed stiffness product
     * C^T A C @p src, summed over the cells. Both vectors have
     * #partitioner; the ghost values of @p src are updated and the ghost
     * contributions of @p dst sent to their owners (collective); the
     * constrained rows of @p dst get nothing.
     */
    template <typename Number>
    void
    apply_add(const Q1CellStiffness<dim, Number>                       &kernel,
              const Number                                              factor,
              const dealii::LinearAlgebra::distributed::Vector<Number> &src,
              dealii::LinearAlgebra::distributed::Vector<Number> &dst) const;

    /** Bytes of this rank. */
    std::size_t
    memory_consumption() const;

    /** The layout of the vectors that apply_add() reads and writes. */
    std::shared_ptr<const dealii::Utilities::MPI::Partitioner> partitioner;

  private:
    /** The mark of a constrained DoF in #dofs: the high bit. */
    static constexpr unsigned int constrained_mark = 1U << 31;

    /** The value of @p src at the cell's DoF entry @p dof (C x). */
    template <typename Number>
    Number
    read(const unsigned int                                        dof,
         const dealii::LinearAlgebra::distributed::Vector<Number> &src) const;

    /** Add @p value to @p dst at the cell's DoF entry @p dof (C^T y). */
    template <typename Number>
    void
    add(const unsigned int                                  dof,
        const Number                                        value,
        dealii::LinearAlgebra::distributed::Vector<Number> &dst) const;

    std::vector<unsigned int>  dofs;
    std::vector<unsigned char> cell_level;
    /** h^(dim-2) of the cells of each level. */
    std::vector<double> level_scale;
    /** The entries of constraint k: [constraint_start[k], [k+1]). */
    std::vector<unsigned int>                    constraint_start = {0};
    std::vector<std::pair<unsigned int, double>> constraint_entries;
  };
} // namespace PhaseField

#endif
