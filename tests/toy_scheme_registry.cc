// doc/architecture.md, "How to add a scheme", followed literally in one
// file: a toy scheme with parameters and a statistics column of its own,
// registered with register_scheme() (the registry's registration
// function) and run by willmore_flow's problem class with `Time stepping /
// Scheme = toy` for 2 steps of a circle on a small 2D mesh. Nothing in the
// library knows the toy. A step of the toy is `Sweeps` explicit steps of
// the double well's reaction, U <- U + r U (1 - U^2) at every node (r =
// `Rate`), which sharpens the profile: the area energy changes. The output
// fails if the toy is not used (no toy_sweeps column, or not the value of
// its own parameter), if its description is not in the documentation of
// `Time stepping / Scheme`, or if the registry does not check its terms.

#include "scalar_test_scheme.h"
#include "tests.h"

#include <phasefield/schemes/energies.h>
#include <phasefield/schemes/scheme_registry.h>
#include <phasefield/schemes/time_stepping_scheme.h>
#include <sstream>

namespace
{
  using namespace PhaseField;

  /** Step 3 of the recipe: the toy's own subsection `Toy scheme`. */
  struct ToyParameters
  {
    /** Reaction steps per time step. */
    unsigned int sweeps = 1;
    /** r of U <- U + r U (1 - U^2); r <= 1/2 keeps U in [-1, 1]. */
    double rate = 0.25;

    static void
    declare_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Toy scheme");
      prm.declare_entry("Sweeps",
                        "1",
                        dealii::Patterns::Integer(1),
                        "Reaction steps per time step.");
      prm.declare_entry("Rate",
                        "0.25",
                        dealii::Patterns::Double(0, 0.5),
                        "r of U <- U + r U (1 - U^2).");
      prm.leave_subsection();
    }

    void
    parse_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Toy scheme");
      sweeps = prm.get_integer("Sweeps");
      rate   = prm.get_double("Rate");
      prm.leave_subsection();
    }
  };

  /**
   * Step 1 of the recipe: the scheme class. Its state is U alone, and the
   * pure virtual functions that a scheme of U alone without a solver
   * implements the same way come from Testing::ScalarTestScheme; a step
   * is ToyParameters::sweeps reaction steps (step 4: counted in its own
   * column toy_sweeps).
   */
  template <int dim>
  class ToyScheme : public Testing::ScalarTestScheme<dim>
  {
  public:
    ToyScheme(const SchemeSettings             &settings,
              const Discretization<dim>        &discretization,
              const dealii::ConditionalOStream &pcout)
      : Testing::ScalarTestScheme<dim>(settings, discretization)
      , parameters(settings.own_parameters<ToyParameters>())
    {
      (void)pcout;
    }

    std::string
    name() const override
    {
      return "toy";
    }

    StepReport
    advance(const BlockVector &old_state,
            BlockVector       &state,
            const double       tau) override
    {
      (void)tau;
      state = old_state;
      for (unsigned int sweep = 0; sweep < parameters.sweeps; ++sweep)
        for (double &u : state.block(0))
          u += parameters.rate * u * (1 - u * u);
      this->discretization.distribute_constraints(state);
      StepReport report;
      report.converged = true;
      report.add_count("toy_sweeps", parameters.sweeps);
      return report;
    }

    std::vector<std::string>
    statistics_columns() const override
    {
      std::vector<std::string> columns =
        TimeSteppingScheme<dim>::statistics_columns();
      columns.emplace_back("toy_sweeps");
      return columns;
    }

  private:
    const ToyParameters parameters;
  };

  /** Step 5 of the recipe: the toy's registry entry. */
  SchemeEntry
  toy_entry()
  {
    SchemeEntry entry;
    entry.name        = "toy";
    entry.description = "explicit steps of the double well's reaction (a "
                        "test of the scheme registry).";
    entry.set_factory<ToyScheme>();
    entry.set_parameters<ToyParameters>();
    return entry;
  }

  /** Is the toy's description part of the doc of `Time stepping / Scheme`? */
  bool
  documented()
  {
    dealii::ParameterHandler prm;
    WillmoreFlowParameters::declare_parameters(prm);
    std::ostringstream help;
    prm.print_parameters(help, dealii::ParameterHandler::JSON);
    return help.str().find("toy: explicit steps of the double well's "
                           "reaction (a test of the scheme registry). "
                           "[none]") != std::string::npos;
  }

  /** The InputError of a toy run that needs a term the toy does not take. */
  std::string
  terms_message()
  {
    const ModelTerms needed = ModelTerms().with("fixed values");
    try
      {
        check_scheme_terms("toy", needed, "this test");
      }
    catch (const InputError &error)
      {
        return error.what();
      }
    return "no error";
  }
} // namespace



int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  register_scheme(toy_entry());
  Testing::log() << "toy documented in Time stepping / Scheme: "
                 << (documented() ? "yes" : "NO") << std::endl;
  Testing::log() << terms_message() << std::endl;

  std::vector<std::string> header;
  const auto               rows   = Testing::run_willmore(R"(
set Dimension = 2
subsection Geometry
  set Shape = circle
  set Radius = 0.3
end
subsection Mesh
  set Finest level = 5
  set Coarsest level = 3
end
subsection Time stepping
  set Scheme = toy
  set Number of steps = 2
end
subsection Toy scheme
  set Sweeps = 3
end
subsection Output
  set VTU interval = 0
end
)",
                                          header);
  const int                sweeps = Testing::column(header, "toy_sweeps");
  Testing::log() << "toy_sweeps column: " << (sweeps >= 0 ? "yes" : "NO")
                 << std::endl;
  const int area = Testing::column(header, "area_energy");
  for (const auto &row : rows)
    Testing::log() << "step " << row[0] << ": toy_sweeps "
                   << (sweeps >= 0 ? row[sweeps] : -1) << ", area energy "
                   << (row[area] != rows[0][area] ? "changed" : "as at step 0")
                   << std::endl;
}
