#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/linear_operator.h>
#include <phasefield/schemes/nested/nested_linear_systems.h>

namespace PhaseField
{
  using namespace dealii;

  template <int dim>
  NestedLinearSystems<dim>::NestedLinearSystems(
    const NestedPhysics<dim> &physics,
    NestedMatrices<dim>      *mesh_matrices)
    : physics(physics)
    , ops(physics.operators())
    , coeff(physics.coefficients())
    , weights(physics.get_weights())
    , mesh_matrices(mesh_matrices)
    , constant_jacobian(mesh_matrices != nullptr && !coeff.double_well &&
                        !coeff.outer.has_restoration_terms())
  {}



  template <int dim>
  NestedMatrices<dim> &
  NestedLinearSystems<dim>::storage(NestedMatrices<dim> &local) const
  {
    return mesh_matrices != nullptr ? *mesh_matrices : local;
  }



  template <int dim>
  unsigned int
  NestedLinearSystems<dim>::solve_jacobian(const BlockVector &z,
                                           const BlockVector &r,
                                           BlockVector       &dz,
                                           LinearSolver      &solver)
  {
    if (coeff.outer.has_restoration_terms())
      return solve_full_system(z, r, dz, solver, 0.);
    NestedMatrices<dim>  local;
    NestedMatrices<dim> &matrices = storage(local);
    // if the matrices do not depend on the state: build (and factorise)
    // them once
    if (!constant_jacobian || !matrices.k || matrices.k->empty())
      {
        build_reduced_matrices(z, matrices, solver.type());
        if (constant_jacobian && solver.type() == LinearSolverType::direct)
          solver.factorize(matrices.s);
      }
    return solve_reduced_system(matrices, r, dz, solver);
  }



  template <int dim>
  unsigned int
  NestedLinearSystems<dim>::solve_shifted_jacobian(const BlockVector &z,
                                                   const BlockVector &r,
                                                   BlockVector       &dz,
                                                   LinearSolver      &solver,
                                                   const double       shift)
  {
    if (coeff.outer.has_restoration_terms())
      return solve_full_system(z, r, dz, solver, shift);
    // the shift enters the U-U block, (1 + a + shift) M, which the
    // elimination keeps exactly (build_reduced_matrices())
    NestedMatrices<dim>  local;
    NestedMatrices<dim> &matrices = storage(local);
    build_reduced_matrices(z, matrices, solver.type(), shift);
    return solve_reduced_system(matrices, r, dz, solver);
  }



  template <int dim>
  unsigned int
  NestedLinearSystems<dim>::solve_with_k(const Vector &v,
                                         LinearSolver &solver,
                                         Vector       &x,
                                         const Vector &rhs) const
  {
    if (solver.type() == LinearSolverType::iterative)
      {
        std::unique_ptr<ShiftedStiffness> k;
        physics.build_k(v, 0., k);
        return solver.solve(*k, x, rhs);
      }
    TrilinosWrappers::SparseMatrix k;
    build_k_matrix(v, 0., k);
    return solver.solve(k, x, rhs);
  }



  template <int dim>
  void
  NestedLinearSystems<dim>::build_k_matrix(
    const Vector                   &v,
    const double                    shift,
    TrilinosWrappers::SparseMatrix &k) const
  {
    ops.stiffness_plus_weighted_mass(weights.inner_tau,
                                     physics.k_weights(v, shift),
                                     k);
  }



  template <int dim>
  void
  NestedLinearSystems<dim>::build_reduced_matrices(
    const BlockVector     &z,
    NestedMatrices<dim>   &matrices,
    const LinearSolverType type,
    const double           shift) const
  {
    const double a = weights.a;
    const double w = 1 + a + shift;
    // Khat = K - b M; the mass weight of S, a (1 - a/w), is b for shift 0
    const double b           = a / w;
    const double mass_weight = a - a * b;
    matrices.uu_weight       = w;

    const Vector &v = z.block(Field::V);
    const Vector &p = z.block(Field::P);

    physics.build_k(v, 0., matrices.k);

    // the diagonal part of S: b M + E
    Vector &diagonal = matrices.diagonal;
    diagonal.reinit(v, true);
    const double      *m = ops.lumped_mass.begin();
    const unsigned int n = v.locally_owned_size();
    for (unsigned int i = 0; i < n; ++i)
      diagonal.begin()[i] =
        m[i] * (mass_weight + weights.e(v.begin()[i], p.begin()[i]));

    if (type == LinearSolverType::direct)
      {
        // S = w Khat M^-1 Khat + diagonal, Khat = ttau L + M[k(V) - b]
        if (!matrices.stiffness_square)
          matrices.stiffness_square =
            std::make_unique<StiffnessSquare<dim>>(ops);
        matrices.stiffness_square->assemble(
          w, weights.inner_tau, physics.k_weights(v, b), diagonal, matrices.s);
      }
    else
      {
        physics.build_k(v, b, matrices.k_hat);
        physics.build_schur_factor(
          v, b, w, mass_weight, matrices.g, matrices.interface_mode);
      }
  }



