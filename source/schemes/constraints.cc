#include <cmath>
#include <deal.II/base/mpi.h>
#include <deal.II/base/numbers.h>
#include <phasefield/core/constants.h>
#include <phasefield/schemes/constraints.h>

namespace PhaseField
{
  using namespace dealii;

  namespace
  {
    /** Int (1-U)/2 with the lumped mass. Collective. */
    template <int dim>
    double
    inside_measure(const LumpedOperators<dim> &operators, const Vector &u)
    {
      const double *m   = operators.lumped_mass.begin();
      double        sum = 0;
      for (unsigned int i = 0; i < u.locally_owned_size(); ++i)
        sum += m[i] * 0.5 * (1 - u.begin()[i]);
      return Utilities::MPI::sum(sum, u.get_mpi_communicator());
    }



    /**
     * The area functional (3/4) a_eps[U] as an AreaTerm, whose value is
     * scale a_eps / eps.
     */
    template <int dim>
    AreaTerm<dim>
    area_functional_term(const LumpedOperators<dim> &operators,
                         const double                epsilon)
    {
      return AreaTerm<dim>(operators,
                           Constants::geometric_unit * epsilon,
                           epsilon);
    }



    /**
     * The reduced volume of a body of inside measure @p volume and area
     * @p area: V over the volume of the ball of the same area (3D), or
     * 4 pi V / A^2 (2D); 1 for the ball.
     */
    double
    reduced_volume(const int dim, const double volume, const double area)
    {
      if (dim == 2)
        return 4 * numbers::PI * volume / (area * area);
      return 6 * std::sqrt(numbers::PI) * volume / std::pow(area, 1.5);
    }



    /** The inverse of reduced_volume(): the volume of @p v at @p area. */
    double
    volume_of_reduced_volume(const int dim, const double v, const double area)
    {
      return v / reduced_volume(dim, 1., area);
    }
  } // namespace



  ScalarConstraints::ScalarConstraints(const ConstraintParameters &parameters,
                                       const double                epsilon)
    : epsilon(epsilon)
    , reduced_volume(parameters.reduced_volume)
  {
    if (parameters.volume)
      {
        kinds.push_back(ScalarConstraint::volume);
        targets.push_back(parameters.volume_value);
      }
    if (parameters.area)
      {
        kinds.push_back(ScalarConstraint::area);
        targets.push_back(parameters.area_value);
      }
    multipliers.assign(kinds.size(), 0.);
    lambda.assign(kinds.size(), 0.);
  }



  std::string
  ScalarConstraints::name()
  {
    return "volume and area constraints";
  }



  std::shared_ptr<ScalarConstraints>
  ScalarConstraints::of(const OuterEnergy &outer)
  {
    const auto entry = outer.registered_terms.find(name());
    if (entry == outer.registered_terms.end())
      return nullptr;
    return std::any_cast<std::shared_ptr<ScalarConstraints>>(entry->second);
  }



  template <int dim>
  double
  ScalarConstraints::value_of(const ScalarConstraint      kind,
                              const LumpedOperators<dim> &operators,
                              const Vector               &u) const
  {
    if (kind == ScalarConstraint::volume)
      return inside_measure(operators, u);
    return area_functional_term(operators, epsilon).value(u);
  }



  template <int dim>
  double
  ScalarConstraints::value(const unsigned int          j,
                           const LumpedOperators<dim> &operators,
                           const Vector               &u) const
  {
    return value_of(kinds[j], operators, u);
  }



  template <int dim>
  void
  ScalarConstraints::add_gradient(const unsigned int          j,
                                  const LumpedOperators<dim> &operators,
                                  const Vector               &u,
                                  const double                factor,
                                  Vector                     &g) const
  {
    if (kinds[j] == ScalarConstraint::volume)
      g.add(-0.5 * factor, operators.lumped_mass);
    else
      area_functional_term(operators, epsilon).add_gradient(u, factor, g);
  }



  template <int dim>
  void
  ScalarConstraints::add_hessian_vmult(const unsigned int          j,
                                       const LumpedOperators<dim> &operators,
                                       const Vector               &u,
                                       const Vector               &d,
                                       const double                factor,
                                       Vector                     &y) const
  {
    // the inside measure is linear in U
    if (kinds[j] == ScalarConstraint::area)
      area_functional_term(operators, epsilon)
        .add_hessian_vmult(u, d, factor, y);
  }



  template <int dim>
  void
  ScalarConstraints::set_missing_targets(const LumpedOperators<dim> &operators,
                                         const Vector               &u)
  {
    for (unsigned int j = 0; j < size(); ++j)
      if (targets[j] == 0)
        targets[j] = value(j, operators, u);
    if (reduced_volume != 0)
      targets[index(ScalarConstraint::volume)] =
        volume_of_reduced_volume(dim,
                                 reduced_volume,
                                 targets[index(ScalarConstraint::area)]);
  }



  double
  ScalarConstraints::to_residual_units(const double tau) const
  {
    return tau / (Constants::geometric_unit * epsilon);
  }



  unsigned int
  ScalarConstraints::index(const ScalarConstraint kind) const
  {
    unsigned int j = 0;
    while (j < size() && kinds[j] != kind)
      ++j;
    return j;
  }



