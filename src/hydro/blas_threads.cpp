// OpenBLAS's pool of work buffers, taken under a lock. Debian's serial OpenBLAS (0.3.21, built
// single-threaded) hands out its buffers without one: two threads calling dsyrk at once may be
// given the same buffer, and then one of them gets a wrong result (26 of 40,000 random calls on
// two threads, none with the lock). The executables export these two functions
// (cmake: --export-dynamic-symbol), so that OpenBLAS's own calls to them, which go through the
// dynamic linker, come here; the real ones are the next definitions in the search order. Other
// BLAS libraries never call them.

#include "hydro/blas_threads.hpp"

#include <dlfcn.h>

#include <cstdio>
#include <cstdlib>
#include <mutex>

namespace {

std::mutex& pool_lock() {
  static std::mutex lock;
  return lock;
}

template <class Function>
Function next_definition(const char* name) {
  void* found = dlsym(RTLD_NEXT, name);
  if (!found) {  // only OpenBLAS calls these, so it is loaded
    std::fprintf(stderr, "hydrodda: %s not found in the BLAS library\n", name);
    std::abort();
  }
  return reinterpret_cast<Function>(found);
}

}  // namespace

extern "C" {

__attribute__((visibility("default"))) void* blas_memory_alloc(int procpos) {
  static const auto real = next_definition<void* (*)(int)>("blas_memory_alloc");
  const std::lock_guard<std::mutex> guard(pool_lock());
  return real(procpos);
}

__attribute__((visibility("default"))) void blas_memory_free(void* buffer) {
  static const auto real = next_definition<void (*)(void*)>("blas_memory_free");
  const std::lock_guard<std::mutex> guard(pool_lock());
  real(buffer);
}

}  // extern "C"

namespace hydrodda::hydro {

bool blas_is_thread_safe() {
  static const bool guarded = dlsym(RTLD_DEFAULT, "blas_memory_alloc") == reinterpret_cast<void*>(&blas_memory_alloc);
  return guarded;
}

}  // namespace hydrodda::hydro
