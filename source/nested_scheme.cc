#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>

#include <phasefield/nested_scheme.h>

#include <cmath>

namespace PhaseField
{
  using namespace dealii;

  /** A matrix and its LU factorisation, usable as a preconditioner. */
  class ReducedSystemSolver::Factorization
  {
  public:
    explicit Factorization(const TrilinosWrappers::SparseMatrix &matrix)
      : control(1, 0)
      , solver(control,
               TrilinosWrappers::SolverDirect::AdditionalData(false,
                                                              "Amesos_Mumps"))
    {
      factorized_matrix.copy_from(matrix);
      solver.initialize(factorized_matrix);
    }

    void
    vmult(TrilinosWrappers::MPI::Vector &      dst,
          const TrilinosWrappers::MPI::Vector &src) const
    {
      solver.solve(dst, src);
    }

    types::global_dof_index
    size() const
    {
      return factorized_matrix.m();
    }

  private:
    TrilinosWrappers::SparseMatrix         factorized_matrix;
    SolverControl                          control;
    mutable TrilinosWrappers::SolverDirect solver;
  };



  ReducedSystemSolver::ReducedSystemSolver(
    const LinearSolverType type,
    const double           relative_tolerance,
    const unsigned int     max_iterations,
    const bool             symmetric,
    const unsigned int     refactorization_threshold)
    : solver_type(type)
    , relative_tolerance(relative_tolerance)
    , max_iterations(max_iterations)
    , symmetric(symmetric)
    , refactorization_threshold(refactorization_threshold)
    , tolerance(relative_tolerance)
  {
    Assert(type != LinearSolverType::automatic,
           ExcMessage("Resolve 'auto' before constructing the solver."));
  }



  ReducedSystemSolver::~ReducedSystemSolver() = default;



  void
  ReducedSystemSolver::set_tolerance(const double relative_tolerance)
  {
    tolerance = std::max(relative_tolerance, this->relative_tolerance);
  }



  void
  ReducedSystemSolver::reset()
  {
    factorization.reset();
    last_iterations = 0;
  }



  unsigned int
  ReducedSystemSolver::solve(const TrilinosWrappers::SparseMatrix &matrix,
                             TrilinosWrappers::MPI::Vector &       solution,
                             const TrilinosWrappers::MPI::Vector & rhs)
  {
    SolverControl control(max_iterations,
                          tolerance * rhs.l2_norm(),
                          false,
                          false);
    solution = 0;
    if (solver_type == LinearSolverType::direct && constant_matrix &&
        factorization && factorization->size() == matrix.m())
      {
        factorization->vmult(solution, rhs);
        last_iterations = 1;
        return last_iterations;
      }
    if (solver_type == LinearSolverType::direct)
      {
        if (!factorization || factorization->size() != matrix.m() ||
            last_iterations > refactorization_threshold)
          {
            factorization = std::make_unique<Factorization>(matrix);
            ++factorization_count;
          }
        SolverGMRES<TrilinosWrappers::MPI::Vector> gmres(
          control,
          SolverGMRES<TrilinosWrappers::MPI::Vector>::AdditionalData(
            50, /*right_preconditioning=*/true));
        gmres.solve(matrix, solution, rhs, *factorization);
      }
    else
      {
        TrilinosWrappers::PreconditionAMG                 amg;
        TrilinosWrappers::PreconditionAMG::AdditionalData amg_data;
        amg_data.elliptic              = true;
        amg_data.higher_order_elements = false;
        amg_data.smoother_sweeps       = 2;
        amg_data.aggregation_threshold = 0.02;
        amg.initialize(matrix, amg_data);
        if (symmetric)
          {
            SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
            cg.solve(matrix, solution, rhs, amg);
          }
        else
          {
            SolverGMRES<TrilinosWrappers::MPI::Vector> gmres(
              control,
              SolverGMRES<TrilinosWrappers::MPI::Vector>::AdditionalData(
                50, /*right_preconditioning=*/true));
            gmres.solve(matrix, solution, rhs, amg);
          }
      }
    last_iterations = control.last_step();
    return last_iterations;
  }



