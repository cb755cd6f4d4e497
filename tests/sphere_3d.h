// Willmore flow of a sphere in 3D (stationary under Willmore flow) on a
// small adaptive mesh with an iterative solver (the tests sphere_3d and
// sphere_3d_matrix_free): Newton
// converges, the sphere stays put (inside volume constant to 0.5%; its
// value is above 4/3 pi r^3 by the O((eps/r)^2) profile correction, about
// 10% at eps/r = 0.21), and the energies are near 8 pi and 4 pi r^2 for
// this coarse resolution (eps = 2h, so only within 10% and 5%). Then a
// quarter cylinder, which moves like the 2D quarter circle: its radius
// growth checks the speed of the 3D flow.

#ifndef phasefield_tests_sphere_3d_h
#define phasefield_tests_sphere_3d_h

#include "tests.h"

#include <cmath>

namespace Testing
{
  /** The parameter that selects the linear solver @p type. */
  inline std::string
  solver(const std::string &type)
  {
    return "subsection Linear solver\n  set Type = " + type + "\nend\n";
  }

  /**
   * The checks of the sphere and the quarter cylinder with
   * `Linear solver / Type` = @p solver_type (iterative or matrix-free).
   */
  inline void
  check_sphere_3d(const std::string &solver_type)
  {
    std::vector<std::string> header;
    const auto rows = Testing::run_willmore(R"(
set Dimension = 3
subsection Geometry
  set Shape = sphere
  set Radius = 0.3
end
subsection Mesh
  set Finest level = 5
  set Coarsest level = 2
  set Band width = 3
end
subsection Phase field
  set Epsilon = 2*h
end
subsection Time stepping
  set Tau = h^2
  set Inner tau = h^2/4
  set Number of steps = 2
end
subsection Linear solver
  # 6x the most CG iterations one Newton iteration needs here (35), so
  # that CG on a wrong (indefinite) system fails within seconds
  set Maximum iterations = 200
end
subsection Output
  set VTU interval = 0
end
)" + solver(solver_type),
                                            header);
    Testing::print_columns(rows, header, Testing::checked_columns());
    const double pi   = M_PI;
    const auto  &last = rows.back();
    const double w    = last[Testing::column(header, "willmore_energy")];
    const double a    = last[Testing::column(header, "area_energy")];
    const double vol  = last[Testing::column(header, "inside_measure")];
    const double vol0 = rows[0][Testing::column(header, "inside_measure")];
    Testing::log() << "Willmore energy within 10% of 8 pi: "
                   << (std::abs(w / (8 * pi) - 1) < 0.10 ? "yes" : "NO")
                   << "\narea within 5% of 4 pi r^2: "
                   << (std::abs(a / (4 * pi * 0.09) - 1) < 0.05 ? "yes" : "NO")
                   << "\nvolume constant within 0.5%: "
                   << (std::abs(vol / vol0 - 1) < 0.005 ? "yes" : "NO")
                   << std::endl;

    // A stationary sphere cannot tell a solver that does nothing from a
    // right one: a quarter cylinder of radius 0.4 along x_3 (natural
    // boundary conditions, so it meets the faces x_3 = 0, 1 at right angles)
    // has one principal curvature 1/r and moves like the circle of the 2D
    // tests, r(t) = (2t + r0^4)^(1/4), Willmore energy pi/(4r). At this
    // resolution (eps/r = 0.16) the growth is 7% slow and the energy 5% low.
    std::vector<std::string> cylinder_header;
    const auto cylinder = Testing::run_willmore(R"(
set Dimension = 3
subsection Geometry
  set Shape = function
  set Expression = sqrt(x^2+y^2)-0.4
end
subsection Mesh
  set Finest level = 5
  set Coarsest level = 2
  set Band width = 3
end
subsection Phase field
  set Epsilon = 2*h
end
subsection Time stepping
  set Tau = 0.03*h
  set Inner tau = h^2/4
  set Number of steps = 3
end
subsection Linear solver
  # 6x the most CG iterations one Newton iteration needs here (35), so
  # that CG on a wrong (indefinite) system fails within seconds
  set Maximum iterations = 200
end
subsection Output
  set VTU interval = 0
end
)" + solver(solver_type),
                                                cylinder_header,
                                                "results_cylinder");
    Testing::log() << "quarter cylinder:" << std::endl;
    Testing::check_quarter_circle(cylinder, cylinder_header, 0.4, 0.10, 0.20);
  }
} // namespace Testing

#endif
