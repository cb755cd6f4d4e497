#include <cmath>
#include <deal.II/base/mpi.h>
#include <phasefield/mesh/narrow_band.h>

namespace PhaseField
{
  namespace NarrowBand
  {
    using namespace dealii;

    template <int dim>
    void
    refine_around_zero_level_set(
      parallel::distributed::Triangulation<dim> &triangulation,
      const Function<dim>                       &signed_distance,
      const double                               band_width,
      const double                               epsilon,
      const unsigned int                         finest_level)
    {
      while (true)
        {
          unsigned int n_flagged = 0;
          for (const auto &cell : triangulation.active_cell_iterators())
            if (cell->is_locally_owned() && cell->level() < int(finest_level))
              {
                const double d = signed_distance.value(cell->center());
                if (std::abs(d) < band_width * epsilon + 0.5 * cell->diameter())
                  {
                    cell->set_refine_flag();
                    ++n_flagged;
                  }
              }
          if (Utilities::MPI::sum(n_flagged,
                                  triangulation.get_communicator()) == 0)
            break;
          triangulation.execute_coarsening_and_refinement();
        }
    }



    template <int dim>
    bool
    flag_cells_from_phase_field(const DoFHandler<dim> &dof_handler,
                                const TrilinosWrappers::MPI::Vector &u,
                                const double                         band_width,
                                const unsigned int finest_level,
                                const unsigned int coarsest_level,
                                const double       coarsening_band_width)
    {
      const double threshold = std::tanh(band_width);
      const double coarsening_threshold =
        std::tanh(std::max(band_width, coarsening_band_width));
      Vector<double> values(dof_handler.get_fe().n_dofs_per_cell());
      unsigned int   n_flagged = 0;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            cell->get_dof_values(u, values);
            bool in_band = false, in_wide_band = false, positive = false,
                 negative = false;
            for (const double value : values)
              {
                in_band = in_band || (std::abs(value) < threshold);
                in_wide_band =
                  in_wide_band || (std::abs(value) < coarsening_threshold);
                positive = positive || (value > 0);
                negative = negative || (value < 0);
              }
            in_band      = in_band || (positive && negative);
            in_wide_band = in_wide_band || in_band;
            cell->clear_refine_flag();
            cell->clear_coarsen_flag();
            if (in_band && cell->level() < int(finest_level))
              {
                cell->set_refine_flag();
                ++n_flagged;
              }
            else if (!in_wide_band && cell->level() > int(coarsest_level))
              {
                cell->set_coarsen_flag();
                ++n_flagged;
              }
          }
      return Utilities::MPI::sum(
               n_flagged, dof_handler.get_triangulation().get_communicator()) >
             0;
    }



    template void
    refine_around_zero_level_set<2>(parallel::distributed::Triangulation<2> &,
                                    const Function<2> &,
                                    const double,
                                    const double,
                                    const unsigned int);
    template void
    refine_around_zero_level_set<3>(parallel::distributed::Triangulation<3> &,
                                    const Function<3> &,
                                    const double,
                                    const double,
                                    const unsigned int);
    template bool
    flag_cells_from_phase_field<2>(const DoFHandler<2> &,
                                   const TrilinosWrappers::MPI::Vector &,
                                   const double,
                                   const unsigned int,
                                   const unsigned int,
                                   const double);
    template bool
    flag_cells_from_phase_field<3>(const DoFHandler<3> &,
                                   const TrilinosWrappers::MPI::Vector &,
                                   const double,
                                   const unsigned int,
                                   const unsigned int,
                                   const double);
  } // namespace NarrowBand
} // namespace PhaseField
