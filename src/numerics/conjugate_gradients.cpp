#include "numerics/conjugate_gradients.hpp"

namespace hydrodda::numerics {
namespace {

bool residual_converged(const CgStoppingRule& rule, const Eigen::VectorXd& r) {
  return rule.residual_converged && rule.residual_converged(r);
}

CgVerdict check(const CgStoppingRule& rule, int iteration, const Eigen::VectorXd& r, const Eigen::VectorXd& z) {
  return rule.check ? rule.check(iteration, r, z) : CgVerdict::go_on;
}

}  // namespace

int run_preconditioned_cg(const VectorOperator& multiply, const VectorOperator& precondition,
                          const CgStoppingRule& rule, int max_iterations, Eigen::VectorXd& x,
                          Eigen::VectorXd& r, long& iterations) {
  if (residual_converged(rule, r)) return 0;
  Eigen::VectorXd z(r.size()), q(r.size());
  precondition(r, z);
  CgVerdict verdict = check(rule, 0, r, z);
  if (verdict != CgVerdict::go_on) return verdict == CgVerdict::converged ? 0 : -1;
  Eigen::VectorXd p = z;
  double rz = r.dot(z);
  for (int it = 1; it <= max_iterations; ++it) {
    ++iterations;
    multiply(p, q);
    const double curvature = p.dot(q);
    if (!(curvature > 0.0) || !(rz > 0.0)) return -1;
    const double alpha = rz / curvature;
    x += alpha * p;
    r -= alpha * q;
    if (residual_converged(rule, r)) return it;
    precondition(r, z);
    verdict = check(rule, it, r, z);
    if (verdict != CgVerdict::go_on) return verdict == CgVerdict::converged ? it : -1;
    const double rz_new = r.dot(z);
    p = z + (rz_new / rz) * p;
    rz = rz_new;
  }
  return -1;
}

int solve_by_conjugate_gradients(const VectorOperator& multiply, const VectorOperator& precondition,
                                 const Eigen::VectorXd& b, const Eigen::VectorXd& guess, double tolerance,
                                 int max_iterations, Eigen::VectorXd& x, long& iterations) {
  const double b_norm = b.norm();
  x = Eigen::VectorXd::Zero(b.size());
  if (b_norm == 0.0) return 0;
  const double scale = 1.0 / b_norm;
  const Eigen::VectorXd unit_b = scale * b;
  Eigen::VectorXd r = unit_b;
  if (guess.size() == b.size()) {
    const Eigen::VectorXd start = scale * guess;
    Eigen::VectorXd q(b.size());
    multiply(start, q);
    q = unit_b - q;
    if (q.norm() < 1.0) {
      x = start;
      r = q;
    }
  }
  const CgStoppingRule rule{[tolerance](const Eigen::VectorXd& residual) { return residual.norm() <= tolerance; }, {}};
  const int taken = run_preconditioned_cg(multiply, precondition, rule, max_iterations, x, r, iterations);
  if (taken >= 0) x *= b_norm;
  return taken;
}

}  // namespace hydrodda::numerics
