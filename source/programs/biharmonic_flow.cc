/**
 * biharmonic_flow: convergence study of the nested variational time
 * discretization of the biharmonic heat flow (thesis chapter 4, the linear
 * model problem of the Willmore scheme) against exact solutions with
 * Dirichlet, Neumann or periodic boundary conditions, in 2D and 3D, with
 * MPI.
 *
 * Usage: biharmonic_flow <parameter file>; biharmonic_flow --help lists
 * every parameter. See doc/biharmonic_flow.md.
 */
#include <phasefield/core/program.h>
#include <phasefield/problems/biharmonic_parameters.h>
#include <phasefield/problems/biharmonic_problem.h>

int
main(int argc, char **argv)
{
  using namespace PhaseField;
  return run_program(
    argc,
    argv,
    "biharmonic_flow",
    [](dealii::ParameterHandler &prm) {
      BiharmonicParameters::declare_parameters(prm);
    },
    [](dealii::ParameterHandler &prm) {
      BiharmonicParameters parameters;
      parameters.parse_parameters(prm);
      if (parameters.dimension == 2)
        run_biharmonic_convergence_study<2>(parameters);
      else
        run_biharmonic_convergence_study<3>(parameters);
    });
}
