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



    namespace
    {
      /**
       * Whether the vertex values @p values of a cell put it into the band
       * |u| < @p threshold, or u changes sign on it.
       */
      bool
      in_band(const dealii::Vector<double> &values, const double threshold)
      {
        bool near = false, positive = false, negative = false;
        for (const double value : values)
          {
            near     = near || (std::abs(value) < threshold);
            positive = positive || (value > 0);
            negative = negative || (value < 0);
          }
        return near || (positive && negative);
      }



      /**
       * Whether @p cell is the first child of a group of active siblings
       * that all lie outside the band |u| < @p threshold: the group that
       * flag_cells_from_phase_field() would coarsen. Groups with a sibling
       * that is not active, or artificial here, are not counted.
       */
      template <int dim>
      bool
      first_of_group_outside_band(
        const typename DoFHandler<dim>::active_cell_iterator &cell,
        const Vector                                         &u,
        const double                                          threshold,
        dealii::Vector<double>                               &values)
      {
        if (cell->level() == 0 || cell->parent()->child(0) != cell)
          return false;
        for (const auto &sibling : cell->parent()->child_iterators())
          {
            if (!sibling->is_active() || sibling->is_artificial())
              return false;
            sibling->get_dof_values(u, values);
            if (in_band(values, threshold))
              return false;
          }
        return true;
      }
    } // namespace



    template <int dim>
    bool
    flag_cells_from_phase_field(const DoFHandler<dim> &dof_handler,
                                const Vector          &u,
                                const double           band_width,
                                const unsigned int     finest_level,
                                const unsigned int     coarsest_level,
                                const double           coarsening_band_width)
    {
      const double threshold = std::tanh(band_width);
      const double coarsening_threshold =
        std::tanh(std::max(band_width, coarsening_band_width));
      dealii::Vector<double> values(dof_handler.get_fe().n_dofs_per_cell());
      unsigned int           n_flagged = 0;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            cell->get_dof_values(u, values);
            const bool in_narrow_band = in_band(values, threshold);
            const bool in_wide_band =
              in_narrow_band || in_band(values, coarsening_threshold);
            cell->clear_refine_flag();
            cell->clear_coarsen_flag();
            if (in_narrow_band && cell->level() < int(finest_level))
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



    template <int dim>
    bool
    band_fits(const DoFHandler<dim> &dof_handler,
              const Vector          &u,
              const double           inner_width,
              const double           outer_width,
              const unsigned int     finest_level)
    {
      const double inner_threshold = std::tanh(std::max(inner_width, 0.));
      const double outer_threshold = std::tanh(outer_width);
      dealii::Vector<double> values(dof_handler.get_fe().n_dofs_per_cell());
      unsigned int           n_misfits = 0;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const bool finest = cell->level() == int(finest_level);
            if (!finest)
              cell->get_dof_values(u, values);
            if ((!finest && in_band(values, inner_threshold)) ||
                (finest && std::isfinite(outer_width) &&
                 first_of_group_outside_band<dim>(
                   cell, u, outer_threshold, values)))
              ++n_misfits;
          }
      return Utilities::MPI::sum(
               n_misfits, dof_handler.get_triangulation().get_communicator()) ==
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
                                   const Vector &,
                                   const double,
                                   const unsigned int,
                                   const unsigned int,
                                   const double);
    template bool
    flag_cells_from_phase_field<3>(const DoFHandler<3> &,
                                   const Vector &,
                                   const double,
                                   const unsigned int,
                                   const unsigned int,
                                   const double);
    template bool
    band_fits<2>(const DoFHandler<2> &,
                 const Vector &,
                 const double,
                 const double,
                 const unsigned int);
    template bool
    band_fits<3>(const DoFHandler<3> &,
                 const Vector &,
                 const double,
                 const double,
                 const unsigned int);
  } // namespace NarrowBand
} // namespace PhaseField
