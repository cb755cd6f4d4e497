#include <cstdlib>
#include <dlfcn.h>
#include <phasefield/core/blas_kernels.h>
#include <strings.h>

namespace PhaseField
{
  namespace
  {
    /** OpenBLAS's kernel set for this CPU, if it has a better one than
     * Prescott; nullptr otherwise. */
    const char *
    supported_core_type()
    {
      __builtin_cpu_init();
      if (__builtin_cpu_supports("avx512f") &&
          __builtin_cpu_supports("avx512cd") &&
          __builtin_cpu_supports("avx512dq") &&
          __builtin_cpu_supports("avx512bw") &&
          __builtin_cpu_supports("avx512vl"))
        return "SkylakeX";
      if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma"))
        return "Haswell";
      return nullptr;
    }

    /** A function of the loaded libraries, nullptr if none has it. */
    template <typename Function>
    Function
    loaded_function(const char *name)
    {
      return reinterpret_cast<Function>(dlsym(RTLD_DEFAULT, name));
    }
  } // namespace



  std::string
  select_blas_kernels()
  {
    using CoreName = char *(*)();
    using Hook     = void (*)();
    // Exported by OpenBLAS built with DYNAMIC_ARCH (Debian's): the kernel
    // choice of its load-time constructor, made again by these two.
    const auto core_name = loaded_function<CoreName>("openblas_get_corename");
    const auto quit      = loaded_function<Hook>("gotoblas_dynamic_quit");
    const auto init      = loaded_function<Hook>("gotoblas_dynamic_init");
    if (core_name == nullptr || quit == nullptr || init == nullptr ||
        std::getenv("OPENBLAS_CORETYPE") != nullptr ||
        strcasecmp(core_name(), "Prescott") != 0)
      return "";

    const char *core_type = supported_core_type();
    if (core_type == nullptr)
      return "";
    setenv("OPENBLAS_CORETYPE", core_type, 1);
    quit();
    init();
    return std::string("OpenBLAS did not recognise this CPU and chose its "
                       "Prescott kernels; now using its ") +
           core_name() +
           " kernels, which the CPU supports (set OPENBLAS_CORETYPE to "
           "choose).";
  }
} // namespace PhaseField
