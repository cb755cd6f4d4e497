#include <phasefield/schemes/augmented_lagrangian_scheme.h>
#include <phasefield/schemes/nested_scheme.h>
#include <phasefield/schemes/semi_implicit_scheme.h>
#include <phasefield/schemes/time_stepping_scheme.h>

namespace PhaseField
{
  template <int dim>
  std::unique_ptr<TimeSteppingScheme<dim>>
  create_time_stepping_scheme(const SchemeSettings             &settings,
                              const Discretization<dim>        &discretization,
                              const dealii::ConditionalOStream &pcout)
  {
    switch (settings.scheme)
      {
        case Scheme::nested:
          return std::make_unique<NestedScheme<dim>>(settings,
                                                     discretization,
                                                     pcout);
        case Scheme::semi_implicit:
          if (settings.outer_energy.has_restoration_terms() ||
              settings.outer_energy.forcing != nullptr || !settings.double_well)
            throw InputError(
              "<Time stepping / Scheme> = semi-implicit has no area term, "
              "fixed values or forcing: use Scheme = nested.");
          return std::make_unique<SemiImplicitScheme<dim>>(settings,
                                                           discretization,
                                                           pcout);
        case Scheme::augmented_lagrangian:
          return std::make_unique<AugmentedLagrangianScheme<dim>>(
            settings, discretization, pcout);
      }
    throw InputError("Unknown <Time stepping / Scheme>.");
  }



  template std::unique_ptr<TimeSteppingScheme<2>>
  create_time_stepping_scheme(const SchemeSettings &,
                              const Discretization<2> &,
                              const dealii::ConditionalOStream &);
  template std::unique_ptr<TimeSteppingScheme<3>>
  create_time_stepping_scheme(const SchemeSettings &,
                              const Discretization<3> &,
                              const dealii::ConditionalOStream &);
} // namespace PhaseField
