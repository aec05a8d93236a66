#include "numerics/anderson.hpp"

namespace hydrodda::numerics {

Eigen::VectorXd AndersonAccelerator::next(const Eigen::VectorXd& x, const Eigen::VectorXd& g) {
  if (!history_.empty() && history_.back().image.size() != g.size()) history_.clear();
  history_.push_back({g - x, g});
  if (static_cast<int>(history_.size()) > depth_ + 1) history_.pop_front();
  const int m = static_cast<int>(history_.size()) - 1;
  if (m == 0 || g.size() == 0) return g;
  Eigen::MatrixXd delta_f(g.size(), m);
  Eigen::MatrixXd delta_g(g.size(), m);
  for (int i = 0; i < m; ++i) {
    delta_f.col(i) = history_[i + 1].residual - history_[i].residual;
    delta_g.col(i) = history_[i + 1].image - history_[i].image;
  }
  // Rank-revealing QR: passes that barely differ make ΔF nearly singular, and the pivoting
  // drops those columns instead of amplifying round-off.
  const Eigen::VectorXd gamma = delta_f.colPivHouseholderQr().solve(history_.back().residual);
  if (!gamma.allFinite()) {
    history_.clear();
    return g;
  }
  return g - delta_g * gamma;
}

}  // namespace hydrodda::numerics
