#include <Epetra_MultiVector.h>
#include <Epetra_Vector.h>
#include <Teuchos_ParameterList.hpp>
#include <algorithm>
#include <deal.II/base/exceptions.h>
#include <phasefield/mesh/algebraic_multigrid.h>
#include <string>
#include <vector>

namespace PhaseField
{
  namespace
  {
    /**
     * The Chebyshev smoother divides by the diagonal and the aggregation
     * assumes a positive definite matrix: with a non-positive diagonal
     * entry (a coefficient of the wrong sign) ML's coarsening stalls and the
     * coarse direct solver factorises a level of nearly the fine size for
     * minutes. Throw instead, on all ranks (Epetra's minimum is global).
     */
    void
    assert_positive_diagonal(const Epetra_RowMatrix &matrix)
    {
      Epetra_Vector diagonal(matrix.RowMatrixRowMap());
      matrix.ExtractDiagonalCopy(diagonal);
      double minimum = 0.;
      diagonal.MinValue(&minimum);
      AssertThrow(minimum > 0.,
                  dealii::ExcMessage(
                    "The algebraic multigrid needs a matrix with a positive "
                    "diagonal, but its smallest diagonal entry is " +
                    std::to_string(minimum) +
                    ": the matrix is not positive definite (a coefficient "
                    "of the wrong sign?)."));
    }
  } // namespace



  AlgebraicMultigrid::AlgebraicMultigrid(const Epetra_RowMatrix &matrix,
                                         const Vector           *slow_mode,
                                         const unsigned int smoother_sweeps)
  {
    assert_positive_diagonal(matrix);
    dealii::TrilinosWrappers::PreconditionAMG::AdditionalData settings;
    settings.elliptic              = true;
    settings.higher_order_elements = false;
    settings.smoother_sweeps       = smoother_sweeps;
    settings.aggregation_threshold = 0.02;
    // the coarse size is not in AdditionalData: set it in ML's list
    Teuchos::ParameterList              parameters;
    std::unique_ptr<Epetra_MultiVector> constant_modes;
    settings.set_parameters(parameters, constant_modes, matrix);
    parameters.set("coarse: max size", static_cast<int>(multigrid_coarse_size));
    // near null space {1, slow mode}, column by column (ML copies it
    // during the set-up)
    std::vector<double> modes;
    if (slow_mode != nullptr)
      {
        const unsigned int n = slow_mode->locally_owned_size();
        modes.assign(2 * n, 1.);
        std::copy(slow_mode->begin(), slow_mode->end(), modes.begin() + n);
        parameters.set("null space: type", "pre-computed");
        parameters.set("null space: dimension", 2);
        parameters.set("null space: vectors", modes.data());
        parameters.set("null space: add default vectors", false);
      }
    multigrid.initialize(matrix, parameters);
  }



  void
  AlgebraicMultigrid::vmult(Vector &dst, const Vector &src) const
  {
    multigrid.vmult(dst, src);
  }
} // namespace PhaseField
