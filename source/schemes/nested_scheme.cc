#include <cmath>
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/linear_operator.h>
#include <iostream>
#include <limits>
#include <phasefield/schemes/energies.h>
#include <phasefield/schemes/nested_scheme.h>
#include <phasefield/solvers/descent_solver.h>
#include <phasefield/solvers/newton_solver.h>

namespace PhaseField
{
  using namespace dealii;

  // ---------------------------------------------------------------------
  // The inner problem (3.18b): R_P(U, V) = 0 for V at fixed U
  // ---------------------------------------------------------------------

  /**
   * The inner (Allen-Cahn) problem R_P(U, V) = 0 in V for a fixed U, as a
   * NonlinearSystem in the one-block vector (V). Its Jacobian K(V) is
   * positive definite for ttau < eps^2/2 (a convex inner energy).
   */
  template <int dim>
  class NestedStep<dim>::InnerProblem : public NonlinearSystem
  {
  public:
    InnerProblem(const NestedStep<dim> &step, const Vector &u)
      : step(step)
      , u(u)
    {}

    void
    residual(const BlockVector &z, BlockVector &r) const override
    {
      step.inner_residual(u, z.block(0), r.block(0));
    }

    double
    residual_norm(const BlockVector &r) const override
    {
      return step.ops.dual_norm(r.block(0));
    }

    /** The tolerance of the inner problem is absolute. */
    double
    term_scale(const BlockVector &) const override
    {
      return 1;
    }

    unsigned int
    solve_jacobian(const BlockVector &z,
                   const BlockVector &r,
                   BlockVector       &dz,
                   LinearSolver      &solver) override
    {
      Vector rhs(r.block(0));
      rhs *= -1;
      const unsigned int iterations =
        step.solve_with_k(z.block(0), solver, dz.block(0), rhs);
      step.ops.zero_constrained(dz.block(0));
      return iterations;
    }

    void
    distribute_constraints(BlockVector &z) const override
    {
      step.discretization.get_constraints().distribute(z.block(0));
    }

  private:
    const NestedStep<dim> &step;
    const Vector          &u;
  };



  // ---------------------------------------------------------------------
  // One step: residual and Jacobian of the saddle point of (3.19)
  // ---------------------------------------------------------------------

  template <int dim>
  NestedStep<dim>::NestedStep(const Discretization<dim> &discretization,
                              const NestedCoefficients  &coefficients,
                              const Vector              &old_u,
                              ReducedMatrices           *mesh_matrices)
    : discretization(discretization)
    , ops(discretization.get_operators())
    , coeff(coefficients)
    , weights(coefficients)
    , old_u(old_u)
    , mesh_matrices(mesh_matrices)
    , constant_jacobian(mesh_matrices != nullptr && !coefficients.double_well &&
                        !coefficients.outer.has_restoration_terms())
  {}



  template <int dim>
  void
  NestedStep<dim>::residual(const BlockVector &z, BlockVector &r) const
  {
    const double  a   = weights.a;
    const double  c   = weights.c;
    const auto   &L   = ops.stiffness;
    Vector       &r_u = r.block(Field::U);
    Vector       &r_v = r.block(Field::V);
    Vector       &r_p = r.block(Field::P);
    const Vector &u   = z.block(Field::U);
    const Vector &v   = z.block(Field::V);
    const Vector &p   = z.block(Field::P);

    // stiffness parts first: r_v = ttau L P, r_p = ttau L V
    L.vmult(r_v, p);
    r_v *= weights.inner_tau;
    L.vmult(r_p, v);
    r_p *= weights.inner_tau;

    const unsigned int n  = u.locally_owned_size();
    const double      *m  = ops.lumped_mass.begin();
    const double      *uk = old_u.begin();
    const double      *f =
      coeff.outer.forcing ? coeff.outer.forcing->begin() : nullptr;
    const double forcing_factor = coeff.tau / coeff.epsilon;
    for (unsigned int i = 0; i < n; ++i)
      {
        const double ui = u.begin()[i], vi = v.begin()[i], pi = p.begin()[i];
        const double k_diag = m[i] * weights.k(vi);
        r_u.begin()[i]      = m[i] * ((ui - uk[i]) - a * (vi - ui) - pi);
        if (f)
          r_u.begin()[i] -= forcing_factor * f[i];
        r_v.begin()[i] += a * m[i] * (vi - ui) + k_diag * pi;
        r_p.begin()[i] += m[i] * ((vi - ui) + c * DoubleWell::d_psi(vi));
      }
    // the area term; no U-row at fixed U values
    add_area_gradient(u, 1., r_u);
    zero_fixed_u(r_u);
    for (unsigned int b = 0; b < 3; ++b)
      ops.zero_constrained(r.block(b));
  }



