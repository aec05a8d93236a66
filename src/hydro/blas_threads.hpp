#pragma once
// Whether this process may call BLAS and LAPACK from two threads at once.

namespace hydrodda::hydro {

// True where OpenBLAS's pool of work buffers is guarded by a lock (blas_threads.cpp): in the
// program and its tests, whose executables take the pool's two functions in front of
// OpenBLAS's. False in a module loaded into another process (the Python module), where
// OpenBLAS's own come first: BLAS is then called from one thread at a time.
bool blas_is_thread_safe();

}  // namespace hydrodda::hydro
