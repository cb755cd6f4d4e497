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
} // namespace PhaseField
