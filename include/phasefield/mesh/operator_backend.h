#ifndef phasefield_mesh_operator_backend_h
#define phasefield_mesh_operator_backend_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <functional>
#include <memory>
#include <phasefield/core/linear_algebra.h>
#include <phasefield/core/parameters.h>
#include <phasefield/mesh/stiffness_operator.h>
#include <string>
#include <vector>

namespace PhaseField
{
  /**
   * What a backend's factory gets to set up the stiffness operator L of one
   * mesh (LumpedOperators::reinit()): the scalar Q1 DoFs, their
   * constraints (hanging nodes and boundary conditions) and the lumped
   * mass, all of which outlive the operator until
   * LumpedOperators::release().
   */
  template <int dim>
  struct StiffnessSetup
  {
    const dealii::DoFHandler<dim>           &dof_handler;
    const dealii::AffineConstraints<double> &constraints;
    const Vector                            &lumped_mass;
    StiffnessQuadrature                      stiffness_quadrature;
    /** Homogeneous Dirichlet conditions on the whole boundary. */
    bool     dirichlet;
    MPI_Comm mpi_communicator;
  };

  /** Makes the stiffness operator of one mesh. Collective. */
  template <int dim>
  using StiffnessFactory = std::function<std::shared_ptr<StiffnessOperator>(
    const StiffnessSetup<dim> &)>;

  /**
   * One operator backend: how the stiffness operator L and its shifted
   * operators f L + D are applied and preconditioned. The registry
   * (register_operator_backend()) makes `Linear solver / Type` = name
   * choose it with the iterative solver; LumpedOperators builds L with its
   * factory, Discretization sets up the mesh as it says, and the schemes
   * print its descriptions. The library's backends are registered in
   * source/mesh/operator_backends.cc.
   */
  struct OperatorBackendEntry
  {
    /** The value of `Linear solver / Type` that chooses it. */
    std::string name;
    /** The user documentation, part of `Type`'s in `--help`. */
    std::string documentation;
    /** The linear solver as the nested scheme prints it. */
    std::string solver_description;
    /** The preconditioner as the augmented Lagrangian scheme prints it. */
    std::string preconditioner_description;
    /**
     * Does L need the levels of the mesh (a multigrid hierarchy of the
     * triangulation and level DoFs)? Such a backend does not support
     * periodic boundary conditions.
     */
    bool multigrid_levels = false;
    /**
     * Is L a TrilinosStiffness, whose matrix the direct solvers and the
     * assembled Jacobians read (LumpedOperators::stiffness_matrix())?
     */
    bool assembled_matrix = false;
    /** The factories in 2D and 3D. */
    StiffnessFactory<2> make_stiffness_2d;
    StiffnessFactory<3> make_stiffness_3d;

    /** Both factories from the class template @p Factory's make(). */
    template <template <int> class Factory>
    void
    set_factory()
    {
      make_stiffness_2d = &Factory<2>::make;
      make_stiffness_3d = &Factory<3>::make;
    }

    /** The factory of dimension @p dim. */
    template <int dim>
    const StiffnessFactory<dim> &
    make_stiffness() const
    {
      if constexpr (dim == 2)
        return make_stiffness_2d;
      else
        return make_stiffness_3d;
    }
  };

  /**
   * Add @p entry to the registry and its name and documentation to the
   * values of `Linear solver / Type` (linear_solver_type_values()); before
   * the parameters are declared. Throws if the name is taken.
   */
  void
  register_operator_backend(const OperatorBackendEntry &entry);

  /** The registered backends, in the order of registration. */
  const std::vector<OperatorBackendEntry> &
  registered_operator_backends();

  /** The backend named @p name; throws if none is. */
  const OperatorBackendEntry &
  operator_backend(const std::string &name);
} // namespace PhaseField

#endif
