#include <Amesos.h>
#include <Amesos_BaseSolver.h>
#include <Amesos_Mumps.h>
#include <Epetra_LinearProblem.h>
#include <phasefield/solvers/direct_factorization.h>

namespace PhaseField
{
  using namespace dealii;

  DirectFactorization::DirectFactorization(
    const TrilinosWrappers::SparseMatrix &matrix,
    const unsigned int                    pivoting_workspace_percent)
    : control(1, 0)
    , solver(control,
             TrilinosWrappers::SolverDirect::AdditionalData(false,
                                                            "Amesos_Mumps"))
  {
    factorized_matrix.copy_from(matrix);
    if (pivoting_workspace_percent == 0)
      {
        solver.initialize(factorized_matrix);
        return;
      }
    problem = std::make_unique<Epetra_LinearProblem>();
    problem->SetOperator(
      const_cast<Epetra_CrsMatrix *>(&factorized_matrix.trilinos_matrix()));
    Amesos factory;
    indefinite_solver.reset(factory.Create("Amesos_Mumps", *problem));
    AssertThrow(indefinite_solver != nullptr,
                ExcMessage("Trilinos Amesos has no MUMPS."));
    if (auto *mumps = dynamic_cast<Amesos_Mumps *>(indefinite_solver.get()))
      mumps->SetICNTL(14, pivoting_workspace_percent);
    const int symbolic = indefinite_solver->SymbolicFactorization();
    const int numeric  = indefinite_solver->NumericFactorization();
    AssertThrow(symbolic == 0 && numeric == 0,
                ExcMessage("MUMPS could not factorise the Newton matrix "
                           "(error " +
                           std::to_string(symbolic != 0 ? symbolic : numeric) +
                           ")."));
  }



  DirectFactorization::~DirectFactorization() = default;



  void
  DirectFactorization::vmult(TrilinosWrappers::MPI::Vector       &dst,
                             const TrilinosWrappers::MPI::Vector &src) const
  {
    if (!indefinite_solver)
      {
        solver.solve(dst, src);
        return;
      }
    problem->SetLHS(&dst.trilinos_vector());
    problem->SetRHS(const_cast<Epetra_MultiVector *>(&src.trilinos_vector()));
    AssertThrow(indefinite_solver->Solve() == 0,
                ExcMessage("MUMPS failed to solve the Newton system."));
  }
} // namespace PhaseField
