// CHOLMOD through Eigen's CholmodSupport; supernodal_correction.cpp reads the factor it makes.
#include <omp.h>

#include <mutex>
#include <optional>

#include <Eigen/CholmodSupport>

#include "numerics/blas_threads.hpp"
#include "numerics/cholmod_solver.hpp"
#include "numerics/nested_dissection.hpp"
#include "numerics/supernodal_correction.hpp"
#include "numerics/supernodal_factorization.hpp"
#include "base/metis_lock.hpp"

namespace hydrodda::numerics {
namespace {

// While one lives, every OpenMP parallel region the calling thread starts runs on that thread
// alone (no level of parallelism may be active). CHOLMOD's supernodal factorisation opens a
// region of CHOLMOD_OMP_NUM_THREADS = 4 threads, fixed when Debian built it, for each update
// of more than 64 rows: a fork and a join for each, more threads than this machine's two cores,
// and at 10^6 triangles an exact pass (factorisation and solve) took 1.43 s against 0.79 s
// serial (bench_hydro LatePassFlow/10/0/0, the same as with OMP_THREAD_LIMIT=1).
class SerialOpenMP {
 public:
  SerialOpenMP() : levels_(omp_get_max_active_levels()) { omp_set_max_active_levels(0); }
  ~SerialOpenMP() { omp_set_max_active_levels(levels_); }
  SerialOpenMP(const SerialOpenMP&) = delete;
  SerialOpenMP& operator=(const SerialOpenMP&) = delete;

 private:
  int levels_;
};

// Eigen's supernodal LLᵀ, with its CHOLMOD factor in reach of the low-rank correction.
class SupernodalLLT : public Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Upper> {
 public:
  // analyzePattern() with the pivot order given (CHOLMOD's own postordering still applied).
  void analyse_in_order(const SparseMatrix& upper, std::vector<int> order) {
    cholmod_common& common = cholmod();
    if (m_cholmodFactor) cholmod_free_factor(&m_cholmodFactor, &common);
    m_cholmodFactor = nullptr;
    common.nmethods = 1;
    common.method[0].ordering = CHOLMOD_GIVEN;
    cholmod_sparse a = Eigen::viewAsCholmod(upper.selfadjointView<Eigen::Upper>());
    m_cholmodFactor = cholmod_analyze_p(&a, order.data(), nullptr, 0, &common);
    if (!m_cholmodFactor) throw std::runtime_error("CHOLMOD could not analyse the flow matrix");
    m_isInitialized = true;
    m_info = Eigen::Success;
    m_analysisIsOk = true;
    m_factorizationIsOk = false;
  }
  cholmod_factor* factor() const { return m_cholmodFactor; }
  // After the factor's values were filled outside Eigen (SupernodalFactorization).
  void mark_factorized() {
    m_info = Eigen::Success;
    m_factorizationIsOk = true;
  }
  // Eigen's solve() const changes it too (it is mutable there).
  cholmod_common* common() const { return &const_cast<SupernodalLLT*>(this)->cholmod(); }
};

class CholmodSolver final : public SparseCholesky {
 public:
  explicit CholmodSolver(FillOrdering ordering) : ordering_(ordering) {
    // The ordering is paid once per mesh, the numeric factorisation every coupling
    // iteration: METIS analyses more slowly than AMD but refactors 10-50% faster on these
    // meshes (docs/performance.md), so it is the default, as nested dissection on two cores.
    if (ordering == FillOrdering::automatic)
      factor_.cholmod().nmethods = 0;  // CHOLMOD's choice: AMD, METIS if AMD's fill is poor
  }

