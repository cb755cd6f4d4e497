#include <deal.II/base/exceptions.h>
#include <phasefield/mesh/operator_backend.h>

namespace PhaseField
{
  namespace
  {
    std::vector<OperatorBackendEntry> &
    backends()
    {
      static std::vector<OperatorBackendEntry> entries;
      return entries;
    }
  } // namespace



  void
  register_operator_backend(const OperatorBackendEntry &entry)
  {
    AssertThrow(entry.name != "auto" && entry.name != "direct",
                dealii::ExcMessage("The operator backend name <" + entry.name +
                                   "> is a value of <Linear "
                                   "solver / Type> already."));
    for (const OperatorBackendEntry &other : backends())
      AssertThrow(other.name != entry.name,
                  dealii::ExcMessage("The operator backend <" + entry.name +
                                     "> is registered twice."));
    backends().push_back(entry);
    linear_solver_type_values().push_back({entry.name, entry.documentation});
  }



  const std::vector<OperatorBackendEntry> &
  registered_operator_backends()
  {
    return backends();
  }



  const OperatorBackendEntry &
  operator_backend(const std::string &name)
  {
    for (const OperatorBackendEntry &entry : backends())
      if (entry.name == name)
        return entry;
    AssertThrow(false,
                dealii::ExcMessage("No operator backend is named <" + name +
                                   ">."));
    return backends().front();
  }
} // namespace PhaseField
