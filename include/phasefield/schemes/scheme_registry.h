#ifndef phasefield_schemes_scheme_registry_h
#define phasefield_schemes_scheme_registry_h

#include <any>
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>
#include <functional>
#include <memory>
#include <phasefield/core/parameters.h>
#include <phasefield/mesh/discretization.h>
#include <phasefield/schemes/time_stepping_scheme.h>
#include <set>
#include <string>
#include <vector>

/**
 * The scheme registry: one SchemeEntry per time-stepping scheme, with its
 * name (the value of `Time stepping / Scheme`), its documentation, the
 * model terms it takes, its own parameters and its factory. The built-in
 * schemes are listed in source/schemes/scheme_registry.cc; a test adds
 * its own with register_scheme(). The programs declare and parse the
 * scheme choice with declare_scheme_parameters() and
 * parse_scheme_parameters(), and make schemes with
 * create_time_stepping_scheme(); nothing else chooses between schemes.
 */
namespace PhaseField
{
  /**
   * Terms of a model beyond the Willmore flow of the Allen-Cahn phase
   * field, by the names of their entries in the registry of model terms
   * (energy_term_registry.h, e.g. "area term", "fixed values"): what a
   * scheme takes (SchemeEntry::terms) or what a problem needs. The
   * registry checks the one against the other, in check_scheme_terms()
   * only.
   */
  class ModelTerms
  {
  public:
    /**
     * Every registered term, also those registered later: a scheme that
     * adds the terms of make_outer_energy_terms() to its step takes every
     * energy term.
     */
    static ModelTerms
    all();

    /** The terms that a scheme with @p settings must take. */
    static ModelTerms
    needed_by(const SchemeSettings &settings);

    /** Add the registered term @p name. */
    ModelTerms &
    with(const std::string &name);

    /** Remove the registered term @p name. */
    ModelTerms &
    without(const std::string &name);

    /** Is the term @p name here? */
    bool
    has(const std::string &name) const;

    /**
     * The names of the terms set here and not in @p offered, e.g.
     * "fixed values" (empty if @p offered has them all), in the order of
     * registration.
     */
    std::vector<std::string>
    missing_in(const ModelTerms &offered) const;

  private:
    /** Every term but those of names (all()), or those of names only. */
    bool every = false;
    /** The terms set, or with every those not set. */
    std::set<std::string> names;
  };

  /** Makes a scheme of dimension @p dim (SchemeEntry::set_factory()). */
  template <int dim>
  using SchemeFactory = std::function<std::unique_ptr<TimeSteppingScheme<dim>>(
    const SchemeSettings &,
    const Discretization<dim> &,
    const dealii::ConditionalOStream &)>;

  /** One time-stepping scheme as the parameters and the problems see it. */
  struct SchemeEntry
  {
    /** The value of `Time stepping / Scheme`, e.g. "nested". */
    std::string name;
    /**
     * The user documentation: it becomes, after the name, part of the
     * documentation of `Time stepping / Scheme` in `--help`.
     */
    std::string description;
    /** The model terms that the scheme takes. */
    ModelTerms terms;
    /**
     * Does the scheme run on the matrix-free backend (it only applies the
     * stiffness operator and solves with its shifted operators)? `Linear
     * solver / Type` = auto chooses that backend in 3D for such a scheme
     * (resolve_solver_choice()). A scheme that leaves it false gets the
     * assembled backend under auto.
     */
    bool matrix_free = false;
    /** Declares the scheme's own subsection (empty: it has none). */
    std::function<void(dealii::ParameterHandler &)> declare_parameters;
    /**
     * Parses the scheme's own subsection into the value that
     * SchemeSettings::own_parameters() returns (empty: none).
     */
    std::function<std::any(dealii::ParameterHandler &)> parse_parameters;
    /** The factories in 2D and 3D. */
    SchemeFactory<2> create_2d;
    SchemeFactory<3> create_3d;

    /**
     * The factories make SchemeType<dim>(settings, discretization, pcout):
     * the constructor of every scheme.
     */
    template <template <int> class SchemeType>
    void
    set_factory()
    {
      create_2d = [](const SchemeSettings             &settings,
                     const Discretization<2>          &discretization,
                     const dealii::ConditionalOStream &pcout) {
        return std::make_unique<SchemeType<2>>(settings, discretization, pcout);
      };
      create_3d = [](const SchemeSettings             &settings,
                     const Discretization<3>          &discretization,
                     const dealii::ConditionalOStream &pcout) {
        return std::make_unique<SchemeType<3>>(settings, discretization, pcout);
      };
    }

    /**
     * The scheme owns the subsection of @p Parameters: its static
     * declare_parameters(prm) and its parse_parameters(prm) on a default
     * object, whose result the scheme reads with
     * SchemeSettings::own_parameters<Parameters>().
     */
    template <typename Parameters>
    void
    set_parameters()
    {
      declare_parameters = &Parameters::declare_parameters;
      parse_parameters   = [](dealii::ParameterHandler &prm) {
        Parameters parameters;
        parameters.parse_parameters(prm);
        return std::any(parameters);
      };
    }
  };

  /**
   * Add @p entry to the registry, after the built-in schemes, before the
   * parameters are declared. Its name must be new.
   */
  void
  register_scheme(const SchemeEntry &entry);

  /** All schemes, the built-in ones first, in the order of registration. */
  const std::vector<SchemeEntry> &
  registered_schemes();

  /** The scheme @p name; InputError if there is none. */
  const SchemeEntry &
  scheme_entry(const std::string &name);

  /**
   * Declare `Time stepping / Scheme` (every registered name, the first
   * one the default, documented by the descriptions and terms of all) and
   * the schemes' own subsections.
   */
  void
  declare_scheme_parameters(dealii::ParameterHandler &prm);

  /**
   * Read `Time stepping / Scheme` and the chosen scheme's own subsection;
   * check_scheme_terms() with @p needed and @p program first.
   */
  SchemeChoice
  parse_scheme_parameters(dealii::ParameterHandler &prm,
                          const ModelTerms         &needed  = ModelTerms(),
                          const std::string        &program = "");

  /**
   * Throw an InputError if the scheme @p name does not take every term of
   * @p needed (that @p program needs, if not empty); the message names the
   * missing terms and the schemes that take them all.
   */
  void
  check_scheme_terms(const std::string &name,
                     const ModelTerms  &needed,
                     const std::string &program = "");

  /**
   * The one place that resolves `Linear solver / Type` (@p solver) for the
   * scheme @p scheme in dimension @p dim: direct is MUMPS on the assembled
   * backend; the name of an operator backend is the iterative solver on
   * it; auto is direct in 2D, and in 3D iterative on the matrix-free
   * backend if the scheme runs on it (SchemeEntry::matrix_free) and the
   * boundary conditions are not periodic (@p periodic), on the assembled
   * one otherwise. The measurements behind the choice: doc/benchmarks.md,
   * "3D linear solver: iterative against matrix-free".
   */
  SolverChoice
  resolve_solver_choice(const LinearSolverParameters &solver,
                        const std::string            &scheme,
                        const int                     dim,
                        const bool                    periodic = false);

  /**
   * The scheme @p settings.scheme on @p discretization, which must outlive
   * it. Throws InputError (check_scheme_terms()) if it does not take the
   * terms of @p settings (ModelTerms::needed_by()).
   */
  template <int dim>
  std::unique_ptr<TimeSteppingScheme<dim>>
  create_time_stepping_scheme(const SchemeSettings             &settings,
                              const Discretization<dim>        &discretization,
                              const dealii::ConditionalOStream &pcout);
} // namespace PhaseField

#endif
