#pragma once
// The flow model's sparse Cholesky: numerics/' CHOLMOD backend (numerics/cholmod_solver.hpp),
// and the interface's types as the flow solver's files name them.

#include "numerics/cholmod_solver.hpp"

namespace hydrodda::hydro {

using numerics::CorrectedFactor;
using numerics::FillOrdering;
using numerics::LowRankTerm;
using numerics::make_cholmod_solver;
using numerics::SingularSystem;
using numerics::SparseMatrix;

}  // namespace hydrodda::hydro
