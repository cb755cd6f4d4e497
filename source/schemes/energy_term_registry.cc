#include <phasefield/core/parameters.h>
#include <phasefield/schemes/constraints.h>
#include <phasefield/schemes/energy_term_registry.h>

namespace PhaseField
{
  using namespace dealii;

  namespace
  {
    // ---------------------------------------------------------------------
    // The built-in terms: one entry each, listed in built_in_terms().
    // ---------------------------------------------------------------------

    /** The AreaTerm on @p operators (deduces the dimension). */
    template <int dim>
    std::unique_ptr<EnergyTerm>
    make_area_term(const LumpedOperators<dim> &operators,
                   const double                scale,
                   const double                epsilon)
    {
      return std::make_unique<AreaTerm<dim>>(operators, scale, epsilon);
    }



    /** The area functional eta a_eps[U] (OuterEnergy::area_weight != 0). */
    ModelTermEntry
    area_entry()
    {
      ModelTermEntry entry;
      entry.name    = "area term";
      entry.present = [](const OuterEnergy &outer) {
        return outer.area_weight != 0;
      };
      entry.set_factory([](const OuterEnergy &outer,
                           const auto        &operators,
                           const double       tau,
                           const double       epsilon) {
        return make_area_term(operators, tau * outer.area_weight, epsilon);
      });
      return entry;
    }



    /** A forcing (OuterEnergy::forcing, the biharmonic model). */
    ModelTermEntry
    forcing_entry()
    {
      ModelTermEntry entry;
      entry.name    = "forcing";
      entry.present = [](const OuterEnergy &outer) {
        return outer.forcing != nullptr;
      };
      entry.set_factory([](const OuterEnergy &outer,
                           const auto &,
                           const double tau,
                           const double epsilon) {
        return std::unique_ptr<EnergyTerm>(
          std::make_unique<ForcingEnergyTerm>(*outer.forcing, tau / epsilon));
      });
      return entry;
    }



    /**
     * A model property of the outer energy without an EnergyTerm, present
     * where @p present says so.
     */
    ModelTermEntry
    property_entry(const std::string                       &name,
                   std::function<bool(const OuterEnergy &)> present)
    {
      ModelTermEntry entry;
      entry.name    = name;
      entry.present = std::move(present);
      return entry;
    }



    /**
     * The built-in terms in the order of the documentation of `Time
     * stepping / Scheme`. Energy terms: the area term and the forcing.
     * Model properties, which a scheme takes in its own code: fixed U
     * values (a constraint, NestedPhysics::zero_fixed_u()), the biharmonic
     * model (no double well, a setting of the scheme), a Willmore weight
     * mu != 1 (the weight of the Willmore term, part of the nested step
     * itself) and the data term (OuterEnergy::data_term, shape from
     * contour's mismatch: the step takes its Gauss-Newton model through
     * make_data_term() and judges the step by the term itself, which
     * needs a path of its own). Last the volume and area constraints
     * (constraints.h), an energy term whose multipliers the nested scheme
     * solves for (ConstrainedNestedStep).
     */
    std::vector<ModelTermEntry>
    built_in_terms()
    {
      return {area_entry(),
              property_entry("fixed values",
                             [](const OuterEnergy &outer) {
                               return outer.fixed_u != nullptr;
                             }),
              forcing_entry(),
              property_entry("biharmonic model", {}),
              property_entry("Willmore weight",
                             [](const OuterEnergy &outer) {
                               return outer.willmore_weight != 1;
                             }),
              property_entry("mismatch term",
                             [](const OuterEnergy &outer) {
                               return outer.data_term != nullptr;
                             }),
              constraints_entry()};
    }



    /** The registered terms, built-in ones first. */
    std::vector<ModelTermEntry> &
    registry()
    {
      static std::vector<ModelTermEntry> entries = built_in_terms();
      return entries;
    }



    template <int dim>
    const EnergyTermFactory<dim> &
    factory(const ModelTermEntry &entry);

    template <>
    const EnergyTermFactory<2> &
    factory<2>(const ModelTermEntry &entry)
    {
      return entry.create_2d;
    }

    template <>
    const EnergyTermFactory<3> &
    factory<3>(const ModelTermEntry &entry)
    {
      return entry.create_3d;
    }



    template <int dim>
    const TermStatistics<dim> &
    statistics(const ModelTermEntry &entry);

    template <>
    const TermStatistics<2> &
    statistics<2>(const ModelTermEntry &entry)
    {
      return entry.statistics_2d;
    }

