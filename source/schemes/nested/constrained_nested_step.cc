#include <deal.II/base/mpi.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>
#include <phasefield/schemes/nested/constrained_nested_step.h>

namespace PhaseField
{
  using namespace dealii;

  template <int dim>
  ConstrainedNestedStep<dim>::ConstrainedNestedStep(
    NestedStep<dim>           &step,
    ScalarConstraints         &constraints,
    const Discretization<dim> &discretization)
    : step(step)
    , constraints(constraints)
    , discretization(discretization)
  {}



  template <int dim>
  BlockVector
  ConstrainedNestedStep<dim>::extended_state(
    const BlockVector         &state,
    const std::vector<double> &lambda) const
  {
    const MPI_Comm     comm = discretization.get_mpi_communicator();
    const unsigned int n    = constraints.size();
    IndexSet           owned_multipliers(n);
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      owned_multipliers.add_range(0, n);
    const IndexSet &owned = discretization.get_operators().locally_owned_dofs;
    BlockVector z(std::vector<IndexSet>{owned, owned, owned, owned_multipliers},
                  comm);
    for (unsigned int b = 0; b < multiplier_block; ++b)
      z.block(b) = state.block(b);
    set_scalars(z.block(multiplier_block), lambda);
    return z;
  }



  template <int dim>
  std::vector<double>
  ConstrainedNestedStep<dim>::multipliers(const BlockVector &z) const
  {
    const Vector       &block = z.block(multiplier_block);
    std::vector<double> values(constraints.size(), 0.);
    for (unsigned int j = 0; j < block.locally_owned_size(); ++j)
      values[j] = block.begin()[j];
    for (double &value : values)
      value = Utilities::MPI::sum(value, block.get_mpi_communicator());
    return values;
  }



  template <int dim>
  void
  ConstrainedNestedStep<dim>::copy_nested_state(const BlockVector &z,
                                                BlockVector       &state)
  {
    for (unsigned int b = 0; b < multiplier_block; ++b)
      state.block(b) = z.block(b);
  }



  template <int dim>
  void
  ConstrainedNestedStep<dim>::set_scalars(Vector                    &block,
                                          const std::vector<double> &values)
  {
    for (unsigned int j = 0; j < block.locally_owned_size(); ++j)
      block.begin()[j] = values[j];
  }



  template <int dim>
  void
  ConstrainedNestedStep<dim>::use_multipliers_of(const BlockVector &z) const
  {
    constraints.set_step_multipliers(multipliers(z));
  }



  template <int dim>
  BlockVector
  ConstrainedNestedStep<dim>::nested_part(const BlockVector &z) const
  {
    const IndexSet &owned = discretization.get_operators().locally_owned_dofs;
    BlockVector     part(std::vector<IndexSet>(multiplier_block, owned),
                     discretization.get_mpi_communicator());
    for (unsigned int b = 0; b < multiplier_block; ++b)
      part.block(b) = z.block(b);
    return part;
  }



  template <int dim>
  Vector
  ConstrainedNestedStep<dim>::constraint_gradient(const unsigned int j,
                                                  const Vector      &u) const
  {
    const LumpedOperators<dim> &ops = discretization.get_operators();
    Vector                      g(u);
    g = 0;
    constraints.add_gradient(j, ops, u, 1., g);
    ops.zero_constrained(g);
    return g;
  }



  template <int dim>
  void
  ConstrainedNestedStep<dim>::residual(const BlockVector &z,
                                       BlockVector       &r) const
  {
    use_multipliers_of(z);
    // blocks U, V, P: the nested residual with the ConstraintTerm
    step.residual(z, r);
    const LumpedOperators<dim> &ops = discretization.get_operators();
    std::vector<double>         violation(constraints.size());
    for (unsigned int j = 0; j < constraints.size(); ++j)
      violation[j] =
        constraints.value(j, ops, z.block(Field::U)) - constraints.target(j);
    set_scalars(r.block(multiplier_block), violation);
  }



