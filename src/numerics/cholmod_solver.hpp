#pragma once
// The CHOLMOD backend of the sparse Cholesky interface (sparse_cholesky.hpp), which the flow
// model solves with: CHOLMOD's analysis, on an ordering by nested dissection made beside the
// program (nested_dissection.hpp), and the program's own numeric factorisation on two threads
// (supernodal_factorization.hpp) with its low-rank correction (supernodal_correction.hpp); or
// CHOLMOD's own ordering and factorisation throughout.

#include <memory>

#include "numerics/sparse_cholesky.hpp"

namespace hydrodda::numerics {

// Fill-reducing ordering of the symbolic analysis: METIS (nested dissection; slower to
// analyse, faster to refactor) or CHOLMOD's automatic choice (AMD first).
enum class FillOrdering { metis, automatic };

// CHOLMOD supernodal Cholesky (LLᵀ) through Eigen's CholmodSupport.
std::unique_ptr<SparseCholesky> make_cholmod_solver(FillOrdering ordering = FillOrdering::metis);

}  // namespace hydrodda::numerics
