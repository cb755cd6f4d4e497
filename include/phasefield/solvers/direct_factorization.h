#ifndef phasefield_solvers_direct_factorization_h
#define phasefield_solvers_direct_factorization_h

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <memory>
#include <phasefield/core/linear_algebra.h>

class Amesos_BaseSolver;
class Epetra_LinearProblem;

namespace PhaseField
{
  /**
   * A copy of a sparse matrix and its LU factorisation by MUMPS (through
   * Trilinos Amesos), usable as a preconditioner (vmult() applies the
   * inverse). For indefinite matrices (pivoting_workspace_percent > 0)
   * MUMPS gets that much extra workspace (ICNTL(14)) for the fill-in of
   * delayed pivots.
   */
  class DirectFactorization
  {
  public:
    DirectFactorization(const dealii::TrilinosWrappers::SparseMatrix &matrix,
                        const unsigned int pivoting_workspace_percent);
    ~DirectFactorization();

    /**
     * Factorise @p matrix instead. If it has the sparsity pattern of the
     * matrix factorised before (the Newton matrices on one mesh), only its
     * values are copied and MUMPS's analysis (ordering and symbolic
     * factorisation) is reused: just the numeric factorisation is
     * repeated.
     */
    void
    refactorize(const dealii::TrilinosWrappers::SparseMatrix &matrix);

    /** dst = A^-1 src. */
    void
    vmult(Vector &dst, const Vector &src) const;

    /** Number of rows of the factorised matrix. */
    dealii::types::global_dof_index
    size() const
    {
      return factorized_matrix.m();
    }

  private:
    /** Analyse and factorise factorized_matrix. */
    void
    analyze_and_factorize();

    /** Factorise factorized_matrix with the analysis kept. */
    bool
    factorize_numerically();

    dealii::TrilinosWrappers::SparseMatrix factorized_matrix;
    std::unique_ptr<Epetra_LinearProblem>  problem;
    std::unique_ptr<Amesos_BaseSolver>     solver;
    const unsigned int                     pivoting_workspace_percent;
  };
} // namespace PhaseField

#endif
