#include <phasefield/schemes/double_well.h>
#include <phasefield/schemes/energy_terms.h>

namespace PhaseField
{
  template <int dim>
  AreaTerm<dim>::AreaTerm(const LumpedOperators<dim> &operators,
                          const double                scale,
                          const double                epsilon)
    : ops(operators)
    , scale(scale)
    , epsilon(epsilon)
  {}



  template <int dim>
  double
  AreaTerm<dim>::value(const Vector &u) const
  {
    return scale * area_functional(ops, u, epsilon) / epsilon;
  }



  template <int dim>
  template <typename NodalPotential>
  void
  AreaTerm<dim>::add_term(const Vector         &x,
                          const double          factor,
                          const NodalPotential &potential,
                          Vector               &y) const
  {
    Vector l_x(x);
    ops.stiffness_operator().vmult(l_x, x);
    const double       s   = factor * scale;
    const double       c_u = 1. / (2 * epsilon * epsilon);
    const double      *m   = ops.lumped_mass.begin();
    const unsigned int n   = x.locally_owned_size();
    for (unsigned int i = 0; i < n; ++i)
      y.begin()[i] += s * (l_x.begin()[i] + c_u * m[i] * potential(i));
  }



  template <int dim>
  void
  AreaTerm<dim>::add_gradient(const Vector &u,
                              const double  factor,
                              Vector       &g) const
  {
    add_term(
      u,
      factor,
      [&](const unsigned int i) { return DoubleWell::d_psi(u.begin()[i]); },
      g);
  }



  template <int dim>
  void
  AreaTerm<dim>::add_hessian_vmult(const Vector &u,
                                   const Vector &d,
                                   const double  factor,
                                   Vector       &y) const
  {
    add_term(
      d,
      factor,
      [&](const unsigned int i) {
        return DoubleWell::d2_psi(u.begin()[i]) * d.begin()[i];
      },
      y);
  }



  ForcingEnergyTerm::ForcingEnergyTerm(const Vector &forcing,
                                       const double  scale)
    : forcing(forcing)
    , scale(scale)
  {}



  double
  ForcingEnergyTerm::value(const Vector &u) const
  {
    return -scale * (forcing * u);
  }



  void
  ForcingEnergyTerm::add_gradient(const Vector &,
                                  const double factor,
                                  Vector      &g) const
  {
    g.add(-factor * scale, forcing);
  }



  void
  ForcingEnergyTerm::add_hessian_vmult(const Vector &,
                                       const Vector &,
                                       const double,
                                       Vector &) const
  {}



  ScaledTerm::ScaledTerm(const EnergyTerm &term, const double scale)
    : term(term)
    , scale(scale)
  {}



  ScaledTerm::ScaledTerm(std::unique_ptr<EnergyTerm> owned_term,
                         const double                scale)
    : owned(std::move(owned_term))
    , term(*owned)
    , scale(scale)
  {}



  double
  ScaledTerm::value(const Vector &u) const
  {
    return scale * term.value(u);
  }



  void
  ScaledTerm::add_gradient(const Vector &u,
                           const double  factor,
                           Vector       &g) const
  {
    term.add_gradient(u, scale * factor, g);
  }



  void
  ScaledTerm::add_hessian_vmult(const Vector &u,
                                const Vector &d,
                                const double  factor,
                                Vector       &y) const
  {
    term.add_hessian_vmult(u, d, scale * factor, y);
  }



  std::unique_ptr<EnergyTerm>
  make_data_term(const OuterEnergy &outer,
                 const double       tau,
                 const double       epsilon,
                 const Vector      &old_u)
  {
    if (outer.data_term == nullptr)
      return nullptr;
    std::unique_ptr<EnergyTerm> model = outer.data_term->step_model(old_u);
    if (model)
      return std::make_unique<ScaledTerm>(std::move(model), tau / epsilon);
    return std::make_unique<ScaledTerm>(*outer.data_term, tau / epsilon);
  }



  double
  weighted_regularisation(const OuterEnergy &outer, const Energies &e)
  {
    return outer.willmore_weight * e.willmore + outer.area_weight * e.area;
  }



  template class AreaTerm<2>;
  template class AreaTerm<3>;
} // namespace PhaseField
