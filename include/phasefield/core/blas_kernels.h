#ifndef phasefield_core_blas_kernels_h
#define phasefield_core_blas_kernels_h

#include <string>

namespace PhaseField
{
  /**
   * Let OpenBLAS use the kernels the CPU supports when it did not recognise
   * the CPU.
   *
   * The direct solver (MUMPS) spends most of its time in dense BLAS
   * kernels. OpenBLAS picks its kernels by CPU model when it is loaded; the
   * one in Debian 12 (0.3.21) does not know newer models (e.g. the Sapphire
   * Rapids of the CI machine type) and falls back to its Prescott (SSE3)
   * kernels. On such a CPU this function selects OpenBLAS's SkylakeX
   * kernels if the CPU has AVX-512 (F, CD, DQ, BW, VL), else its Haswell
   * kernels if it has AVX2 and FMA, as the environment variable
   * OPENBLAS_CORETYPE would have at load time, and the runs with the
   * direct solver are faster (doc/benchmarks.md, "OpenBLAS kernels").
   *
   * Nothing is changed if OPENBLAS_CORETYPE is set (the user's choice),
   * if the BLAS library is not OpenBLAS with run-time kernel selection, or
   * if OpenBLAS chose other kernels than Prescott. Call it before the first
   * BLAS call.
   *
   * @return a one-line message saying what was changed, empty if nothing.
   */
  std::string
  select_blas_kernels();
} // namespace PhaseField

#endif