  template <int dim>
  Energies
  phase_field_energies(const LumpedOperators<dim> &         operators,
                       const TrilinosWrappers::MPI::Vector &u,
                       const double                         epsilon)
  {
    const double *     m         = operators.lumped_mass.begin();
    const unsigned int n         = u.locally_owned_size();
    double             potential = 0, inside = 0;
    for (unsigned int i = 0; i < n; ++i)
      {
        const double ui = u.begin()[i];
        potential += m[i] * DoubleWell::psi(ui);
        inside += m[i] * 0.5 * (1 - ui);
      }
    const MPI_Comm comm   = u.get_mpi_communicator();
    potential             = Utilities::MPI::sum(potential, comm);
    inside                = Utilities::MPI::sum(inside, comm);
    const double gradient = operators.stiffness_product(u);

    Energies e;
    e.willmore = 0;
    // 3/4 normalises the tanh profile: Int sech^4 = 4/3 per unit area.
    e.area           = 0.75 * 0.5 * (epsilon * gradient + potential / epsilon);
    e.inside_measure = inside;
    return e;
  }



  template <int dim>
  NestedScheme<dim>::NestedScheme(const LumpedOperators<dim> &operators,
                                  const NestedCoefficients &  coefficients)
    : ops(operators)
    , coeff(coefficients)
  {}



  template <int dim>
  void
  NestedScheme<dim>::residual(const Vector &     old_u,
                              const BlockVector &z,
                              BlockVector &      r,
                              const Vector *     forcing) const
  {
    const double a       = coeff.a();
    const double c       = coeff.c();
    const double ttau    = coeff.inner_tau;
    const auto & L       = ops.stiffness;
    Vector &     r_u     = r.block(Field::U);
    Vector &     r_v     = r.block(Field::V);
    Vector &     r_p     = r.block(Field::P);
    const Vector &u      = z.block(Field::U);
    const Vector &v      = z.block(Field::V);
    const Vector &p      = z.block(Field::P);

    // stiffness parts first: r_v = ttau L P, r_p = ttau L V
    L.vmult(r_v, p);
    r_v *= ttau;
    L.vmult(r_p, v);
    r_p *= ttau;

    const unsigned int n  = u.locally_owned_size();
    const double *     m  = ops.lumped_mass.begin();
    const double *     uk = old_u.begin();
    const double *     f  = forcing ? forcing->begin() : nullptr;
    const double       forcing_factor = coeff.tau / coeff.epsilon;
    for (unsigned int i = 0; i < n; ++i)
      {
        const double ui = u.begin()[i], vi = v.begin()[i], pi = p.begin()[i];
        const double k_diag = m[i] * (1 + c * DoubleWell::d2_psi(vi));
        r_u.begin()[i] = m[i] * ((ui - uk[i]) - a * (vi - ui) - pi);
        if (f)
          r_u.begin()[i] -= forcing_factor * f[i];
        r_v.begin()[i] += a * m[i] * (vi - ui) + k_diag * pi;
        r_p.begin()[i] += m[i] * ((vi - ui) + c * DoubleWell::d_psi(vi));
      }
    for (unsigned int b = 0; b < 3; ++b)
      ops.zero_constrained(r.block(b));
  }



  template <int dim>
  double
  NestedScheme<dim>::residual_norm(const BlockVector &r) const
  {
    double sum = 0;
    for (unsigned int b = 0; b < 3; ++b)
      sum += std::pow(ops.dual_norm(r.block(b)), 2);
    return std::sqrt(sum);
  }



  template <int dim>
  void
  NestedScheme<dim>::build_k(const Vector &                  v,
                             const double                    shift,
                             TrilinosWrappers::SparseMatrix &k) const
  {
    k.copy_from(ops.stiffness);
    k *= coeff.inner_tau;
    const double       c = coeff.c();
    const double *     m = ops.lumped_mass.begin();
    const unsigned int n = v.locally_owned_size();
    for (unsigned int i = 0; i < n; ++i)
      {
        const types::global_dof_index g =
          ops.locally_owned_dofs.nth_index_in_set(i);
        k.add(g,
              g,
              m[i] * (1 - shift + c * DoubleWell::d2_psi(v.begin()[i])));
      }
    k.compress(VectorOperation::add);
  }



