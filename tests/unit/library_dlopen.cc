// The library is compiled with the initial-exec thread-local storage model
// (CMakeLists.txt: the stages' thread_local scratch without a call to
// __tls_get_addr per cell). Such a library's thread-local data must fit
// the static TLS block, whose reserve for libraries loaded at run time is
// small (glibc: glibc.rtld.optional_static_tls, 512 B by default). A
// program that is not linked to libfsgmpm.so and loads it with dlopen()
// (a Python binding, say) must still get it: this program is that program.
// It links neither the library nor deal.II, so dlopen() loads both.

#include <dlfcn.h>

#include <cstdio>

int
main()
{
  void *handle = dlopen(FSGMPM_LIBRARY, RTLD_NOW | RTLD_LOCAL);
  if (handle == nullptr)
    {
      std::fprintf(stderr,
                   "dlopen(%s) failed: %s\n",
                   FSGMPM_LIBRARY,
                   dlerror());
      return 1;
    }
  // The simulator's constructor: the library is usable, not only mapped.
  if (dlsym(handle, "_ZN6fsgmpm9SimulatorILi2EEC1ERN6dealii16ParameterHandlerE")
      == nullptr)
    {
      std::fprintf(stderr, "no fsgmpm::Simulator<2> in %s\n", FSGMPM_LIBRARY);
      return 1;
    }
  std::printf("loaded %s\n", FSGMPM_LIBRARY);
  dlclose(handle);
  return 0;
}