  template <int dim>
  template <typename NodalPotential>
  void
  NestedStep<dim>::add_area_term(const Vector         &x,
                                 const double          factor,
                                 const NodalPotential &potential,
                                 Vector               &y) const
  {
    if (coeff.outer.area_weight == 0)
      return;
    Vector l_x(x);
    ops.stiffness.vmult(l_x, x);
    const double       scale = factor * weights.area_factor;
    const double       c_u   = weights.area_potential_factor;
    const double      *m     = ops.lumped_mass.begin();
    const unsigned int n     = x.locally_owned_size();
    for (unsigned int i = 0; i < n; ++i)
      y.begin()[i] += scale * (l_x.begin()[i] + c_u * m[i] * potential(i));
  }



  template <int dim>
  void
  NestedStep<dim>::add_area_gradient(const Vector &u,
                                     const double  factor,
                                     Vector       &g) const
  {
    add_area_term(
      u,
      factor,
      [&](const unsigned int i) { return DoubleWell::d_psi(u.begin()[i]); },
      g);
  }



  template <int dim>
  void
  NestedStep<dim>::add_area_hessian_vmult(const Vector &u,
                                          const Vector &d,
                                          const double  factor,
                                          Vector       &y) const
  {
    add_area_term(
      d,
      factor,
      [&](const unsigned int i) {
        return DoubleWell::d2_psi(u.begin()[i]) * d.begin()[i];
      },
      y);
  }



  template <int dim>
  void
  NestedStep<dim>::zero_fixed_u(Vector &u_block) const
  {
    if (coeff.outer.fixed_u == nullptr)
      return;
    const unsigned int n = u_block.locally_owned_size();
    for (unsigned int i = 0; i < n; ++i)
      if (u_is_fixed(i))
        u_block.begin()[i] = 0;
  }



  template <int dim>
  bool
  NestedStep<dim>::u_is_fixed(const unsigned int i) const
  {
    return coeff.outer.fixed_u != nullptr &&
           coeff.outer.fixed_u->is_element(
             ops.locally_owned_dofs.nth_index_in_set(i));
  }



  template <int dim>
  double
  NestedStep<dim>::residual_norm(const BlockVector &r) const
  {
    double sum = 0;
    for (unsigned int b = 0; b < 3; ++b)
      sum += std::pow(ops.dual_norm(r.block(b)), 2);
    return std::sqrt(sum);
  }



  template <int dim>
  double
  NestedStep<dim>::term_scale(const BlockVector &z) const
  {
    Vector difference(z.block(Field::V));
    difference -= z.block(Field::U);
    return std::sqrt(ops.mass_product(z.block(Field::U), z.block(Field::U))) +
           weights.a * std::sqrt(ops.mass_product(difference, difference)) +
           std::sqrt(ops.mass_product(z.block(Field::P), z.block(Field::P)));
  }



  template <int dim>
  double
  NestedStep<dim>::roundoff_level(const BlockVector &z) const
  {
    const auto norm = [this](const Vector &x) {
      return std::sqrt(ops.mass_product(x, x));
    };
    const double u = norm(z.block(Field::U));
    return std::numeric_limits<double>::epsilon() *
           (u + weights.a * (u + norm(z.block(Field::V))) +
            norm(z.block(Field::P)));
  }



  template <int dim>
  void
  NestedStep<dim>::distribute_constraints(BlockVector &z) const
  {
    discretization.distribute_constraints(z);
  }



  template <int dim>
  void
  NestedStep<dim>::jacobian_vmult(const BlockVector &z,
                                  const BlockVector &x,
                                  BlockVector       &y,
                                  const double       shift) const
  {
    StiffnessPlusDiagonal k;
    build_k(z.block(Field::V), 0., k);
    apply_jacobian(k, z, x, y, shift);
  }



