#include <cmath>
#include <phasefield/problems/restoration_parameters.h>
#include <phasefield/schemes/scheme_registry.h>

namespace PhaseField
{
  using namespace dealii;

  namespace
  {
    /** Parse `x0, y0, x1, y1` (empty allowed if @p may_be_empty). */
    Box2D
    parse_box(const std::string &text,
              const std::string &parameter_name,
              const bool         may_be_empty)
    {
      const std::vector<double> values =
        parse_double_list(text, parameter_name);
      Box2D box;
      if (values.empty() && may_be_empty)
        return box;
      if (values.size() != 4 || !(values[0] < values[2]) ||
          !(values[1] < values[3]) || values[0] < 0 || values[1] < 0 ||
          values[2] > 1 || values[3] > 1)
        throw InputError("The parameter <" + parameter_name + "> = <" + text +
                         "> must be a box x0, y0, x1, y1 inside [0,1]^2 "
                         "with x0 < x1 and y0 < y1.");
      box.lower = {values[0], values[1]};
      box.upper = {values[2], values[3]};
      return box;
    }
  } // namespace



  void
  RestorationParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Restoration");
    prm.declare_entry("Eta",
                      "1",
                      Patterns::Double(),
                      "Weight eta >= 0 of the area functional in the outer "
                      "energy (thesis (5.7)): Willmore energy + eta * area.");
    prm.declare_entry("Region",
                      "0.25, 0.25, 0.75, 0.75",
                      Patterns::Anything(),
                      "The restoration region x0, y0, x1, y1 (open box in "
                      "[0,1]^2, the computational domain). U is held at its "
                      "initial values at every node outside it; V and P are "
                      "free everywhere. The corners must be multiples of "
                      "2^-(Mesh / Coarsest level), so that no cell straddles "
                      "the region boundary.");
    prm.declare_entry("Damage",
                      "",
                      Patterns::Anything(),
                      "Box x0, y0, x1, y1 removed from the initial shape "
                      "(set to the outside phase): the destroyed part of the "
                      "image. Empty: no damage. Must lie inside Region.");
    prm.declare_entry("Picture resolution",
                      "512",
                      Patterns::Integer(16, 4096),
                      "Pixels per side of the PNG pictures of the phase field "
                      "over [0,1]^2 (initial.png, restored.png).");
    prm.leave_subsection();
    prm.enter_subsection("Geometry");
    prm.declare_entry("Image file",
                      "",
                      Patterns::Anything(),
                      "Grayscale (or colour) PNG image of Shape = image, "
                      "mapped onto [0,1]^2 (its longer side spans [0,1]); "
                      "a path relative to the working directory.");
    prm.declare_entry("Threshold",
                      "0.5",
                      Patterns::Double(),
                      "Shape = image: pixels with gray value (in [0,1]) "
                      "below the threshold are inside the shape.");
    prm.leave_subsection();
  }



  void
  RestorationParameters::parse_parameters(ParameterHandler     &prm,
                                          const MeshParameters &mesh)
  {
    prm.enter_subsection("Restoration");
    eta    = prm.get_double("Eta");
    region = parse_box(prm.get("Region"), "Restoration / Region", false);
    damage = parse_box(prm.get("Damage"), "Restoration / Damage", true);
    picture_resolution = prm.get_integer("Picture resolution");
    prm.leave_subsection();
    prm.enter_subsection("Geometry");
    image_file = prm.get("Image file");
    threshold  = prm.get_double("Threshold");
    prm.leave_subsection();

    if (!(eta >= 0))
      throw InputError("<Restoration / Eta> must be >= 0, but is " +
                       std::to_string(eta) + ".");
    if (!(threshold > 0 && threshold < 1))
      throw InputError("<Geometry / Threshold> must lie in (0, 1), but is " +
                       std::to_string(threshold) + ".");
    if (!damage.empty() && (damage.lower[0] < region.lower[0] ||
                            damage.lower[1] < region.lower[1] ||
                            damage.upper[0] > region.upper[0] ||
                            damage.upper[1] > region.upper[1]))
      throw InputError("<Restoration / Damage> must lie inside <Restoration / "
                       "Region>: outside the region U is held at the damaged "
                       "image, so the damage there could not be restored.");
    const double coarse_h =
      std::ldexp(1.0, -static_cast<int>(mesh.coarsest_level));
    for (const double x :
         {region.lower[0], region.lower[1], region.upper[0], region.upper[1]})
      if (std::abs(x / coarse_h - std::round(x / coarse_h)) > 1e-12)
        throw InputError(
          "The corners of <Restoration / Region> must be multiples of "
          "2^-(Mesh / Coarsest level) = " +
          std::to_string(coarse_h) +
          ", so that no cell straddles the region boundary (otherwise a "
          "hanging node outside the region would depend on values inside).");
  }



  void
  EdgeRestorationParameters::declare_parameters(ParameterHandler &prm)
  {
    WillmoreParameters::declare_parameters(
      prm,
      "damaged circle|cross|bar|image",
      "Images of edge restoration: damaged circle (circle of Center, "
      "Radius), cross (Center, Sizes = arm length, arm width), bar (Center, "
      "Sizes = length, width), image (Image file, Threshold); see "
      "<Restoration / Damage>.");
    RestorationParameters::declare_parameters(prm);
    declare_scheme_parameters(prm);
  }



  void
  EdgeRestorationParameters::parse_parameters(ParameterHandler &prm)
  {
    willmore.parse_parameters(prm);
    restoration.parse_parameters(prm, willmore.mesh);
    if (willmore.dimension != 2)
      throw InputError("edge_restoration works in 2D only: <Dimension> must "
                       "be 2.");
    const ModelTerms needed =
      ModelTerms().with("area term").with("fixed values");
    willmore.model.scheme =
      parse_scheme_parameters(prm, needed, "edge_restoration");
    const std::string &shape = willmore.geometry.shape;
    if (shape == "image" && restoration.image_file.empty())
      throw InputError("Shape = image needs <Geometry / Image file>.");
  }
} // namespace PhaseField