  double
  ScalarConstraints::pressure() const
  {
    // 0, not -0, before the first step
    const unsigned int j = index(ScalarConstraint::volume);
    return j < size() && multipliers[j] != 0 ? -multipliers[j] : 0.;
  }



  double
  ScalarConstraints::tension() const
  {
    const unsigned int j = index(ScalarConstraint::area);
    return j < size() ? multipliers[j] : 0.;
  }



  // ---------------------------------------------------------------------
  // The term of the step and its registry entry
  // ---------------------------------------------------------------------

  template <int dim>
  ConstraintTerm<dim>::ConstraintTerm(const ScalarConstraints    &constraints,
                                      const LumpedOperators<dim> &operators)
    : constraints(constraints)
    , ops(operators)
  {}



  template <int dim>
  double
  ConstraintTerm<dim>::value(const Vector &u) const
  {
    double sum = 0;
    for (unsigned int j = 0; j < constraints.size(); ++j)
      sum += constraints.step_multipliers()[j] *
             (constraints.value(j, ops, u) - constraints.target(j));
    return sum;
  }



  template <int dim>
  void
  ConstraintTerm<dim>::add_gradient(const Vector &u,
                                    const double  factor,
                                    Vector       &g) const
  {
    for (unsigned int j = 0; j < constraints.size(); ++j)
      constraints.add_gradient(
        j, ops, u, factor * constraints.step_multipliers()[j], g);
  }



  template <int dim>
  void
  ConstraintTerm<dim>::add_hessian_vmult(const Vector &u,
                                         const Vector &d,
                                         const double  factor,
                                         Vector       &y) const
  {
    for (unsigned int j = 0; j < constraints.size(); ++j)
      constraints.add_hessian_vmult(
        j, ops, u, d, factor * constraints.step_multipliers()[j], y);
  }



  namespace
  {
    /** The ConstraintTerm of @p outer (deduces the dimension). */
    template <int dim>
    std::unique_ptr<EnergyTerm>
    make_constraint_term(const OuterEnergy          &outer,
                         const LumpedOperators<dim> &operators)
    {
      return std::make_unique<ConstraintTerm<dim>>(
        *ScalarConstraints::of(outer), operators);
    }



    /** The values of the statistics columns of constraints_entry(). */
    template <int dim>
    std::vector<double>
    constraint_statistics(const OuterEnergy          &outer,
                          const LumpedOperators<dim> &operators,
                          const Vector               &u)
    {
      const ScalarConstraints &constraints = *ScalarConstraints::of(outer);
      const double             volume =
        constraints.value_of(ScalarConstraint::volume, operators, u);
      const double area =
        constraints.value_of(ScalarConstraint::area, operators, u);
      std::vector<double> values{constraints.pressure(),
                                 constraints.tension(),
                                 0.,
                                 0.,
                                 reduced_volume(dim, volume, area)};
      for (unsigned int j = 0; j < constraints.size(); ++j)
        {
          const bool v = constraints.kind(j) == ScalarConstraint::volume;
          if (constraints.target(j) != 0)
            values[v ? 2 : 3] = (v ? volume : area) / constraints.target(j) - 1;
        }
      return values;
    }
  } // namespace



  ModelTermEntry
  constraints_entry()
  {
    ModelTermEntry entry;
    entry.name = ScalarConstraints::name();
    entry.set_factory(
      [](const OuterEnergy &outer,
         const auto        &operators,
         const double,
         const double) { return make_constraint_term(outer, operators); });
    entry.set_statistics(
      {"pressure", "tension", "volume_change", "area_change", "reduced_volume"},
      [](const OuterEnergy &outer, const auto &operators, const Vector &u) {
        return constraint_statistics(outer, operators, u);
      });
    return entry;
  }



  template double
  ScalarConstraints::value_of(const ScalarConstraint,
                              const LumpedOperators<2> &,
                              const Vector &) const;
  template double
  ScalarConstraints::value_of(const ScalarConstraint,
                              const LumpedOperators<3> &,
                              const Vector &) const;
  template double
  ScalarConstraints::value(const unsigned int,
                           const LumpedOperators<2> &,
                           const Vector &) const;
  template double
  ScalarConstraints::value(const unsigned int,
                           const LumpedOperators<3> &,
                           const Vector &) const;
  template void
  ScalarConstraints::add_gradient(const unsigned int,
                                  const LumpedOperators<2> &,
                                  const Vector &,
                                  const double,
                                  Vector &) const;
  template void
  ScalarConstraints::add_gradient(const unsigned int,
                                  const LumpedOperators<3> &,
                                  const Vector &,
                                  const double,
                                  Vector &) const;
  template void
  ScalarConstraints::add_hessian_vmult(const unsigned int,
                                       const LumpedOperators<2> &,
                                       const Vector &,
                                       const Vector &,
                                       const double,
                                       Vector &) const;
  template void
  ScalarConstraints::add_hessian_vmult(const unsigned int,
                                       const LumpedOperators<3> &,
                                       const Vector &,
                                       const Vector &,
                                       const double,
                                       Vector &) const;
  template void
  ScalarConstraints::set_missing_targets(const LumpedOperators<2> &,
                                         const Vector &);
  template void
  ScalarConstraints::set_missing_targets(const LumpedOperators<3> &,
                                         const Vector &);
  template class ConstraintTerm<2>;
  template class ConstraintTerm<3>;
} // namespace PhaseField