  template <int dim>
  unsigned int
  NestedScheme<dim>::solve_newton_system(const BlockVector &  z,
                                         const BlockVector &  r,
                                         BlockVector &        dz,
                                         ReducedSystemSolver &solver) const
  {
    ReducedMatrices matrices;
    build_reduced_matrices(z, matrices);
    return solve_newton_system(matrices, r, dz, solver);
  }



  template <int dim>
  void
  NestedScheme<dim>::build_reduced_matrices(const BlockVector &z,
                                            ReducedMatrices &  matrices) const
  {
    const double a = coeff.a();
    const double b = a / (1 + a);
    const double c = coeff.c();

    const Vector &v = z.block(Field::V);
    const Vector &p = z.block(Field::P);

    TrilinosWrappers::SparseMatrix k_hat;
    build_k(v, 0., matrices.k);
    build_k(v, b, k_hat);

    // S = (1+a) Khat M^-1 Khat + b M + D
    TrilinosWrappers::SparseMatrix &s = matrices.s;
    Vector weight(ops.inverse_lumped_mass);
    weight *= (1 + a);
    k_hat.mmult(s, k_hat, weight);
    const double *     m = ops.lumped_mass.begin();
    const unsigned int n = v.locally_owned_size();
    for (unsigned int i = 0; i < n; ++i)
      {
        const types::global_dof_index g =
          ops.locally_owned_dofs.nth_index_in_set(i);
        s.add(g,
              g,
              m[i] * (b + c * DoubleWell::d3_psi(v.begin()[i]) * p.begin()[i]));
      }
    s.compress(VectorOperation::add);
  }



  template <int dim>
  unsigned int
  NestedScheme<dim>::solve_newton_system(const ReducedMatrices &matrices,
                                         const BlockVector &    r,
                                         BlockVector &          dz,
                                         ReducedSystemSolver &  solver) const
  {
    const double a = coeff.a();

    const auto &  k   = matrices.k;
    const Vector &r_u = r.block(Field::U);
    const Vector &r_v = r.block(Field::V);
    const Vector &r_p = r.block(Field::P);

    // rhs = -R_V + a R_P - K M^-1 ((1+a) R_P + R_U)
    Vector tmp(r_p), rhs(r_v);
    tmp *= (1 + a);
    tmp += r_u;
    tmp.scale(ops.inverse_lumped_mass);
    k.vmult(rhs, tmp);
    rhs *= -1;
    rhs -= r_v;
    rhs.add(a, r_p);
    ops.zero_constrained(rhs);

    Vector &du = dz.block(Field::U);
    Vector &dv = dz.block(Field::V);
    Vector &dp = dz.block(Field::P);
    const unsigned int iterations = solver.solve(matrices.s, dv, rhs);
    ops.zero_constrained(dv);

    // dU = M^-1 (K dV + R_P)
    Vector k_dv(dv);
    k.vmult(k_dv, dv);
    du = k_dv;
    du += r_p;
    du.scale(ops.inverse_lumped_mass);

    // dP = M^-1 ((1+a) K dV - a M dV + (1+a) R_P + R_U)
    const double *     m = ops.lumped_mass.begin();
    const unsigned int n = dv.locally_owned_size();
    for (unsigned int i = 0; i < n; ++i)
      dp.begin()[i] = ops.inverse_lumped_mass.begin()[i] *
                      ((1 + a) * (k_dv.begin()[i] + r_p.begin()[i]) -
                       a * m[i] * dv.begin()[i] + r_u.begin()[i]);
    for (unsigned int bl = 0; bl < 3; ++bl)
      ops.zero_constrained(dz.block(bl));
    return iterations;
  }



