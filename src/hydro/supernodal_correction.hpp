#pragma once
// A CHOLMOD supernodal LLᵀ factor corrected by a low-rank term (Sherman–Morrison–Woodbury):
// the solve of A + U S Uᵀ from the factor of A, at the cost of sparse half-solves with the
// columns of U rather than a new factorisation. Written by hand: CHOLMOD's own sparse solve
// (cholmod_spsolve) solves its columns densely, a whole triangular solve each.

#include <cholmod.h>

#include <memory>

#include "hydro/linear_solver.hpp"

namespace hydrodda::hydro {

// `factor`: a numeric supernodal LLᵀ factor with int indices (std::logic_error otherwise).
// It and `common` must outlive the result and stay unchanged while it is used. Throws
// SingularSystem when the corrected matrix is singular to working precision.
std::unique_ptr<CorrectedFactor> correct_supernodal_factor(cholmod_factor* factor, cholmod_common* common,
                                                           const LowRankTerm& term);

}  // namespace hydrodda::hydro
