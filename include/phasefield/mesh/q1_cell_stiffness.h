#ifndef phasefield_mesh_q1_cell_stiffness_h
#define phasefield_mesh_q1_cell_stiffness_h

#include <array>
#include <cmath>
#include <deal.II/base/quadrature.h>
#include <deal.II/base/utilities.h>

namespace PhaseField
{
  /**
   * The Q1 stiffness matrix of an axis-parallel cube cell of edge h,
   * h^(dim-2) A_ref, applied to the DoF values of a cell (Q1Cells reads
   * them with the constraints resolved and distributes the result): every
   * cell of the meshes of [0,1]^dim here is such a cube. A_ref, the matrix of
   * the unit cube with the stiffness rule, is precomputed, so a cell costs
   * 2^dim x 2^dim multiply-adds instead of the evaluation and integration at
   * the quadrature points of the general FEEvaluation path, whose evaluate()
   * and integrate() dominated the matrix-free runs (doc/benchmarks.md, "Choices
   * in the code").
   */
  template <int dim, typename Number>
  class Q1CellStiffness
  {
  public:
    /** Q1 DoFs of a cell, lexicographic (FE_Q's order of the vertices). */
    static constexpr unsigned int n = 1U << dim;

    /** A_ref for the 1D stiffness rule @p rule (two points). */
    explicit Q1CellStiffness(const dealii::Quadrature<1> &rule)
    {
      // 1D: stiffness k(a, b) = (+-1)(+-1) exactly; mass by the rule
      double mass_1d[2][2] = {{0, 0}, {0, 0}};
      for (unsigned int q = 0; q < rule.size(); ++q)
        {
          const double x     = rule.point(q)[0];
          const double phi[] = {1 - x, x};
          for (unsigned int a = 0; a < 2; ++a)
            for (unsigned int b = 0; b < 2; ++b)
              mass_1d[a][b] += phi[a] * phi[b] * rule.weight(q);
        }
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = 0; j < n; ++j)
          {
            double a_ij = 0;
            for (unsigned int d = 0; d < dim; ++d)
              {
                double term = 1;
                for (unsigned int e = 0; e < dim; ++e)
                  {
                    const unsigned int ie = (i >> e) & 1, je = (j >> e) & 1;
                    term *= e == d ? (ie == je ? 1. : -1.) : mass_1d[ie][je];
                  }
                a_ij += term;
              }
            reference[i][j] = static_cast<Number>(a_ij);
          }
    }

    /** The values of the cell's DoFs become @p scale A_ref times them. */
    void
    apply(Number (&values)[n], const Number scale) const
    {
      // A_ref is symmetric: accumulate its columns, a loop over the n
      // values of a column that the compiler vectorises
      Number result[n] = {};
      for (unsigned int j = 0; j < n; ++j)
        {
          const Number v_j = scale * values[j];
          for (unsigned int i = 0; i < n; ++i)
            result[i] += reference[j][i] * v_j;
        }
      for (unsigned int i = 0; i < n; ++i)
        values[i] = result[i];
    }

  private:
    alignas(4 * sizeof(Number)) Number reference[n][n];
  };
} // namespace PhaseField

#endif