  template <int dim>
  void
  NestedStep<dim>::apply_jacobian(const StiffnessPlusDiagonal &k,
                                  const BlockVector           &z,
                                  const BlockVector           &x_in,
                                  BlockVector                 &y,
                                  const double                 shift) const
  {
    // with fixed U values, J has identity U-rows and U-columns there
    BlockVector x(x_in);
    for (unsigned int i = 0; i < x.block(0).locally_owned_size(); ++i)
      if (u_is_fixed(i))
        x.block(Field::U).begin()[i] = 0;

    const double a = weights.a;
    k.vmult(y.block(Field::V), x.block(Field::P));
    k.vmult(y.block(Field::P), x.block(Field::V));
    Vector l_x(x.block(Field::U));
    ops.stiffness.vmult(l_x, x.block(Field::U));
    const double      *m = ops.lumped_mass.begin();
    const double      *u = z.block(Field::U).begin();
    const double      *v = z.block(Field::V).begin();
    const double      *p = z.block(Field::P).begin();
    const unsigned int n = x.block(0).locally_owned_size();
    for (unsigned int i = 0; i < n; ++i)
      {
        const double xu = x.block(Field::U).begin()[i];
        const double xv = x.block(Field::V).begin()[i];
        const double xp = x.block(Field::P).begin()[i];
        y.block(Field::U).begin()[i] =
          u_is_fixed(i) ? x_in.block(Field::U).begin()[i] :
                          m[i] * (weights.uu(u[i], shift) * xu - a * xv - xp) +
                            weights.area_factor * l_x.begin()[i];
        y.block(Field::V).begin()[i] +=
          m[i] * (-a * xu + (a + weights.e(v[i], p[i])) * xv);
        y.block(Field::P).begin()[i] += -m[i] * xu;
      }
    for (unsigned int b = 0; b < 3; ++b)
      ops.zero_constrained(y.block(b));
  }



  // ---------------------------------------------------------------------
  // The Newton system: elimination (no restoration terms) ...
  // ---------------------------------------------------------------------

  template <int dim>
  typename NestedStep<dim>::Vector
  NestedStep<dim>::k_weights(const Vector &v, const double shift) const
  {
    Vector             weight(v);
    const unsigned int n = v.locally_owned_size();
    for (unsigned int i = 0; i < n; ++i)
      weight.begin()[i] = weights.k(v.begin()[i], shift);
    return weight;
  }



  template <int dim>
  void
  NestedStep<dim>::build_k(const Vector                   &v,
                           const double                    shift,
                           TrilinosWrappers::SparseMatrix &k) const
  {
    ops.stiffness_plus_weighted_mass(weights.inner_tau, k_weights(v, shift), k);
  }



  template <int dim>
  void
  NestedStep<dim>::build_k(const Vector          &v,
                           const double           shift,
                           StiffnessPlusDiagonal &k) const
  {
    ops.stiffness_plus_weighted_mass(weights.inner_tau, k_weights(v, shift), k);
  }



  template <int dim>
  unsigned int
  NestedStep<dim>::solve_with_k(const Vector &v,
                                LinearSolver &solver,
                                Vector       &x,
                                const Vector &rhs) const
  {
    const auto solve = [&](auto &&k) {
      build_k(v, 0., k);
      return solver.solve(k, x, rhs);
    };
    return solver.type() == LinearSolverType::iterative ?
             solve(StiffnessPlusDiagonal()) :
             solve(TrilinosWrappers::SparseMatrix());
  }



  template <int dim>
  unsigned int
  NestedStep<dim>::solve_jacobian(const BlockVector &z,
                                  const BlockVector &r,
                                  BlockVector       &dz,
                                  LinearSolver      &solver)
  {
    if (coeff.outer.has_restoration_terms())
      return solve_full_system(z, r, dz, solver, 0.);
    ReducedMatrices  local;
    ReducedMatrices &matrices = reduced_matrix_storage(local);
    // if the matrices do not depend on the state: build (and factorise)
    // them once
    if (!constant_jacobian || matrices.k.empty())
      {
        build_reduced_matrices(z, matrices, solver.type());
        if (constant_jacobian && solver.type() == LinearSolverType::direct)
          solver.factorize(matrices.s);
      }
    return solve_reduced_system(matrices, r, dz, solver);
  }



