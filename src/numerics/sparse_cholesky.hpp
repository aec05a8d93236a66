#pragma once
// A sparse Cholesky factorisation of a symmetric positive definite matrix, behind one
// interface for its backends (CHOLMOD's, cholmod_solver.hpp): the pattern is analysed
// once (ordering, symbolic factorisation), then each new set of values is only factorised
// numerically; the factor may be kept to precondition later matrices, corrected by a low-rank
// term (kept_factor.hpp). Another backend (e.g. PETSc) implements the same calls.

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace hydrodda::numerics {

// Column-major; only the upper triangle (row <= column) is stored and read: the triangle
// CHOLMOD's supernodal factorisation works on, which it then permutes into one copy; a lower
// triangle it transposes twice, holding two (45 MB each at 10^6 triangles).
using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

// A factorisation failed: the matrix is singular or not positive definite.
class SingularSystem : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A low-rank term U S Uᵀ to add to a factored matrix: column j of U has the entries
// (row[k], value[k]) for k in [start[j], start[j + 1]); S = diag(weight).
struct LowRankTerm {
  std::vector<int> start{0};
  std::vector<int> row;
  std::vector<double> value;
  std::vector<double> weight;
  int columns() const { return static_cast<int>(weight.size()); }
};

// The inverse of a factored matrix with a low-rank term added, applied without factoring
// the sum. Valid while the factorisation it was made from stands.
class CorrectedFactor {
 public:
  virtual ~CorrectedFactor() = default;
  // x = (A + U S Uᵀ)⁻¹ b.
  virtual Eigen::VectorXd solve(const Eigen::VectorXd& b) const = 0;
};

class SparseCholesky {
 public:
  virtual ~SparseCholesky() = default;
  // Symbolic analysis of the pattern of `upper`; its values are not read.
  virtual void analyse(const SparseMatrix& upper) = 0;
  // Numeric factorisation of a matrix with the analysed pattern; throws SingularSystem.
  virtual void factorize(const SparseMatrix& upper) = 0;
  // x = A⁻¹ b with the last factorisation. Refused (std::logic_error) while the factor is kept
  // for preconditioning.
  virtual Eigen::VectorXd solve(const Eigen::VectorXd& b) const = 0;
  // From here until the next factorize(), the factor serves as a preconditioner only
  // (precondition() and correct()): a backend may keep it in lower precision.
  virtual void keep_for_preconditioning() {}
  // Whether the factor is kept for preconditioning in lower precision now.
  virtual bool kept_for_preconditioning() const { return false; }
  // x = M⁻¹ b, M the factored matrix as kept for preconditioning: A itself, or its factor's
  // values rounded (still a fixed symmetric positive definite M, close to A).
  virtual Eigen::VectorXd precondition(const Eigen::VectorXd& b) const { return solve(b); }
  virtual std::string name() const = 0;
  // The last factorisation (as kept for preconditioning) corrected by `term`; null where the
  // backend has no such update.
  virtual std::unique_ptr<CorrectedFactor> correct(const LowRankTerm& term) const {
    (void)term;
    return nullptr;
  }
};

}  // namespace hydrodda::numerics