  template <int dim>
  unsigned int
  NestedLinearSystems<dim>::solve_reduced_system(
    const NestedMatrices<dim> &matrices,
    const BlockVector         &r,
    BlockVector               &dz,
    LinearSolver              &solver) const
  {
    const double a = weights.a;
    const double w = matrices.uu_weight;

    const auto   &k   = *matrices.k;
    const Vector &r_u = r.block(Field::U);
    const Vector &r_v = r.block(Field::V);
    const Vector &r_p = r.block(Field::P);

    // rhs = -R_V + a R_P - K M^-1 (w R_P + R_U), w = 1 + a (+ shift)
    Vector tmp(r_p), rhs(r_v);
    tmp *= w;
    tmp += r_u;
    tmp.scale(ops.inverse_lumped_mass);
    k.vmult(rhs, tmp);
    rhs *= -1;
    rhs -= r_v;
    rhs.add(a, r_p);
    ops.zero_constrained(rhs);

    Vector            &du = dz.block(Field::U);
    Vector            &dv = dz.block(Field::V);
    Vector            &dp = dz.block(Field::P);
    const unsigned int iterations =
      solver.type() == LinearSolverType::direct ?
        solver.solve(matrices.s, dv, rhs) :
        solver.solve_product_form(*matrices.k_hat,
                                  w,
                                  matrices.diagonal,
                                  *matrices.g,
                                  ops.lumped_mass,
                                  ops.inverse_lumped_mass,
                                  dv,
                                  rhs,
                                  &matrices.interface_mode);
    ops.zero_constrained(dv);

    // dU = M^-1 (K dV + R_P)
    Vector k_dv(dv);
    k.vmult(k_dv, dv);
    du = k_dv;
    du += r_p;
    du.scale(ops.inverse_lumped_mass);

    // dP = M^-1 (w K dV - a M dV + w R_P + R_U)
    const double      *m = ops.lumped_mass.begin();
    const unsigned int n = dv.locally_owned_size();
    for (unsigned int i = 0; i < n; ++i)
      dp.begin()[i] = ops.inverse_lumped_mass.begin()[i] *
                      (w * (k_dv.begin()[i] + r_p.begin()[i]) -
                       a * m[i] * dv.begin()[i] + r_u.begin()[i]);
    for (unsigned int bl = 0; bl < 3; ++bl)
      ops.zero_constrained(dz.block(bl));
    return iterations;
  }



  template <int dim>
  void
  NestedLinearSystems<dim>::reinit_full_jacobian(
    TrilinosWrappers::SparseMatrix &j) const
  {
    const auto                   &L      = ops.stiffness_matrix();
    const IndexSet               &owned  = ops.locally_owned_dofs;
    const unsigned int            n      = owned.n_elements();
    const types::global_dof_index n_dofs = owned.size();
    const auto                    index  = [](const types::global_dof_index g,
                          const unsigned int field) { return 3 * g + field; };

    IndexSet owned3(3 * n_dofs);
    for (unsigned int i = 0; i < n; ++i)
      {
        const types::global_dof_index g = owned.nth_index_in_set(i);
        owned3.add_range(index(g, 0), index(g, 0) + 3);
      }
    owned3.compress();

    // the nodal 3x3 blocks but PP, the stiffness pattern in UU, VP, PV
    DynamicSparsityPattern dsp(3 * n_dofs, 3 * n_dofs, owned3);
    for (unsigned int i = 0; i < n; ++i)
      {
        const types::global_dof_index g = owned.nth_index_in_set(i);
        for (unsigned int row = 0; row < 3; ++row)
          for (unsigned int col = 0; col < 3; ++col)
            if (!(row == Field::P && col == Field::P))
              dsp.add(index(g, row), index(g, col));
        for_each_entry_in_row(
          L, g, [&](const types::global_dof_index col, const double) {
            dsp.add(index(g, Field::U), index(col, Field::U));
            dsp.add(index(g, Field::V), index(col, Field::P));
            dsp.add(index(g, Field::P), index(col, Field::V));
          });
      }
    j.reinit(owned3,
             owned3,
             dsp,
             physics.get_discretization().get_mpi_communicator());
  }