  template <int dim>
  double
  ConstrainedNestedStep<dim>::residual_norm(const BlockVector &r) const
  {
    double sum = std::pow(step.residual_norm(r), 2);
    for (const double violation : multipliers(r))
      sum += violation * violation;
    return std::sqrt(sum);
  }



  template <int dim>
  double
  ConstrainedNestedStep<dim>::term_scale(const BlockVector &z) const
  {
    double scale = step.term_scale(z);
    for (unsigned int j = 0; j < constraints.size(); ++j)
      scale += std::abs(constraints.target(j));
    return scale;
  }



  template <int dim>
  double
  ConstrainedNestedStep<dim>::roundoff_level(const BlockVector &z) const
  {
    return step.roundoff_level(z);
  }



  template <int dim>
  unsigned int
  ConstrainedNestedStep<dim>::solve_jacobian(const BlockVector &z,
                                             const BlockVector &r,
                                             BlockVector       &dz,
                                             LinearSolver      &solver)
  {
    use_multipliers_of(z);
    const unsigned int n        = constraints.size();
    const BlockVector  z_nested = nested_part(z);
    const Vector      &u        = z_nested.block(Field::U);
    // x = -J^-1 R and Y_j = J^-1 B_j^T
    BlockVector  x(z_nested);
    unsigned int iterations =
      step.solve_jacobian(z_nested, nested_part(r), x, solver);
    std::vector<BlockVector> y(n, z_nested);
    std::vector<Vector>      gradients;
    for (unsigned int j = 0; j < n; ++j)
      {
        gradients.push_back(constraint_gradient(j, u));
        BlockVector minus_b(z_nested);
        minus_b = 0;
        minus_b.block(Field::U).equ(-1., gradients[j]);
        iterations += step.solve_jacobian(z_nested, minus_b, y[j], solver);
      }
    // (B Y) dlambda = B x + R_c
    const std::vector<double> violation = multipliers(r);
    FullMatrix<double>        by(n, n);
    dealii::Vector<double>    rhs(n), dlambda(n);
    for (unsigned int i = 0; i < n; ++i)
      {
        rhs(i) = gradients[i] * x.block(Field::U) + violation[i];
        for (unsigned int j = 0; j < n; ++j)
          by(i, j) = gradients[i] * y[j].block(Field::U);
      }
    by.gauss_jordan();
    by.vmult(dlambda, rhs);
    for (unsigned int j = 0; j < n; ++j)
      x.add(-dlambda(j), y[j]);
    for (unsigned int b = 0; b < multiplier_block; ++b)
      dz.block(b) = x.block(b);
    set_scalars(dz.block(multiplier_block),
                std::vector<double>(dlambda.begin(), dlambda.end()));
    return iterations;
  }



  template <int dim>
  void
  ConstrainedNestedStep<dim>::distribute_constraints(BlockVector &z) const
  {
    for (unsigned int b = 0; b < multiplier_block; ++b)
      discretization.get_constraints().distribute(z.block(b));
  }



  template <int dim>
  void
  ConstrainedNestedStep<dim>::jacobian_vmult(const BlockVector &z,
                                             const BlockVector &x,
                                             BlockVector       &y) const
  {
    use_multipliers_of(z);
    const BlockVector z_nested = nested_part(z);
    BlockVector       y_nested(z_nested);
    step.jacobian_vmult(z_nested, nested_part(x), y_nested);
    const std::vector<double> dlambda = multipliers(x);
    std::vector<double>       b_x(constraints.size());
    for (unsigned int j = 0; j < constraints.size(); ++j)
      {
        const Vector g = constraint_gradient(j, z_nested.block(Field::U));
        y_nested.block(Field::U).add(dlambda[j], g);
        b_x[j] = g * x.block(Field::U);
      }
    for (unsigned int b = 0; b < multiplier_block; ++b)
      y.block(b) = y_nested.block(b);
    set_scalars(y.block(multiplier_block), b_x);
  }



  template class ConstrainedNestedStep<2>;
  template class ConstrainedNestedStep<3>;
} // namespace PhaseField
