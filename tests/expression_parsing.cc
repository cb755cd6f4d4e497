// Parameters written as expressions in h (4*h, h^2, 0.03*h, 2^-6), and
// the error messages for malformed or non-positive values.

#include "tests.h"

#include <phasefield/core/parameters.h>
#include <phasefield/geometry/shapes.h>

using namespace PhaseField;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double                             h = 1. / 128;
  for (const std::string e : {"4*h", "h^2", "0.03*h", "2^-6", "h^3", "1e-3"})
    Testing::log() << e << " = " << evaluate_expression_in_h(e, h, "test")
                   << std::endl;

  for (const std::string e : {"4*", "2*k", "sqrt(-h)"})
    try
      {
        evaluate_expression_in_h(e, h, "Phase field / Epsilon");
        Testing::log() << e << ": NO ERROR" << std::endl;
      }
    catch (const InputError &error)
      {
        const std::string message = error.what();
        Testing::log() << e << ": error naming the parameter: "
                       << (message.find("Phase field / Epsilon") !=
                               std::string::npos ?
                             "yes" :
                             "NO")
                       << std::endl;
      }

  ModelParameters model;
  model.epsilon_expression   = "4*h";
  model.tau_expression       = "-h";
  model.inner_tau_expression = "h^2";
  try
    {
      model.evaluate(h);
      Testing::log() << "negative tau: NO ERROR" << std::endl;
    }
  catch (const InputError &error)
    {
      Testing::log() << "negative tau: " << error.what() << std::endl;
    }

  // A signed distance given as an expression is evaluated like the
  // built-in circle.
  GeometryParameters geometry;
  geometry.shape                = "function";
  geometry.expression           = "sqrt((x-0.5)^2+(y-0.5)^2)-0.25";
  const auto f                  = Shapes::create_signed_distance<2>(geometry);
  geometry.shape                = "circle";
  geometry.radius               = 0.25;
  const auto             circle = Shapes::create_signed_distance<2>(geometry);
  const dealii::Point<2> p(0.1, 0.7);
  Testing::log() << "function " << f->value(p) << " circle " << circle->value(p)
                 << std::endl;

  geometry.shape      = "function";
  geometry.expression = "sqrt((x-0.5)^2+(y-0.5)^2-0.25";
  try
    {
      Shapes::create_signed_distance<2>(geometry);
      Testing::log() << "malformed expression: NO ERROR" << std::endl;
    }
  catch (const InputError &error)
    {
      Testing::log()
        << "malformed expression: error naming the parameter: "
        << (std::string(error.what()).find("Geometry / Expression") !=
                std::string::npos ?
              "yes" :
              "NO")
        << std::endl;
    }
}
