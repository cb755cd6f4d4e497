#ifndef phasefield_schemes_outer_energy_h
#define phasefield_schemes_outer_energy_h

#include <any>
#include <deal.II/base/index_set.h>
#include <map>
#include <phasefield/core/linear_algebra.h>
#include <string>

namespace PhaseField
{
  class EnergyTerm;

  /**
   * The regularisation energy that a time step of the nested scheme
   * decreases, beyond the distance term eps ||u - u^k||^2 (thesis (3.17a),
   * generalised as in (5.7) and (6.3)):
   *
   *   eps ||u-u^k||^2 + 2 tau (mu (eps/2) ||(v-u)/ttau||^2 + eta a_eps[u]
   *                            - <f, u>)
   *
   * with the Willmore weight mu, the area weight eta, the area functional
   * a_eps[u] = (1/2) Int eps |grad u|^2 + Psi(u)/eps, and a forcing f
   * (the biharmonic model problem). Willmore flow is mu = 1, eta = 0; edge
   * restoration is mu = 1, eta > 0 with U fixed outside the restoration
   * region; shape from contour passes its mu and eta.
   *
   * The index set and the forcing are referred to, not copied: their
   * owner (the problem) keeps them up to date when the mesh changes.
   */
  struct OuterEnergy
  {
    /** mu: weight of the Willmore term. */
    double willmore_weight = 1;

    /** eta: weight of the area functional a_eps[U]. */
    double area_weight = 0;

    /**
     * Global indices of the DoFs (at least the locally relevant ones) at
     * which U is held at its value of the previous step (the C^1 data of
     * thesis Definition 5.1); nullptr: U is free everywhere. V and P stay
     * free.
     */
    const dealii::IndexSet *fixed_u = nullptr;

    /**
     * Nodal forcing F = M I_h(f), already multiplied by the lumped mass;
     * nullptr: none. It enters the outer energy as -2 tau F.U.
     */
    const Vector *forcing = nullptr;

    /**
     * A data term d[u] of the problem, in the units of mu W and eta A as
     * the thesis prints them in (6.3) (shape from contour's monolithic
     * coupling: the mismatch j[u] = gamma Int (alpha* - alpha[u])^2, thesis
     * 6.5 and 7.3); nullptr: none. It enters the outer energy as
     * 2 tau d[u], so that a step minimises
     * eps ||u-u^k||^2 + 2 tau (e_reg[u] + d[u]) (make_data_term()). Its
     * Hessian is applied matrix-free (EnergyTerm::add_hessian_vmult(), a
     * Gauss-Newton product for the mismatch). Referred to, not copied.
     */
    const EnergyTerm *data_term = nullptr;

    /**
     * The data of the energy terms registered with register_model_term()
     * (energy_term_registry.h) by the term's name: what its factory reads
     * (e.g. its weight, or a pointer to data that its owner keeps up to
     * date). A registered term without a present() of its own is present
     * where its name is here.
     */
    std::map<std::string, std::any> registered_terms;

    /**
     * Are the area term, a data term, fixed U values or registered terms
     * present? The UU block of the Jacobian is then not diagonal.
     */
    bool
    has_restoration_terms() const
    {
      return area_weight != 0 || fixed_u != nullptr || data_term != nullptr ||
             !registered_terms.empty();
    }
  };
} // namespace PhaseField

#endif
