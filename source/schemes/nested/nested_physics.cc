#include <cmath>
#include <limits>
#include <phasefield/schemes/energies.h>
#include <phasefield/schemes/energy_term_registry.h>
#include <phasefield/schemes/nested/nested_physics.h>

namespace PhaseField
{
  using namespace dealii;

  template <int dim>
  NestedPhysics<dim>::NestedPhysics(const Discretization<dim> &discretization,
                                    const NestedCoefficients  &coefficients,
                                    const Vector              &old_u)
    : discretization(discretization)
    , ops(discretization.get_operators())
    , stiffness(ops.stiffness_operator())
    , coeff(coefficients)
    , weights(coefficients)
    , old_u(old_u)
    , terms(make_outer_energy_terms(coefficients.outer,
                                    ops,
                                    coefficients.tau,
                                    coefficients.epsilon))
    , data_term(make_data_term(coefficients.outer,
                               coefficients.tau,
                               coefficients.epsilon,
                               old_u))
  {}



  template <int dim>
  void
  NestedPhysics<dim>::add_terms_gradient(const Vector &u,
                                         const double  factor,
                                         Vector       &g) const
  {
    for (const auto &term : terms)
      term->add_gradient(u, factor, g);
    if (data_term)
      data_term->add_gradient(u, factor, g);
  }



  template <int dim>
  void
  NestedPhysics<dim>::add_terms_hessian_vmult(const Vector &u,
                                              const Vector &d,
                                              const double  factor,
                                              Vector       &y) const
  {
    for (const auto &term : terms)
      term->add_hessian_vmult(u, d, factor, y);
    if (data_term)
      data_term->add_hessian_vmult(u, d, factor, y);
  }



  template <int dim>
  void
  NestedPhysics<dim>::residual(const BlockVector &z, BlockVector &r) const
  {
    const double  a   = weights.a;
    const double  c   = weights.c;
    Vector       &r_u = r.block(Field::U);
    Vector       &r_v = r.block(Field::V);
    Vector       &r_p = r.block(Field::P);
    const Vector &u   = z.block(Field::U);
    const Vector &v   = z.block(Field::V);
    const Vector &p   = z.block(Field::P);

    // stiffness parts first: r_v = ttau L P, r_p = ttau L V
    stiffness.vmult(r_v, p);
    r_v *= weights.inner_tau;
    stiffness.vmult(r_p, v);
    r_p *= weights.inner_tau;

    const unsigned int n  = u.locally_owned_size();
    const double      *m  = ops.lumped_mass.begin();
    const double      *uk = old_u.begin();
    for (unsigned int i = 0; i < n; ++i)
      {
        const double ui = u.begin()[i], vi = v.begin()[i], pi = p.begin()[i];
        const double k_diag = m[i] * weights.k(vi);
        r_u.begin()[i]      = m[i] * ((ui - uk[i]) - a * (vi - ui) - pi);
        r_v.begin()[i] += a * m[i] * (vi - ui) + k_diag * pi;
        r_p.begin()[i] += m[i] * ((vi - ui) + c * DoubleWell::d_psi(vi));
      }
    // the area term; no U-row at fixed U values
    add_terms_gradient(u, 1., r_u);
    zero_fixed_u(r_u);
    for (unsigned int b = 0; b < 3; ++b)
      ops.zero_constrained(r.block(b));
  }



  template <int dim>
  void
  NestedPhysics<dim>::zero_fixed_u(Vector &u_block) const
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
  NestedPhysics<dim>::u_is_fixed(const unsigned int i) const
  {
    return coeff.outer.fixed_u != nullptr &&
           coeff.outer.fixed_u->is_element(
             ops.locally_owned_dofs.nth_index_in_set(i));
  }



  template <int dim>
  double
  NestedPhysics<dim>::residual_norm(const BlockVector &r) const
  {
    double sum = 0;
    for (unsigned int b = 0; b < 3; ++b)
      sum += std::pow(ops.dual_norm(r.block(b)), 2);
    return std::sqrt(sum);
  }



  template <int dim>
  double
  NestedPhysics<dim>::term_scale(const BlockVector &z) const
  {
    Vector difference(z.block(Field::V));
    difference -= z.block(Field::U);
    return mass_norm(z.block(Field::U)) + weights.a * mass_norm(difference) +
           mass_norm(z.block(Field::P));
  }



  template <int dim>
  double
  NestedPhysics<dim>::roundoff_level(const BlockVector &z) const
  {
    const double u = mass_norm(z.block(Field::U));
    return std::numeric_limits<double>::epsilon() *
           (u + weights.a * (u + mass_norm(z.block(Field::V))) +
            mass_norm(z.block(Field::P)));
  }



  template <int dim>
  void
  NestedPhysics<dim>::jacobian_vmult(const BlockVector &z,
                                     const BlockVector &x,
                                     BlockVector       &y,
                                     const double       shift) const
  {
    std::unique_ptr<ShiftedStiffness> k;
    build_k(z.block(Field::V), 0., k);
    apply_jacobian(*k, z, x, y, shift);
  }



