#include <cmath>
#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/mapping_q1.h>
#include <map>
#include <phasefield/core/statistics.h>
#include <phasefield/geometry/images.h>
#include <phasefield/geometry/shapes.h>
#include <phasefield/problems/restoration_problem.h>

namespace PhaseField
{
  using namespace dealii;

  namespace
  {
    /**
     * Willmore flow with the area term and fixed values outside the
     * region, from the damaged image.
     */
    PhaseFieldProblem<2>::Setup
    restoration_setup(const EdgeRestorationParameters &parameters,
                      const IndexSet                  &fixed_u_dofs)
    {
      const RestorationParameters &restoration = parameters.restoration;
      PhaseFieldProblem<2>::Setup  setup;
      setup.program_name = "edge_restoration";
      setup.signed_distance =
        Images::create_damaged_image(parameters.willmore.geometry,
                                     restoration.image_file,
                                     restoration.threshold,
                                     restoration.damage);
      setup.outer_energy.area_weight = restoration.eta;
      setup.outer_energy.fixed_u     = &fixed_u_dofs;
      // coarsen only where 1 - |U| < 1 - tanh(6) = 1.2e-5 (Band width 4):
      // the energy then changes by about 1e-10 at a re-meshing, not 1e-7
      constexpr double coarsening_band_factor = 1.5;
      setup.coarsening_band_factor            = coarsening_band_factor;
      return setup;
    }
  } // namespace



  RestorationProblem::RestorationProblem(
    const EdgeRestorationParameters &parameters)
    // the set is referred to by the outer energy, filled once the mesh
    // exists (setup_fixed_u())
    : PhaseFieldProblem<2>(parameters.willmore,
                           restoration_setup(parameters, fixed_u_dofs))
    , restoration(parameters.restoration)
  {}



  void
  RestorationProblem::initialize_fields()
  {
    setup_fixed_u();
    PhaseFieldProblem<2>::initialize_fields();
  }



  void
  RestorationProblem::after_remesh(BlockVector &state)
  {
    setup_fixed_u();
    reset_fixed_u(state);
  }



  void
  RestorationProblem::after_load(BlockVector               &state,
                                 const std::vector<double> &problem_data)
  {
    (void)state;
    (void)problem_data;
    setup_fixed_u();
  }



  Checkpoint::Parameters
  RestorationProblem::own_checkpoint_parameters() const
  {
    const auto box = [](const Box2D &b) {
      return b.empty() ? std::string() :
                         Checkpoint::exact_values(b.lower) + ", " +
                           Checkpoint::exact_values(b.upper);
    };
    Checkpoint::Parameters recorded = {
      {"Restoration / Eta", Checkpoint::exact_value(restoration.eta)},
      {"Restoration / Region", box(restoration.region)},
      {"Restoration / Damage", box(restoration.damage)}};
    const GeometryParameters &geometry = willmore_parameters.geometry;
    if (geometry.shape == "image")
      {
        recorded.emplace_back("Geometry / Shape", "image");
        recorded.emplace_back("Geometry / Image file", restoration.image_file);
        recorded.emplace_back("Geometry / Threshold",
                              Checkpoint::exact_value(restoration.threshold));
      }
    else
      for (const auto &entry : Checkpoint::geometry_parameters(geometry))
        recorded.push_back(entry);
    return recorded;
  }



  void
  RestorationProblem::setup_fixed_u()
  {
    const DoFHandler<2>      &dof_handler = discretization.get_dof_handler();
    const LumpedOperators<2> &operators   = discretization.get_operators();
    fixed_u_dofs.clear();
    fixed_u_dofs.set_size(dof_handler.n_dofs());
    initial_u.reinit(operators.locally_owned_dofs, mpi_communicator);
    const Shapes::PhaseFieldProfile<2> u0(*setup.signed_distance,
                                          level_parameters.model.epsilon);
    discretization.interpolate(u0, initial_u);
    discretization.get_constraints().distribute(initial_u);
    std::map<types::global_dof_index, Point<2>> support_points;
    DoFTools::map_dofs_to_support_points(MappingQ1<2>(),
                                         dof_handler,
                                         support_points);
    for (const auto &[dof, point] : support_points)
      if (!restoration.region.contains(point))
        fixed_u_dofs.add_index(dof);
    fixed_u_dofs.compress();
  }



  void
  RestorationProblem::reset_fixed_u(BlockVector &state) const
  {
    Vector         &u     = state.block(0);
    const IndexSet &owned = discretization.get_operators().locally_owned_dofs;
    const unsigned int n  = u.locally_owned_size();
    for (unsigned int i = 0; i < n; ++i)
      if (fixed_u_dofs.is_element(owned.nth_index_in_set(i)))
        u.begin()[i] = initial_u.begin()[i];
  }



  double
  RestorationProblem::fixed_u_deviation(const BlockVector &state) const
  {
    const Vector   &u     = state.block(0);
    const IndexSet &owned = discretization.get_operators().locally_owned_dofs;
    const unsigned int n  = u.locally_owned_size();
    double             deviation = 0;
    for (unsigned int i = 0; i < n; ++i)
      if (fixed_u_dofs.is_element(owned.nth_index_in_set(i)))
        deviation =
          std::max(deviation, std::abs(u.begin()[i] - initial_u.begin()[i]));
    return Utilities::MPI::max(deviation, mpi_communicator);
  }



  std::vector<std::string>
  RestorationProblem::extra_columns() const
  {
    return {"weighted_energy", "fixed_u_deviation"};
  }



  std::vector<double>
  RestorationProblem::extra_values(const BlockVector &state,
                                   const Energies    &energies) const
  {
    return {energies.willmore + restoration.eta * energies.area,
            fixed_u_deviation(state)};
  }



  void
  RestorationProblem::run()
  {
    PhaseFieldProblem<2>::run();
    write_pictures();
  }



  void
  RestorationProblem::write_pictures() const
  {
    const unsigned int        n = restoration.picture_resolution;
    const std::vector<double> restored =
      Images::sample_on_pixel_grid(discretization.get_dof_handler(),
                                   solution.block(0),
                                   n);
    // on rank 0; a failed write stops every rank
    run_on_root(mpi_communicator, [&]() {
      // the initial data is a function: sample it directly
      const Shapes::PhaseFieldProfile<2> u0(*setup.signed_distance,
                                            willmore_parameters.model.epsilon);
      std::vector<double>                initial(n * n);
      for (unsigned int j = 0; j < n; ++j)
        for (unsigned int i = 0; i < n; ++i)
          initial[j * n + i] = u0.value(Point<2>((i + 0.5) / n, (j + 0.5) / n));
      const std::string &directory = willmore_parameters.output_directory;
      const Box2D       &region    = restoration.region;
      Images::write_picture(initial, n, region, directory + "/initial.png");
      Images::write_picture(restored, n, region, directory + "/restored.png");
      std::cout << "Pictures: " << directory << "/initial.png, " << directory
                << "/restored.png" << std::endl;
    });
  }
} // namespace PhaseField
