#include <cmath>
#include <deal.II/base/mpi.h>
#include <phasefield/core/mesh_size.h>
#include <phasefield/core/message_text.h>
#include <phasefield/geometry/interface_sample.h>
#include <phasefield/problems/initial_shape_check.h>
#include <sstream>

namespace PhaseField
{
  namespace
  {
    /** @p value with 3 significant digits. */
    std::string
    short_number(const double value)
    {
      std::ostringstream text;
      text.precision(3);
      text << value;
      return text.str();
    }

    /** "the initial shape (<Geometry / Shape> = circle)". */
    std::string
    shape_name(const GeometryParameters &geometry)
    {
      return "the initial shape (<" + geometry.subsection +
             " / Shape> = " + geometry.shape + ")";
    }

    /** Refuse a shape whose interface does not cross the domain. */
    void
    check_interface_in_domain(const Shapes::InterfaceSample &sample,
                              const GeometryParameters      &geometry,
                              const unsigned int             dim)
    {
      const std::string domain = "the domain [0,1]^" + std::to_string(dim);
      const std::string shape  = "T" + shape_name(geometry).substr(1);
      const std::string remedy = ": there is no interface to evolve. Move <" +
                                 geometry.subsection +
                                 " / Center> or change the shape's size.";
      if (sample.smallest > sample.half_diagonal)
        throw InputError(shape + " lies entirely outside " + domain +
                         " (its signed distance is at least " +
                         short_number(sample.smallest) + " everywhere in it)" +
                         remedy);
      if (sample.largest < -sample.half_diagonal)
        throw InputError(shape + " contains all of " + domain +
                         " (its signed distance is at most " +
                         short_number(sample.largest) + " everywhere in it)" +
                         remedy);
    }

    /** Refuse an epsilon beyond the largest distance to the interface. */
    void
    check_epsilon_against_domain(const Shapes::InterfaceSample &sample,
                                 const WillmoreParameters      &parameters)
    {
      const double farthest =
        std::max(sample.largest, -sample.smallest) + sample.half_diagonal;
      const double epsilon = parameters.model.epsilon;
      if (epsilon <= farthest)
        return;
      throw InputError(
        "<Phase field / Epsilon> = <" +
        abbreviated(parameters.model.epsilon_expression) + "> evaluates to " +
        short_number(epsilon) +
        ", but no point of the domain is farther than " +
        short_number(farthest) + " from the interface of " +
        shape_name(parameters.geometry) +
        ": U = tanh(d / epsilon) lies between -tanh(1) and tanh(1) "
        "everywhere, with no bulk phase. Use an epsilon well below the size "
        "of the shape, e.g. 4*h.");
    }

    /** Refuse a narrow band whose finest cells alone do not fit. */
    void
    check_band_fits(const Shapes::InterfaceSample &sample,
                    const WillmoreParameters      &finest,
                    const unsigned int             dim)
    {
      const MeshParameters &mesh = finest.mesh;
      if (!mesh.adaptive)
        return;
      const double half_width = mesh.band_width * finest.model.epsilon;
      const double n_cells =
        sample.band_volume(half_width) / std::pow(mesh.h(), dim);
      MeshSize::check_mesh_fits(
        n_cells,
        dim,
        dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD),
        "<Mesh / Finest level> = " + std::to_string(mesh.finest_level) +
          " with <Mesh / Adaptive> = true is a narrow band (<Mesh / Band "
          "width> * epsilon = " +
          short_number(half_width) + " on either side of the interface of " +
          shape_name(finest.geometry) +
          ") whose finest cells alone are, by an estimate from the "
          "interface's extent, at least",
        "Use a smaller level, a smaller <Mesh / Band width> or "
        "<Phase field / Epsilon>, or more ranks.");
    }
  } // namespace



  template <int dim>
  void
  check_initial_shape(const dealii::Function<dim> &signed_distance,
                      const WillmoreParameters    &first,
                      const WillmoreParameters    &finest)
  {
    const Shapes::InterfaceSample sample =
      Shapes::sample_interface(signed_distance);
    check_interface_in_domain(sample, first.geometry, dim);
    check_epsilon_against_domain(sample, first);
    check_band_fits(sample, finest, dim);
  }



  std::string
  epsilon_resolution_warning(const WillmoreParameters &parameters)
  {
    const double h       = parameters.mesh.h();
    const double epsilon = parameters.model.epsilon;
    if (epsilon >= h)
      return "";
    return "<Phase field / Epsilon> = " + short_number(epsilon) + " is " +
           short_number(epsilon / h) + " h at h = " + short_number(h) +
           ": the mesh hardly resolves the interface (fewer than about four "
           "cells across |U| < tanh(2)), so energies and the interface's "
           "motion are inaccurate; use at least 2*h (below h/2 is refused).";
  }



  template void
  check_initial_shape<2>(const dealii::Function<2> &,
                         const WillmoreParameters &,
                         const WillmoreParameters &);
  template void
  check_initial_shape<3>(const dealii::Function<3> &,
                         const WillmoreParameters &,
                         const WillmoreParameters &);
} // namespace PhaseField
