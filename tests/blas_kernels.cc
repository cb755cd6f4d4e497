// select_blas_kernels(): on a CPU with AVX2 and FMA, OpenBLAS does not use
// its Prescott (SSE3) kernels afterwards unless the user chose them with
// OPENBLAS_CORETYPE, and matrix products (dgemm, the kernels MUMPS spends
// its time in) computed with the kernels selected at run time agree with
// a plain triple loop.

#include "tests.h"

#include <cstdlib>
#include <deal.II/lac/lapack_full_matrix.h>
#include <dlfcn.h>
#include <phasefield/core/blas_kernels.h>
#include <strings.h>

using namespace dealii;

namespace
{
  /** OpenBLAS's kernel set, empty if the BLAS is not OpenBLAS. */
  std::string
  openblas_core_name()
  {
    using CoreName = char *(*)();
    const auto function =
      reinterpret_cast<CoreName>(dlsym(RTLD_DEFAULT, "openblas_get_corename"));
    return function == nullptr ? std::string() : std::string(function());
  }

  /** Entry (i, j) of a deterministic test matrix. */
  double
  entry(const unsigned int i, const unsigned int j, const unsigned int seed)
  {
    return std::sin(1.0 + i * 0.37 + j * 0.11 * seed);
  }

  /** Largest |A B - (A B)_loop| relative to the largest |(A B)_loop|. */
  double
  product_error()
  {
    const unsigned int       m = 201, k = 157, n = 183;
    LAPACKFullMatrix<double> a(m, k), b(k, n), c(m, n);
    for (unsigned int i = 0; i < m; ++i)
      for (unsigned int j = 0; j < k; ++j)
        a(i, j) = entry(i, j, 1);
    for (unsigned int i = 0; i < k; ++i)
      for (unsigned int j = 0; j < n; ++j)
        b(i, j) = entry(i, j, 2);
    a.mmult(c, b);
    double error = 0, largest = 0;
    for (unsigned int i = 0; i < m; ++i)
      for (unsigned int j = 0; j < n; ++j)
        {
          double sum = 0;
          for (unsigned int l = 0; l < k; ++l)
            sum += a(i, l) * b(l, j);
          error   = std::max(error, std::abs(c(i, j) - sum));
          largest = std::max(largest, std::abs(sum));
        }
    return error / largest;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool user_choice = std::getenv("OPENBLAS_CORETYPE") != nullptr;
  PhaseField::select_blas_kernels();

  __builtin_cpu_init();
  const bool cpu_has_avx2 =
    __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  const bool prescott =
    strcasecmp(openblas_core_name().c_str(), "Prescott") == 0;
  Testing::log() << "Prescott kernels only where the CPU lacks AVX2 or the "
                    "user chose them: "
                 << (!prescott || !cpu_has_avx2 || user_choice ? "yes" : "no")
                 << std::endl;
  Testing::log() << "dgemm agrees with a loop to 1e-13: "
                 << (product_error() < 1e-13 ? "yes" : "no") << std::endl;
}
