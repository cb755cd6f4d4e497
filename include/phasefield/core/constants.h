#ifndef phasefield_core_constants_h
#define phasefield_core_constants_h

/**
 * Numbers that appear in more than one layer of the library, each with the
 * reason for its value.
 */
namespace PhaseField
{
  namespace Constants
  {
    /**
     * The factor that turns phase-field energies into geometric units: the
     * optimal profile tanh(s/eps) has Int (eps/2 |u'|^2 + Psi(u)/(2 eps)) ds
     * = 4/3 per unit interface, so (3/4) a_eps[u] is the length (area) of
     * the interface and (3/4) (1/2) eps Int ((U-V)/ttau)^2 its Willmore
     * energy: pi/r for a circle of radius r, 8 pi for a sphere.
     */
    constexpr double geometric_unit = 0.75;

    /**
     * Relative round-off of a sum of terms of size one in double precision,
     * with a margin of about 100 ulp: residual norms, Newton decrements and
     * energy changes below this (relative to the terms they are made of)
     * carry no information.
     */
    constexpr double roundoff = 1e-14;
  } // namespace Constants
} // namespace PhaseField

#endif
