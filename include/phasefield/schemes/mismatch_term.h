#ifndef phasefield_schemes_mismatch_term_h
#define phasefield_schemes_mismatch_term_h

#include <phasefield/core/linear_algebra.h>
#include <phasefield/geometry/huffman_labeling.h>
#include <phasefield/mesh/discretization.h>
#include <phasefield/schemes/energy_terms.h>
#include <vector>

namespace PhaseField
{
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
    /** @p u with the ghost values that the column integrals read. */
    Vector
    ghosted(const Vector &u) const;

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
} // namespace PhaseField

#endif
