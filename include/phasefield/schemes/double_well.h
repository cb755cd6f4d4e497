#ifndef phasefield_schemes_double_well_h
#define phasefield_schemes_double_well_h

namespace PhaseField
{
  /** The double well Psi(v) = (1-v^2)^2 and its derivatives. */
  namespace DoubleWell
  {
    inline double
    psi(const double v)
    {
      return (1 - v * v) * (1 - v * v);
    }
    inline double
    d_psi(const double v)
    {
      return -4 * v * (1 - v * v);
    }
    inline double
    d2_psi(const double v)
    {
      return -4 + 12 * v * v;
    }
    inline double
    d3_psi(const double v)
    {
      return 24 * v;
    }
  } // namespace DoubleWell
} // namespace PhaseField

#endif
