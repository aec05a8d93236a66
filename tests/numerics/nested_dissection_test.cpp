// order_by_nested_dissection: a permutation, the same on every call and whether the helper
// process orders the second half or this one does, whose factorisation solves as CHOLMOD's own
// (AMD) ordering does; for a graph split in two, one ordered whole, and one in two pieces.

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <string>
#include <vector>

#include "numerics/cholmod_solver.hpp"
#include "numerics/nested_dissection.hpp"

namespace hydrodda::numerics {
namespace {

// The P1 Laplacian's pattern on an nx × ny grid of squares cut into triangles, plus a shift
// (SPD), upper triangle: the graph of a flow matrix.
SparseMatrix grid_matrix(int nx, int ny) {
  const int n = nx * ny;
  std::vector<Eigen::Triplet<double>> entries;
  const auto couple = [&](int a, int b) { entries.emplace_back(std::min(a, b), std::max(a, b), -1.0); };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int p = j * nx + i;
      entries.emplace_back(p, p, 6.01);
      if (i + 1 < nx) couple(p, p + 1);
      if (j + 1 < ny) couple(p, p + nx);
      if (i + 1 < nx && j + 1 < ny) couple(p, p + nx + 1);
    }
  SparseMatrix a(n, n);
  a.setFromTriplets(entries.begin(), entries.end());
  return a;
}

bool is_permutation_of_unknowns(const std::vector<int>& order, int n) {
  std::vector<int> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  std::vector<int> all(n);
  std::iota(all.begin(), all.end(), 0);
  return sorted == all;
}

// Solves with the default (nested dissection) and the automatic (AMD) ordering: both are
// exact factorisations, so they agree to round-off (condition number about 1e3 here).
void expect_same_solution_as_amd(const SparseMatrix& a) {
  auto dissected = make_cholmod_solver(FillOrdering::metis);
  auto amd = make_cholmod_solver(FillOrdering::automatic);
  for (auto* solver : {dissected.get(), amd.get()}) {
    solver->analyse(a);
    solver->factorize(a);
  }
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(a.rows(), -1.0, 3.0);
  const Eigen::VectorXd x = dissected->solve(b), y = amd->solve(b);
  EXPECT_LE((x - y).lpNorm<Eigen::Infinity>(), 1e-12 * y.lpNorm<Eigen::Infinity>());
}

TEST(NestedDissection, SplitsALargeGraphAndOrdersEveryUnknownOnce) {
  const SparseMatrix a = grid_matrix(220, 110);  // 24,200 unknowns: split, half to the helper
  ASSERT_GE(a.rows(), kSplitFrom);
  const FillOrder split = order_by_nested_dissection(a);
  const std::vector<int>& order = split.order;
  EXPECT_TRUE(is_permutation_of_unknowns(order, static_cast<int>(a.rows())));
  EXPECT_EQ(order, order_by_nested_dissection(a).order);                          // deterministic
  EXPECT_EQ(order, order_by_nested_dissection(a, /*with_helper=*/false).order);  // the helper's half is METIS's
  // The halves: about half the unknowns each, a separator of about one grid column (110), and
  // no edge between the halves.
  EXPECT_GT(split.halves[0], 10000);
  EXPECT_GT(split.halves[1], 10000);
  EXPECT_LT(static_cast<int>(a.rows()) - split.halves[0] - split.halves[1], 400);
  const std::vector<int> part = split.parts();
  for (int j = 0; j < a.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(a, j); it; ++it)
      if (part[it.row()] != 2 && part[j] != 2) {
        EXPECT_EQ(part[it.row()], part[j]);
      }
  expect_same_solution_as_amd(a);
}

TEST(NestedDissection, OrdersASmallGraphWhole) {
  const SparseMatrix a = grid_matrix(40, 30);
  const FillOrder whole = order_by_nested_dissection(a);
  EXPECT_TRUE(is_permutation_of_unknowns(whole.order, static_cast<int>(a.rows())));
  EXPECT_EQ(whole.halves[0] + whole.halves[1], 0);
  EXPECT_TRUE(whole.parts().empty());
  expect_same_solution_as_amd(a);
}

// Two grids with no edge between them: the separator is empty, and each half is one grid.
TEST(NestedDissection, OrdersAGraphInTwoPiecesWithAnEmptySeparator) {
  const SparseMatrix one = grid_matrix(160, 80);
  const int n = static_cast<int>(one.rows());
  std::vector<Eigen::Triplet<double>> entries;
  for (int offset : {0, n})
    for (int j = 0; j < one.outerSize(); ++j)
      for (SparseMatrix::InnerIterator it(one, j); it; ++it)
        entries.emplace_back(static_cast<int>(it.row()) + offset, j + offset, it.value());
  SparseMatrix two(2 * n, 2 * n);
  two.setFromTriplets(entries.begin(), entries.end());
  const FillOrder order = order_by_nested_dissection(two);
  EXPECT_TRUE(is_permutation_of_unknowns(order.order, 2 * n));
  EXPECT_EQ(order.halves[0] + order.halves[1], 2 * n);
  expect_same_solution_as_amd(two);
}

// The helper program itself (beside the program, as a run finds it): given a graph on its
// standard input, it writes the order that this process gives the same graph (ordered whole,
// below kSplitFrom), so a split ordering that uses it is the one made without it. The graph is
// built as order_by_nested_dissection builds it (columns ascending, each column's rows
// ascending), since METIS's order depends on the order of the neighbours; idx_t is 32 bits in
// Debian's METIS (IDXTYPEWIDTH).
TEST(NestedDissection, TheHelperOrdersAGraphAsThisProcessDoes) {
  const SparseMatrix a = grid_matrix(60, 50);
  const int n = static_cast<int>(a.rows());
  std::vector<std::vector<std::int32_t>> neighbours(n);
  for (int j = 0; j < n; ++j)
    for (SparseMatrix::InnerIterator it(a, j); it; ++it)
      if (it.row() != j) {
        neighbours[it.row()].push_back(j);
        neighbours[j].push_back(static_cast<std::int32_t>(it.row()));
      }
  std::vector<std::int32_t> xadj{0}, adjncy;
  for (const auto& list : neighbours) {
    adjncy.insert(adjncy.end(), list.begin(), list.end());
    xadj.push_back(static_cast<std::int32_t>(adjncy.size()));
  }
  namespace fs = std::filesystem;
  const fs::path helper = fs::path(HYDRODDA_BINARY).parent_path() / "hydrodda_order";
  ASSERT_TRUE(fs::exists(helper)) << helper;
  const fs::path folder = fs::temp_directory_path() / ("hydrodda_order_test_" + std::to_string(::getpid()));
  fs::create_directories(folder);
  {
    std::ofstream in(folder / "graph", std::ios::binary);
    const std::int64_t header[2] = {n, static_cast<std::int64_t>(adjncy.size())};
    in.write(reinterpret_cast<const char*>(header), sizeof header);
    in.write(reinterpret_cast<const char*>(xadj.data()), static_cast<std::streamsize>(xadj.size() * 4));
    in.write(reinterpret_cast<const char*>(adjncy.data()), static_cast<std::streamsize>(adjncy.size() * 4));
  }
  const std::string command =
      helper.string() + " < " + (folder / "graph").string() + " > " + (folder / "order").string();
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  std::ifstream out(folder / "order", std::ios::binary);
  std::vector<std::int32_t> order(n);
  out.read(reinterpret_cast<char*>(order.data()), static_cast<std::streamsize>(order.size() * 4));
  EXPECT_EQ(out.gcount(), static_cast<std::streamsize>(order.size() * 4));
  fs::remove_all(folder);
  EXPECT_EQ(std::vector<int>(order.begin(), order.end()), order_by_nested_dissection(a).order);
}

}  // namespace
}  // namespace hydrodda::numerics
