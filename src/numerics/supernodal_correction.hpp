#pragma once
// A CHOLMOD supernodal LLᵀ factor corrected by a low-rank term (Sherman–Morrison–Woodbury):
// the solve of A + U S Uᵀ from the factor of A, at the cost of sparse half-solves with the
// columns of U rather than a new factorisation. Written by hand: CHOLMOD's own sparse solve
// (cholmod_spsolve) solves its columns densely, a whole triangular solve each.

#include <cholmod.h>

#include <functional>
#include <memory>
#include <vector>

#include "numerics/cholmod_solver.hpp"

namespace hydrodda::numerics {

// The elimination tree of a supernodal analysis, which every correction walks: it depends on
// the pattern alone, so it is made once per analysis, not once per correction.
struct SupernodalTree {
  std::vector<int> supernode_of_column;  // per elimination position
  std::vector<int> parent;               // per supernode: its parent, −1 at a root
  std::vector<int> position;             // per unknown: its elimination position (Perm's inverse)
};
// `factor`: a supernodal LLᵀ analysis (or factor) with int indices (std::logic_error otherwise).
SupernodalTree make_supernodal_tree(const cholmod_factor* factor);

// The two halves of a solve with the factor, L Lᵀ = P A Pᵀ: v ← L⁻¹ P v and v ← Pᵀ L⁻ᵀ v
// (SupernodalFactorization's, on two threads); empty: CHOLMOD's.
struct HalfSolves {
  std::function<void(Eigen::VectorXd&)> forward;
  std::function<void(Eigen::VectorXd&)> backward;
};

// `factor`: a numeric supernodal LLᵀ factor with int indices (std::logic_error otherwise), and
// `tree` its analysis's; or its analysis with the factor's values in single precision,
// `single` (SupernodalFactorization::single_values), and `halves` that solve with them: the
// result is then the exact inverse of Pᵀ L̃ L̃ᵀ P + U S Uᵀ. The factor and `common` (and what
// `halves` calls) must outlive the result and stay unchanged while it is used. Throws
// SingularSystem when the corrected matrix is singular to working precision.
std::unique_ptr<CorrectedFactor> correct_supernodal_factor(cholmod_factor* factor, cholmod_common* common,
                                                           const SupernodalTree& tree, const LowRankTerm& term,
                                                           HalfSolves halves = {}, const float* single = nullptr);

}  // namespace hydrodda::numerics
