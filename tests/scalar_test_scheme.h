#ifndef phasefield_tests_scalar_test_scheme_h
#define phasefield_tests_scalar_test_scheme_h

#include <deal.II/base/conditional_ostream.h>
#include <phasefield/mesh/discretization.h>
#include <phasefield/schemes/energies.h>
#include <phasefield/schemes/time_stepping_scheme.h>
#include <string>
#include <vector>

namespace Testing
{
  /**
   * The parts of a test scheme whose state is U alone and that has no
   * solver: field names, initialisation, the energies of U (Willmore energy
   * 0), no re-meshing data, no curvature. A test scheme adds name() and
   * advance() (and what else it tests).
   */
  template <int dim>
  class ScalarTestScheme : public PhaseField::TimeSteppingScheme<dim>
  {
  public:
    ScalarTestScheme(const PhaseField::SchemeSettings      &settings,
                     const PhaseField::Discretization<dim> &discretization)
      : settings(settings)
      , discretization(discretization)
    {}

    std::vector<std::string>
    field_names() const override
    {
      return {"U"};
    }

    std::string
    linear_solver_description() const override
    {
      return "none";
    }

    void
    initialize(PhaseField::BlockVector &state, const double tau) override
    {
      (void)tau;
      discretization.distribute_constraints(state);
    }

    void
    before_remesh() override
    {}

    void
    after_remesh(PhaseField::BlockVector &state, const double tau) override
    {
      (void)state;
      (void)tau;
    }

    void
    reset_solver() override
    {}

    PhaseField::Energies
    energies(const PhaseField::BlockVector &state) const override
    {
      return PhaseField::phase_field_energies(discretization.get_operators(),
                                              state.block(0),
                                              settings.epsilon);
    }

    unsigned int
    n_factorizations() const override
    {
      return 0;
    }

    void
    curvature(const PhaseField::BlockVector &state,
              PhaseField::Vector            &curvature) const override
    {
      (void)state;
      curvature = 0;
    }

  protected:
    const PhaseField::SchemeSettings       settings;
    const PhaseField::Discretization<dim> &discretization;
  };
} // namespace Testing

#endif