  void analyse(const SparseMatrix& upper) override {
    analysed_ = factored_ = false;
    tree_.reset();
    numeric_.reset();
    if (ordering_ == FillOrdering::metis) {
      const FillOrder order = order_by_nested_dissection(upper);
      factor_.analyse_in_order(upper, order.order);
      numeric_.emplace(factor_.factor(), factor_.common(), upper, order.parts());
      // CHOLMOD's workspace, sized for the analysis (about 20 bytes an unknown): the
      // factorisation and the solves are numeric_'s, which keeps its own.
      cholmod_free_work(factor_.common());
    } else {
      const std::lock_guard<std::mutex> one_at_a_time(base::metis_lock());  // CHOLMOD may order with METIS
      factor_.analyzePattern(upper);
    }
    analysed_ = true;
  }

  void factorize(const SparseMatrix& upper) override {
    if (!analysed_) throw std::logic_error("CholmodSolver::factorize before analyse");
    factored_ = false;
    if (numeric_) {
      numeric_->factorize(upper, /*two_threads=*/true);
      factor_.mark_factorized();
      factored_ = true;
      return;
    }
    {
      const SerialOpenMP serial;
      const std::unique_lock<std::mutex> blas = hold_blas();
      factor_.factorize(upper);
    }
    if (factor_.info() != Eigen::Success)
      throw SingularSystem("CHOLMOD: the matrix is singular or not positive definite");
    factored_ = true;
  }

  Eigen::VectorXd solve(const Eigen::VectorXd& b) const override {
    if (numeric_ && numeric_->in_single_precision())
      throw std::logic_error("CholmodSolver::solve with the factor kept for preconditioning");
    return precondition(b);
  }

  // The factorisation on two threads keeps its factor in single precision: the solves that
  // precondition CG read 130 MB rather than 260 MB at 10^6 triangles.
  void keep_for_preconditioning() override {
    if (!factored_) throw std::logic_error("CholmodSolver::keep_for_preconditioning before factorize");
    if (numeric_) numeric_->keep_in_single_precision();
  }

  bool kept_for_preconditioning() const override { return numeric_ && numeric_->in_single_precision(); }

  Eigen::VectorXd precondition(const Eigen::VectorXd& b) const override {
    if (numeric_ && factored_) return numeric_->solve(b, /*two_threads=*/true);
    const std::unique_lock<std::mutex> blas = hold_blas();
    Eigen::VectorXd x = factor_.solve(b);
    if (factor_.info() != Eigen::Success) throw SingularSystem("CHOLMOD: the solve failed");
    return x;
  }

  std::string name() const override {
    return numeric_ ? "supernodal LLT on CHOLMOD's analysis" : "CHOLMOD supernodal LLT";
  }

  std::unique_ptr<CorrectedFactor> correct(const LowRankTerm& term) const override {
    if (!factored_) throw std::logic_error("CholmodSolver::correct before factorize");
    if (numeric_) {
      const SupernodalFactorization* numeric = &*numeric_;
      HalfSolves halves{[numeric](Eigen::VectorXd& v) { numeric->solve_forward(v, /*two_threads=*/true); },
                        [numeric](Eigen::VectorXd& v) { numeric->solve_backward(v, /*two_threads=*/true); }};
      return correct_supernodal_factor(factor_.factor(), factor_.common(), numeric->tree(), term, std::move(halves),
                                       numeric->single_values());
    }
    if (!tree_) tree_ = make_supernodal_tree(factor_.factor());
    return correct_supernodal_factor(factor_.factor(), factor_.common(), *tree_, term);
  }

 private:
  FillOrdering ordering_;
  SupernodalLLT factor_;
  bool analysed_ = false;
  bool factored_ = false;
  // Of CHOLMOD's own analysis (the AMD ordering), made at its first correction; numeric_ has its own.
  mutable std::optional<SupernodalTree> tree_;
  // The numeric factorisation on two threads, of the nested-dissection analysis.
  std::optional<SupernodalFactorization> numeric_;
};

}  // namespace

std::unique_ptr<SparseCholesky> make_cholmod_solver(FillOrdering ordering) {
  return std::make_unique<CholmodSolver>(ordering);
}

}  // namespace hydrodda::numerics
