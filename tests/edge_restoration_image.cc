// Shape = image: a tiny grayscale PNG (a dark disc of radius 0.3 on a light
// background, 32 x 32 pixels, written here with VTK) is read, turned into a
// signed distance (checked against the exact one of the disc to within 1.5
// pixels: the pixelated edge) and restored for two steps.

#include "tests.h"

#include <cmath>
#include <deal.II/base/point.h>
#include <phasefield/geometry/images.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  constexpr unsigned int                   n = 32;
  const dealii::Point<2>                   center(0.5, 0.5);
  constexpr double                         radius = 0.3;
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    {
      vtkNew<vtkImageData> image;
      image->SetDimensions(n, n, 1);
      image->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
      for (unsigned int y = 0; y < n; ++y)
        for (unsigned int x = 0; x < n; ++x)
          *static_cast<unsigned char *>(image->GetScalarPointer(x, y, 0)) =
            center.distance(dealii::Point<2>((x + 0.5) / n, (y + 0.5) / n)) <
                radius ?
              20 :
              230;
      vtkNew<vtkPNGWriter> writer;
      writer->SetFileName("disc.png");
      writer->SetInputData(image);
      writer->Write();
    }
  MPI_Barrier(MPI_COMM_WORLD);

  const PhaseField::Images::ImageDistance distance("disc.png", 0.5);
  double                                  max_error = 0;
  for (unsigned int i = 0; i <= 20; ++i)
    for (unsigned int j = 0; j <= 20; ++j)
      {
        const dealii::Point<2> p(0.2 + 0.03 * i, 0.2 + 0.03 * j);
        max_error =
          std::max(max_error,
                   std::abs(distance.value(p) - (center.distance(p) - radius)));
      }
  Testing::log() << "image " << distance.nx << " x " << distance.ny
                 << ", signed distance within 1.5 pixels of the exact one: "
                 << (max_error < 1.5 / n ? "yes" : "NO") << std::endl;
  if (max_error >= 1.5 / n)
    Testing::log() << "  max error " << max_error << std::endl;

  std::vector<std::string> header;
  const auto               rows = Testing::run_restoration(R"(
set Dimension = 2
subsection Geometry
  set Shape = image
  set Image file = disc.png
  set Threshold = 0.5
end
subsection Restoration
  set Eta    = 1
  set Region = 0.5, 0.25, 0.75, 0.75
  set Picture resolution = 32
end
subsection Mesh
  set Finest level = 6
  set Coarsest level = 2
end
subsection Time stepping
  set Tau = 0.03*h
  set Inner tau = h^2
  set Number of steps = 2
end
subsection Output
  set VTU interval = 0
end
)",
                                             header);
  Testing::check_restoration_table(rows, header);
}
