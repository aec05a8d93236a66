// OpenBLAS's pool of work buffers, taken under a lock. Debian's serial OpenBLAS (0.3.21, built
// single-threaded) hands out its buffers without one: two threads calling dsyrk at once may be
// given the same buffer, and then one of them gets a wrong result (26 of 40,000 random calls on
// two threads, none with the lock). The executables export these two functions
// (cmake: --export-dynamic-symbol), so that OpenBLAS's own calls to them, which go through the
// dynamic linker, come here; the real ones are the next definitions in the search order. Other
// BLAS libraries never call them.

#include "numerics/blas_threads.hpp"

#include <dlfcn.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <mutex>

namespace {

std::atomic<bool> pool_reached{false};  // OpenBLAS called blas_memory_alloc below

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

void dsyrk_(const char* uplo, const char* trans, const int* n, const int* k, const double* alpha, const double* a,
            const int* lda, const double* beta, double* c, const int* ldc);

__attribute__((visibility("default"))) void* blas_memory_alloc(int procpos) {
  static const auto real = next_definition<void* (*)(int)>("blas_memory_alloc");
  pool_reached.store(true);
  const std::lock_guard<std::mutex> guard(pool_lock());
  return real(procpos);
}

__attribute__((visibility("default"))) void blas_memory_free(void* buffer) {
  static const auto real = next_definition<void (*)(void*)>("blas_memory_free");
  const std::lock_guard<std::mutex> guard(pool_lock());
  real(buffer);
}

}  // extern "C"

namespace hydrodda::numerics {

// OpenBLAS binds its calls of the pool's functions once, in the scope it was loaded in: a
// library loaded before this code (NumPy's OpenBLAS, then the Python module) keeps its own,
// though dlsym from here finds these. So ask OpenBLAS itself: a 1 × 1 dsyrk takes a buffer.
bool blas_is_thread_safe() {
  static const bool guarded = [] {
    if (dlsym(RTLD_NEXT, "blas_memory_alloc") == nullptr) return true;  // not OpenBLAS
    static constexpr int n = 1;
    static constexpr double one = 1.0, zero = 0.0, a = 1.0;
    double c = 0.0;
    dsyrk_("L", "N", &n, &n, &one, &a, &n, &zero, &c, &n);
    return pool_reached.load();
  }();
  return guarded;
}

std::unique_lock<std::mutex> hold_blas() {
  if (blas_is_thread_safe()) return {};
  static std::mutex one_caller;
  return std::unique_lock<std::mutex>(one_caller);
}

}  // namespace hydrodda::numerics
