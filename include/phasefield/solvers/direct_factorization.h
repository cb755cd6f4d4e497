#ifndef phasefield_solvers_direct_factorization_h
#define phasefield_solvers_direct_factorization_h

#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <memory>

class Amesos_BaseSolver;
class Epetra_LinearProblem;

namespace PhaseField
{
  /**
   * A copy of a sparse matrix and its LU factorisation by MUMPS (through
   * Trilinos Amesos), usable as a preconditioner (vmult() applies the
   * inverse). For indefinite matrices (pivoting_workspace_percent > 0)
   * MUMPS is called through Amesos directly, with that much extra
   * workspace (ICNTL(14)) for the fill-in of delayed pivots.
   */
  class DirectFactorization
  {
  public:
    DirectFactorization(const dealii::TrilinosWrappers::SparseMatrix &matrix,
                        const unsigned int pivoting_workspace_percent);
    ~DirectFactorization();

    /** dst = A^-1 src. */
    void
    vmult(dealii::TrilinosWrappers::MPI::Vector       &dst,
          const dealii::TrilinosWrappers::MPI::Vector &src) const;

    /** Number of rows of the factorised matrix. */
    dealii::types::global_dof_index
    size() const
    {
      return factorized_matrix.m();
    }

  private:
    dealii::TrilinosWrappers::SparseMatrix         factorized_matrix;
    dealii::SolverControl                          control;
    mutable dealii::TrilinosWrappers::SolverDirect solver;
    std::unique_ptr<Epetra_LinearProblem>          problem;
    std::unique_ptr<Amesos_BaseSolver>             indefinite_solver;
  };
} // namespace PhaseField

#endif
