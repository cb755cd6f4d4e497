#ifndef phasefield_schemes_mismatch_term_h
#define phasefield_schemes_mismatch_term_h

#include <phasefield/core/linear_algebra.h>
#include <phasefield/geometry/huffman_labeling.h>
#include <phasefield/mesh/discretization.h>
#include <phasefield/schemes/energy_terms.h>
#include <vector>

namespace PhaseField
{
  template <int dim>
  class MismatchModel;

  /**
   * The mismatch of shape from contour (thesis 6.2),
   *
   *   j[U] = gamma Int (alpha* - alpha[U])^2 dx',
   *
   * with the phase-field Huffman labeling alpha[U] (HuffmanLabeling) and
   * the target labeling alpha* on the pixel grid of one level. Its
   * gradient is J^T 2 gamma W (alpha[U] - alpha*), with J the linearised
   * labeling and W the quadrature weights of the grid; j has no Hessian
   * where sign(d_d U) jumps, and add_hessian_vmult() is the Gauss-Newton
   * product J^T 2 gamma W J d (two column integrations). The values are
   * j itself (gamma included), not divided by 2 eps as the nested step's
   * residual is: the explicit step of thesis Algorithm 6.1 is
   * eps M (U - U^{k+1/3}) = -tau G with G the gradient.
   */
  template <int dim>
  class MismatchTerm : public EnergyTerm
  {
  public:
    /** alpha[U], j and the labeling error Int |alpha* - alpha[U]| dx'. */
    struct Evaluation
    {
      std::vector<double> alpha;
      double              energy         = 0;
      double              labeling_error = 0;
    };

    /**
     * The term on @p discretization (which must outlive it) for the pixel
     * grid of level @p level, the labeling @p target on it and the
     * weight @p gamma.
     */
    MismatchTerm(const Discretization<dim> &discretization,
                 const unsigned int         level,
                 std::vector<double>        target,
                 const double               gamma);

    std::string
    name() const override
    {
      return "mismatch";
    }
    bool
    gauss_newton() const override
    {
      return true;
    }
    double
    value(const Vector &u) const override;
    void
    add_gradient(const Vector &u,
                 const double  factor,
                 Vector       &g) const override;
    void
    add_hessian_vmult(const Vector &u,
                      const Vector &d,
                      const double  factor,
                      Vector       &y) const override;

    /**
     * The Gauss-Newton model of j at @p u0 (MismatchModel): the step model
     * of the monolithic coupling.
     */
    std::unique_ptr<EnergyTerm>
    step_model(const Vector &u0) const override;

    /** alpha[@p u], j and the labeling error. Collective. */
    Evaluation
    evaluate(const Vector &u) const;

    /** The pixel grid. */
    const HuffmanLabeling::LabelingGrid<dim> &
    grid() const
    {
      return labeling_grid;
    }

  private:
    friend class MismatchModel<dim>;

    /** @p u with the ghost values that the column integrals read. */
    Vector
    ghosted(const Vector &u) const;

    /**
     * J @p d, the labeling linearised at the ghosted state @p u (its
     * signs; column differences of at most @p kink_width frozen), for a
     * locally owned @p d (constraints distributed here).
     */
    std::vector<double>
    jacobian_product(const Vector &u,
                     const Vector &d,
                     const double  kink_width = 0) const;

    /**
     * @p y += @p factor J^T 2 gamma W @p residual, for a residual on the
     * grid points (the ghosted state @p u fixes the signs; column
     * differences of at most @p kink_width frozen).
     */
    void
    add_transposed(const Vector              &u,
                   const std::vector<double> &residual,
                   const double               factor,
                   Vector                    &y,
                   const double               kink_width = 0) const;

    const Discretization<dim>               &discretization;
    const HuffmanLabeling::LabelingGrid<dim> labeling_grid;
    const std::vector<double>                target;
    const double                             gamma;
  };



  /**
   * The Gauss-Newton model of the mismatch at a state U0,
   *
   *   j_0[U] = gamma Int (alpha[U0] + J0 (U - U0) - alpha*)^2 dx',
   *
   * with J0 the labeling linearised at U0 (the signs of its column
   * differences), in which the column differences of U0 smaller than
   * kink_width in magnitude are frozen (J0 is zero there). alpha[U] is
   * piecewise linear in U, so j_0 = j wherever no column difference has
   * changed sign since U0 and the frozen ones have not changed; where one
   * has, j_0 is the quadratic continuation of j across the kink. Its
   * gradient is 2 gamma
   * J0^T W (alpha[U0] + J0 (U - U0) - alpha*) and its Hessian exactly 2 gamma
   * J0^T W J0 (the Gauss-Newton product of j at U0), so Newton's method on a
   * step with it converges where it cycles on j itself (the kinks); the time
   * loop accepts the step by the energy law with j (the merit function).
   */
  template <int dim>
  class MismatchModel : public EnergyTerm
  {
  public:
    /** The model of @p term (which must outlive it) at @p u0. Collective. */
    MismatchModel(const MismatchTerm<dim> &term, const Vector &u0);

    std::string
    name() const override
    {
      return "mismatch model";
    }
    double
    value(const Vector &u) const override;
    void
    add_gradient(const Vector &u,
                 const double  factor,
                 Vector       &g) const override;
    void
    add_hessian_vmult(const Vector &u,
                      const Vector &d,
                      const double  factor,
                      Vector       &y) const override;

    /**
     * Column differences |U0(x', top) - U0(x', bottom)| (U jumps by 2
     * across the interface) at most this are frozen in the model: there
     * the sign of J0 is that of round-off or of the flat tanh tails, and
     * a step crosses zero, where j rises as |s| while j_0 falls. With only
     * the exact zeros frozen, the monolithic step of the built-in default
     * at level 5 broke the energy law with j from step 8 on at every
     * tau down to Tau/16, by the same 0.004 (2026-11-29,
     * doc/shape_from_contour.md, "The monolithic coupling").
     */
    static constexpr double kink_width = 0;

    /**
     * The smallest |s0| in the curvature 1/|s0| of the majoriser
     * (HuffmanLabeling::add_kink_curvature_product()).
     */
    static constexpr double curvature_floor = 1e-4;

  private:
    /** alpha[U0] + J0 (@p u - U0) - alpha* at the points of the grid. */
    std::vector<double>
    linear_residual(const Vector &u) const;

    /** @p y += @p factor C @p d with the majoriser's curvature C. */
    void
    add_curvature(const Vector &d, const double factor, Vector &y) const;

    const MismatchTerm<dim> &term;
    /** U0, locally owned. */
    const Vector u0_owned;
    /** U0, ghosted (the signs of J0). */
    const Vector u0;
    /** alpha[U0] - alpha*. */
    std::vector<double> residual0;
    /** gamma w_q max(alpha[U0] - alpha*, 0) (add_curvature()). */
    std::vector<double> curvature_weight;
  };
} // namespace PhaseField

#endif
