#include <phasefield/schemes/augmented_lagrangian_parameters.h>
#include <phasefield/schemes/augmented_lagrangian_scheme.h>
#include <phasefield/schemes/constraints.h>
#include <phasefield/schemes/energy_term_registry.h>
#include <phasefield/schemes/nested_scheme.h>
#include <phasefield/schemes/scheme_registry.h>
#include <phasefield/schemes/semi_implicit_scheme.h>
#include <utility>

namespace PhaseField
{
  using namespace dealii;

  namespace
  {
    // ---------------------------------------------------------------------
    // The built-in schemes: one entry each, listed in built_in_schemes().
    // ---------------------------------------------------------------------

    SchemeEntry
    nested_entry()
    {
      SchemeEntry entry;
      entry.name = "nested";
      entry.description =
        "the nested variational time discretization (thesis chapter 3), "
        "Newton on the (U,V,P) saddle-point system.";
      entry.terms       = ModelTerms::all();
      entry.matrix_free = true;
      entry.set_factory<NestedScheme>();
      return entry;
    }



    SchemeEntry
    semi_implicit_entry()
    {
      SchemeEntry entry;
      entry.name = "semi-implicit";
      entry.description =
        "the Du-Liu-Wang scheme (thesis section 5.2), Newton on (U,F) with "
        "F = eps Lap U + (2/eps) U(1-U^2); it does not use Inner tau.";
      entry.set_factory<SemiImplicitScheme>();
      return entry;
    }



    SchemeEntry
    augmented_lagrangian_entry()
    {
      SchemeEntry entry;
      entry.name = "augmented lagrangian";
      entry.description =
        "the nested step as the minimisation of an augmented Lagrangian in "
        "(U,V) by a trust-region method (thesis chapter 7; subsection "
        "Augmented Lagrangian).";
      entry.terms = ModelTerms::all()
                      .without("mismatch term")
                      .without(ScalarConstraints::name());
      entry.matrix_free = true;
      entry.set_factory<AugmentedLagrangianScheme>();
      entry.set_parameters<AugmentedLagrangianParameters>();
      return entry;
    }



    /** The built-in schemes, the default (`nested`) first. */
    std::vector<SchemeEntry>
    built_in_schemes()
    {
      return {nested_entry(),
              semi_implicit_entry(),
              augmented_lagrangian_entry()};
    }



    // ---------------------------------------------------------------------
    // The registry
    // ---------------------------------------------------------------------

    /** The registered schemes, built-in ones first. */
    std::vector<SchemeEntry> &
    registry()
    {
      static std::vector<SchemeEntry> entries = built_in_schemes();
      return entries;
    }



    /** "a", "a and b", "a, b and c" with @p last_separator for "and". */
    std::string
    join(const std::vector<std::string> &words,
         const std::string              &separator,
         const std::string              &last_separator)
    {
      std::string text;
      for (unsigned int i = 0; i < words.size(); ++i)
        text += (i == 0                ? "" :
                 i + 1 == words.size() ? last_separator :
                                         separator) +
                words[i];
      return text;
    }



    /** The names of the schemes that take every term of @p needed. */
    std::vector<std::string>
    schemes_taking(const ModelTerms &needed)
    {
      std::vector<std::string> names;
      for (const SchemeEntry &entry : registered_schemes())
        if (needed.missing_in(entry.terms).empty())
          names.push_back(entry.name);
      return names;
    }



    /** The documentation of `Time stepping / Scheme`. */
    std::string
    scheme_documentation()
    {
      std::string text =
        "The time discretization; in brackets the terms beyond Willmore "
        "flow that a scheme takes (a program that needs another one "
        "rejects it).";
      for (const SchemeEntry &entry : registered_schemes())
        {
          std::vector<std::string> taken;
          for (const ModelTermEntry &term : registered_model_terms())
            if (entry.terms.has(term.name))
              taken.push_back(term.name);
          text += " " + entry.name + ": " + entry.description + " [" +
                  (taken.empty() ? "none" : join(taken, ", ", ", ")) + "]";
        }
      return text;
    }



    /** The factory of @p entry in dimension @p dim. */
    template <int dim>
    const SchemeFactory<dim> &
    factory(const SchemeEntry &entry);

    template <>
    const SchemeFactory<2> &
    factory<2>(const SchemeEntry &entry)
    {
      return entry.create_2d;
    }

    template <>
    const SchemeFactory<3> &
    factory<3>(const SchemeEntry &entry)
    {
      return entry.create_3d;
    }
  } // namespace



  ModelTerms
  ModelTerms::all()
  {
    ModelTerms terms;
    terms.every = true;
    return terms;
  }



  ModelTerms
  ModelTerms::needed_by(const SchemeSettings &settings)
  {
    ModelTerms terms;
    for (const ModelTermEntry &entry : registered_model_terms())
      if (is_present(entry, settings.outer_energy))
        terms.with(entry.name);
    if (!settings.double_well)
      terms.with("biharmonic model");
    return terms;
  }



