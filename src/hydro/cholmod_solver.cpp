// The one file that includes CHOLMOD (through Eigen's CholmodSupport).
#include <Eigen/CholmodSupport>

#include "hydro/linear_solver.hpp"

namespace hydrodda::hydro {
namespace {

class CholmodSolver final : public LinearSolver {
 public:
  explicit CholmodSolver(FillOrdering ordering) {
    // The ordering is paid once per mesh, the numeric factorisation every coupling
    // iteration: METIS costs 3x AMD's analysis but refactors 20% faster on these meshes
    // (docs/performance.md), so it is the default.
    if (ordering == FillOrdering::metis) {
      factor_.cholmod().nmethods = 1;
      factor_.cholmod().method[0].ordering = CHOLMOD_METIS;
    } else {
      factor_.cholmod().nmethods = 0;  // CHOLMOD's choice: AMD, METIS if AMD's fill is poor
    }
  }

  void analyse(const SparseMatrix& upper) override {
    factor_.analyzePattern(upper);
    analysed_ = true;
  }

  void factorize(const SparseMatrix& upper) override {
    if (!analysed_) throw std::logic_error("CholmodSolver::factorize before analyse");
    factor_.factorize(upper);
    if (factor_.info() != Eigen::Success)
      throw SingularSystem("CHOLMOD: the matrix is singular or not positive definite");
  }

  Eigen::VectorXd solve(const Eigen::VectorXd& b) const override {
    Eigen::VectorXd x = factor_.solve(b);
    if (factor_.info() != Eigen::Success) throw SingularSystem("CHOLMOD: the solve failed");
    return x;
  }

  std::string name() const override { return "CHOLMOD supernodal LLT"; }

 private:
  Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Upper> factor_;
  bool analysed_ = false;
};

}  // namespace

std::unique_ptr<LinearSolver> make_cholmod_solver(FillOrdering ordering) {
  return std::make_unique<CholmodSolver>(ordering);
}

}  // namespace hydrodda::hydro