    template <>
    const TermStatistics<3> &
    statistics<3>(const ModelTermEntry &entry)
    {
      return entry.statistics_3d;
    }


    template <int dim>
    const TermEnergy<dim> &
    energy(const ModelTermEntry &entry);

    template <>
    const TermEnergy<2> &
    energy<2>(const ModelTermEntry &entry)
    {
      return entry.energy_2d;
    }

    template <>
    const TermEnergy<3> &
    energy<3>(const ModelTermEntry &entry)
    {
      return entry.energy_3d;
    }
  } // namespace



  void
  register_model_term(const ModelTermEntry &entry)
  {
    for (const ModelTermEntry &existing : registry())
      AssertThrow(existing.name != entry.name,
                  ExcMessage("The model term <" + entry.name +
                             "> is registered already."));
    AssertThrow(!entry.name.empty() &&
                  bool(entry.create_2d) == bool(entry.create_3d) &&
                  bool(entry.statistics_2d) == bool(entry.statistics_3d) &&
                  bool(entry.energy_2d) == bool(entry.energy_3d) &&
                  (entry.statistics_columns.empty() || entry.statistics_2d),
                ExcMessage("A model term entry needs a name, and factories "
                           "and statistics in 2D and 3D or in neither."));
    registry().push_back(entry);
  }



  const std::vector<ModelTermEntry> &
  registered_model_terms()
  {
    return registry();
  }



  bool
  is_present(const ModelTermEntry &entry, const OuterEnergy &outer)
  {
    return entry.present ? entry.present(outer) :
                           outer.registered_terms.count(entry.name) > 0;
  }



  template <int dim>
  std::vector<std::unique_ptr<EnergyTerm>>
  make_outer_energy_terms(const OuterEnergy          &outer,
                          const LumpedOperators<dim> &operators,
                          const double                tau,
                          const double                epsilon)
  {
    std::vector<std::unique_ptr<EnergyTerm>> terms;
    for (const ModelTermEntry &entry : registered_model_terms())
      if (factory<dim>(entry) && is_present(entry, outer))
        terms.push_back(factory<dim>(entry)(outer, operators, tau, epsilon));
    return terms;
  }



  std::vector<std::string>
  energy_term_columns(const OuterEnergy &outer)
  {
    std::vector<std::string> columns;
    for (const ModelTermEntry &entry : registered_model_terms())
      if (is_present(entry, outer))
        columns.insert(columns.end(),
                       entry.statistics_columns.begin(),
                       entry.statistics_columns.end());
    return columns;
  }



  template <int dim>
  double
  registered_terms_energy(const OuterEnergy          &outer,
                          const LumpedOperators<dim> &operators,
                          const Vector               &u)
  {
    double sum = 0;
    for (const ModelTermEntry &entry : registered_model_terms())
      if (energy<dim>(entry) && is_present(entry, outer))
        sum += energy<dim>(entry)(outer, operators, u);
    return sum;
  }



  template <int dim>
  std::vector<double>
  energy_term_values(const OuterEnergy          &outer,
                     const LumpedOperators<dim> &operators,
                     const Vector               &u)
  {
    std::vector<double> values;
    for (const ModelTermEntry &entry : registered_model_terms())
      if (statistics<dim>(entry) && is_present(entry, outer))
        {
          const std::vector<double> term_values =
            statistics<dim>(entry)(outer, operators, u);
          AssertThrow(term_values.size() == entry.statistics_columns.size(),
                      ExcMessage("The model term <" + entry.name +
                                 "> has another number of statistics "
                                 "values than columns."));
          values.insert(values.end(), term_values.begin(), term_values.end());
        }
    return values;
  }



  template std::vector<std::unique_ptr<EnergyTerm>>
  make_outer_energy_terms(const OuterEnergy &,
                          const LumpedOperators<2> &,
                          const double,
                          const double);
  template std::vector<std::unique_ptr<EnergyTerm>>
  make_outer_energy_terms(const OuterEnergy &,
                          const LumpedOperators<3> &,
                          const double,
                          const double);
  template double
  registered_terms_energy(const OuterEnergy &,
                          const LumpedOperators<2> &,
                          const Vector &);
  template double
  registered_terms_energy(const OuterEnergy &,
                          const LumpedOperators<3> &,
                          const Vector &);
  template std::vector<double>
  energy_term_values(const OuterEnergy &,
                     const LumpedOperators<2> &,
                     const Vector &);
  template std::vector<double>
  energy_term_values(const OuterEnergy &,
                     const LumpedOperators<3> &,
                     const Vector &);
} // namespace PhaseField
