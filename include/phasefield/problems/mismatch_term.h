#ifndef phasefield_problems_mismatch_term_h
#define phasefield_problems_mismatch_term_h

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
     * signs), for a locally owned @p d (constraints distributed here).
     */
    std::vector<double>
    jacobian_product(const Vector &u, const Vector &d) const;

    /**
     * @p y += @p factor J^T 2 gamma W @p residual, for a residual on the
     * grid points (the ghosted state @p u fixes the signs).
     */
    void
    add_transposed(const Vector              &u,
                   const std::vector<double> &residual,
                   const double               factor,
                   Vector                    &y) const;

    const Discretization<dim>               &discretization;
    const HuffmanLabeling::LabelingGrid<dim> labeling_grid;
    const std::vector<double>                target;
    const double                             gamma;
  };



  /**
   * The step model of the mismatch at a state U0 (the start of a
   * monolithic contour step): the second-order Taylor model at U0 of j
   * with every column difference's |s| replaced by its quadratic
   * majoriser (s^2 + s0^2) / (2 |s0|) (equal to |s| at s0 = s(U0)),
   *
   *   j_0[U] = gamma Int (alpha[U0] + J0 (U - U0) - alpha*)^2 dx'
   *            + (1/2) (U - U0) . C (U - U0),
   *
   * with J0 the labeling linearised at U0 (the signs of its column
   * differences) and C the curvature of the majoriser where alpha[U0] >
   * alpha* (HuffmanLabeling::add_kink_curvature_product(), weights
   * gamma w_q (alpha - alpha*), 1/|s0| floored at curvature_floor). So
   * j_0 = j at U0 with the same gradient, and its Hessian 2 gamma J0^T W
   * J0 + C is the Gauss-Newton product of j plus a positive part.
   *
   * Why C: alpha[U] is piecewise linear in U with kinks where a column
   * difference s changes sign, and j rises as |s| at a kink where alpha >
   * alpha* (too many labels), most of all in the flat parts of the
   * profile where |s0| is tiny. Newton's method on j itself cycled there
   * (the residual alternating between two values); on the Gauss-Newton
   * model without C the steps crossed those kinks, and j rose where the
   * model fell, so that the energy law with j failed at every tau down to
   * Tau/16 (doc/shape_from_contour.md, "The monolithic coupling"). C keeps
   * the steps from crossing them: a step of the model then lowers j to
   * second order, and the time loop accepts it by the energy law with j
   * (the merit function).
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
