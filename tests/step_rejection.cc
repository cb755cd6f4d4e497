// TimeLoop rejects a converged step whose result jumped to another branch
// and retries it with half the time step (issue 52 item 6): two toy schemes,
// registered as the recipe of doc/architecture.md says, take a step of
// size tau to U unchanged if tau <= 0.3 Tau and otherwise to another state:
// - "toy vanish": U = 1 everywhere (the inside measure drops to 0: the
//   augmented Lagrangian's level-6 cube), rejected by `Time stepping /
//   Largest inside change factor`;
// - "toy rise": U / 2 (the area energy rises, the inside measure grows by
//   less than the factor 4), and the toy has an energy law with the area as
//   its energy and no dissipation, so the step breaks it.
// Both steps are taken at Tau / 4 after two halvings (columns tau and
// step_halvings, the inside measure unchanged), and the messages name the
// reason. With the factor 0 the vanishing step is taken at Tau (inside
// measure 0). A scheme whose jumps were not rejected, or that halved
// converged steps for another reason, gives other rows.

#include "scalar_test_scheme.h"
#include "tests.h"

#include <iostream>
#include <phasefield/schemes/energies.h>
#include <phasefield/schemes/scheme_registry.h>
#include <phasefield/schemes/time_stepping_scheme.h>
#include <sstream>

namespace
{
  using namespace PhaseField;

  /** Steps of size tau above this (0.3 Tau of the run below) jump. */
  constexpr double jump_limit = 3e-4;

  /**
   * A scheme whose step keeps U for small steps and jumps to another state
   * (vanish: U = 1; otherwise U / 2 with an energy law of the area) for
   * large ones.
   */
  template <int dim, bool vanish>
  class JumpingToy : public Testing::ScalarTestScheme<dim>
  {
  public:
    JumpingToy(const SchemeSettings             &settings,
               const Discretization<dim>        &discretization,
               const dealii::ConditionalOStream &pcout)
      : Testing::ScalarTestScheme<dim>(settings, discretization)
    {
      (void)pcout;
    }

    std::string
    name() const override
    {
      return vanish ? "toy vanish" : "toy rise";
    }

    StepReport
    advance(const BlockVector &old_state,
            BlockVector       &state,
            const double       tau) override
    {
      state = old_state;
      if (tau > jump_limit)
        {
          if (vanish)
            state.block(0) = 1.;
          else
            state.block(0) *= 0.5;
        }
      this->discretization.distribute_constraints(state);
      StepReport report;
      report.converged = true;
      return report;
    }

    bool
    has_energy_law() const override
    {
      return !vanish;
    }

    double
    energy_law_energy(const Energies &energies) const override
    {
      return energies.area;
    }
  };

  template <int dim>
  using VanishingToy = JumpingToy<dim, true>;
  template <int dim>
  using RisingToy = JumpingToy<dim, false>;

  template <template <int> class Scheme>
  SchemeEntry
  entry(const std::string &name)
  {
    SchemeEntry e;
    e.name        = name;
    e.description = "a step that jumps for large tau (a test of TimeLoop).";
    e.set_factory<Scheme>();
    return e;
  }

  /**
   * Run @p scheme for one step of a circle with the inside change factor
   * @p factor; log the row of step 1 and whether the printed output holds
   * @p message.
   */
  void
  run(const std::string &scheme,
      const std::string &factor,
      const std::string &message)
  {
    std::ostringstream       printed;
    std::streambuf          *cout_buffer = std::cout.rdbuf(printed.rdbuf());
    std::vector<std::string> header;
    const auto rows = Testing::run_willmore(R"(
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
  set Scheme = )" + scheme + R"(
  set Tau = 0.001
  set Number of steps = 1
  set Largest inside change factor = )" + factor +
                                              R"(
end
subsection Newton
  set Maximum step halvings = 2
end
subsection Output
  set VTU interval = 0
end
)",
                                            header);
    std::cout.rdbuf(cout_buffer);
    const auto &step1 = rows.back();
    const auto  value = [&](const std::string &name) {
      return step1[Testing::column(header, name)];
    };
    const double inside_0 =
      rows.front()[Testing::column(header, "inside_measure")];
    Testing::log()
      << scheme << ", factor " << factor << ": step 1 tau " << value("tau")
      << ", step_halvings " << value("step_halvings") << ", inside measure "
      << (value("inside_measure") == inside_0 ? "unchanged" : "changed")
      << ", message \"" << message << "\": "
      << (printed.str().find(message) != std::string::npos ? "yes" : "NO")
      << std::endl;
  }
} // namespace



int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  register_scheme(entry<VanishingToy>("toy vanish"));
  register_scheme(entry<RisingToy>("toy rise"));
  run("toy vanish",
      "4",
      "by more than the factor <Time stepping / Largest inside change "
      "factor> = 4 (the solver jumped to another branch), retrying with "
      "half the time step, tau = 0.0005");
  run("toy rise",
      "4",
      "energy + dissipation exceeds the energy before the step by");
  run("toy vanish", "0", "step    1");
}