  ModelTerms &
  ModelTerms::with(const std::string &name)
  {
    bool registered = false;
    for (const ModelTermEntry &entry : registered_model_terms())
      registered = registered || entry.name == name;
    AssertThrow(registered,
                ExcMessage("There is no model term <" + name + ">."));
    if (every)
      names.erase(name);
    else
      names.insert(name);
    return *this;
  }



  ModelTerms &
  ModelTerms::without(const std::string &name)
  {
    if (every)
      names.insert(name);
    else
      names.erase(name);
    return *this;
  }



  bool
  ModelTerms::has(const std::string &name) const
  {
    return every != (names.count(name) > 0);
  }



  std::vector<std::string>
  ModelTerms::missing_in(const ModelTerms &offered) const
  {
    std::vector<std::string> missing;
    for (const ModelTermEntry &entry : registered_model_terms())
      if (has(entry.name) && !offered.has(entry.name))
        missing.push_back(entry.name);
    return missing;
  }



  void
  register_scheme(const SchemeEntry &entry)
  {
    for (const SchemeEntry &existing : registry())
      AssertThrow(existing.name != entry.name,
                  ExcMessage("The scheme <" + entry.name +
                             "> is registered already."));
    AssertThrow(!entry.name.empty() && entry.create_2d && entry.create_3d,
                ExcMessage("A scheme entry needs a name and factories."));
    registry().push_back(entry);
  }



  const std::vector<SchemeEntry> &
  registered_schemes()
  {
    return registry();
  }



  const SchemeEntry &
  scheme_entry(const std::string &name)
  {
    std::vector<std::string> names;
    for (const SchemeEntry &entry : registered_schemes())
      {
        if (entry.name == name)
          return entry;
        names.push_back(entry.name);
      }
    throw InputError("Unknown <Time stepping / Scheme> = <" + name +
                     ">; use one of " + join(names, "|", "|") + ".");
  }



  void
  declare_scheme_parameters(ParameterHandler &prm)
  {
    std::vector<std::string> names;
    for (const SchemeEntry &entry : registered_schemes())
      names.push_back(entry.name);
    prm.enter_subsection("Time stepping");
    prm.declare_entry("Scheme",
                      names.front(),
                      Patterns::Selection(join(names, "|", "|")),
                      scheme_documentation());
    prm.leave_subsection();
    for (const SchemeEntry &entry : registered_schemes())
      if (entry.declare_parameters)
        entry.declare_parameters(prm);
  }



  SchemeChoice
  parse_scheme_parameters(ParameterHandler  &prm,
                          const ModelTerms  &needed,
                          const std::string &program)
  {
    SchemeChoice choice;
    prm.enter_subsection("Time stepping");
    choice.name = prm.get("Scheme");
    prm.leave_subsection();
    check_scheme_terms(choice.name, needed, program);
    const SchemeEntry &entry = scheme_entry(choice.name);
    if (entry.parse_parameters)
      choice.parameters = entry.parse_parameters(prm);
    return choice;
  }



  SolverChoice
  resolve_solver_choice(const LinearSolverParameters &solver,
                        const std::string            &scheme,
                        const int                     dim,
                        const bool                    periodic)
  {
    SolverChoice choice;
    if (solver.type == "direct" || (solver.type == "auto" && dim == 2))
      return choice;
    choice.type    = LinearSolverType::iterative;
    choice.backend = solver.type != "auto" ? solver.type :
                     !periodic && scheme_entry(scheme).matrix_free ?
                                             OperatorBackendNames::matrix_free :
                                             OperatorBackendNames::assembled;
    return choice;
  }



  void
  check_scheme_terms(const std::string &name,
                     const ModelTerms  &needed,
                     const std::string &program)
  {
    const std::vector<std::string> missing =
      needed.missing_in(scheme_entry(name).terms);
    if (missing.empty())
      return;
    const std::vector<std::string> alternatives = schemes_taking(needed);
    throw InputError(
      "<Time stepping / Scheme> = " + name + " has no " +
      join(missing, ", no ", " and no ") +
      (program.empty() ? "" : ", which " + program + " needs") + ": " +
      (alternatives.empty() ? "no scheme has all of these." :
                              "use <Time stepping / Scheme> = " +
                                join(alternatives, ", ", " or ") + "."));
  }



  template <int dim>
  std::unique_ptr<TimeSteppingScheme<dim>>
  create_time_stepping_scheme(const SchemeSettings             &settings,
                              const Discretization<dim>        &discretization,
                              const dealii::ConditionalOStream &pcout)
  {
    check_scheme_terms(settings.scheme.name, ModelTerms::needed_by(settings));
    const SchemeEntry &entry = scheme_entry(settings.scheme.name);
    std::unique_ptr<TimeSteppingScheme<dim>> scheme =
      factory<dim>(entry)(settings, discretization, pcout);
    AssertThrow(scheme->name() == entry.name,
                ExcMessage("The scheme registered as <" + entry.name +
                           "> calls itself <" + scheme->name() + ">."));
    return scheme;
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
