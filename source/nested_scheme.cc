#include <Amesos.h>
#include <Amesos_BaseSolver.h>
#include <Amesos_Mumps.h>
#include <Epetra_LinearProblem.h>
#include <cmath>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <limits>
#include <phasefield/nested_scheme.h>

namespace PhaseField
{
  using namespace dealii;

  /**
   * A matrix and its LU factorisation, usable as a preconditioner. For
   * indefinite matrices (pivoting_workspace_percent > 0) MUMPS is called
   * through Amesos directly, with that much extra workspace (ICNTL(14))
   * for the fill-in of delayed pivots.
   */
  class ReducedSystemSolver::Factorization
  {
  public:
    Factorization(const TrilinosWrappers::SparseMatrix &matrix,
                  const unsigned int pivoting_workspace_percent)
      : control(1, 0)
      , solver(control,
               TrilinosWrappers::SolverDirect::AdditionalData(false,
                                                              "Amesos_Mumps"))
    {
      factorized_matrix.copy_from(matrix);
      if (pivoting_workspace_percent == 0)
        {
          solver.initialize(factorized_matrix);
          return;
        }
      problem = std::make_unique<Epetra_LinearProblem>();
      problem->SetOperator(
        const_cast<Epetra_CrsMatrix *>(&factorized_matrix.trilinos_matrix()));
      Amesos factory;
      indefinite_solver.reset(factory.Create("Amesos_Mumps", *problem));
      AssertThrow(indefinite_solver != nullptr,
                  ExcMessage("Trilinos Amesos has no MUMPS."));
      if (auto *mumps = dynamic_cast<Amesos_Mumps *>(indefinite_solver.get()))
        mumps->SetICNTL(14, pivoting_workspace_percent);
      const int symbolic = indefinite_solver->SymbolicFactorization();
      const int numeric  = indefinite_solver->NumericFactorization();
      AssertThrow(symbolic == 0 && numeric == 0,
                  ExcMessage(
                    "MUMPS could not factorise the Newton matrix "
                    "(error " +
                    std::to_string(symbolic != 0 ? symbolic : numeric) + ")."));
    }

    void
    vmult(TrilinosWrappers::MPI::Vector       &dst,
          const TrilinosWrappers::MPI::Vector &src) const
    {
      if (!indefinite_solver)
        {
          solver.solve(dst, src);
          return;
        }
      problem->SetLHS(&dst.trilinos_vector());
      problem->SetRHS(const_cast<Epetra_MultiVector *>(&src.trilinos_vector()));
      AssertThrow(indefinite_solver->Solve() == 0,
                  ExcMessage("MUMPS failed to solve the Newton system."));
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
    std::unique_ptr<Epetra_LinearProblem>  problem;
    std::unique_ptr<Amesos_BaseSolver>     indefinite_solver;
  };



  namespace
  {
    /**
     * Settings of the algebraic multigrid cycles (Trilinos ML) of the
     * iterative solvers: aggregation for a scalar second-order operator,
     * three Chebyshev sweeps per level (measured on the 3D cube: two sweeps
     * need twice the CG iterations, more than three do not pay).
     */
    TrilinosWrappers::PreconditionAMG::AdditionalData
    multigrid_settings()
    {
      TrilinosWrappers::PreconditionAMG::AdditionalData data;
      data.elliptic              = true;
      data.higher_order_elements = false;
      data.smoother_sweeps       = 3;
      data.aggregation_threshold = 0.02;
      return data;
    }



    /**
     * dst = A diag(@p diagonal) A src for a symmetric operator A, i.e. the
     * symmetric product of A, a diagonal and A; @p tmp is scratch space.
     */
    template <typename Operator>
    void
    apply_symmetric_product(const Operator                      &a,
                            const TrilinosWrappers::MPI::Vector &diagonal,
                            TrilinosWrappers::MPI::Vector       &tmp,
                            TrilinosWrappers::MPI::Vector       &dst,
                            const TrilinosWrappers::MPI::Vector &src)
    {
      a.vmult(tmp, src);
      tmp.scale(diagonal);
      a.vmult(dst, tmp);
    }



