// The mismatch term of the contour tests on the adaptive test mesh: the
// target is the labeling of a sphere of radius 0.25 at the domain's centre
// (another sphere than the test mesh's), on the pixel grid of the mesh's
// finest level.
#ifndef phasefield_tests_sphere_mismatch_h
#define phasefield_tests_sphere_mismatch_h

#include "adaptive_test_mesh.h"

#include <deal.II/base/point.h>
#include <phasefield/geometry/huffman_labeling.h>
#include <phasefield/geometry/shapes.h>
#include <phasefield/problems/mismatch_term.h>
#include <vector>

namespace Testing
{
  /** Radius of the target sphere. */
  constexpr double target_sphere_radius = 0.25;

  /** The target labeling alpha* on the pixel grid of @p mesh. */
  template <int dim>
  std::vector<double>
  sphere_target_labeling(const AdaptiveTestMesh<dim> &mesh)
  {
    dealii::Point<dim> centre;
    for (unsigned int d = 0; d < dim; ++d)
      centre[d] = 0.5;
    const PhaseField::Shapes::SphereDistance<dim> target_sphere(
      centre, target_sphere_radius);
    const PhaseField::HuffmanLabeling::LabelingGrid<dim> grid(
      mesh.discretization.get_settings().mesh.finest_level);
    return PhaseField::HuffmanLabeling::labeling_of_function(
      PhaseField::Shapes::PhaseFieldProfile<dim>(target_sphere, mesh.eps),
      grid,
      MPI_COMM_WORLD);
  }

  /** The mismatch term with weight @p gamma against that target. */
  template <int dim>
  PhaseField::MismatchTerm<dim>
  sphere_mismatch_term(const AdaptiveTestMesh<dim> &mesh, const double gamma)
  {
    return PhaseField::MismatchTerm<dim>(
      mesh.discretization,
      mesh.discretization.get_settings().mesh.finest_level,
      sphere_target_labeling(mesh),
      gamma);
  }
} // namespace Testing

#endif
