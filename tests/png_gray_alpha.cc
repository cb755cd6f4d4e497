// A gray + alpha PNG is read by its gray value, not by the mean of gray
// and alpha. bad_input/gray_alpha_disc.png is 32 x 32, gray 0 (a black
// disc) or 255, alpha 255 everywhere; decoding its IDAT stream by hand
// (zlib, filter type 0 in every row) gives 316 pixels of gray 0. Averaging
// gray and alpha would make every disc pixel 0.5 and none dark.

#include "tests.h"

#include <phasefield/geometry/images.h>

using namespace PhaseField;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const Images::GrayImage                  image = Images::read_gray_image(
    std::string(SOURCE_DIR) + "/bad_input/gray_alpha_disc.png", "test");
  unsigned int dark = 0;
  for (const double g : image.gray)
    dark += g < 0.5;
  Testing::log() << "size " << image.nx << " x " << image.ny << std::endl;
  Testing::log() << "gray at the centre " << image.gray[16 * image.nx + 16]
                 << ", at a corner " << image.gray[0] << std::endl;
  Testing::log() << "pixels darker than 0.5: " << dark
                 << " (316 decoded by hand): " << (dark == 316 ? "yes" : "NO")
                 << std::endl;
}
