// doc/architecture.md, "Adding an operator backend", followed literally in
// one file: a toy backend whose stiffness operator wraps the assembled one
// (TrilinosStiffness) and counts its products, registered with
// register_operator_backend() (the registry's registration function) and
// run by willmore_flow's problem class with `Linear solver / Type = toy`
// for 2 steps of the nested scheme on a circle on a small 2D mesh. Nothing
// in the library knows the toy. The output fails if the toy is not in the
// documentation of `Linear solver / Type`, if `Type = toy` does not resolve
// to the iterative solver on the toy, if the toy's L is not used, or if the
// run's energies and iteration counts differ from `Type = iterative`'s.

#include "tests.h"

#include <phasefield/mesh/operator_backend.h>
#include <phasefield/schemes/scheme_registry.h>
#include <sstream>

namespace
{
  using namespace PhaseField;

  /** Products with the toy's L on this rank. */
  unsigned int n_products = 0;

  /**
   * Step 1 of the recipe: the stiffness operator, here the assembled one
   * behind a wrapper that counts its products.
   */
  class ToyStiffness : public StiffnessOperator
  {
  public:
    explicit ToyStiffness(std::shared_ptr<StiffnessOperator> assembled)
      : assembled(std::move(assembled))
    {}

    void
    vmult(Vector &dst, const Vector &src) const override
    {
      ++n_products;
      assembled->vmult(dst, src);
    }

    void
    diagonal(Vector &diagonal) const override
    {
      assembled->diagonal(diagonal);
    }

    void
    shift(const double                       factor,
          Vector                            &diagonal,
          std::unique_ptr<ShiftedStiffness> &op) const override
    {
      assembled->shift(factor, diagonal, op);
    }

    std::size_t
    memory_consumption() const override
    {
      return assembled->memory_consumption();
    }

  private:
    const std::shared_ptr<StiffnessOperator> assembled;
  };

  /** Step 2 of the recipe: the factory, in 2D and 3D. */
  template <int dim>
  struct ToyFactory
  {
    static std::shared_ptr<StiffnessOperator>
    make(const StiffnessSetup<dim> &setup)
    {
      return std::make_shared<ToyStiffness>(
        operator_backend(OperatorBackendNames::assembled)
          .make_stiffness<dim>()(setup));
    }
  };

  /** Step 3 of the recipe: the toy's registry entry. */
  OperatorBackendEntry
  toy_entry()
  {
    OperatorBackendEntry entry;
    entry.name          = "toy";
    entry.documentation = "the assembled operator behind a counter (a test "
                          "of the operator backend registry)";
    entry.solver_description         = "toy (CG + AMG)";
    entry.preconditioner_description = "algebraic multigrid";
    entry.set_factory<ToyFactory>();
    return entry;
  }

  /** Is the toy's documentation part of `Linear solver / Type`'s? */
  bool
  documented()
  {
    dealii::ParameterHandler prm;
    WillmoreFlowParameters::declare_parameters(prm);
    std::ostringstream help;
    prm.print_parameters(help, dealii::ParameterHandler::JSON);
    return help.str().find("toy: the assembled operator behind a counter "
                           "(a test of the operator backend registry);") !=
           std::string::npos;
  }

  /** The statistics of 2 nested steps with `Linear solver / Type`. */
  std::vector<std::vector<double>>
  run(const std::string &type, std::vector<std::string> &header)
  {
    return Testing::run_willmore(R"(
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
  set Number of steps = 2
end
subsection Linear solver
  set Type = )" + type + R"(
end
subsection Output
  set VTU interval = 0
end
)",
                                 header);
  }
} // namespace



int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  register_operator_backend(toy_entry());
  Testing::log() << "toy documented in Linear solver / Type: "
                 << (documented() ? "yes" : "NO") << std::endl;
  LinearSolverParameters parameters;
  parameters.type           = "toy";
  const SolverChoice choice = resolve_solver_choice(parameters, "nested", 2);
  Testing::log() << "Type = toy resolves to: "
                 << (choice.type == LinearSolverType::iterative ? "iterative" :
                                                                  "direct")
                 << " on " << choice.backend << std::endl;

  std::vector<std::string> header, toy_header;
  const auto               assembled = run("iterative", header);
  const unsigned int       before    = n_products;
  const auto               toy       = run("toy", toy_header);
  Testing::log() << "toy's L applied: "
                 << (dealii::Utilities::MPI::min(n_products - before,
                                                 MPI_COMM_WORLD) > 0 ?
                       "yes" :
                       "NO")
                 << std::endl;
  const double difference =
    Testing::max_relative_difference({header, assembled, {}},
                                     {toy_header, toy, {}});
  Testing::log() << "statistics as with Type = iterative: "
                 << (difference == 0 ? "yes" : "NO") << std::endl;
  const int energy = Testing::column(header, "willmore_energy");
  for (const auto &row : toy)
    Testing::log() << "step " << row[0] << ": Willmore energy " << row[energy]
                   << std::endl;
}
