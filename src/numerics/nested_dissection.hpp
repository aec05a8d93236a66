#pragma once
// The fill-reducing ordering of the flow matrix, nested dissection on two cores: one vertex
// separator splits the matrix's graph in two, METIS orders one half here while a helper process
// (hydrodda_order, beside the program) orders the other, and the separator comes last (George,
// "Nested dissection of a regular finite element mesh", SIAM J. Numer. Anal. 10, 1973;
// METIS_NodeND makes the same first cut, then orders the halves one after the other). Written
// here because CHOLMOD calls METIS on one core: at a million triangles the ordering takes
// 1.1 s on two against 2.2 s, for the same fill.

#include <vector>

#include "numerics/cholmod_solver.hpp"

namespace hydrodda::numerics {

// A pivot order: order[k] is the unknown eliminated k-th (CHOLMOD's Perm). Where a separator
// split the graph, order's first halves[0] unknowns are one half, the next halves[1] the other,
// and the rest the separator; halves is {0, 0} where the graph was ordered whole.
struct FillOrder {
  std::vector<int> order;
  int halves[2] = {0, 0};
  // Per unknown: 0 or 1, its half, 2 in the separator; empty where the graph was not split.
  std::vector<int> parts() const;
};

// The pivot order of the symmetric matrix whose upper triangle is `upper` (its values are not
// read). Below kSplitFrom unknowns,
// or where the separator leaves a half empty, METIS orders the whole graph in one go; where the
// helper cannot be started or fails, this process orders both halves in turn, to the same order.
// Deterministic: the same pattern gives the same order on any machine. `with_helper` false, or
// a process of one thread (numerics::thread_count): both halves here, in turn. Throws
// std::runtime_error when METIS fails.
FillOrder order_by_nested_dissection(const SparseMatrix& upper, bool with_helper = true);

inline constexpr int kSplitFrom = 20000;

}  // namespace hydrodda::numerics
