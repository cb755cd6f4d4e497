// doc/architecture.md, "Adding an energy term", followed literally in one
// file: a toy energy term T[U] = (s/2) ||U - c||^2_M (lumped mass M) with
// a statistics column of its own, registered with register_model_term()
// (the registry's registration function). Nothing in the library knows
// the toy.
//
// - A nested step (NestedStep, 2D adaptive mesh with hanging nodes) with
//   the toy in its outer energy: R_U agrees with central differences of
//   the step's outer energy, and the Jacobian (the toy's Hessian applied
//   matrix-free) with central differences of R_U; the Newton solve solves
//   it.
// - willmore_flow's problem class with the toy's data in its outer energy
//   for 2 steps of a circle: the toy_energy column is written, the steps
//   converge, T falls from step to step (c = -1, the inside phase, pulls
//   U inwards: the circle grows), and the inside measure grows more than
//   without the term (the column is then absent).

#include "adaptive_test_mesh.h"
#include "tests.h"

#include <phasefield/problems/willmore_problem.h>
#include <phasefield/schemes/energy_term_registry.h>
#include <phasefield/schemes/nested_scheme.h>
#include <phasefield/schemes/scheme_registry.h>

namespace
{
  using namespace PhaseField;

  /** Step 1 of the recipe: the term's name and its data. */
  const std::string toy_name = "toy term";
  struct ToyData
  {
    /** s */
    double weight = 1;
    /** c */
    double target = 1;
  };

  /**
   * Step 2 of the recipe: the term, @p scale T[U] with
   * T[U] = (s/2) ||U - c||^2_M: gradient scale s M (U - c), Hessian
   * scale s M.
   */
  template <int dim>
  class ToyTerm : public EnergyTerm
  {
  public:
    ToyTerm(const LumpedOperators<dim> &operators,
            const ToyData              &data,
            const double                scale)
      : ops(operators)
      , data(data)
      , scale(scale)
    {}

    std::string
    name() const override
    {
      return toy_name;
    }

    double
    value(const Vector &u) const override
    {
      Vector d(u);
      d.add(-data.target);
      return 0.5 * scale * data.weight * ops.mass_product(d, d);
    }

    void
    add_gradient(const Vector &u, const double factor, Vector &g) const override
    {
      const double s = factor * scale * data.weight;
      for (unsigned int i = 0; i < u.locally_owned_size(); ++i)
        g.begin()[i] +=
          s * ops.lumped_mass.begin()[i] * (u.begin()[i] - data.target);
    }

    void
    add_hessian_vmult(const Vector &,
                      const Vector &d,
                      const double  factor,
                      Vector       &y) const override
    {
      const double s = factor * scale * data.weight;
      for (unsigned int i = 0; i < d.locally_owned_size(); ++i)
        y.begin()[i] += s * ops.lumped_mass.begin()[i] * d.begin()[i];
    }

  private:
    const LumpedOperators<dim> &ops;
    const ToyData               data;
    const double                scale;
  };

  /** The toy of @p outer times @p scale (deduces the dimension). */
  template <int dim>
  std::unique_ptr<EnergyTerm>
  make_toy(const OuterEnergy          &outer,
           const LumpedOperators<dim> &operators,
           const double                scale)
  {
    return std::make_unique<ToyTerm<dim>>(
      operators,
      std::any_cast<ToyData>(outer.registered_terms.at(toy_name)),
      scale);
  }

  /**
   * Step 3 of the recipe: the entry: a step of size tau minimises
   * eps ||U - U^k||^2 + 2 tau (... + T[U]), so the factory makes
   * (tau / eps) T in the units of the residual; the column toy_energy
   * and the value in the energy law are T itself.
   */
  ModelTermEntry
  toy_entry()
  {
    ModelTermEntry entry;
    entry.name = toy_name;
    entry.set_factory([](const OuterEnergy &outer,
                         const auto        &operators,
                         const double       tau,
                         const double       epsilon) {
      return make_toy(outer, operators, tau / epsilon);
    });
    entry.set_statistics(
      {"toy_energy"},
      [](const OuterEnergy &outer, const auto &operators, const Vector &u) {
        return std::vector<double>{make_toy(outer, operators, 1.)->value(u)};
      });
    entry.set_energy(
      [](const OuterEnergy &outer, const auto &operators, const Vector &u) {
        return make_toy(outer, operators, 1.)->value(u);
      });
    return entry;
  }

  /** Step 4 of the recipe: a problem whose outer energy has the toy. */
  class ToyProblem : public WillmoreProblem<2>
  {
  public:
    using WillmoreProblem<2>::WillmoreProblem;

  protected:
    OuterEnergy
    scheme_outer_energy() const override
    {
      OuterEnergy outer = WillmoreProblem<2>::scheme_outer_energy();
      outer.registered_terms[toy_name] = ToyData{0.5, -1};
      return outer;
    }
  };

