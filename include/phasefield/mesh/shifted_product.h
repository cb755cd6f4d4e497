#ifndef phasefield_mesh_shifted_product_h
#define phasefield_mesh_shifted_product_h

#include <phasefield/core/linear_algebra.h>

namespace PhaseField
{
  /**
   * @p y = @p factor @p y + diag(@p d) @p x on the locally owned entries:
   * the product with f L + D once @p y holds L @p x (the shifted operators
   * of both backends, StiffnessPlusDiagonal and
   * MatrixFreeShiftedStiffness).
   */
  inline void
  scale_and_add_diagonal(const double  factor,
                         const Vector &d,
                         const Vector &x,
                         Vector       &y)
  {
    const unsigned int n  = y.locally_owned_size();
    const double      *di = d.begin();
    const double      *xi = x.begin();
    double            *yi = y.begin();
    for (unsigned int i = 0; i < n; ++i)
      yi[i] = factor * yi[i] + di[i] * xi[i];
  }
} // namespace PhaseField

#endif