  template <int dim>
  void
  NestedLinearSystems<dim>::assemble_full_jacobian(
    const BlockVector              &z,
    const double                    shift,
    TrilinosWrappers::SparseMatrix &j) const
  {
    const double       a           = weights.a;
    const double       area_factor = weights.area_factor;
    const auto        &L           = ops.stiffness_matrix();
    const IndexSet    &owned       = ops.locally_owned_dofs;
    const unsigned int n           = owned.n_elements();
    const double      *m           = ops.lumped_mass.begin();
    const double      *u           = z.block(Field::U).begin();
    const double      *v           = z.block(Field::V).begin();
    const double      *p           = z.block(Field::P).begin();

    // U rows and columns replaced by the identity: fixed and constrained
    std::vector<bool> identity_row(n, false);
    for (unsigned int i = 0; i < n; ++i)
      identity_row[i] = physics.u_is_fixed(i);
    for (const unsigned int i : ops.constrained_local_indices)
      identity_row[i] = true;
    const auto fixed_column = [&](const types::global_dof_index g) {
      return coeff.outer.fixed_u != nullptr &&
             coeff.outer.fixed_u->is_element(g);
    };
    const double p_scale = a;
    const auto   index   = [](const types::global_dof_index g,
                          const unsigned int field) { return 3 * g + field; };
    if (j.m() == 0)
      reinit_full_jacobian(j);
    else
      j = 0;

    for (unsigned int i = 0; i < n; ++i)
      {
        const types::global_dof_index g      = owned.nth_index_in_set(i);
        const double                  k_diag = m[i] * weights.k(v[i]);
        if (identity_row[i])
          j.add(index(g, Field::U), index(g, Field::U), 1.);
        else
          {
            j.add(index(g, Field::U),
                  index(g, Field::U),
                  m[i] * weights.uu(u[i], shift));
            j.add(index(g, Field::U), index(g, Field::V), -a * m[i]);
            j.add(index(g, Field::U), index(g, Field::P), -p_scale * m[i]);
            j.add(index(g, Field::V), index(g, Field::U), -a * m[i]);
            j.add(index(g, Field::P), index(g, Field::U), -p_scale * m[i]);
          }
        j.add(index(g, Field::V),
              index(g, Field::V),
              m[i] * (a + weights.e(v[i], p[i])));
        j.add(index(g, Field::V), index(g, Field::P), p_scale * k_diag);
        j.add(index(g, Field::P), index(g, Field::V), p_scale * k_diag);
        for_each_entry_in_row(
          L, g, [&](const types::global_dof_index col, const double value) {
            if (!identity_row[i] && !fixed_column(col))
              j.add(index(g, Field::U),
                    index(col, Field::U),
                    area_factor * value);
            j.add(index(g, Field::V),
                  index(col, Field::P),
                  p_scale * weights.inner_tau * value);
            j.add(index(g, Field::P),
                  index(col, Field::V),
                  p_scale * weights.inner_tau * value);
          });
      }
    j.compress(VectorOperation::add);
  }



