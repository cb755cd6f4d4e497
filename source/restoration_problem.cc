#include <cmath>
#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <phasefield/images.h>
#include <phasefield/restoration_problem.h>
#include <phasefield/shapes.h>
#include <phasefield/willmore_problem.h>

namespace PhaseField
{
  using namespace dealii;

  std::vector<double>
  sample_on_pixel_grid(const DoFHandler<2>                 &dof_handler,
                       const TrilinosWrappers::MPI::Vector &u,
                       const unsigned int                   n)
  {
    IndexSet relevant;
    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
    TrilinosWrappers::MPI::Vector ghosted(dof_handler.locally_owned_dofs(),
                                          relevant,
                                          u.get_mpi_communicator());
    ghosted = u;

    // every pixel centre lies in exactly one half-open cell [x0,x1)x[y0,y1)
    std::vector<double> values(n * n, 0.);
    const auto          first_pixel = [n](const double x) {
      return static_cast<int>(std::ceil(x * n - 0.5));
    };
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          // Q1 vertices 0..3: (0,0), (1,0), (0,1), (1,1) of the cell
          const Point<2> lower = cell->vertex(0), upper = cell->vertex(3);
          const double   width = upper[0] - lower[0];
          double         corner[4];
          for (unsigned int v = 0; v < 4; ++v)
            corner[v] = ghosted(cell->vertex_dof_index(v, 0));
          for (int j = std::max(0, first_pixel(lower[1]));
               j < std::min<int>(n, first_pixel(upper[1]));
               ++j)
            for (int i = std::max(0, first_pixel(lower[0]));
                 i < std::min<int>(n, first_pixel(upper[0]));
                 ++i)
              {
                const double sx = ((i + 0.5) / n - lower[0]) / width;
                const double sy = ((j + 0.5) / n - lower[1]) / width;
                values[j * n + i] =
                  (1 - sy) * ((1 - sx) * corner[0] + sx * corner[1]) +
                  sy * ((1 - sx) * corner[2] + sx * corner[3]);
              }
        }
    Utilities::MPI::sum(values, u.get_mpi_communicator(), values);
    return values;
  }



  RestorationProblem::RestorationProblem(
    const EdgeRestorationParameters &parameters)
    : prm(parameters)
  {}



  void
  RestorationProblem::run()
  {
    const RestorationParameters &restoration = prm.restoration;
    WillmoreProblemOptions<2>    options;
    options.program_name = "edge_restoration";
    options.area_weight  = restoration.eta;
    // a stationary restored edge must not make the mesh alternate
    options.refine_unrefined_islands = false;
    // coarsen only where 1 - |U| < 1 - tanh(6) = 1.2e-5 (Band width 4): the
    // energy then changes by about 1e-10 at a re-meshing, not 1e-7
    constexpr double coarsening_band_factor = 1.5;
    options.coarsening_band_factor          = coarsening_band_factor;
    options.signed_distance =
      Images::create_damaged_image(prm.willmore.geometry, restoration);
    const Box2D region = restoration.region;
    options.u_is_free  = [region](const Point<2> &p) {
      return p[0] > region.lower[0] && p[0] < region.upper[0] &&
             p[1] > region.lower[1] && p[1] < region.upper[1];
    };

    WillmoreProblem<2> problem(prm.willmore, options);
    problem.run();

    const MPI_Comm            comm = MPI_COMM_WORLD;
    const unsigned int        n    = restoration.picture_resolution;
    const std::vector<double> restored =
      sample_on_pixel_grid(problem.get_dof_handler(),
                           problem.state().block(0),
                           n);
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        // the initial data is a function: sample it directly
        const Shapes::PhaseFieldProfile<2> u0(*options.signed_distance,
                                              prm.willmore.model.epsilon);
        std::vector<double>                initial(n * n);
        for (unsigned int j = 0; j < n; ++j)
          for (unsigned int i = 0; i < n; ++i)
            initial[j * n + i] =
              u0.value(Point<2>((i + 0.5) / n, (j + 0.5) / n));
        const std::string &directory = prm.willmore.output_directory;
        Images::write_picture(initial, n, region, directory + "/initial.png");
        Images::write_picture(restored, n, region, directory + "/restored.png");
        std::cout << "Pictures: " << directory << "/initial.png, " << directory
                  << "/restored.png" << std::endl;
      }
  }
} // namespace PhaseField
