#include <cmath>
#include <phasefield/problems/mismatch_term.h>

namespace PhaseField
{
  template <int dim>
  MismatchTerm<dim>::MismatchTerm(const Discretization<dim> &discretization,
                                  const unsigned int         level,
                                  std::vector<double>        target,
                                  const double               gamma)
    : discretization(discretization)
    , labeling_grid(level)
    , target(std::move(target))
    , gamma(gamma)
  {
    AssertDimension(this->target.size(), labeling_grid.size());
  }



  template <int dim>
  Vector
  MismatchTerm<dim>::ghosted(const Vector &u) const
  {
    const LumpedOperators<dim> &ops = discretization.get_operators();
    Vector                      v(ops.locally_owned_dofs,
             ops.locally_relevant_dofs,
             u.get_mpi_communicator());
    v = u;
    return v;
  }



  template <int dim>
  typename MismatchTerm<dim>::Evaluation
  MismatchTerm<dim>::evaluate(const Vector &u) const
  {
    Evaluation e;
    e.alpha = HuffmanLabeling::labeling(discretization.get_dof_handler(),
                                        ghosted(u),
                                        labeling_grid);
    const unsigned int  n = labeling_grid.size();
    std::vector<double> squared(n), absolute(n);
    for (unsigned int i = 0; i < n; ++i)
      {
        squared[i]  = std::pow(target[i] - e.alpha[i], 2);
        absolute[i] = std::abs(target[i] - e.alpha[i]);
      }
    e.energy         = gamma * labeling_grid.integrate(squared);
    e.labeling_error = labeling_grid.integrate(absolute);
    return e;
  }



  template <int dim>
  double
  MismatchTerm<dim>::value(const Vector &u) const
  {
    return evaluate(u).energy;
  }



  template <int dim>
  void
  MismatchTerm<dim>::add_transposed(const Vector              &u,
                                    const std::vector<double> &residual,
                                    const double               factor,
                                    Vector                    &y) const
  {
    std::vector<double> r(labeling_grid.size());
    for (unsigned int i = 0; i < labeling_grid.size(); ++i)
      r[i] = 2 * gamma * labeling_grid.weight(i) * residual[i];
    Vector product(y);
    product = 0;
    HuffmanLabeling::add_labeling_derivative(discretization.get_dof_handler(),
                                             discretization.get_constraints(),
                                             u,
                                             labeling_grid,
                                             r,
                                             product);
    y.add(factor, product);
  }



  template <int dim>
  void
  MismatchTerm<dim>::add_gradient(const Vector &u,
                                  const double  factor,
                                  Vector       &g) const
  {
    const Vector        u_ghosted = ghosted(u);
    std::vector<double> residual =
      HuffmanLabeling::labeling(discretization.get_dof_handler(),
                                u_ghosted,
                                labeling_grid);
    for (unsigned int i = 0; i < labeling_grid.size(); ++i)
      residual[i] -= target[i];
    add_transposed(u_ghosted, residual, factor, g);
  }



  template <int dim>
  std::vector<double>
  MismatchTerm<dim>::jacobian_product(const Vector &u, const Vector &d) const
  {
    Vector d_constrained(d);
    discretization.get_constraints().distribute(d_constrained);
    return HuffmanLabeling::labeling_derivative(
      discretization.get_dof_handler(),
      u,
      ghosted(d_constrained),
      labeling_grid);
  }



  template <int dim>
  void
  MismatchTerm<dim>::add_hessian_vmult(const Vector &u,
                                       const Vector &d,
                                       const double  factor,
                                       Vector       &y) const
  {
    const Vector u_ghosted = ghosted(u);
    add_transposed(u_ghosted, jacobian_product(u_ghosted, d), factor, y);
  }



  template <int dim>
  std::unique_ptr<EnergyTerm>
  MismatchTerm<dim>::step_model(const Vector &u0) const
  {
    return std::make_unique<MismatchModel<dim>>(*this, u0);
  }



  template <int dim>
  MismatchModel<dim>::MismatchModel(const MismatchTerm<dim> &term,
                                    const Vector            &u0)
    : term(term)
    , u0_owned(u0)
    , u0(term.ghosted(u0))
  {
    residual0 = HuffmanLabeling::labeling(term.discretization.get_dof_handler(),
                                          this->u0,
                                          term.labeling_grid);
    curvature_weight.resize(residual0.size());
    for (unsigned int i = 0; i < residual0.size(); ++i)
      {
        residual0[i] -= term.target[i];
        curvature_weight[i] = term.gamma * term.labeling_grid.weight(i) *
                              std::max(residual0[i], 0.);
      }
  }



  template <int dim>
  void
  MismatchModel<dim>::add_curvature(const Vector &d,
                                    const double  factor,
                                    Vector       &y) const
  {
    const Discretization<dim> &discretization = term.discretization;
    Vector                     d_constrained(d);
    discretization.get_constraints().distribute(d_constrained);
    Vector product(y);
    product = 0;
    HuffmanLabeling::add_kink_curvature_product(
      discretization.get_dof_handler(),
      discretization.get_constraints(),
      u0,
      term.ghosted(d_constrained),
      term.labeling_grid,
      curvature_weight,
      curvature_floor,
      product);
    y.add(factor, product);
  }



  template <int dim>
  std::vector<double>
  MismatchModel<dim>::linear_residual(const Vector &u) const
  {
    Vector difference(u);
    difference.add(-1., u0_owned);
    std::vector<double> r = term.jacobian_product(u0, difference);
    for (unsigned int i = 0; i < r.size(); ++i)
      r[i] += residual0[i];
    return r;
  }



  template <int dim>
  double
  MismatchModel<dim>::value(const Vector &u) const
  {
    std::vector<double> squared = linear_residual(u);
    for (double &r : squared)
      r *= r;
    Vector difference(u);
    difference.add(-1., u0_owned);
    Vector curvature(u);
    curvature = 0;
    add_curvature(difference, 1., curvature);
    return term.gamma * term.labeling_grid.integrate(squared) +
           0.5 * (difference * curvature);
  }



  template <int dim>
  void
  MismatchModel<dim>::add_gradient(const Vector &u,
                                   const double  factor,
                                   Vector       &g) const
  {
    term.add_transposed(u0, linear_residual(u), factor, g);
    Vector difference(u);
    difference.add(-1., u0_owned);
    add_curvature(difference, factor, g);
  }



  template <int dim>
  void
  MismatchModel<dim>::add_hessian_vmult(const Vector &,
                                        const Vector &d,
                                        const double  factor,
                                        Vector       &y) const
  {
    term.add_transposed(u0, term.jacobian_product(u0, d), factor, y);
    add_curvature(d, factor, y);
  }



  template class MismatchTerm<2>;
  template class MismatchTerm<3>;
  template class MismatchModel<2>;
  template class MismatchModel<3>;
} // namespace PhaseField
