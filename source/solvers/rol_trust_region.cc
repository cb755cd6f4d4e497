#include <ROL_StatusTest.hpp>
#include <ROL_TypeU_TrustRegionAlgorithm.hpp>
#include <deal.II/optimization/rol/vector_adaptor.h>
#include <limits>
#include <phasefield/solvers/rol_trust_region.h>
#include <sstream>

namespace PhaseField
{
  namespace
  {
    using Adaptor = dealii::Rol::VectorAdaptor<BlockVector>;

    /** The block vector of a ROL vector made by this file. */
    const BlockVector &
    block_vector(const ROL::Vector<double> &v)
    {
      return *dynamic_cast<const Adaptor &>(v).getVector();
    }

    BlockVector &
    block_vector(ROL::Vector<double> &v)
    {
      return *dynamic_cast<Adaptor &>(v).getVector();
    }



    /**
     * A TrustRegionObjective as a ROL::Objective. Values and gradients are
     * taken at the conforming version of ROL's point; the gradient also
     * sets the point of the Hessian products and the preconditioner, which
     * ROL applies at the last accepted iterate, where it took the gradient.
     */
    class RolObjective : public ROL::Objective<double>
    {
    public:
      RolObjective(TrustRegionObjective &objective, const BlockVector &layout)
        : objective(objective)
        , conforming(layout)
      {}

      double
      value(const ROL::Vector<double> &x, double &) override
      {
        conforming = block_vector(x);
        objective.distribute_constraints(conforming);
        return objective.value(conforming);
      }

      void
      gradient(ROL::Vector<double>       &g,
               const ROL::Vector<double> &x,
               double &) override
      {
        conforming = block_vector(x);
        objective.distribute_constraints(conforming);
        objective.gradient(conforming, block_vector(g));
        last_gradient_norm = objective.gradient_norm(block_vector(g));
      }

      void
      hessVec(ROL::Vector<double>       &hv,
              const ROL::Vector<double> &v,
              const ROL::Vector<double> &,
              double &) override
      {
        objective.hessian_vmult(block_vector(v), block_vector(hv));
        ++n_hessian_products;
      }

      void
      precond(ROL::Vector<double>       &pv,
              const ROL::Vector<double> &v,
              const ROL::Vector<double> &,
              double &) override
      {
        objective.precondition(block_vector(v), block_vector(pv));
      }

      /** objective.gradient_norm() of the last gradient. */
      double       last_gradient_norm = std::numeric_limits<double>::infinity();
      unsigned int n_hessian_products = 0;

    private:
      TrustRegionObjective &objective;
      BlockVector           conforming;
    };



    /**
     * Continue while the gradient norm of the objective (not ROL's l2
     * norm of the coefficients) is above the tolerance and iterations are
     * left.
     */
    class GradientNormTest : public ROL::StatusTest<double>
    {
    public:
      GradientNormTest(const RolObjective       &objective,
                       const TrustRegionControl &control)
        : objective(objective)
        , control(control)
      {}

      bool
      check(ROL::AlgorithmState<double> &state) override
      {
        return objective.last_gradient_norm > control.gradient_tolerance &&
               state.iter < static_cast<int>(control.max_iterations);
      }

    private:
      const RolObjective       &objective;
      const TrustRegionControl &control;
    };



    /** ROL's parameters with the constants of trust_region_minimize(). */
    ROL::ParameterList
    rol_parameters(const TrustRegionControl &control)
    {
      ROL::ParameterList  list;
      ROL::ParameterList &tr = list.sublist("Step").sublist("Trust Region");
      tr.set("Subproblem Solver", "Truncated CG");
      // ROL computes its own initial radius for a value <= 0
      tr.set("Initial Radius",
             control.initial_radius > 0 ? control.initial_radius : -1.);
      tr.set("Step Acceptance Threshold", TrustRegion::accept_ratio);
      tr.set("Radius Shrinking Threshold", TrustRegion::shrink_ratio);
      tr.set("Radius Growing Threshold", TrustRegion::grow_ratio);
      tr.set("Radius Shrinking Rate (Negative rho)", TrustRegion::shrink);
      tr.set("Radius Shrinking Rate (Positive rho)", TrustRegion::shrink);
      tr.set("Radius Growing Rate", TrustRegion::grow);
      ROL::ParameterList &krylov = list.sublist("General").sublist("Krylov");
      krylov.set("Iteration Limit",
                 static_cast<int>(control.max_cg_iterations));
      // ROL stops CG at min(absolute, relative |g|)
      krylov.set("Absolute Tolerance", std::numeric_limits<double>::max());
      krylov.set("Relative Tolerance", TrustRegion::cg_forcing);
      list.sublist("General").set("Output Level", 0);
      return list;
    }
  } // namespace



  TrustRegionReport
  rol_trust_region_minimize(TrustRegionObjective     &objective,
                            BlockVector              &x,
                            const TrustRegionControl &control)
  {
    RolObjective rol_objective(objective, x);
    objective.distribute_constraints(x);
    Adaptor rol_x(ROL::makePtrFromRef(x));
    auto    g = ROL::makePtr<BlockVector>(x);
    Adaptor rol_g(g);

    ROL::ParameterList                       list = rol_parameters(control);
    ROL::TypeU::TrustRegionAlgorithm<double> algorithm(list);
    algorithm.setStatusTest(ROL::makePtr<GradientNormTest>(rol_objective,
                                                           control),
                            false);
    std::ostringstream history; // ROL prints nothing at Output Level 0
    algorithm.run(rol_x, rol_g, rol_objective, history);
    objective.distribute_constraints(x);

    TrustRegionReport report;
    report.iterations    = algorithm.getState()->iter;
    report.cg_iterations = rol_objective.n_hessian_products;
    report.gradient_norm = rol_objective.last_gradient_norm;
    report.converged     = report.gradient_norm <= control.gradient_tolerance;
    report.radius        = algorithm.getState()->searchSize;
    // the next gradient() of the caller sets the point of Hessian products
    return report;
  }
} // namespace PhaseField