  /** R_U and J of a nested step with the toy against central differences. */
  void
  check_step()
  {
    const MPI_Comm                     comm = MPI_COMM_WORLD;
    const Testing::AdaptiveTestMesh<2> mesh;
    const LumpedOperators<2>          &ops = mesh.operators;
    NestedCoefficients                 coeff;
    coeff.epsilon                          = mesh.eps;
    coeff.tau                              = 0.03 * mesh.h;
    coeff.inner_tau                        = mesh.h * mesh.h;
    coeff.outer.registered_terms[toy_name] = ToyData{2, -0.5};

    Vector old_u(ops.locally_owned_dofs, comm);
    mesh.discretization.interpolate(Shapes::PhaseFieldProfile<2>(mesh.sphere,
                                                                 mesh.eps),
                                    old_u);
    mesh.constraints.distribute(old_u);
    NestedStep<2> step(mesh.discretization, coeff, old_u);
    LinearSolver  solver(LinearSolverType::direct, 1e-12, 2000);
    step.set_inner_solver(solver);

    const std::vector<dealii::IndexSet> parts(3, ops.locally_owned_dofs);
    BlockVector z(parts, comm), x(parts, comm), r(parts, comm);
    z.block(Field::U) = old_u;
    Vector direction(old_u);
    Testing::fill_smoothly(direction, 1, 2.9);
    mesh.constraints.set_zero(direction);
    mesh.constraints.distribute(direction);
    z.block(Field::U).add(0.02, direction);
    step.initialize_v_and_p(z, solver, 1e-10);
    for (unsigned int b = 0; b < 3; ++b)
      {
        x.block(b) = direction;
        x.block(b) *= (b + 1.);
      }

    // R_U against the outer energy, V and P re-solved for U
    const double fd_step   = 1e-6;
    const auto   energy_at = [&](const double s) {
      BlockVector trial(z);
      trial.block(Field::U).add(s, x.block(Field::U));
      step.solve_inner_problem(trial, solver, 1e-13);
      return step.outer_energy(trial);
    };
    step.solve_inner_problem(z, solver, 1e-13);
    step.residual(z, r);
    const double slope = r.block(Field::U) * x.block(Field::U);
    const double fd =
      (energy_at(fd_step) - energy_at(-fd_step)) / (2 * fd_step);
    Testing::log() << "nested step with the toy: |dE/dU x - R_U.x| / |R_U.x| "
                   << Testing::below(std::abs(fd - slope) / std::abs(slope),
                                     1e-6)
                   << std::endl;

    // J against central differences of R
    BlockVector zp(z), zm(z), rp(r), rm(r), jx(r), dz(r);
    zp.add(fd_step, x);
    zm.add(-fd_step, x);
    step.residual(zp, rp);
    step.residual(zm, rm);
    rp -= rm;
    rp /= 2 * fd_step;
    step.jacobian_vmult(z, x, jx);
    rp -= jx;
    Testing::log() << "  block U: |J x - FD| / |J x| "
                   << Testing::below(ops.dual_norm(rp.block(Field::U)) /
                                       ops.dual_norm(jx.block(Field::U)),
                                     1e-6)
                   << std::endl;
    step.solve_jacobian(z, r, dz, solver);
    step.jacobian_vmult(z, dz, jx);
    jx += r;
    Testing::log() << "  |J dz + R| / |R| "
                   << Testing::below(step.residual_norm(jx) /
                                       step.residual_norm(r),
                                     1e-6)
                   << std::endl;
  }

  const std::string circle = R"(
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
subsection Output
  set VTU interval = 0
end
)";

  /** 2 steps of a circle by @p Problem; the rows of statistics.csv. */
  template <typename Problem>
  std::vector<std::vector<double>>
  run(std::vector<std::string> &header, const std::string &directory)
  {
    dealii::ParameterHandler prm;
    WillmoreFlowParameters::declare_parameters(prm);
    prm.parse_input_from_string(circle +
                                "\nset Output directory = " + directory + "\n");
    WillmoreFlowParameters parameters;
    parameters.parse_parameters(prm);
    Problem(parameters).run();
    return Testing::read_csv(directory + "/statistics.csv", header);
  }
} // namespace



int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  // Step 3 of the recipe: the registration
  register_model_term(toy_entry());
  Testing::log() << "nested takes the toy: "
                 << (scheme_entry("nested").terms.has(toy_name) ? "yes" : "NO")
                 << ", semi-implicit: "
                 << (scheme_entry("semi-implicit").terms.has(toy_name) ? "YES" :
                                                                         "no")
                 << std::endl;
  check_step();

  std::vector<std::string> header, plain_header;
  const auto               rows = run<ToyProblem>(header, "results");
  const auto plain = run<WillmoreProblem<2>>(plain_header, "results_plain");
  const int  toy   = Testing::column(header, "toy_energy");
  Testing::log() << "toy_energy column: " << (toy >= 0 ? "yes" : "NO")
                 << ", without the term: "
                 << (Testing::column(plain_header, "toy_energy") >= 0 ? "YES" :
                                                                        "no")
                 << ", the other columns as without: "
                 << (std::vector<std::string>(header.begin(),
                                              header.begin() + toy) ==
                         std::vector<std::string>(plain_header.begin(),
                                                  plain_header.begin() + toy) ?
                       "yes" :
                       "NO")
                 << std::endl;
  const int newton   = Testing::column(header, "newton_iterations");
  const int halvings = Testing::column(header, "step_halvings");
  const int inside   = Testing::column(header, "inside_measure");
  for (unsigned int i = 1; i < rows.size(); ++i)
    Testing::log() << "step " << rows[i][0] << ": Newton iterations "
                   << rows[i][newton] << ", halvings " << rows[i][halvings]
                   << ", toy energy "
                   << (rows[i][toy] < rows[i - 1][toy] ? "fell" : "ROSE")
                   << ", inside measure "
                   << (rows[i][inside] > plain[i][inside] ? "larger" :
                                                            "NOT LARGER")
                   << " than without" << std::endl;
}
