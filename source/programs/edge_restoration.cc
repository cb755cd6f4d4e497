/**
 * edge_restoration: continuation of image edges by Willmore flow plus a
 * weighted area term inside a restoration region, with C^1 data outside
 * (thesis section 5.3), on adaptive meshes, in 2D, with MPI.
 *
 * Usage: edge_restoration <parameter file>; edge_restoration --help lists
 * every parameter. See doc/edge_restoration.md.
 */
#include <phasefield/core/program.h>
#include <phasefield/problems/restoration_parameters.h>
#include <phasefield/problems/restoration_problem.h>

int
main(int argc, char **argv)
{
  using namespace PhaseField;
  return run_program(
    argc,
    argv,
    "edge_restoration",
    [](dealii::ParameterHandler &prm) {
      EdgeRestorationParameters::declare_parameters(prm);
    },
    [](dealii::ParameterHandler &prm) {
      EdgeRestorationParameters parameters;
      parameters.parse_parameters(prm);
      RestorationProblem(parameters).run();
    });
}
