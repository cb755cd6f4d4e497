#include <iostream>
#include <limits>
#include <phasefield/core/statistics.h>
#include <phasefield/geometry/images.h>
#include <phasefield/geometry/shapes.h>
#include <phasefield/mesh/zero_level_surface.h>
#include <phasefield/problems/willmore_problem.h>
#include <phasefield/schemes/constraints.h>
#include <phasefield/schemes/scheme_registry.h>

namespace PhaseField
{
  void
  WillmoreFlowParameters::declare_parameters(dealii::ParameterHandler &prm)
  {
    WillmoreParameters::declare_parameters(prm);
    ConstraintParameters::declare_parameters(prm);
    declare_scheme_parameters(prm);
  }



  void
  WillmoreFlowParameters::parse_parameters(dealii::ParameterHandler &prm)
  {
    WillmoreParameters::parse_parameters(prm);
    constraints.parse_parameters(prm);
    ModelTerms needed;
    if (constraints.any())
      {
        needed.with(ScalarConstraints::name());
        if (model.coarse_start_level != 0)
          throw InputError(
            "Constraints / Volume and Area = fixed hold the values of the "
            "phase field on Finest level; they cannot be combined with "
            "Time stepping / Coarse start level = " +
            std::to_string(model.coarse_start_level) + " (set it to 0).");
      }
    model.scheme = parse_scheme_parameters(prm, needed, "willmore_flow");
  }



  namespace
  {
    /** Willmore flow of the `Geometry` shape. */
    template <int dim>
    typename PhaseFieldProblem<dim>::Setup
    willmore_setup(const WillmoreParameters   &parameters,
                   const ConstraintParameters &constraints)
    {
      typename PhaseFieldProblem<dim>::Setup setup;
      setup.program_name = "willmore_flow";
      setup.signed_distance =
        Shapes::create_signed_distance<dim>(parameters.geometry);
      if (constraints.any())
        setup.outer_energy.registered_terms[ScalarConstraints::name()] =
          std::make_shared<ScalarConstraints>(constraints,
                                              parameters.model.epsilon);
      return setup;
    }
  } // namespace



  template <int dim>
  WillmoreProblem<dim>::WillmoreProblem(const WillmoreParameters   &parameters,
                                        const ConstraintParameters &constraints)
    : PhaseFieldProblem<dim>(parameters,
                             willmore_setup<dim>(parameters, constraints))
    , constraints(constraints)
  {}



  template <int dim>
  Checkpoint::Parameters
  WillmoreProblem<dim>::own_checkpoint_parameters() const
  {
    if (!constraints.any())
      return {};
    const auto state = [](const bool fixed) {
      return std::string(fixed ? "fixed" : "free");
    };
    return {{"Constraints / Volume", state(constraints.volume)},
            {"Constraints / Area", state(constraints.area)},
            {"Constraints / Volume value",
             Checkpoint::exact_value(constraints.volume_value)},
            {"Constraints / Area value",
             Checkpoint::exact_value(constraints.area_value)},
            {"Constraints / Reduced volume",
             Checkpoint::exact_value(constraints.reduced_volume)}};
  }



  template <int dim>
  double
  WillmoreProblem<dim>::l2_error(const BlockVector &state,
                                 const double       time) const
  {
    const WillmoreParameters &parameters = this->willmore_parameters;
    const double radius = Shapes::exact_radius(parameters.geometry, dim, time);
    if (radius < 0)
      return std::numeric_limits<double>::quiet_NaN();
    const Shapes::SphereDistance<dim> distance(
      Shapes::shape_center<dim>(parameters.geometry), radius);
    const Shapes::PhaseFieldProfile<dim> exact(distance,
                                               parameters.model.epsilon);
    return this->discretization.error(state.block(0),
                                      exact,
                                      dealii::VectorTools::L2_norm);
  }



  template <int dim>
  void
  WillmoreProblem<dim>::run()
  {
    PhaseFieldProblem<dim>::run();
    if constexpr (dim == 2)
      {
        const std::vector<double> values =
          Images::sample_on_pixel_grid(this->discretization.get_dof_handler(),
                                       this->solution.block(0),
                                       picture_pixels);
        const std::string filename =
          this->willmore_parameters.output_directory + "/phase_field.png";
        // on rank 0; a failed write stops every rank
        run_on_root(this->mpi_communicator, [&]() {
          Images::write_picture_with_zero_contour(values,
                                                  picture_pixels,
                                                  filename);
          std::cout << "Picture: " << filename << std::endl;
        });
      }
    else
      {
        const std::string filename =
          this->willmore_parameters.output_directory + "/surface.png";
        // the continuous Q1 field: hanging nodes on their constraints
        Vector u = this->solution.block(0);
        this->discretization.get_constraints().distribute(u);
        ZeroLevelSurface::write_picture(this->discretization.get_dof_handler(),
                                        this->discretization.ghosted_copy(u),
                                        filename);
        this->pcout << "Picture: " << filename << std::endl;
      }
  }



  template class WillmoreProblem<2>;
  template class WillmoreProblem<3>;
} // namespace PhaseField
