#ifndef phasefield_schemes_energies_h
#define phasefield_schemes_energies_h

#include <phasefield/core/linear_algebra.h>
#include <phasefield/mesh/lumped_operators.h>

namespace PhaseField
{
  /**
   * Energies of a phase field in geometric units (Constants::geometric_unit):
   * a circle of radius r has Willmore energy pi/r and length 2 pi r, a
   * sphere 8 pi and 4 pi r^2.
   */
  struct Energies
  {
    /**
     * (3/4) (1/2) eps Int ((U-V)/ttau)^2 (nested scheme) or
     * (3/4) w_eps[U] (semi-implicit scheme): pi/r for a circle.
     */
    double willmore = 0;
    /** (3/4) a_eps[U]: the perimeter / surface area. */
    double area = 0;
    /** Int (1-U)/2: the measure of the inside phase. */
    double inside_measure = 0;
    /**
     * The value of the data term (OuterEnergy::data_term; shape from
     * contour's monolithic coupling: the mismatch j) in thesis units, 0
     * without one.
     */
    double data_term = 0;
    /**
     * The sum of the values of the registered energy terms in the energy
     * law (registered_terms_energy()) in thesis units, 0 without any.
     */
    double registered_terms = 0;
  };

  /**
   * The area functional a_eps[U] = (1/2) Int eps |grad U|^2 + Psi(U)/eps
   * (lumped) and the inside measure Int (1-U)/2 of @p u; in the result
   * the area in geometric units, (3/4) a_eps[U], and the Willmore energy
   * left at zero (it depends on the scheme).
   */
  template <int dim>
  Energies
  phase_field_energies(const LumpedOperators<dim> &operators,
                       const Vector               &u,
                       const double                epsilon);

  /** a_eps[U] = (1/2) Int eps |grad U|^2 + Psi(U)/eps (lumped). */
  template <int dim>
  double
  area_functional(const LumpedOperators<dim> &operators,
                  const Vector               &u,
                  const double                epsilon);
} // namespace PhaseField

#endif
