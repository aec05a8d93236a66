#pragma once
// Whether this process may call BLAS and LAPACK from two threads at once.

#include <mutex>

namespace hydrodda::numerics {

// True where OpenBLAS's own calls reach the lock around its pool of work buffers
// (blas_threads.cpp), or where the BLAS is not OpenBLAS: in the program and its tests, whose
// executables take the pool's two functions in front of OpenBLAS's, and in the Python module
// when it loaded OpenBLAS itself. False in the Python module imported after NumPy had loaded
// OpenBLAS, whose calls then keep its own functions: BLAS is called from one thread at a time.
bool blas_is_thread_safe();

// To hold while calling BLAS or LAPACK (directly or through CHOLMOD's supernodal routines):
// where blas_is_thread_safe() is false, a lock that one thread at a time holds, so that two
// runs in one process (two Python threads) are not handed the same buffer; else nothing held.
std::unique_lock<std::mutex> hold_blas();

}  // namespace hydrodda::numerics
