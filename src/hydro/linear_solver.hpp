#pragma once
// The flow model's sparse Cholesky backend (numerics/sparse_cholesky.hpp's interface):
// CHOLMOD's analysis, on an ordering by nested dissection made beside the program
// (nested_dissection.hpp), and the program's own numeric factorisation on two threads
// (supernodal_factorization.hpp) with its low-rank correction (supernodal_correction.hpp).

#include <memory>

#include "numerics/sparse_cholesky.hpp"

namespace hydrodda::hydro {

// The interface's types, as the backend's files name them.
using numerics::CorrectedFactor;
using numerics::LowRankTerm;
using numerics::SingularSystem;
using numerics::SparseMatrix;

// Fill-reducing ordering of the symbolic analysis: METIS (nested dissection; slower to
// analyse, faster to refactor) or CHOLMOD's automatic choice (AMD first).
enum class FillOrdering { metis, automatic };

// CHOLMOD supernodal Cholesky (LLᵀ) through Eigen's CholmodSupport.
std::unique_ptr<numerics::SparseCholesky> make_cholmod_solver(FillOrdering ordering = FillOrdering::metis);

}  // namespace hydrodda::hydro
