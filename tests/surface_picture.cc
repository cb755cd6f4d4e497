// The picture of the surface U = 0 (ZeroLevelSurface::write_picture(),
// SurfacePicture::render()) of the sphere of radius 0.3 of the adaptive
// test mesh (its nodal distance interpolant), on 1 and 2 ranks:
// - the sphere's outline is a disc of radius fill_fraction / 2 of the
//   picture's width (the sphere is its own bounding sphere), so the share
//   of non-white pixels is pi (0.45)^2 = 0.6362 (within 3%: the vertices
//   of the discrete surface lie up to O(h^2) inside the sphere, and its
//   outline is a polygon); a blank picture has share 0;
// - the surface is shaded: its grays lie between ambient and full light
//   (0.25 * 0.85 and 0.85 of white), with many distinct values, the
//   brightest (normals towards the light) in the upper left quadrant;
// - the picture does not depend on the order of the triangles (the
//   reversed order gives the same pixels), so the gathered triangles of
//   any number of ranks give the same picture;
// - the PNG file holds render()'s pixels;
// - without triangles the picture is white.

#include "adaptive_test_mesh.h"
#include "tests.h"

#include <algorithm>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <deal.II/base/numbers.h>
#include <filesystem>
#include <iomanip>
#include <phasefield/geometry/images.h>
#include <phasefield/geometry/surface_picture.h>
#include <phasefield/mesh/zero_level_surface.h>
#include <set>

namespace
{
  using namespace dealii;
  namespace SurfacePicture = PhaseField::SurfacePicture;

  /** The triangles of @p triangles in reversed order. */
  std::vector<double>
  reversed(const std::vector<double> &triangles)
  {
    std::vector<double> out;
    out.reserve(triangles.size());
    for (std::size_t t = triangles.size(); t >= 9; t -= 9)
      out.insert(out.end(), triangles.begin() + t - 9, triangles.begin() + t);
    return out;
  }

  /** Print what the gray picture @p picture (of a sphere) shows. */
  void
  check_sphere_picture(const PhaseField::Images::GrayImage &picture)
  {
    const double   white = 1, tolerance = 1. / 255;
    const double   lowest    = 0.25 * 0.85 - tolerance;
    const double   highest   = 0.85 + tolerance;
    unsigned int   n_surface = 0, n_out_of_range = 0;
    double         brightest = 0;
    std::set<long> grays;
    for (const double g : picture.gray)
      if (g < white - tolerance)
        {
          ++n_surface;
          n_out_of_range += (g < lowest || g > highest);
          grays.insert(std::lround(255 * g));
          brightest = std::max(brightest, g);
        }
    const double share    = double(n_surface) / picture.gray.size();
    const double expected = numbers::PI * std::pow(0.45, 2);
    Testing::log() << "share of surface pixels " << std::setprecision(3)
                   << share << ", expected " << expected << ": "
                   << (std::abs(share / expected - 1) < 0.03 ? "yes" : "NO")
                   << std::endl;
    Testing::log() << "grays between ambient and full light: "
                   << (n_out_of_range == 0 ? "yes" : "NO")
                   << ", more than 50 distinct grays: "
                   << (grays.size() > 50 ? "yes" : "NO") << std::endl;
    // the centroid of the brightest pixels, relative to the centre
    double       x = 0, y = 0;
    unsigned int n = 0;
    for (unsigned int j = 0; j < picture.ny; ++j)
      for (unsigned int i = 0; i < picture.nx; ++i)
        if (picture.gray[j * picture.nx + i] > brightest - 2 * tolerance)
          {
            x += i + 0.5 - 0.5 * picture.nx;
            y += j + 0.5 - 0.5 * picture.ny;
            ++n;
          }
    Testing::log() << "brightest pixels in the upper left quadrant: "
                   << (n > 0 && x < 0 && y > 0 ? "yes" : "NO") << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  Testing::AdaptiveTestMesh<3>     mesh;
  PhaseField::Vector u(mesh.discretization.get_operators().locally_owned_dofs,
                       MPI_COMM_WORLD);
  mesh.discretization.interpolate(mesh.sphere, u);
  mesh.constraints.distribute(u);
  const PhaseField::Vector ghosted = mesh.discretization.ghosted_copy(u);

  std::filesystem::create_directories("results");
  const std::string filename = "results/sphere.png";
  PhaseField::ZeroLevelSurface::write_picture(mesh.dof_handler,
                                              ghosted,
                                              filename);
  const std::vector<double> triangles =
    PhaseField::ZeroLevelSurface::gathered_triangles(mesh.dof_handler, ghosted);
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    {
      const unsigned int                  n = SurfacePicture::default_pixels;
      const PhaseField::Images::GrayImage picture =
        PhaseField::Images::read_gray_image(filename, "test");
      Testing::log() << filename << ": " << picture.nx << " x " << picture.ny
                     << std::endl;
      check_sphere_picture(picture);

      const std::vector<unsigned char> pixels =
        SurfacePicture::render(triangles, n, n);
      Testing::log() << "the reversed triangles give the same pixels: "
                     << (SurfacePicture::render(reversed(triangles), n, n) ==
                             pixels ?
                           "yes" :
                           "NO")
                     << std::endl;
      bool same_as_file = picture.gray.size() == std::size_t(n) * n;
      for (std::size_t i = 0; same_as_file && i < picture.gray.size(); ++i)
        same_as_file = std::lround(255 * picture.gray[i]) == pixels[3 * i];
      Testing::log() << "the file holds render()'s pixels: "
                     << (same_as_file ? "yes" : "NO") << std::endl;

      const std::vector<unsigned char> empty = SurfacePicture::render({}, n, n);
      Testing::log() << "without triangles white: "
                     << (std::all_of(empty.begin(),
                                     empty.end(),
                                     [](const unsigned char c) {
                                       return c == 255;
                                     }) ?
                           "yes" :
                           "NO")
                     << std::endl;
    }
}