  template <int dim>
  void
  NestedScheme<dim>::jacobian_vmult(const BlockVector &z,
                                    const BlockVector &x,
                                    BlockVector &      y) const
  {
    const double a = coeff.a();
    const double c = coeff.c();
    TrilinosWrappers::SparseMatrix k;
    build_k(z.block(Field::V), 0., k);
    k.vmult(y.block(Field::V), x.block(Field::P));
    k.vmult(y.block(Field::P), x.block(Field::V));
    const double *     m = ops.lumped_mass.begin();
    const unsigned int n = x.block(0).locally_owned_size();
    for (unsigned int i = 0; i < n; ++i)
      {
        const double xu = x.block(Field::U).begin()[i];
        const double xv = x.block(Field::V).begin()[i];
        const double xp = x.block(Field::P).begin()[i];
        const double d  = c * DoubleWell::d3_psi(z.block(Field::V).begin()[i]) *
                         z.block(Field::P).begin()[i];
        y.block(Field::U).begin()[i] =
          m[i] * ((1 + a) * xu - a * xv - xp);
        y.block(Field::V).begin()[i] += m[i] * (-a * xu + (a + d) * xv);
        y.block(Field::P).begin()[i] += -m[i] * xu;
      }
    for (unsigned int b = 0; b < 3; ++b)
      ops.zero_constrained(y.block(b));
  }



  template <int dim>
  unsigned int
  NestedScheme<dim>::initialize_v_and_p(BlockVector &        z,
                                        ReducedSystemSolver &solver,
                                        const double               tolerance) const
  {
    const double  a = coeff.a();
    const double  c = coeff.c();
    const Vector &u = z.block(Field::U);
    Vector &      v = z.block(Field::V);
    Vector &      p = z.block(Field::P);
    const double *m = ops.lumped_mass.begin();
    const unsigned int n = u.locally_owned_size();

    // V: Newton on R_P(U, V) = M(V-U) + c M Psi'(V) + ttau L V = 0,
    // whose Jacobian is K(V).
    v = u;
    Vector       r(u), dv(u);
    unsigned int iterations = 0;
    double       r0         = -1;
    for (; iterations < 50; ++iterations)
      {
        ops.stiffness.vmult(r, v);
        r *= coeff.inner_tau;
        for (unsigned int i = 0; i < n; ++i)
          r.begin()[i] += m[i] * ((v.begin()[i] - u.begin()[i]) +
                                  c * DoubleWell::d_psi(v.begin()[i]));
        ops.zero_constrained(r);
        const double norm = ops.dual_norm(r);
        if (r0 < 0)
          r0 = norm;
        if (norm <= tolerance * r0 || norm < 1e-14)
          break;
        TrilinosWrappers::SparseMatrix k;
        build_k(v, 0., k);
        r *= -1;
        solver.solve(k, dv, r);
        ops.zero_constrained(dv);
        v += dv;
      }
    AssertThrow(iterations < 50,
                ExcMessage("The initialisation of V (Algorithm 3.1) did not "
                           "converge in 50 Newton iterations."));

    // P: K(V) P = -a M (V - U)
    TrilinosWrappers::SparseMatrix k;
    build_k(v, 0., k);
    for (unsigned int i = 0; i < n; ++i)
      r.begin()[i] = -a * m[i] * (v.begin()[i] - u.begin()[i]);
    ops.zero_constrained(r);
    solver.solve(k, p, r);
    ops.zero_constrained(p);
    return iterations;
  }



  template <int dim>
  Energies
  NestedScheme<dim>::energies(const BlockVector &z) const
  {
    const double  ttau = coeff.inner_tau;
    Vector        curvature(z.block(Field::U));
    curvature -= z.block(Field::V);
    curvature /= ttau;

    Energies e = phase_field_energies(ops, z.block(Field::U), coeff.epsilon);
    // 3/4 normalises the tanh profile, as for the area.
    e.willmore =
      0.75 * 0.5 * coeff.epsilon * ops.mass_product(curvature, curvature);
    return e;
  }



  template <int dim>
  double
  NestedScheme<dim>::term_scale(const BlockVector &z) const
  {
    Vector difference(z.block(Field::V));
    difference -= z.block(Field::U);
    return std::sqrt(ops.mass_product(z.block(Field::U), z.block(Field::U))) +
           coeff.a() * std::sqrt(ops.mass_product(difference, difference)) +
           std::sqrt(ops.mass_product(z.block(Field::P), z.block(Field::P)));
  }



  template class NestedScheme<2>;
  template class NestedScheme<3>;
  template Energies
  phase_field_energies(const LumpedOperators<2> &,
                       const TrilinosWrappers::MPI::Vector &,
                       const double);
  template Energies
  phase_field_energies(const LumpedOperators<3> &,
                       const TrilinosWrappers::MPI::Vector &,
                       const double);
} // namespace PhaseField
