#include <deal.II/base/mpi.h>
#include <phasefield/core/constants.h>
#include <phasefield/schemes/double_well.h>
#include <phasefield/schemes/energies.h>

namespace PhaseField
{
  using namespace dealii;

  namespace
  {
    /** Int Psi(U) and Int (1-U)/2, both lumped, summed over all ranks. */
    template <int dim>
    std::pair<double, double>
    potential_and_inside(const LumpedOperators<dim> &operators, const Vector &u)
    {
      const double      *m         = operators.lumped_mass.begin();
      const unsigned int n         = u.locally_owned_size();
      double             potential = 0, inside = 0;
      for (unsigned int i = 0; i < n; ++i)
        {
          const double ui = u.begin()[i];
          potential += m[i] * DoubleWell::psi(ui);
          inside += m[i] * 0.5 * (1 - ui);
        }
      const MPI_Comm comm = u.get_mpi_communicator();
      return {Utilities::MPI::sum(potential, comm),
              Utilities::MPI::sum(inside, comm)};
    }
  } // namespace



  template <int dim>
  double
  area_functional(const LumpedOperators<dim> &operators,
                  const Vector               &u,
                  const double                epsilon)
  {
    const double potential = potential_and_inside(operators, u).first;
    const double gradient  = operators.stiffness_product(u);
    return 0.5 * (epsilon * gradient + potential / epsilon);
  }



  template <int dim>
  Energies
  phase_field_energies(const LumpedOperators<dim> &operators,
                       const Vector               &u,
                       const double                epsilon)
  {
    const auto [potential, inside] = potential_and_inside(operators, u);
    const double gradient          = operators.stiffness_product(u);

    Energies e;
    e.area = Constants::geometric_unit * 0.5 *
             (epsilon * gradient + potential / epsilon);
    e.inside_measure = inside;
    return e;
  }



  template Energies
  phase_field_energies(const LumpedOperators<2> &,
                       const Vector &,
                       const double);
  template Energies
  phase_field_energies(const LumpedOperators<3> &,
                       const Vector &,
                       const double);
  template double
  area_functional(const LumpedOperators<2> &, const Vector &, const double);
  template double
  area_functional(const LumpedOperators<3> &, const Vector &, const double);
} // namespace PhaseField
