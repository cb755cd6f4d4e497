// Discretization::partition_balance(), which every adaptive program prints
// at its end: the narrow band of a sphere (radius 0.3, eps = 2h, level 5)
// on 1, 2 and 4 ranks. Checked against quantities computed here from each
// rank's own counts:
//
// - the fewest and most cells and DoFs are the global minimum and maximum
//   of the locally owned counts (a function that returned this rank's
//   counts, or swapped them, fails on 2 and 4 ranks);
// - p4est gives every rank the same number of cells up to one;
// - the locally owned DoFs add up to the DoFs of the field, so the mean
//   lies between the fewest and the most.
//
// The mesh does not depend on the number of ranks (refinement only), so
// the totals printed are the same on 1, 2 and 4 ranks.

#include "tests.h"

#include <phasefield/geometry/shapes.h>
#include <phasefield/mesh/discretization.h>

using namespace dealii;
using namespace PhaseField;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  auto                            &log = Testing::log();

  constexpr unsigned int      level = 5;
  Discretization<3>::Settings settings{};
  settings.mesh.coarsest_level = 2;
  settings.mesh.finest_level   = level;
  settings.mesh.adaptive       = true;
  settings.mesh.band_width     = 4;
  Discretization<3>               discretization(settings, MPI_COMM_WORLD);
  const Shapes::SphereDistance<3> sphere(Point<3>(0.5, 0.5, 0.5), 0.3);
  discretization.create_mesh(&sphere, 2. / (1 << level));

  const MPI_Comm comm  = MPI_COMM_WORLD;
  const auto    &tria  = discretization.get_triangulation();
  const double   cells = tria.n_locally_owned_active_cells();
  const double   dofs = discretization.get_dof_handler().n_locally_owned_dofs();
  const auto     balance = discretization.partition_balance();

  const auto yes = [](const bool b) { return b ? "yes" : "NO"; };
  log << "cells " << tria.n_global_active_cells() << ", DoFs "
      << discretization.n_dofs() << '\n';
  log << "ranks counted: "
      << yes(balance.n_ranks == Utilities::MPI::n_mpi_processes(comm)) << '\n';
  log << "extremes of the owned cells: "
      << yes(balance.min_cells == Utilities::MPI::min(cells, comm) &&
             balance.max_cells == Utilities::MPI::max(cells, comm))
      << '\n';
  log << "extremes of the owned DoFs: "
      << yes(balance.min_dofs == Utilities::MPI::min(dofs, comm) &&
             balance.max_dofs == Utilities::MPI::max(dofs, comm))
      << '\n';
  log << "cells per rank differ by at most one: "
      << yes(balance.max_cells - balance.min_cells <= 1) << '\n';
  log << "owned DoFs add up, mean between fewest and most: "
      << yes(Utilities::MPI::sum(dofs, comm) == discretization.n_dofs() &&
             balance.min_dofs * balance.n_ranks <= discretization.n_dofs() &&
             discretization.n_dofs() <= balance.max_dofs * balance.n_ranks)
      << '\n';
}
