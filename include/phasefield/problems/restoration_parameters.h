#ifndef phasefield_restoration_parameters_h
#define phasefield_restoration_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <phasefield/core/parameters.h>
#include <phasefield/geometry/images.h>
#include <string>
#include <vector>

namespace PhaseField
{
  /**
   * Parameters of edge restoration (thesis section 5.3) that willmore_flow
   * does not have: subsection `Restoration` and the entries `Image file`
   * and `Threshold` of subsection `Geometry`.
   */
  struct RestorationParameters
  {
    /** Weight eta of the area term (thesis (5.7)). */
    double eta;
    /** The open restoration region; U is fixed outside it. */
    Box2D region;
    /** The damaged part of the built-in image (removed from the shape). */
    Box2D damage;
    /** Side of the square PNG pictures of the phase field, in pixels. */
    unsigned int picture_resolution;
    /** Grayscale PNG image of Shape = image. */
    std::string image_file;
    /** Pixels darker than this (gray value in [0,1]) are inside. */
    double threshold;

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    /**
     * Parse and validate; @p mesh is needed to check that the region is
     * aligned with the coarsest mesh.
     */
    void
    parse_parameters(dealii::ParameterHandler &prm, const MeshParameters &mesh);
  };

  /** All parameters of edge_restoration. */
  struct EdgeRestorationParameters
  {
    WillmoreParameters    willmore;
    RestorationParameters restoration;

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };
} // namespace PhaseField

#endif
