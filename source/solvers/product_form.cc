#include <Epetra_MultiVector.h>
#include <Teuchos_ParameterList.hpp>
#include <phasefield/solvers/product_form.h>

namespace PhaseField
{
  dealii::TrilinosWrappers::PreconditionAMG::AdditionalData
  multigrid_settings()
  {
    dealii::TrilinosWrappers::PreconditionAMG::AdditionalData data;
    data.elliptic              = true;
    data.higher_order_elements = false;
    data.smoother_sweeps       = 3;
    data.aggregation_threshold = 0.02;
    return data;
  }



  void
  initialize_multigrid(dealii::TrilinosWrappers::PreconditionAMG    &multigrid,
                       const dealii::TrilinosWrappers::SparseMatrix &matrix)
  {
    Teuchos::ParameterList              parameters;
    std::unique_ptr<Epetra_MultiVector> constant_modes;
    multigrid_settings().set_parameters(parameters, constant_modes, matrix);
    parameters.set("coarse: max size",
                   static_cast<int>(multigrid_coarse_size));
    multigrid.initialize(matrix, parameters);
  }



} // namespace PhaseField
