#pragma once
// The DDA stiffness matrix as the step assembles it: symmetric, made of 6×6 blocks, one block
// row and column per moving block; off the diagonal, one block per pair of blocks a closed
// contact joins.

#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Sparse>

namespace hydrodda::dda {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;
using Matrix6 = Eigen::Matrix<double, 6, 6>;
using Vector6 = Eigen::Matrix<double, 6, 1>;

using Matrix6Array = std::vector<Matrix6>;

struct BlockMatrix {
  int block_count = 0;
  Matrix6Array diagonal;                    // block (b, b)
  std::vector<std::pair<int, int>> pairs;   // (column, row), row > column, sorted
  Matrix6Array off;                         // block (row, column) of each pair

  int size() const { return 6 * block_count; }
  // y = A x.
  void multiply(const Eigen::VectorXd& x, Eigen::VectorXd& y) const;
  // The block rows first … last − 1 of y = A x, y already of A's size: each block row gets
  // its terms in the order multiply adds them, so that rows split between threads come out
  // bit for bit as one multiply makes them.
  void multiply_rows(const Eigen::VectorXd& x, Eigen::VectorXd& y, int first, int last) const;
  bool all_finite() const;
  // The compressed lower triangle, for solvers that take a scalar sparse matrix.
  SparseMatrix lower_triangle() const;
};

// An elimination order of the blocks (order[k]: the block eliminated k-th) by approximate
// minimum degree (Amestoy, Davis & Duff 1996, through Eigen) on the block graph, 6× smaller
// than the scalar one.
std::vector<int> order_by_minimum_degree(const BlockMatrix& a);

// The block form of a scalar symmetric matrix given by its lower triangle (size 6 × blocks):
// the pattern is that of the entries present. For tests and for callers holding a scalar matrix.
BlockMatrix block_form(const SparseMatrix& lower, int block_count);

}  // namespace hydrodda::dda