  template <int dim>
  unsigned int
  NestedLinearSystems<dim>::solve_full_system(const BlockVector &z,
                                              const BlockVector &r,
                                              BlockVector       &dz,
                                              LinearSolver      &solver,
                                              const double       shift) const
  {
    if (coeff.outer.fixed_u == nullptr)
      return solve_area_system(z, r, dz, solver, shift);
    AssertThrow(coeff.outer.data_term == nullptr &&
                  coeff.outer.registered_terms.empty(),
                ExcMessage("The assembled 3-field Jacobian of fixed U "
                           "values has no data term (OuterEnergy::"
                           "data_term) and no registered energy term."));
    AssertThrow(solver.type() == LinearSolverType::direct,
                ExcMessage("The 3-field Newton system of edge restoration "
                           "needs <Linear solver / Type> = direct (or auto "
                           "in 2D)."));
    // delayed pivots of the indefinite 3-field matrix need more workspace
    constexpr unsigned int workspace_percent = 200;
    solver.set_pivoting_workspace(workspace_percent);
    // The factorisation of an earlier Newton matrix (same mesh) is kept
    // as GMRES preconditioner while it works; the LinearSolver factorises
    // this matrix (reusing MUMPS's analysis) when GMRES needs more than a
    // few iterations with it or stagnates (J is indefinite).
    NestedMatrices<dim>             local;
    TrilinosWrappers::SparseMatrix &j = storage(local).full_jacobian;
    assemble_full_jacobian(z, shift, j);
    const MPI_Comm comm = z.block(0).get_mpi_communicator();
    Vector         rhs(j.locally_owned_range_indices(), comm);
    Vector         x(rhs);
    // owned DoFs are contiguous, so (field b, local i) is local entry 3i+b
    const unsigned int n = ops.locally_owned_dofs.n_elements();
    // J' = S J S with S = diag(1, 1, a): dZ = S y, J' y = -S R
    const double scale[3] = {1., 1., weights.a};
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int b = 0; b < 3; ++b)
        rhs.begin()[3 * i + b] = -scale[b] * r.block(b).begin()[i];
    const unsigned int iterations = solver.solve(j, x, rhs);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int b = 0; b < 3; ++b)
        dz.block(b).begin()[i] = scale[b] * x.begin()[3 * i + b];
    // exactly zero, not zero to the solver tolerance
    for (unsigned int i = 0; i < n; ++i)
      if (physics.u_is_fixed(i))
        dz.block(Field::U).begin()[i] = 0;
    for (unsigned int b = 0; b < 3; ++b)
      ops.zero_constrained(dz.block(b));
    return iterations;
  }



  template <int dim>
  unsigned int
  NestedLinearSystems<dim>::solve_area_system(const BlockVector &z,
                                              const BlockVector &r,
                                              BlockVector       &dz,
                                              LinearSolver      &solver,
                                              const double       shift) const
  {
    NestedMatrices<dim>  local;
    NestedMatrices<dim> &matrices = storage(local);
    build_reduced_matrices(z, matrices, solver.type(), shift);
    if (!matrices.preconditioner_solver)
      matrices.preconditioner_solver =
        std::make_unique<LinearSolver>(solver.type(),
                                       area_preconditioner_tolerance,
                                       area_preconditioner_max_iterations);
    LinearSolver &reduced_solver = *matrices.preconditioner_solver;
    // iterative: one multigrid hierarchy of this S for all the solves
    // with it (direct: a kept factorisation while it preconditions well)
    if (solver.type() == LinearSolverType::iterative)
      {
        reduced_solver.set_constant_matrix(true);
        reduced_solver.reset();
      }

    LinearOperator<BlockVector> jacobian;
    jacobian.vmult = [&](BlockVector &y, const BlockVector &x) {
      physics.apply_jacobian(*matrices.k, z, x, y, shift);
    };
    // the elimination solves J0 dZ = -R: dst = J0^-1 src
    BlockVector                 minus_src(r);
    LinearOperator<BlockVector> preconditioner;
    preconditioner.vmult = [&](BlockVector &dst, const BlockVector &src) {
      minus_src = src;
      minus_src *= -1;
      solve_reduced_system(matrices, minus_src, dst, reduced_solver);
    };
    BlockVector rhs(r);
    rhs *= -1;
    const unsigned int iterations =
      solver.solve_flexible(jacobian, dz, rhs, preconditioner);
    for (unsigned int b = 0; b < 3; ++b)
      ops.zero_constrained(dz.block(b));
    return iterations;
  }



  template struct NestedMatrices<2>;
  template struct NestedMatrices<3>;
  template class NestedLinearSystems<2>;
  template class NestedLinearSystems<3>;
} // namespace PhaseField
