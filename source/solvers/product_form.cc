#include <Epetra_MultiVector.h>
#include <Teuchos_ParameterList.hpp>
#include <phasefield/solvers/product_form.h>

namespace PhaseField
{
  void
  initialize_multigrid(dealii::TrilinosWrappers::PreconditionAMG    &multigrid,
                       const dealii::TrilinosWrappers::SparseMatrix &matrix)
  {
    dealii::TrilinosWrappers::PreconditionAMG::AdditionalData settings;
    settings.elliptic              = true;
    settings.higher_order_elements = false;
    settings.smoother_sweeps       = 3;
    settings.aggregation_threshold = 0.02;
    // the coarse size is not in AdditionalData: set it in ML's list
    Teuchos::ParameterList              parameters;
    std::unique_ptr<Epetra_MultiVector> constant_modes;
    settings.set_parameters(parameters, constant_modes, matrix);
    parameters.set("coarse: max size", static_cast<int>(multigrid_coarse_size));
    multigrid.initialize(matrix, parameters);
  }
} // namespace PhaseField