    /** S = diag(d) + w Khat M^-1 Khat applied to a vector. */
    class ProductFormMatrix
    {
    public:
      ProductFormMatrix(const TrilinosWrappers::SparseMatrix &k_hat,
                        const double                          w,
                        const TrilinosWrappers::MPI::Vector  &d,
                        const TrilinosWrappers::MPI::Vector  &inverse_mass)
        : k_hat(k_hat)
        , w(w)
        , d(d)
        , inverse_mass(inverse_mass)
        , tmp(d)
      {}

      void
      vmult(TrilinosWrappers::MPI::Vector       &dst,
            const TrilinosWrappers::MPI::Vector &src) const
      {
        apply_symmetric_product(k_hat, inverse_mass, tmp, dst, src);
        dst *= w;
        tmp = src;
        tmp.scale(d);
        dst += tmp;
      }

    private:
      const TrilinosWrappers::SparseMatrix &k_hat;
      const double                          w;
      const TrilinosWrappers::MPI::Vector  &d;
      const TrilinosWrappers::MPI::Vector  &inverse_mass;
      mutable TrilinosWrappers::MPI::Vector tmp;
    };



    /**
     * The preconditioner G^-1 M G^-1 of
     * ReducedSystemSolver::solve_product_form(), with one multigrid cycle
     * for each G^-1.
     */
    class SchurPreconditioner
    {
    public:
      SchurPreconditioner(const TrilinosWrappers::SparseMatrix &g,
                          const TrilinosWrappers::MPI::Vector  &mass)
        : mass(mass)
        , tmp(mass)
      {
        multigrid.initialize(g, multigrid_settings());
      }

      void
      vmult(TrilinosWrappers::MPI::Vector       &dst,
            const TrilinosWrappers::MPI::Vector &src) const
      {
        apply_symmetric_product(multigrid, mass, tmp, dst, src);
      }

