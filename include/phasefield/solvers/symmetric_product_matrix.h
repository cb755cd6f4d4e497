#ifndef phasefield_solvers_symmetric_product_matrix_h
#define phasefield_solvers_symmetric_product_matrix_h

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <phasefield/core/linear_algebra.h>
#include <phasefield/mesh/lumped_operators.h>
#include <phasefield/solvers/linear_solver.h>

namespace PhaseField
{
  /**
   * The assembled matrix S = A diag(w) A + diag(e) with
   * A = f L + M[k] + diag(c), for the stiffness matrix L and the lumped
   * mass M of a LumpedOperators: a Schur complement that a direct solver
   * factorises (the augmented Lagrangian's preconditioner S_V). One sparse
   * matrix product per assembly.
   */
  class SymmetricProductMatrix
  {
  public:
    /**
     * Assemble S for A = @p f L + M[@p k] + diag(@p c), w = @p w and
     * e = @p e (nodal vectors, @p c and @p e already multiplied by the mass
     * where they are masses).
     */
    template <int dim>
    void
    assemble(const LumpedOperators<dim> &operators,
             const double                f,
             const Vector               &k,
             const Vector               &c,
             const Vector               &w,
             const Vector               &e);

    /**
     * Factorise S with the direct @p solver; S has the same sparsity
     * pattern at every assembly on one mesh, so the solver keeps its
     * analysis.
     */
    void
    factorize(LinearSolver &solver) const;

    /** @p x = S^-1 @p rhs with the factorisation of @p solver. */
    void
    solve(LinearSolver &solver, Vector &x, const Vector &rhs) const;

  private:
    dealii::TrilinosWrappers::SparseMatrix matrix;
  };
} // namespace PhaseField

#endif
