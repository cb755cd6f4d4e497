#ifndef phasefield_schemes_energy_term_registry_h
#define phasefield_schemes_energy_term_registry_h

#include <functional>
#include <memory>
#include <phasefield/core/linear_algebra.h>
#include <phasefield/mesh/lumped_operators.h>
#include <phasefield/schemes/energy_terms.h>
#include <phasefield/schemes/outer_energy.h>
#include <string>
#include <vector>

/**
 * The registry of model terms: one ModelTermEntry per term beyond the
 * Willmore flow of the Allen-Cahn phase field, with its name (in the
 * messages of the scheme registry and the documentation of `Time stepping /
 * Scheme`), when a model has it, and, for an energy term, the factory of
 * its EnergyTerm for a step and its statistics columns. The built-in
 * entries are listed in source/schemes/energy_term_registry.cc; a new term
 * adds its own with register_model_term() (doc/architecture.md, "Adding an
 * energy term"). ModelTerms (scheme_registry.h), make_outer_energy_terms()
 * and the time loop's statistics columns read this list only.
 */
namespace PhaseField
{
  /**
   * Makes the EnergyTerm of a model term for a step of size tau of the
   * outer energy in the units of the nested step's residual (the outer
   * energy divided by 2 eps): (outer, operators, tau, epsilon).
   */
  template <int dim>
  using EnergyTermFactory =
    std::function<std::unique_ptr<EnergyTerm>(const OuterEnergy &,
                                              const LumpedOperators<dim> &,
                                              const double,
                                              const double)>;

  /**
   * The values of a term's statistics columns at the phase field U:
   * (outer, operators, U).
   */
  template <int dim>
  using TermStatistics =
    std::function<std::vector<double>(const OuterEnergy &,
                                      const LumpedOperators<dim> &,
                                      const Vector &)>;

  /**
   * The value of a term in the energy law at the phase field U in the
   * units of Energies::data_term: (outer, operators, U).
   */
  template <int dim>
  using TermEnergy = std::function<
    double(const OuterEnergy &, const LumpedOperators<dim> &, const Vector &)>;

  /**
   * One model term. An energy term has factories (the nested step and the
   * augmented Lagrangian add its value, gradient and Hessian product); a
   * model property (fixed U values, no double well, a Willmore weight
   * mu != 1) or a term that the schemes take by a path of their own (the
   * data term, OuterEnergy::data_term) has none: the schemes that take it
   * do so in their own code.
   */
  struct ModelTermEntry
  {
    /** The name in messages and docs, e.g. "area term". */
    std::string name;
    /**
     * Does a model with the outer energy @p outer have the term? Empty for
     * the biharmonic model, a setting of the scheme
     * (SchemeSettings::double_well = false; ModelTerms::needed_by()), and,
     * for a term registered with register_model_term(): its name is in
     * OuterEnergy::registered_terms.
     */
    std::function<bool(const OuterEnergy &)> present;
    /** The factories in 2D and 3D (empty: no EnergyTerm of its own). */
    EnergyTermFactory<2> create_2d;
    EnergyTermFactory<3> create_3d;
    /**
     * Its columns in statistics.csv, written when the term is present,
     * after the columns of the time loop and the scheme and before those
     * of the problem.
     */
    std::vector<std::string> statistics_columns;
    /** The values of statistics_columns. */
    TermStatistics<2> statistics_2d;
    TermStatistics<3> statistics_3d;
    /**
     * The term's value T in the energy law of the nested step, in thesis
     * units (a step of size tau minimises eps ||U-U^k||^2 + 2 tau (... +
     * T), Energies::registered_terms); empty for the built-in terms, which
     * enter it by weighted_regularisation() or not at all.
     */
    TermEnergy<2> energy_2d;
    TermEnergy<3> energy_3d;

    /**
     * The factories are @p factory, a generic lambda (outer, operators,
     * tau, epsilon) -> std::unique_ptr<EnergyTerm>.
     */
    template <typename Factory>
    void
    set_factory(const Factory &factory)
    {
      create_2d = factory;
      create_3d = factory;
    }

    /**
     * The statistics columns @p columns with the values @p values, a
     * generic lambda (outer, operators, U) -> std::vector<double>.
     */
    template <typename Values>
    void
    set_statistics(const std::vector<std::string> &columns,
                   const Values                   &values)
    {
      statistics_columns = columns;
      statistics_2d      = values;
      statistics_3d      = values;
    }

    /**
     * The value in the energy law is @p energy, a generic lambda (outer,
     * operators, U) -> double.
     */
    template <typename Energy>
    void
    set_energy(const Energy &energy)
    {
      energy_2d = energy;
      energy_3d = energy;
    }
  };

  /**
   * Add @p entry after the registered terms, before the parameters are
   * declared and any scheme is made. Its name must be new; without a
   * present() of its own, it is present where OuterEnergy::registered_terms
   * has its name.
   */
  void
  register_model_term(const ModelTermEntry &entry);

  /** All terms, the built-in ones first, in the order of registration. */
  const std::vector<ModelTermEntry> &
  registered_model_terms();

  /** Does @p outer have the term @p entry? */
  bool
  is_present(const ModelTermEntry &entry, const OuterEnergy &outer);

  /**
   * The terms of @p outer with factories, for a step of size @p tau, in
   * the order of registration (the area term with s = tau eta and the
   * forcing with s = tau / eps where their weights are set), in the units
   * of the nested step's residual.
   */
  template <int dim>
  std::vector<std::unique_ptr<EnergyTerm>>
  make_outer_energy_terms(const OuterEnergy          &outer,
                          const LumpedOperators<dim> &operators,
                          const double                tau,
                          const double                epsilon);

  /** The statistics columns of the terms that @p outer has. */
  std::vector<std::string>
  energy_term_columns(const OuterEnergy &outer);

  /**
   * The sum of the energy-law values (ModelTermEntry::energy_2d) of the
   * terms that @p outer has at the phase field @p u.
   */
  template <int dim>
  double
  registered_terms_energy(const OuterEnergy          &outer,
                          const LumpedOperators<dim> &operators,
                          const Vector               &u);

  /** The values of energy_term_columns() at the phase field @p u. */
  template <int dim>
  std::vector<double>
  energy_term_values(const OuterEnergy          &outer,
                     const LumpedOperators<dim> &operators,
                     const Vector               &u);
} // namespace PhaseField

#endif
