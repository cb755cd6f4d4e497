// The checks of Discretization::save()'s files (mesh/saved_files.h) that
// find a checkpoint cut short at write time (a file size limit, a quota, a
// full disk: deal.II's and p4est's writers do not report such writes). A
// circle at level 6 (adaptive, coarsest level 2) with two fields is saved:
//
// - each file has the size expected_files() gives, and check() accepts
//   the save;
// - the fields loaded back into a new Discretization have the
//   field_checksum() of the saved ones (on 1 and 2 ranks: the checksum
//   does not depend on the DoF numbering or the partition);
// - each file one byte short is refused with a WriteError naming it, and
//   so is the p4est file with the last cell changed (same size);
// - the last value of _fixed.data changed (same size, same header) is
//   accepted by check(), but the fields loaded back have another
//   checksum: the reload after a checkpoint write finds it.

#include "tests.h"

#include <deal.II/base/function_lib.h>
#include <filesystem>
#include <phasefield/core/file_io.h>
#include <phasefield/geometry/shapes.h>
#include <phasefield/mesh/discretization.h>
#include <phasefield/mesh/saved_files.h>

using namespace dealii;
using namespace PhaseField;

namespace
{
  constexpr double  eps    = 1. / 32;
  constexpr double  radius = 0.25;
  const std::string base   = "saved/mesh";

  Discretization<2>::Settings
  settings()
  {
    Discretization<2>::Settings s{};
    s.mesh.coarsest_level = 2;
    s.mesh.finest_level   = 6;
    s.mesh.adaptive       = true;
    s.mesh.band_width     = 4;
    return s;
  }

  bool
  root()
  {
    return Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  }

  std::string
  read_file(const std::string &filename)
  {
    std::ifstream in(filename, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in),
                       std::istreambuf_iterator<char>());
  }

  /** Replace @p filename by @p bytes on rank 0; collective. */
  void
  replace_file(const std::string &filename, const std::string &bytes)
  {
    if (root())
      std::ofstream(filename, std::ios::binary) << bytes;
    MPI_Barrier(MPI_COMM_WORLD);
  }

  /** What check() says of the files: "accepted" or the error's file. */
  std::string
  check_result(const Discretization<2> &discretization,
               const std::string       &damaged)
  {
    try
      {
        SavedFiles::check(
          base,
          discretization.get_triangulation(),
          discretization.get_dof_handler().get_fe().n_dofs_per_cell(),
          2);
        return "accepted";
      }
    catch (const WriteError &error)
      {
        const std::string message = error.what();
        return message.find("<" + damaged + ">") != std::string::npos ?
                 "refused, naming the file" :
                 "refused, naming another file: " + message;
      }
  }

  /** The field checksum of the fields loaded from the files. */
  std::uint64_t
  loaded_checksum()
  {
    Discretization<2>       loaded(settings(), MPI_COMM_WORLD);
    PhaseField::BlockVector fields(2);
    loaded.load(base, fields);
    return SavedFiles::field_checksum(loaded.get_dof_handler(), fields);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  auto                            &log = Testing::log();

  Discretization<2>               discretization(settings(), MPI_COMM_WORLD);
  const Shapes::SphereDistance<2> circle(Point<2>(0.5, 0.5), radius);
  discretization.create_mesh(&circle, eps);
  PhaseField::BlockVector fields;
  discretization.reinit(fields, 2);
  discretization.interpolate(Shapes::PhaseFieldProfile<2>(circle, eps),
                             fields.block(0));
  discretization.interpolate(Functions::SquareFunction<2>(), fields.block(1));
  if (root())
    std::filesystem::create_directories("saved");
  MPI_Barrier(MPI_COMM_WORLD);
  discretization.save(base, fields);

  const auto expected = SavedFiles::expected_files(
    base,
    discretization.get_triangulation(),
    discretization.get_dof_handler().get_fe().n_dofs_per_cell(),
    2);
  for (const auto &file : expected)
    log << file.filename << ": expected size = size written: "
        << (file.size == std::filesystem::file_size(file.filename) ? "yes" :
                                                                     "no")
        << std::endl;
  log << "complete save: " << check_result(discretization, "") << std::endl;
  const std::uint64_t saved =
    SavedFiles::field_checksum(discretization.get_dof_handler(), fields);
  log << "fields loaded back have the saved checksum: "
      << (loaded_checksum() == saved ? "yes" : "no") << std::endl;

  for (const auto &file : expected)
    {
      const std::string bytes = read_file(file.filename);
      replace_file(file.filename, bytes.substr(0, bytes.size() - 1));
      log << file.filename
          << " one byte short: " << check_result(discretization, file.filename)
          << std::endl;
      replace_file(file.filename, bytes);
    }

  const std::string mesh = read_file(base);
  std::string       changed_mesh(mesh);
  changed_mesh[changed_mesh.size() - 1] ^= 1;
  replace_file(base, changed_mesh);
  log << base
      << " with its last cell changed: " << check_result(discretization, base)
      << std::endl;
  replace_file(base, mesh);

  const std::string fixed = read_file(base + "_fixed.data");
  std::string       changed_fixed(fixed);
  changed_fixed[changed_fixed.size() - 2] ^= 1;
  replace_file(base + "_fixed.data", changed_fixed);
  log << base << "_fixed.data with its last value changed: "
      << check_result(discretization, "")
      << "; fields loaded back have the saved checksum: "
      << (loaded_checksum() == saved ? "yes" : "no") << std::endl;
  replace_file(base + "_fixed.data", fixed);
  log << "restored: " << check_result(discretization, "") << std::endl;
}
