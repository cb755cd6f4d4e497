#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <phasefield/solvers/lumped_elimination.h>

namespace PhaseField
{
  template <int dim>
  unsigned int
  solve_lumped_elimination(const LumpedOperators<dim> &ops,
                           LumpedTwoFieldMatrix        j,
                           const BlockVector          &r,
                           BlockVector                &dz,
                           LinearSolver               &solver)
  {
    dealii::TrilinosWrappers::SparseMatrix j_uf, j_fu, s;
    ops.stiffness_plus_weighted_mass(j.f_uf, j.w_uf, j_uf);
    ops.stiffness_plus_weighted_mass(j.f_fu, j.w_fu, j_fu);

    // S = J_UU - J_UF (s M)^-1 J_FU
    Vector weight(ops.inverse_lumped_mass);
    weight *= -1. / j.s;
    j_uf.mmult(s, j_fu, weight);
    ops.add_to_diagonal(j.uu, s);

    // rhs = -R_U + J_UF (s M)^-1 R_F
    const Vector &r_u = r.block(0);
    const Vector &r_f = r.block(1);
    Vector        tmp(r_f), rhs(r_u);
    tmp.scale(ops.inverse_lumped_mass);
    tmp /= j.s;
    j_uf.vmult(rhs, tmp);
    rhs -= r_u;
    ops.zero_constrained(rhs);

    Vector            &du         = dz.block(0);
    Vector            &df         = dz.block(1);
    const unsigned int iterations = solver.solve(s, du, rhs);
    ops.zero_constrained(du);

    // dF = (s M)^-1 (-R_F - J_FU dU)
    j_fu.vmult(df, du);
    df += r_f;
    df.scale(ops.inverse_lumped_mass);
    df *= -1. / j.s;
    ops.zero_constrained(df);
    return iterations;
  }



  template unsigned int
  solve_lumped_elimination(const LumpedOperators<2> &,
                           LumpedTwoFieldMatrix,
                           const BlockVector &,
                           BlockVector &,
                           LinearSolver &);
  template unsigned int
  solve_lumped_elimination(const LumpedOperators<3> &,
                           LumpedTwoFieldMatrix,
                           const BlockVector &,
                           BlockVector &,
                           LinearSolver &);
} // namespace PhaseField