  template <int dim>
  void
  NestedPhysics<dim>::apply_jacobian(const ShiftedStiffness &k,
                                     const BlockVector      &z,
                                     const BlockVector      &x_in,
                                     BlockVector            &y,
                                     const double            shift) const
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
    stiffness.vmult(l_x, x.block(Field::U));
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
    // the Hessians that J does not hold matrix-free: registered terms
    // (EnergyTerm::in_nested_jacobian()) and the data term (Gauss-Newton)
    const auto add_matrix_free = [&](const EnergyTerm &term) {
      Vector hd(y.block(Field::U));
      hd = 0;
      term.add_hessian_vmult(z.block(Field::U), x.block(Field::U), 1., hd);
      zero_fixed_u(hd);
      y.block(Field::U) += hd;
    };
    for (const auto &term : terms)
      if (!term->in_nested_jacobian())
        add_matrix_free(*term);
    if (data_term)
      add_matrix_free(*data_term);
    for (unsigned int b = 0; b < 3; ++b)
      ops.zero_constrained(y.block(b));
  }



  template <int dim>
  Vector
  NestedPhysics<dim>::k_weights(const Vector &v, const double shift) const
  {
    Vector             weight(v);
    const unsigned int n = v.locally_owned_size();
    for (unsigned int i = 0; i < n; ++i)
      weight.begin()[i] = weights.k(v.begin()[i], shift);
    return weight;
  }



  template <int dim>
  void
  NestedPhysics<dim>::build_k(const Vector                      &v,
                              const double                       shift,
                              std::unique_ptr<ShiftedStiffness> &k) const
  {
    ops.stiffness_plus_weighted_mass(weights.inner_tau, k_weights(v, shift), k);
  }



  template <int dim>
  void
  NestedPhysics<dim>::build_schur_factor(const Vector                      &v,
                                         const double                       b,
                                         const double                       w,
                                         const double                       m,
                                         std::unique_ptr<ShiftedStiffness> &g,
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
  void
  NestedPhysics<dim>::inner_residual(const Vector &u,
                                     const Vector &v,
                                     Vector       &r) const
  {
    const double       c = weights.c;
    const double      *m = ops.lumped_mass.begin();
    const unsigned int n = u.locally_owned_size();
    stiffness.vmult(r, v);
    r *= weights.inner_tau;
    for (unsigned int i = 0; i < n; ++i)
      r.begin()[i] += m[i] * ((v.begin()[i] - u.begin()[i]) +
                              c * DoubleWell::d_psi(v.begin()[i]));
    ops.zero_constrained(r);
  }



  template <int dim>
  double
  NestedPhysics<dim>::outer_energy(const BlockVector &z) const
  {
    const Vector &u = z.block(Field::U);
    Vector        difference(u);
    difference -= old_u;
    double energy = 0.5 * ops.mass_product(difference, difference);
    difference    = z.block(Field::V);
    difference -= u;
    energy += 0.5 * weights.a * ops.mass_product(difference, difference);
    // 2 tau eta a_eps[U] / (2 eps), -2 tau F.U / (2 eps)
    for (const auto &term : terms)
      energy += term->value(u);
    // 2 tau d[U] / (2 eps)
    if (data_term)
      energy += data_term->value(u);
    return energy;
  }



  template <int dim>
  void
  NestedPhysics<dim>::adjoint_rhs(const BlockVector &z, Vector &r) const
  {
    const Vector      &u = z.block(Field::U);
    const Vector      &v = z.block(Field::V);
    const double      *m = ops.lumped_mass.begin();
    const unsigned int n = u.locally_owned_size();
    r.reinit(u, true);
    for (unsigned int i = 0; i < n; ++i)
      r.begin()[i] = -weights.a * m[i] * (v.begin()[i] - u.begin()[i]);
    ops.zero_constrained(r);
  }



  template <int dim>
  void
  NestedPhysics<dim>::k_vmult(const Vector &v,
                              const Vector &d,
                              Vector       &kd) const
  {
    // K(V) d = ttau L d + M[k(V)] d
    stiffness.vmult(kd, d);
    kd *= weights.inner_tau;
    const double      *m = ops.lumped_mass.begin();
    const unsigned int n = d.locally_owned_size();
    for (unsigned int i = 0; i < n; ++i)
      kd.begin()[i] += m[i] * weights.k(v.begin()[i]) * d.begin()[i];
    ops.zero_constrained(kd);
  }



  template <int dim>
  double
  NestedPhysics<dim>::mass_norm(const Vector &x) const
  {
    return std::sqrt(ops.mass_product(x, x));
  }



  template <int dim>
  double
  NestedPhysics<dim>::outer_energy_error(const BlockVector &z) const
  {
    const Vector &u = z.block(Field::U);
    const Vector &v = z.block(Field::V);
    Vector        r(u);
    inner_residual(u, v, r);
    Vector difference(v);
    difference -= u;
    const double v_error =
      ops.dual_norm(r) +
      std::numeric_limits<double>::epsilon() * (mass_norm(u) + mass_norm(v));
    return weights.a * mass_norm(difference) * v_error;
  }



  template class NestedPhysics<2>;
  template class NestedPhysics<3>;
} // namespace PhaseField
