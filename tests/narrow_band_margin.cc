// `Mesh / Band margin`: the time loop re-meshes only when the band of
// (Band width - Band margin) eps has left the finest level. A circle of
// radius 0.25 at (0.5, 0.5), eps = 2h = 1/32, Band width 4, Band margin 1,
// its mesh made for the circle (every cell within 4 eps + half a diameter
// of it is on the finest level), then the phase field of the circle moved
// by delta along x_1:
//
// - delta = eps/2: every point within 3 eps of the moved circle is within
//   3.5 eps of the first one, so the narrowed band is on the finest level:
//   adapt_to_phase_field() with the margin keeps the mesh; without it
//   (Band margin = 0) cells at the band's edge change, and it re-meshes.
// - delta = 2 eps: points 3 eps inside the moved circle, on the side it
//   moved away from, are 5 eps from the first one, outside its band: the
//   mesh is adapted, repeatedly, until the full band of 4 eps is on the
//   finest level (one adaptation refines a cell by one level, and the
//   circle moved into cells two levels coarser), so a second call keeps
//   the mesh.
// - delta = 0, the band scaled by 1/2 (as for the phase field of a level
//   transition, which is sharpened to half its width): the inner band of
//   1.5 eps is on the finest level, but the mesh has groups of finest
//   sibling cells (of diameter 2 sqrt(2) h = 1.4 eps) out to 4 eps and
//   beyond, outside the scaled band of 2 eps and its margin of 0.5 eps: the
//   mesh is adapted (coarsened), and a second call keeps it.
//
// The answers and the cell counts printed do not depend on the number of
// MPI ranks. (The meshes after coarsening do: without the margin 2146
// cells on 1 rank and 2152 on 2, with the scaled band 1420 and 1432, so
// those counts are not printed.)

#include "tests.h"

#include <limits>
#include <phasefield/geometry/shapes.h>
#include <phasefield/mesh/discretization.h>
#include <phasefield/mesh/narrow_band.h>

using namespace dealii;
using namespace PhaseField;

namespace
{
  constexpr double eps        = 1. / 32;
  constexpr double radius     = 0.25;
  constexpr double band_width = 4;

  Discretization<2>::Settings
  settings()
  {
    Discretization<2>::Settings s{};
    s.mesh.coarsest_level = 2;
    s.mesh.finest_level   = 6;
    s.mesh.adaptive       = true;
    s.mesh.band_width     = band_width;
    s.mesh.band_margin    = 1;
    return s;
  }

  /** Mesh of the circle at (0.5, 0.5), phase field of it moved by delta. */
  struct MovedCircle
  {
    explicit MovedCircle(const double delta)
      : discretization(settings(), MPI_COMM_WORLD)
    {
      const Shapes::SphereDistance<2> circle(Point<2>(0.5, 0.5), radius);
      const Shapes::SphereDistance<2> moved(Point<2>(0.5 + delta, 0.5), radius);
      discretization.create_mesh(&circle, eps);
      discretization.reinit(fields, 1);
      discretization.interpolate(Shapes::PhaseFieldProfile<2>(moved, eps),
                                 fields.block(0));
    }

    /** Is the band of @p width on the finest level? */
    bool
    resolved(const double width) const
    {
      return NarrowBand::band_fits(discretization.get_dof_handler(),
                                   discretization.ghosted_copy(fields.block(0)),
                                   width,
                                   std::numeric_limits<double>::infinity(),
                                   settings().mesh.finest_level);
    }

    unsigned int
    n_cells() const
    {
      return discretization.get_triangulation().n_global_active_cells();
    }

    Discretization<2>                  discretization;
    TrilinosWrappers::MPI::BlockVector fields;
  };

  const char *
  yes_no(const bool b)
  {
    return b ? "yes" : "no";
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  auto                            &log = Testing::log();

  {
    MovedCircle  c(eps / 2);
    const auto   cells = c.n_cells();
    const double width = band_width - settings().mesh.band_margin;
    log << "moved by eps/2: band of 3 eps resolved: "
        << yes_no(c.resolved(width))
        << "; band of 4 eps resolved: " << yes_no(c.resolved(band_width))
        << "\n  with the margin: re-meshed: "
        << yes_no(c.discretization.adapt_to_phase_field(c.fields, 1, true))
        << ", cells " << cells << " -> " << c.n_cells()
        << "\n  without it: re-meshed: "
        << yes_no(c.discretization.adapt_to_phase_field(c.fields, 1, false))
        << std::endl;
  }
  {
    MovedCircle  c(2 * eps);
    const auto   cells = c.n_cells();
    const double width = band_width - settings().mesh.band_margin;
    log << "moved by 2 eps: band of 3 eps resolved: "
        << yes_no(c.resolved(width)) << "\n  with the margin: re-meshed: "
        << yes_no(c.discretization.adapt_to_phase_field(c.fields, 1, true))
        << ", cells " << cells << " -> " << c.n_cells()
        << "\n  band of 4 eps resolved after it: "
        << yes_no(c.resolved(band_width)) << "\n  second call re-meshed: "
        << yes_no(c.discretization.adapt_to_phase_field(c.fields, 1, true))
        << std::endl;
  }
  {
    MovedCircle      c(0);
    const auto       cells = c.n_cells();
    constexpr double scale = 0.5;
    log << "band scaled by 1/2: re-meshed: "
        << yes_no(c.discretization.adapt_to_phase_field(c.fields, scale, true))
        << ", fewer cells: " << yes_no(c.n_cells() < cells)
        << "\n  second call re-meshed: "
        << yes_no(c.discretization.adapt_to_phase_field(c.fields, scale, true))
        << std::endl;
  }
}