    private:
      TrilinosWrappers::PreconditionAMG     multigrid;
      const TrilinosWrappers::MPI::Vector  &mass;
      mutable TrilinosWrappers::MPI::Vector tmp;
    };
  } // namespace



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
                             TrilinosWrappers::MPI::Vector        &solution,
                             const TrilinosWrappers::MPI::Vector  &rhs)
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
        const auto refactorize = [&]() {
          factorization =
            std::make_unique<Factorization>(matrix, pivoting_workspace_percent);
          ++factorization_count;
        };
        bool fresh = false;
        if (!factorization || factorization->size() != matrix.m() ||
            last_iterations > refactorization_threshold)
          {
            refactorize();
            fresh = true;
          }
        SolverGMRES<TrilinosWrappers::MPI::Vector> gmres(
          control,
          SolverGMRES<TrilinosWrappers::MPI::Vector>::AdditionalData(
            50, /*right_preconditioning=*/true));
        try
          {
            gmres.solve(matrix, solution, rhs, *factorization);
          }
        catch (const SolverControl::NoConvergence &)
          {
            // the factorisation of an earlier Newton matrix can be too far
            // from this one to precondition it: factorise this one, once
            if (fresh)
              throw;
            refactorize();
            solution = 0;
            gmres.solve(matrix, solution, rhs, *factorization);
          }
      }
    else
      {
        TrilinosWrappers::PreconditionAMG amg;
        amg.initialize(matrix, multigrid_settings());
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
  phase_field_energies(const LumpedOperators<dim>          &operators,
                       const TrilinosWrappers::MPI::Vector &u,
                       const double                         epsilon)
  {
    const double      *m         = operators.lumped_mass.begin();
    const unsigned int n         = u.locally_owned_size();
    double             potential = 0, inside = 0;
    for (unsigned int i = 0; i < n; ++i)
      {
        const double ui = u.begin()[i];
        potential += m[i] * DoubleWell::psi(ui);
        inside += m[i] * 0.5 * (1 - ui);
      }
    const MPI_Comm comm   = u.get_mpi_communicator();
    potential             = dealii::Utilities::MPI::sum(potential, comm);
    inside                = dealii::Utilities::MPI::sum(inside, comm);
    const double gradient = operators.stiffness_product(u);

    Energies e;
    e.willmore = 0;
    // 3/4 normalises the tanh profile: Int sech^4 = 4/3 per unit area.
    e.area           = 0.75 * 0.5 * (epsilon * gradient + potential / epsilon);
    e.inside_measure = inside;
    return e;
  }



  unsigned int
  ReducedSystemSolver::solve_product_form(
    const TrilinosWrappers::SparseMatrix &k_hat,
    const double                          w,
    const TrilinosWrappers::MPI::Vector  &d,
    const TrilinosWrappers::SparseMatrix &g,
    const TrilinosWrappers::MPI::Vector  &mass,
    const TrilinosWrappers::MPI::Vector  &inverse_mass,
    TrilinosWrappers::MPI::Vector        &solution,
    const TrilinosWrappers::MPI::Vector  &rhs)
  {
    Assert(solver_type == LinearSolverType::iterative, ExcInternalError());
    const ProductFormMatrix   s(k_hat, w, d, inverse_mass);
    const SchurPreconditioner preconditioner(g, mass);
    ++factorization_count;
    SolverControl                           control(max_iterations,
                          tolerance * rhs.l2_norm(),
                          false,
                          false);
    SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
    solution = 0;
    cg.solve(s, solution, rhs, preconditioner);
    last_iterations = control.last_step();
    return last_iterations;
  }



  template <int dim>
  NestedScheme<dim>::NestedScheme(const LumpedOperators<dim> &operators,
                                  const NestedCoefficients   &coefficients)
    : ops(operators)
    , coeff(coefficients)
  {}



  template <int dim>
  void
  NestedScheme<dim>::residual(const Vector      &old_u,
                              const BlockVector &z,
                              BlockVector       &r,
                              const Vector      *forcing) const
  {
    const double  a    = coeff.a();
    const double  c    = coeff.c();
    const double  ttau = coeff.inner_tau;
    const auto   &L    = ops.stiffness;
    Vector       &r_u  = r.block(Field::U);
    Vector       &r_v  = r.block(Field::V);
    Vector       &r_p  = r.block(Field::P);
    const Vector &u    = z.block(Field::U);
    const Vector &v    = z.block(Field::V);
    const Vector &p    = z.block(Field::P);

    // stiffness parts first: r_v = ttau L P, r_p = ttau L V
    L.vmult(r_v, p);
    r_v *= ttau;
    L.vmult(r_p, v);
    r_p *= ttau;

    const unsigned int n              = u.locally_owned_size();
    const double      *m              = ops.lumped_mass.begin();
    const double      *uk             = old_u.begin();
    const double      *f              = forcing ? forcing->begin() : nullptr;
    const double       forcing_factor = coeff.tau / coeff.epsilon;
    for (unsigned int i = 0; i < n; ++i)
      {
        const double ui = u.begin()[i], vi = v.begin()[i], pi = p.begin()[i];
        const double k_diag = m[i] * (1 + c * DoubleWell::d2_psi(vi));
        r_u.begin()[i]      = m[i] * ((ui - uk[i]) - a * (vi - ui) - pi);
        if (f)
          r_u.begin()[i] -= forcing_factor * f[i];
        r_v.begin()[i] += a * m[i] * (vi - ui) + k_diag * pi;
        r_p.begin()[i] += m[i] * ((vi - ui) + c * DoubleWell::d_psi(vi));
      }
    if (coeff.has_restoration_terms())
      {
        // area term tau eta (L U + M Psi'(U) / (2 eps^2)); no U-row at
        // fixed U values
        const double area_factor = coeff.tau * coeff.area_weight;
        const double c_u         = 1. / (2 * coeff.epsilon * coeff.epsilon);
        Vector       l_u(u);
        L.vmult(l_u, u);
        for (unsigned int i = 0; i < n; ++i)
          {
            r_u.begin()[i] +=
              area_factor *
              (l_u.begin()[i] + c_u * m[i] * DoubleWell::d_psi(u.begin()[i]));
            if (u_is_fixed(i))
              r_u.begin()[i] = 0;
          }
      }
    for (unsigned int b = 0; b < 3; ++b)
      ops.zero_constrained(r.block(b));
  }



  template <int dim>
  bool
  NestedScheme<dim>::u_is_fixed(const unsigned int i) const
  {
    return coeff.fixed_u != nullptr &&
           coeff.fixed_u->is_element(
             ops.locally_owned_dofs.nth_index_in_set(i));
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
  NestedScheme<dim>::build_k(const Vector                   &v,
                             const double                    shift,
                             TrilinosWrappers::SparseMatrix &k) const
  {
    ops.stiffness_plus_weighted_mass(coeff.inner_tau,
                                     k_hat_weight(v, shift),
                                     k);
  }



  template <int dim>
  typename NestedScheme<dim>::Vector
  NestedScheme<dim>::k_hat_weight(const Vector &v, const double shift) const
  {
    Vector             weight(v);
    const double       c = coeff.c();
    const unsigned int n = v.locally_owned_size();
    for (unsigned int i = 0; i < n; ++i)
      weight.begin()[i] = 1 - shift + c * DoubleWell::d2_psi(v.begin()[i]);
    return weight;
  }



  template <int dim>
  unsigned int
  NestedScheme<dim>::solve_newton_system(const BlockVector   &z,
                                         const BlockVector   &r,
                                         BlockVector         &dz,
                                         ReducedSystemSolver &solver) const
  {
    if (coeff.has_restoration_terms())
      return solve_full_newton_system(z, r, dz, solver);
    ReducedMatrices matrices;
    build_reduced_matrices(z, matrices, solver.type());
    return solve_newton_system(matrices, r, dz, solver);
  }



  template <int dim>
  void
  NestedScheme<dim>::build_reduced_matrices(const BlockVector     &z,
                                            ReducedMatrices       &matrices,
                                            const LinearSolverType type) const
  {
    const double a = coeff.a();
    const double b = a / (1 + a);
    const double c = coeff.c();

    const Vector &v = z.block(Field::V);
    const Vector &p = z.block(Field::P);

    build_k(v, 0., matrices.k);
    build_k(v, b, matrices.k_hat);

    // the diagonal part of S: b M + D
    Vector &diagonal = matrices.diagonal;
    diagonal.reinit(v, true);
    const double      *m = ops.lumped_mass.begin();
    const unsigned int n = v.locally_owned_size();
    for (unsigned int i = 0; i < n; ++i)
      diagonal.begin()[i] =
        m[i] * (b + c * DoubleWell::d3_psi(v.begin()[i]) * p.begin()[i]);

    if (type == LinearSolverType::direct)
      {
        // S = (1+a) Khat M^-1 Khat + b M + D
        TrilinosWrappers::SparseMatrix &s = matrices.s;
        Vector                          weight(ops.inverse_lumped_mass);
        weight *= (1 + a);
        matrices.k_hat.mmult(s, matrices.k_hat, weight);
        ops.add_to_diagonal(diagonal, s);
      }
    else
      {
        // G = gamma M + sqrt((1+a)/b) Khat, so that b G M^-1 G / gamma^2
        // approximates S (see schur_mass_shift)
        const double scale  = std::sqrt((1 + a) / b);
        Vector       weight = k_hat_weight(v, b);
        weight *= scale;
        weight.add(schur_mass_shift);
        ops.stiffness_plus_weighted_mass(scale * coeff.inner_tau,
                                         weight,
                                         matrices.g);
      }
  }



  template <int dim>
  unsigned int
  NestedScheme<dim>::solve_newton_system(const ReducedMatrices &matrices,
                                         const BlockVector     &r,
                                         BlockVector           &dz,
                                         ReducedSystemSolver   &solver) const
  {
    const double a = coeff.a();

    const auto   &k   = matrices.k;
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

    Vector            &du = dz.block(Field::U);
    Vector            &dv = dz.block(Field::V);
    Vector            &dp = dz.block(Field::P);
    const unsigned int iterations =
      solver.type() == LinearSolverType::direct ?
        solver.solve(matrices.s, dv, rhs) :
        solver.solve_product_form(matrices.k_hat,
                                  1 + a,
                                  matrices.diagonal,
                                  matrices.g,
                                  ops.lumped_mass,
                                  ops.inverse_lumped_mass,
                                  dv,
                                  rhs);
    ops.zero_constrained(dv);

    // dU = M^-1 (K dV + R_P)
    Vector k_dv(dv);
    k.vmult(k_dv, dv);
    du = k_dv;
    du += r_p;
    du.scale(ops.inverse_lumped_mass);

    // dP = M^-1 ((1+a) K dV - a M dV + (1+a) R_P + R_U)
    const double      *m = ops.lumped_mass.begin();
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
  NestedScheme<dim>::assemble_full_jacobian(
    const BlockVector              &z,
    TrilinosWrappers::SparseMatrix &j) const
  {
    const double       a           = coeff.a();
    const double       c           = coeff.c();
    const double       area_factor = coeff.tau * coeff.area_weight;
    const double       c_u         = 1. / (2 * coeff.epsilon * coeff.epsilon);
    const auto        &L           = ops.stiffness;
    const IndexSet    &owned       = ops.locally_owned_dofs;
    const unsigned int n           = owned.n_elements();
    const types::global_dof_index n_dofs = owned.size();
    const double                 *m      = ops.lumped_mass.begin();
    const double                 *u      = z.block(Field::U).begin();
    const double                 *v      = z.block(Field::V).begin();
    const double                 *p      = z.block(Field::P).begin();

    // U rows and columns replaced by the identity: fixed and constrained
    std::vector<bool> identity_row(n, false);
    for (unsigned int i = 0; i < n; ++i)
      identity_row[i] = u_is_fixed(i);
    for (const unsigned int i : ops.constrained_local_indices)
      identity_row[i] = true;
    const auto fixed_column = [&](const types::global_dof_index g) {
      return coeff.fixed_u != nullptr && coeff.fixed_u->is_element(g);
    };
    const double p_scale = full_system_p_scale();
    const auto   index   = [](const types::global_dof_index g,
                          const unsigned int field) { return 3 * g + field; };

    IndexSet owned3(3 * n_dofs);
    for (unsigned int i = 0; i < n; ++i)
      {
        const types::global_dof_index g = owned.nth_index_in_set(i);
        owned3.add_range(index(g, 0), index(g, 0) + 3);
      }
    owned3.compress();

    DynamicSparsityPattern dsp(3 * n_dofs, 3 * n_dofs, owned3);
    for (unsigned int i = 0; i < n; ++i)
      {
        const types::global_dof_index g = owned.nth_index_in_set(i);
        for (unsigned int row = 0; row < 3; ++row)
          for (unsigned int col = 0; col < 3; ++col)
            if (!(row == Field::P && col == Field::P))
              dsp.add(index(g, row), index(g, col));
        for (auto entry = L.begin(g); entry != L.end(g); ++entry)
          {
            const types::global_dof_index col = entry->column();
            dsp.add(index(g, Field::U), index(col, Field::U));
            dsp.add(index(g, Field::V), index(col, Field::P));
            dsp.add(index(g, Field::P), index(col, Field::V));
          }
      }
    j.reinit(owned3, owned3, dsp, z.block(0).get_mpi_communicator());

    for (unsigned int i = 0; i < n; ++i)
      {
        const types::global_dof_index g = owned.nth_index_in_set(i);
        const double k_diag = m[i] * (1 + c * DoubleWell::d2_psi(v[i]));
        if (identity_row[i])
          j.add(index(g, Field::U), index(g, Field::U), 1.);
        else
          {
            j.add(index(g, Field::U),
                  index(g, Field::U),
                  m[i] * ((1 + a + coeff.u_shift) +
                          area_factor * c_u * DoubleWell::d2_psi(u[i])));
            j.add(index(g, Field::U), index(g, Field::V), -a * m[i]);
            j.add(index(g, Field::U), index(g, Field::P), -p_scale * m[i]);
            j.add(index(g, Field::V), index(g, Field::U), -a * m[i]);
            j.add(index(g, Field::P), index(g, Field::U), -p_scale * m[i]);
          }
        j.add(index(g, Field::V),
              index(g, Field::V),
              m[i] * (a + c * DoubleWell::d3_psi(v[i]) * p[i]));
        j.add(index(g, Field::V), index(g, Field::P), p_scale * k_diag);
        j.add(index(g, Field::P), index(g, Field::V), p_scale * k_diag);
        for (auto entry = L.begin(g); entry != L.end(g); ++entry)
          {
            const types::global_dof_index col   = entry->column();
            const double                  value = entry->value();
            if (!identity_row[i] && !fixed_column(col))
              j.add(index(g, Field::U),
                    index(col, Field::U),
                    area_factor * value);
            j.add(index(g, Field::V),
                  index(col, Field::P),
                  p_scale * coeff.inner_tau * value);
            j.add(index(g, Field::P),
                  index(col, Field::V),
                  p_scale * coeff.inner_tau * value);
          }
      }
    j.compress(VectorOperation::add);
  }



  template <int dim>
  unsigned int
  NestedScheme<dim>::solve_full_newton_system(const BlockVector   &z,
                                              const BlockVector   &r,
                                              BlockVector         &dz,
                                              ReducedSystemSolver &solver) const
  {
    AssertThrow(solver.type() == LinearSolverType::direct,
                ExcMessage("The 3-field Newton system of edge restoration "
                           "needs <Linear solver / Type> = direct (or auto "
                           "in 2D)."));
    // delayed pivots of the indefinite 3-field matrix need more workspace
    constexpr unsigned int workspace_percent = 200;
    solver.set_pivoting_workspace(workspace_percent);
    // a fresh factorisation for every Newton matrix: GMRES preconditioned
    // with the factorisation of an earlier, indefinite J may stagnate
    solver.reset();
    TrilinosWrappers::SparseMatrix j;
    assemble_full_jacobian(z, j);
    const MPI_Comm comm = z.block(0).get_mpi_communicator();
    Vector         rhs(j.locally_owned_range_indices(), comm);
    Vector         x(rhs);
    // owned DoFs are contiguous, so (field b, local i) is local entry 3i+b
    const unsigned int n = ops.locally_owned_dofs.n_elements();
    // J' = S J S with S = diag(1, 1, p_scale): dZ = S y, J' y = -S R
    const double scale[3] = {1., 1., full_system_p_scale()};
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
  void
  NestedScheme<dim>::jacobian_vmult(const BlockVector &z,
                                    const BlockVector &x_in,
                                    BlockVector       &y) const
  {
    // with fixed U values, J has identity U-rows and U-columns there
    BlockVector x(x_in);
    for (unsigned int i = 0; i < x.block(0).locally_owned_size(); ++i)
      if (u_is_fixed(i))
        x.block(Field::U).begin()[i] = 0;

    const double                   a = coeff.a();
    const double                   c = coeff.c();
    TrilinosWrappers::SparseMatrix k;
    build_k(z.block(Field::V), 0., k);
    k.vmult(y.block(Field::V), x.block(Field::P));
    k.vmult(y.block(Field::P), x.block(Field::V));
    const double      *m = ops.lumped_mass.begin();
    const unsigned int n = x.block(0).locally_owned_size();
    for (unsigned int i = 0; i < n; ++i)
      {
        const double xu = x.block(Field::U).begin()[i];
        const double xv = x.block(Field::V).begin()[i];
        const double xp = x.block(Field::P).begin()[i];
        const double d  = c * DoubleWell::d3_psi(z.block(Field::V).begin()[i]) *
                         z.block(Field::P).begin()[i];
        y.block(Field::U).begin()[i] =
          m[i] * ((1 + a + coeff.u_shift) * xu - a * xv - xp);
        y.block(Field::V).begin()[i] += m[i] * (-a * xu + (a + d) * xv);
        y.block(Field::P).begin()[i] += -m[i] * xu;
      }
    if (coeff.has_restoration_terms())
      {
        const double  area_factor = coeff.tau * coeff.area_weight;
        const double  c_u         = 1. / (2 * coeff.epsilon * coeff.epsilon);
        const double *u           = z.block(Field::U).begin();
        Vector        l_x(x.block(Field::U));
        ops.stiffness.vmult(l_x, x.block(Field::U));
        for (unsigned int i = 0; i < n; ++i)
          y.block(Field::U).begin()[i] =
            u_is_fixed(i) ?
              x_in.block(Field::U).begin()[i] :
              y.block(Field::U).begin()[i] +
                area_factor *
                  (l_x.begin()[i] + c_u * m[i] * DoubleWell::d2_psi(u[i]) *
                                      x.block(Field::U).begin()[i]);
      }
    for (unsigned int b = 0; b < 3; ++b)
      ops.zero_constrained(y.block(b));
  }



  template <int dim>
  void
  NestedScheme<dim>::inner_residual(const Vector &u,
                                    const Vector &v,
                                    Vector       &r) const
  {
    const double       c = coeff.c();
    const double      *m = ops.lumped_mass.begin();
    const unsigned int n = u.locally_owned_size();
    ops.stiffness.vmult(r, v);
    r *= coeff.inner_tau;
    for (unsigned int i = 0; i < n; ++i)
      r.begin()[i] += m[i] * ((v.begin()[i] - u.begin()[i]) +
                              c * DoubleWell::d_psi(v.begin()[i]));
    ops.zero_constrained(r);
  }



  template <int dim>
  unsigned int
  NestedScheme<dim>::initialize_v_and_p(BlockVector         &z,
                                        ReducedSystemSolver &solver,
                                        const double         tolerance) const
  {
    z.block(Field::V) = z.block(Field::U);
    Vector r(z.block(Field::U));
    inner_residual(z.block(Field::U), z.block(Field::V), r);
    // below 1e-14 the residual is round-off
    constexpr double absolute_floor = 1e-14;
    return solve_inner_problem(
      z, solver, std::max(tolerance * ops.dual_norm(r), absolute_floor));
  }



  template <int dim>
  unsigned int
  NestedScheme<dim>::solve_inner_problem(BlockVector         &z,
                                         ReducedSystemSolver &solver,
                                         const double         tolerance) const
  {
    const double       a = coeff.a();
    const Vector      &u = z.block(Field::U);
    Vector            &v = z.block(Field::V);
    Vector            &p = z.block(Field::P);
    const double      *m = ops.lumped_mass.begin();
    const unsigned int n = u.locally_owned_size();

    // V: Newton on R_P(U, V) = M(V-U) + c M Psi'(V) + ttau L V = 0, whose
    // Jacobian K(V) is positive definite for ttau < eps^2/2 (convex inner
    // energy)
    constexpr unsigned int max_inner_iterations = 50;
    Vector                 r(u), dv(u);
    unsigned int           iterations = 0;
    // Newton stagnates at the round-off of R_P (about 1e-15 in this norm)
    constexpr double roundoff_level = 1e-12;
    double           previous_norm  = std::numeric_limits<double>::max();
    for (;; ++iterations)
      {
        inner_residual(u, v, r);
        const double norm = ops.dual_norm(r);
        if (norm <= tolerance ||
            (norm <= roundoff_level && norm >= 0.5 * previous_norm))
          break;
        previous_norm = norm;
        AssertThrow(iterations < max_inner_iterations,
                    ExcMessage("The inner problem (V for given U, Algorithm "
                               "3.1) did not converge in 50 Newton "
                               "iterations."));
        TrilinosWrappers::SparseMatrix k;
        build_k(v, 0., k);
        r *= -1;
        solver.solve(k, dv, r);
        ops.zero_constrained(dv);
        v += dv;
      }

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
  double
  NestedScheme<dim>::outer_energy(const Vector      &old_u,
                                  const BlockVector &z) const
  {
    const Vector &u = z.block(Field::U);
    Vector        difference(u);
    difference -= old_u;
    double energy = 0.5 * ops.mass_product(difference, difference);
    difference    = z.block(Field::V);
    difference -= u;
    energy += 0.5 * coeff.a() * ops.mass_product(difference, difference);
    if (coeff.area_weight != 0)
      {
        // 2 tau eta a_eps[U] / (2 eps), with a_eps = (4/3) area
        const double area = phase_field_energies(ops, u, coeff.epsilon).area;
        energy +=
          coeff.tau * coeff.area_weight * (4. / 3.) * area / coeff.epsilon;
      }
    return energy;
  }



  template <int dim>
  Energies
  NestedScheme<dim>::energies(const BlockVector &z) const
  {
    const double ttau = coeff.inner_tau;
    Vector       curvature(z.block(Field::U));
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
