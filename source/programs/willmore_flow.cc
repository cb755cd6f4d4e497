/**
 * willmore_flow: Willmore flow of a phase field by the nested variational
 * time discretization, on adaptive meshes, in 2D and 3D, with MPI.
 *
 * Usage: willmore_flow <parameter file>; willmore_flow --help lists every
 * parameter. See doc/willmore_flow.md.
 */
#include <phasefield/core/parameters.h>
#include <phasefield/core/program.h>
#include <phasefield/problems/willmore_problem.h>

int
main(int argc, char **argv)
{
  using namespace PhaseField;
  return run_program(
    argc,
    argv,
    "willmore_flow",
    [](dealii::ParameterHandler &prm) {
      WillmoreFlowParameters::declare_parameters(prm);
    },
    [](dealii::ParameterHandler &prm) {
      WillmoreFlowParameters parameters;
      parameters.parse_parameters(prm);
      if (parameters.dimension == 2)
        WillmoreProblem<2>(parameters, parameters.constraints).run();
      else
        WillmoreProblem<3>(parameters, parameters.constraints).run();
    });
}
