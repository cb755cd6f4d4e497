#include <Amesos.h>
#include <Amesos_BaseSolver.h>
#include <Amesos_Mumps.h>
#include <Epetra_LinearProblem.h>
#include <deal.II/base/mpi.h>
#include <phasefield/solvers/direct_factorization.h>

namespace PhaseField
{
  using namespace dealii;

  DirectFactorization::DirectFactorization(
    const TrilinosWrappers::SparseMatrix &matrix,
    const unsigned int                    pivoting_workspace_percent)
    : pivoting_workspace_percent(pivoting_workspace_percent)
  {
    factorized_matrix.copy_from(matrix);
    analyze_and_factorize();
  }



  DirectFactorization::~DirectFactorization() = default;



  void
  DirectFactorization::analyze_and_factorize()
  {
    // the solver refers to the problem: release it first. Its destructor
    // asks the problem's operator for the communicator, and refactorize()
    // may have replaced that matrix (copy_from() with another pattern,
    // e.g. after a checkpoint's reload): point the problem at the current
    // one, so that the destructor does not read the freed one
    if (problem != nullptr)
      problem->SetOperator(
        const_cast<Epetra_CrsMatrix *>(&factorized_matrix.trilinos_matrix()));
    solver.reset();
    problem = std::make_unique<Epetra_LinearProblem>();
    problem->SetOperator(
      const_cast<Epetra_CrsMatrix *>(&factorized_matrix.trilinos_matrix()));
    Amesos factory;
    solver.reset(factory.Create("Amesos_Mumps", *problem));
    AssertThrow(solver != nullptr, ExcMessage("Trilinos Amesos has no MUMPS."));
    auto *mumps = dynamic_cast<Amesos_Mumps *>(solver.get());
    if (mumps != nullptr && pivoting_workspace_percent > 0)
      mumps->SetICNTL(14, pivoting_workspace_percent);
    const int symbolic = solver->SymbolicFactorization();
    const int numeric  = symbolic == 0 ? solver->NumericFactorization() : 0;
    AssertThrow(symbolic == 0 && numeric == 0,
                ExcMessage("MUMPS could not factorise the Newton matrix "
                           "(error " +
                           std::to_string(symbolic != 0 ? symbolic : numeric) +
                           ")."));
  }



  bool
  DirectFactorization::factorize_numerically()
  {
    // collective: MUMPS reports an error on all ranks
    return solver->NumericFactorization() == 0;
  }



  void
  DirectFactorization::refactorize(const TrilinosWrappers::SparseMatrix &matrix)
  {
    // copy_from() copies the values into the same Epetra matrix if the
    // pattern is the same, and replaces the Epetra matrix otherwise
    const Epetra_CrsMatrix *before = &factorized_matrix.trilinos_matrix();
    factorized_matrix.copy_from(matrix);
    const bool same_pattern =
      dealii::Utilities::MPI::min(
        &factorized_matrix.trilinos_matrix() == before ? 1 : 0,
        factorized_matrix.get_mpi_communicator()) == 1;
    // with the analysis of other values, the pivot order may need more
    // workspace than MUMPS reserved: analyse again if it fails
    if (!same_pattern || !factorize_numerically())
      analyze_and_factorize();
  }



  void
  DirectFactorization::vmult(Vector &dst, const Vector &src) const
  {
    problem->SetLHS(&dst.trilinos_vector());
    problem->SetRHS(const_cast<Epetra_MultiVector *>(&src.trilinos_vector()));
    AssertThrow(solver->Solve() == 0,
                ExcMessage("MUMPS failed to solve the Newton system."));
  }
} // namespace PhaseField
