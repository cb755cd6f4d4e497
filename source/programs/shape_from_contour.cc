/**
 * shape_from_contour: reconstruct a shape from its Huffman labeling along
 * the last axis (thesis chapter 6, Algorithm 6.1) by a multilevel
 * operator splitting of the nested Willmore scheme and a mismatch step,
 * in 2D and 3D, on adaptive meshes, with MPI.
 *
 * Usage: shape_from_contour <parameter file>; shape_from_contour --help
 * lists every parameter. See doc/shape_from_contour.md.
 */
#include <phasefield/core/program.h>
#include <phasefield/problems/contour_parameters.h>
#include <phasefield/problems/contour_problem.h>

int
main(int argc, char **argv)
{
  using namespace PhaseField;
  return run_program(
    argc,
    argv,
    "shape_from_contour",
    [](dealii::ParameterHandler &prm) {
      ContourParameters::declare_parameters(prm);
    },
    [](dealii::ParameterHandler &prm) {
      ContourParameters parameters;
      parameters.parse_parameters(prm);
      if (parameters.willmore.dimension == 2)
        ContourProblem<2>(parameters).run();
      else
        ContourProblem<3>(parameters).run();
    });
}
