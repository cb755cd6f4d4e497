#ifndef phasefield_solvers_lumped_elimination_h
#define phasefield_solvers_lumped_elimination_h

#include <phasefield/core/linear_algebra.h>
#include <phasefield/mesh/lumped_operators.h>
#include <phasefield/solvers/linear_solver.h>

namespace PhaseField
{
  /**
   * A two-field Newton matrix whose second diagonal block is a multiple of
   * the lumped mass,
   *
   *   J = [ diag(uu)           f_uf L + M[w_uf] ]
   *       [ f_fu L + M[w_fu]   s M              ],
   *
   * given by its factors and nodal weights (the semi-implicit scheme's
   * Jacobian, thesis 5.2.2).
   */
  struct LumpedTwoFieldMatrix
  {
    /** The UU block, a diagonal (already multiplied by the mass). */
    Vector uu;
    double f_uf = 0;
    Vector w_uf;
    double f_fu = 0;
    Vector w_fu;
    /** The factor s of the FF block s M. */
    double s = 1;
  };

  /**
   * Solve J [dU; dF] = -[R_U; R_F] (block 0 and 1 of @p r and @p dz) for
   * the @p j on @p operators by eliminating dF (M is diagonal):
   * S dU = -R_U + J_UF (s M)^-1 R_F with the assembled
   * S = J_UU - J_UF (s M)^-1 J_FU (one sparse product; @p solver must be
   * direct), then dF = (s M)^-1 (-R_F - J_FU dU). Returns the iterations
   * of the solver.
   */
  template <int dim>
  unsigned int
  solve_lumped_elimination(const LumpedOperators<dim> &operators,
                           LumpedTwoFieldMatrix        j,
                           const BlockVector          &r,
                           BlockVector                &dz,
                           LinearSolver               &solver);
} // namespace PhaseField

#endif