  template <int dim>
  void
  NestedStep<dim>::build_reduced_matrices(const BlockVector     &z,
                                          ReducedMatrices       &matrices,
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

    build_k(v, 0., matrices.k);

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
          w, weights.inner_tau, k_weights(v, b), diagonal, matrices.s);
      }
    else
      {
        build_k(v, b, matrices.k_hat);
        build_schur_factor(
          v, b, w, mass_weight, matrices.g, matrices.interface_mode);
      }
  }



  template <int dim>
  void
  NestedStep<dim>::build_schur_factor(const Vector          &v,
                                      const double           b,
                                      const double           w,
                                      const double           m,
                                      StiffnessPlusDiagonal &g,
                                      Vector &interface_mode) const
  {
    const double scale  = std::sqrt(w / m);
    Vector       weight = k_weights(v, b);
    weight *= scale;
    weight.add(schur_mass_shift);
    ops.stiffness_plus_weighted_mass(scale * weights.inner_tau, weight, g);
    interface_mode.reinit(v, true);
    for (unsigned int i = 0; i < v.locally_owned_size(); ++i)
      interface_mode.begin()[i] = 1 - v.begin()[i] * v.begin()[i];
  }



  template <int dim>
  unsigned int
  NestedStep<dim>::solve_reduced_system(const ReducedMatrices &matrices,
                                        const BlockVector     &r,
                                        BlockVector           &dz,
                                        LinearSolver          &solver) const
  {
    const double a = weights.a;
    const double w = matrices.uu_weight;

    const auto   &k   = matrices.k;
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
        solver.solve_product_form(matrices.k_hat,
                                  w,
                                  matrices.diagonal,
                                  matrices.g,
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



  // ---------------------------------------------------------------------
  // ... and the assembled 3-field system (restoration terms)
  // ---------------------------------------------------------------------

  template <int dim>
  void
  NestedStep<dim>::reinit_full_jacobian(TrilinosWrappers::SparseMatrix &j) const
  {
    const auto                   &L      = ops.stiffness;
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
    j.reinit(owned3, owned3, dsp, discretization.get_mpi_communicator());
  }



  template <int dim>
  void
  NestedStep<dim>::assemble_full_jacobian(
    const BlockVector              &z,
    const double                    shift,
    TrilinosWrappers::SparseMatrix &j) const
  {
    const double       a           = weights.a;
    const double       area_factor = weights.area_factor;
    const auto        &L           = ops.stiffness;
    const IndexSet    &owned       = ops.locally_owned_dofs;
    const unsigned int n           = owned.n_elements();
    const double      *m           = ops.lumped_mass.begin();
    const double      *u           = z.block(Field::U).begin();
    const double      *v           = z.block(Field::V).begin();
    const double      *p           = z.block(Field::P).begin();

    // U rows and columns replaced by the identity: fixed and constrained
    std::vector<bool> identity_row(n, false);
    for (unsigned int i = 0; i < n; ++i)
      identity_row[i] = u_is_fixed(i);
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
  typename NestedStep<dim>::ReducedMatrices &
  NestedStep<dim>::reduced_matrix_storage(ReducedMatrices &local) const
  {
    return mesh_matrices != nullptr ? *mesh_matrices : local;
  }



  template <int dim>
  TrilinosWrappers::SparseMatrix &
  NestedStep<dim>::full_jacobian_storage(
    TrilinosWrappers::SparseMatrix &local) const
  {
    return mesh_matrices != nullptr ? mesh_matrices->full_jacobian : local;
  }



  template <int dim>
  unsigned int
  NestedStep<dim>::solve_full_system(const BlockVector &z,
                                     const BlockVector &r,
                                     BlockVector       &dz,
                                     LinearSolver      &solver,
                                     const double       shift) const
  {
    if (coeff.outer.fixed_u == nullptr)
      return solve_area_system(z, r, dz, solver, shift);
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
    TrilinosWrappers::SparseMatrix  local;
    TrilinosWrappers::SparseMatrix &j = full_jacobian_storage(local);
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
      if (u_is_fixed(i))
        dz.block(Field::U).begin()[i] = 0;
    for (unsigned int b = 0; b < 3; ++b)
      ops.zero_constrained(dz.block(b));
    return iterations;
  }



  template <int dim>
  unsigned int
  NestedStep<dim>::solve_area_system(const BlockVector &z,
                                     const BlockVector &r,
                                     BlockVector       &dz,
                                     LinearSolver      &solver,
                                     const double       shift) const
  {
    ReducedMatrices  local;
    ReducedMatrices &matrices = reduced_matrix_storage(local);
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
      apply_jacobian(matrices.k, z, x, y, shift);
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



  template <int dim>
  unsigned int
  NestedStep<dim>::solve_shifted_jacobian(const BlockVector &z,
                                          const BlockVector &r,
                                          BlockVector       &dz,
                                          LinearSolver      &solver,
                                          const double       shift)
  {
    if (coeff.outer.has_restoration_terms())
      return solve_full_system(z, r, dz, solver, shift);
    // the shift enters the U-U block, (1 + a + shift) M, which the
    // elimination keeps exactly (build_reduced_matrices())
    ReducedMatrices  local;
    ReducedMatrices &matrices = reduced_matrix_storage(local);
    build_reduced_matrices(z, matrices, solver.type(), shift);
    return solve_reduced_system(matrices, r, dz, solver);
  }



  // ---------------------------------------------------------------------
  // The inner problem and the outer energy as a function of U
  // ---------------------------------------------------------------------

  template <int dim>
  void
  NestedStep<dim>::inner_residual(const Vector &u,
                                  const Vector &v,
                                  Vector       &r) const
  {
    const double       c = weights.c;
    const double      *m = ops.lumped_mass.begin();
    const unsigned int n = u.locally_owned_size();
    ops.stiffness.vmult(r, v);
    r *= weights.inner_tau;
    for (unsigned int i = 0; i < n; ++i)
      r.begin()[i] += m[i] * ((v.begin()[i] - u.begin()[i]) +
                              c * DoubleWell::d_psi(v.begin()[i]));
    ops.zero_constrained(r);
  }



  template <int dim>
  unsigned int
  NestedStep<dim>::initialize_v_and_p(BlockVector  &z,
                                      LinearSolver &solver,
                                      const double  tolerance) const
  {
    z.block(Field::V) = z.block(Field::U);
    Vector r(z.block(Field::U));
    inner_residual(z.block(Field::U), z.block(Field::V), r);
    return solve_inner_problem(
      z, solver, std::max(tolerance * ops.dual_norm(r), Constants::roundoff));
  }



  template <int dim>
  unsigned int
  NestedStep<dim>::solve_inner_problem(BlockVector  &z,
                                       LinearSolver &solver,
                                       const double  tolerance) const
  {
    // V: Newton on R_P(U, V) = 0 with full steps (a convex problem), to
    // the absolute tolerance or until the residual stagnates at round-off
    // (about 1e-15 in this norm); inexact, as the outer Newton method:
    // each linear solve only as tight as the next Newton residual needs
    NewtonControl control;
    control.absolute_tolerance = tolerance;
    control.max_iterations     = 50;
    control.line_search        = false;
    control.roundoff_level     = 1e-12;
    const MPI_Comm comm        = discretization.get_mpi_communicator();
    BlockVector    v(std::vector<IndexSet>(1, ops.locally_owned_dofs), comm);
    v.block(0) = z.block(Field::V);
    InnerProblem     inner(*this, z.block(Field::U));
    const StepReport report = newton_solve(
      inner, v, control, solver, ConditionalOStream(std::cout, false), false);
    AssertThrow(report.converged,
                ExcMessage("The inner problem (V for given U, Algorithm "
                           "3.1) did not converge in 50 Newton "
                           "iterations."));
    z.block(Field::V) = v.block(0);

    // P: K(V) P = -a M (V - U)
    const Vector      &u = z.block(Field::U);
    const Vector      &w = z.block(Field::V);
    Vector            &p = z.block(Field::P);
    const double      *m = ops.lumped_mass.begin();
    const unsigned int n = u.locally_owned_size();
    Vector             r(u);
    for (unsigned int i = 0; i < n; ++i)
      r.begin()[i] = -weights.a * m[i] * (w.begin()[i] - u.begin()[i]);
    ops.zero_constrained(r);
    // P at the solver's own tolerance, not the last one of the Newton solve
    solver.set_tolerance(0);
    solve_with_k(w, solver, p, r);
    ops.zero_constrained(p);
    return report.newton_iterations;
  }



  template <int dim>
  double
  NestedStep<dim>::outer_energy(const BlockVector &z) const
  {
    const Vector &u = z.block(Field::U);
    Vector        difference(u);
    difference -= old_u;
    double energy = 0.5 * ops.mass_product(difference, difference);
    difference    = z.block(Field::V);
    difference -= u;
    energy += 0.5 * weights.a * ops.mass_product(difference, difference);
    if (coeff.outer.area_weight != 0)
      // 2 tau eta a_eps[U] / (2 eps)
      energy += weights.area_factor * area_functional(ops, u, coeff.epsilon) /
                coeff.epsilon;
    if (coeff.outer.forcing != nullptr)
      // -2 tau F.U / (2 eps)
      energy -= coeff.tau / coeff.epsilon * (*coeff.outer.forcing * u);
    return energy;
  }



  template <int dim>
  double
  NestedStep<dim>::project_and_energy(BlockVector &z)
  {
    AssertThrow(inner_solver != nullptr,
                ExcMessage("NestedStep::project_and_energy() needs a solver "
                           "of the inner problem (set_inner_solver())."));
    solve_inner_problem(z, *inner_solver, inner_tolerance);
    return outer_energy(z);
  }



  template <int dim>
  double
  NestedStep<dim>::energy_roundoff(const BlockVector &z,
                                   const double       energy) const
  {
    const Vector &u = z.block(Field::U);
    const Vector &v = z.block(Field::V);
    Vector        r(u);
    inner_residual(u, v, r);
    Vector difference(v);
    difference -= u;
    const auto norm = [this](const Vector &x) {
      return std::sqrt(ops.mass_product(x, x));
    };
    const double v_error =
      ops.dual_norm(r) +
      std::numeric_limits<double>::epsilon() * (norm(u) + norm(v));
    return MinimizationProblem::energy_roundoff(z, energy) +
           weights.a * norm(difference) * v_error;
  }



  // ---------------------------------------------------------------------
  // The scheme: Algorithm 3.1, one step per time step, the energy law
  // ---------------------------------------------------------------------



  template <int dim>
  NestedScheme<dim>::NestedScheme(const SchemeSettings      &settings,
                                  const Discretization<dim> &discretization,
                                  const ConditionalOStream  &pcout)
    : settings(settings)
    , discretization(discretization)
    , pcout(pcout)
    , linear_solver(std::make_unique<LinearSolver>(
        LinearSolver::resolve_type(settings.linear_solver.type, dim),
        settings.linear_solver.relative_tolerance,
        settings.linear_solver.max_iterations,
        /*symmetric=*/true,
        settings.outer_energy.has_restoration_terms() ?
          full_system_refactorization_threshold :
          LinearSolver::default_refactorization_threshold,
        settings.outer_energy.has_restoration_terms() ?
          full_system_refactorization_threshold :
          0))
    , mesh_matrices(
        std::make_unique<typename NestedStep<dim>::ReducedMatrices>())
  {
    linear_solver->set_constant_matrix(linear_model());
    // every step passes mesh_matrices, refilled in place; reset_solver()
    // replaces both together
    linear_solver->set_persistent_matrices(true);
  }



  template <int dim>
  bool
  NestedScheme<dim>::linear_model() const
  {
    return !settings.double_well &&
           !settings.outer_energy.has_restoration_terms();
  }



  template <int dim>
  std::string
  NestedScheme<dim>::name() const
  {
    return "nested";
  }



  template <int dim>
  std::vector<std::string>
  NestedScheme<dim>::field_names() const
  {
    return {"U", "V", "P"};
  }



  template <int dim>
  std::string
  NestedScheme<dim>::linear_solver_description() const
  {
    return linear_solver->type() == LinearSolverType::direct ?
             "direct (MUMPS)" :
             "iterative (CG + AMG)";
  }



  template <int dim>
  std::vector<std::string>
  NestedScheme<dim>::warnings() const
  {
    if (settings.double_well &&
        settings.inner_tau >= 0.5 * std::pow(settings.epsilon, 2))
      return {"Inner tau >= epsilon^2/2; the inner (Allen-Cahn) energy is "
              "then not convex and Newton may fail."};
    return {};
  }



  template <int dim>
  NestedCoefficients
  NestedScheme<dim>::coefficients(const double tau) const
  {
    NestedCoefficients c;
    c.epsilon     = settings.epsilon;
    c.tau         = tau;
    c.inner_tau   = settings.inner_tau;
    c.double_well = settings.double_well;
    c.outer       = settings.outer_energy;
    return c;
  }



  template <int dim>
  std::unique_ptr<LinearSolver>
  NestedScheme<dim>::make_solver(const LinearSolverType type) const
  {
    return std::make_unique<LinearSolver>(
      type,
      settings.linear_solver.relative_tolerance,
      settings.linear_solver.max_iterations);
  }



  template <int dim>
  void
  NestedScheme<dim>::initialize(BlockVector &state, const double tau)
  {
    const NestedStep<dim> step(discretization,
                               coefficients(tau),
                               state.block(Field::U));
    // its own solver: the factorisations of K are no use for S later
    const std::unique_ptr<LinearSolver> solver =
      make_solver(linear_solver->type());
    constexpr double initialization_tolerance = 1e-10;
    step.initialize_v_and_p(state, *solver, initialization_tolerance);
    discretization.distribute_constraints(state);
    first_step_from_initial_data = true;
  }



  template <int dim>
  void
  NestedScheme<dim>::prepare_step(BlockVector &state,
                                  const double state_tau,
                                  const double tau) const
  {
    // P is proportional to tau at the start of a step (R_V = 0 with
    // a = tau / ttau^2): start Newton from the P of this tau
    if (tau != state_tau)
      state.block(Field::P) *= tau / state_tau;
  }



  template <int dim>
  StepReport
  NestedScheme<dim>::advance(const BlockVector &old_state,
                             BlockVector       &state,
                             const double       tau)
  {
    const StepReport report = attempt_step(old_state, state, tau);
    // The first step from the initial data ends when it is accepted: its
    // halved attempts keep the descent fallback (the level-8 cube: Newton's
    // method failed at tau and at tau/2)
    if (report.converged)
      first_step_from_initial_data = false;
    return report;
  }



  template <int dim>
  StartExtrapolation
  NestedScheme<dim>::start_extrapolation() const
  {
    return solves_by_descent() ? StartExtrapolation::profile :
                                 StartExtrapolation::linear;
  }



  template <int dim>
  bool
  NestedScheme<dim>::take_extrapolated_start(const BlockVector &old_state,
                                             const BlockVector &last_result,
                                             BlockVector       &extrapolated,
                                             const double       tau) const
  {
    NestedStep<dim> step(discretization,
                         coefficients(tau),
                         old_state.block(Field::U));
    if (solves_by_descent())
      {
        const std::unique_ptr<LinearSolver> solver =
          make_solver(linear_solver->type());
        step.solve_inner_problem(extrapolated,
                                 *solver,
                                 NestedStep<dim>::inner_tolerance);
        if (settings.verbose)
          pcout << "    descent method: U extrapolated, V and P re-solved"
                << std::endl;
        return true;
      }
    BlockVector residual(last_result);
    const auto  norm_at = [&](const BlockVector &start) {
      step.residual(start, residual);
      return step.residual_norm(residual);
    };
    const double last_norm         = norm_at(last_result);
    const double extrapolated_norm = norm_at(extrapolated);
    if (settings.verbose)
      pcout << "    residual " << extrapolated_norm
            << " at the extrapolated start, " << last_norm
            << " at the last result" << std::endl;
    return extrapolated_norm < last_norm;
  }



  template <int dim>
  bool
  NestedScheme<dim>::solves_by_descent() const
  {
    return settings.outer_energy.fixed_u != nullptr;
  }



  template <int dim>
  StepReport
  NestedScheme<dim>::attempt_step(const BlockVector &old_state,
                                  BlockVector       &state,
                                  const double       tau)
  {
    NestedStep<dim> step(discretization,
                         coefficients(tau),
                         old_state.block(Field::U),
                         mesh_matrices.get());
    NewtonControl   control(settings.newton);
    // a linear system is solved once to the solver's tolerance, not
    // loosely first as inexact Newton does
    control.adapt_linear_tolerance = !linear_model();
    if (linear_model())
      return newton_solve(
        step, state, control, *linear_solver, pcout, settings.verbose);
    // With U fixed outside a region (edge restoration), and in the first
    // step after initialize() with restoration terms, the descent method
    // directly. Otherwise Newton's method with residual damping first: it
    // needs no inner problems (fig6_5_disc.prm, 10 level-6 steps: the
    // same states to the Newton tolerance in 2.0 s instead of 5.8 s of
    // user time).
    const bool first_step  = first_step_from_initial_data;
    const bool restoration = settings.outer_energy.has_restoration_terms();
    if (solves_by_descent() || (first_step && restoration))
      return descent_solve(step, state, control);
    const BlockVector start(state);
    const StepReport  newton = newton_solve(
      step, state, control, *linear_solver, pcout, settings.verbose);
    // Where Newton's method fails, the descent method takes the step from
    // its start before it is halved: the nested step is the minimiser of
    // the outer energy, which every descent iteration lowers (the level-7
    // cube, whose full first step Newton's method could not take). In
    // the Willmore flow only in the first step from the initial data: a
    // later failure means that the flow moves fast, and halving resolves
    // it, where the descent method may find a far lower minimiser (the
    // demo's two circles at step 14: W 25.2 -> 8.9 in one step).
    if (newton.converged || (!restoration && !first_step))
      return newton;
    pcout << "    Newton's method failed: the descent method from the "
             "start of the step"
          << std::endl;
    state = start;
    NewtonControl descent_control(control);
    descent_control.max_iterations = settings.newton.max_descent_iterations;
    StepReport descent = descent_solve(step, state, descent_control);
    descent.newton_iterations += newton.newton_iterations;
    descent.linear_iterations += newton.linear_iterations;
    return descent;
  }



  template <int dim>
  StepReport
  NestedScheme<dim>::descent_solve(NestedStep<dim>     &step,
                                   BlockVector         &state,
                                   const NewtonControl &control)
  {
    // Minimise the outer energy over U with V, P re-solved for every
    // trial U, so that the energy decreases at every iteration (for edge
    // restoration, Newton's method alone converged to critical points
    // that are not minimisers). The inner problem is convex; its own
    // solver keeps the factorisation of K(V).
    const std::unique_ptr<LinearSolver> inner_solver =
      make_solver(linear_solver->type());
    step.set_inner_solver(*inner_solver);
    return minimizing_newton_solve(
      step, state, control, *linear_solver, pcout, settings.verbose);
  }



  template <int dim>
  void
  NestedScheme<dim>::reset_solver()
  {
    linear_solver->reset();
    mesh_matrices =
      std::make_unique<typename NestedStep<dim>::ReducedMatrices>();
  }



  template <int dim>
  void
  NestedScheme<dim>::before_remesh()
  {
    reset_solver();
  }



  template <int dim>
  void
  NestedScheme<dim>::after_remesh(BlockVector &state, const double tau)
  {
    reset_solver();
    if (!settings.outer_energy.has_restoration_terms())
      return;
    // The transferred V is not the inner minimiser on the new mesh, and
    // the energy of the state would not be the one the next step
    // decreases: re-solve V and P for U.
    const std::unique_ptr<LinearSolver> solver =
      make_solver(linear_solver->type());
    NestedStep<dim>(discretization, coefficients(tau), state.block(Field::U))
      .solve_inner_problem(state, *solver, NestedStep<dim>::inner_tolerance);
  }



  template <int dim>
  Energies
  NestedScheme<dim>::energies(const BlockVector &state) const
  {
    const LumpedOperators<dim> &ops = discretization.get_operators();
    Vector                      curvature_field(state.block(Field::U));
    curvature(state, curvature_field);
    Energies e =
      phase_field_energies(ops, state.block(Field::U), settings.epsilon);
    e.willmore = Constants::geometric_unit * 0.5 * settings.epsilon *
                 ops.mass_product(curvature_field, curvature_field);
    return e;
  }



  template <int dim>
  void
  NestedScheme<dim>::curvature(const BlockVector &state,
                               Vector            &curvature) const
  {
    curvature = state.block(Field::U);
    curvature -= state.block(Field::V);
    curvature /= settings.inner_tau;
  }



  template <int dim>
  double
  NestedScheme<dim>::energy_law_energy(const BlockVector &state) const
  {
    const Energies     e     = energies(state);
    const OuterEnergy &outer = settings.outer_energy;
    return outer.willmore_weight * e.willmore + outer.area_weight * e.area;
  }



  template <int dim>
  double
  NestedScheme<dim>::dissipation(const BlockVector &old_state,
                                 const BlockVector &state,
                                 const double       tau) const
  {
    Vector difference(state.block(Field::U));
    difference -= old_state.block(Field::U);
    return Constants::geometric_unit * settings.epsilon / (2 * tau) *
           discretization.get_operators().mass_product(difference, difference);
  }



  template class NestedStep<2>;
  template class NestedStep<3>;
  template class NestedScheme<2>;
  template class NestedScheme<3>;
} // namespace PhaseField
