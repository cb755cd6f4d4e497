#ifndef phasefield_stiffness_plus_diagonal_h
#define phasefield_stiffness_plus_diagonal_h

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

namespace PhaseField
{
  /**
   * The matrix f L + D, for the stiffness matrix L, a number f and a
   * diagonal matrix D, applied from L without being stored. The linearised
   * inner operators K(V) and Khat of the nested scheme have this form
   * (LumpedOperators::stiffness_plus_weighted_mass()): kept as an operator,
   * each costs one vector instead of a sparse matrix of the size of L, and
   * a product with it costs the same as with the matrix. Where a solver
   * needs the entries (a factorisation, a multigrid set-up), build the
   * matrix instead.
   */
  class StiffnessPlusDiagonal
  {
  public:
    /**
     * The operator @p stiffness_factor @p stiffness + diag(@p diagonal);
     * @p stiffness must outlive this object (it is not copied), the
     * contents of @p diagonal are taken over (it is left empty).
     */
    void
    reinit(const dealii::TrilinosWrappers::SparseMatrix &stiffness,
           const double                                  stiffness_factor,
           dealii::TrilinosWrappers::MPI::Vector        &diagonal);

    /** @p dst = (f L + D) @p src. */
    void
    vmult(dealii::TrilinosWrappers::MPI::Vector       &dst,
          const dealii::TrilinosWrappers::MPI::Vector &src) const;

    /** Whether reinit() has not been called yet. */
    bool
    empty() const;

  private:
    const dealii::TrilinosWrappers::SparseMatrix *stiffness = nullptr;
    double                                        stiffness_factor = 0;
    dealii::TrilinosWrappers::MPI::Vector         diagonal;
  };
} // namespace PhaseField

#endif
