#include "numerics/iqn_ils.hpp"

#include <stdexcept>
#include <vector>

namespace hydrodda::numerics {

IqnIls::IqnIls(Settings settings) : settings_(settings) {
  if (settings_.max_columns < 1) throw std::invalid_argument("IQN-ILS: keep at least one column");
  if (!(settings_.filter >= 0.0 && settings_.filter < 1.0))
    throw std::invalid_argument("IQN-ILS: the filter's ε must lie in [0, 1)");
  if (!(settings_.initial_relaxation > 0.0 && settings_.initial_relaxation <= 1.0))
    throw std::invalid_argument("IQN-ILS: the first step's relaxation must lie in (0, 1]");
}

void IqnIls::reset() {
  v_.resize(0, 0);
  w_.resize(0, 0);
  residual_.resize(0);
  image_.resize(0);
}

void IqnIls::restore(History history) {
  v_ = std::move(history.v);
  w_ = std::move(history.w);
  residual_ = std::move(history.residual);
  image_ = std::move(history.image);
}

// Prepends this pass's differences to the last pass's, dropping the oldest past the cap.
void IqnIls::add_columns(const Eigen::VectorXd& residual, const Eigen::VectorXd& image) {
  if (residual_.size() == 0) return;
  const Eigen::Index n = residual.size();
  const Eigen::Index kept = std::min<Eigen::Index>(v_.cols(), settings_.max_columns - 1);
  Eigen::MatrixXd v(n, kept + 1), w(n, kept + 1);
  v.col(0) = residual - residual_;
  w.col(0) = image - image_;
  v.rightCols(kept) = v_.leftCols(kept);
  w.rightCols(kept) = w_.leftCols(kept);
  v_ = std::move(v);
  w_ = std::move(w);
}

// Modified Gram–Schmidt, twice over (a column nearly in the span of the newer ones loses most
// of itself to the first sweep, and round-off with it), newest column first so that a new pass
// displaces the old ones it repeats.
void IqnIls::filter(Eigen::MatrixXd& q, Eigen::MatrixXd& r) {
  const Eigen::Index n = v_.rows(), m = v_.cols();
  q.resize(n, m);
  r = Eigen::MatrixXd::Zero(m, m);
  std::vector<Eigen::Index> kept;
  for (Eigen::Index j = 0; j < m; ++j) {
    const auto k = static_cast<Eigen::Index>(kept.size());
    Eigen::VectorXd u = v_.col(j);
    Eigen::VectorXd coefficients = Eigen::VectorXd::Zero(k);
    for (int sweep = 0; sweep < 2; ++sweep)
      for (Eigen::Index i = 0; i < k; ++i) {
        const double c = q.col(i).dot(u);
        coefficients[i] += c;
        u -= c * q.col(i);
      }
    const double length = u.norm();
    if (!(length > settings_.filter * v_.col(j).norm())) continue;  // also drops a zero column
    q.col(k) = u / length;
    r.col(k).head(k) = coefficients;
    r(k, k) = length;
    kept.push_back(j);
  }
  const auto k = static_cast<Eigen::Index>(kept.size());
  if (k < m) {
    Eigen::MatrixXd v(n, k), w(n, k);
    for (Eigen::Index i = 0; i < k; ++i) {
      v.col(i) = v_.col(kept[i]);
      w.col(i) = w_.col(kept[i]);
    }
    v_ = std::move(v);
    w_ = std::move(w);
  }
  q.conservativeResize(n, k);
  r.conservativeResize(k, k);
}

Eigen::VectorXd IqnIls::next(const Eigen::VectorXd& x, const Eigen::VectorXd& g) {
  if (residual_.size() != 0 && residual_.size() != g.size()) reset();
  const Eigen::VectorXd residual = g - x;
  add_columns(residual, g);
  residual_ = residual;
  image_ = g;
  const Eigen::VectorXd plain = x + settings_.initial_relaxation * residual;
  if (v_.cols() == 0 || g.size() == 0) return plain;
  Eigen::MatrixXd q, r;
  filter(q, r);
  if (v_.cols() == 0) return plain;
  const Eigen::VectorXd c = r.triangularView<Eigen::Upper>().solve(-(q.transpose() * residual));
  const Eigen::VectorXd step = g + w_ * c;
  if (!step.allFinite()) {
    reset();
    return plain;
  }
  return step;
}

}  // namespace hydrodda::numerics
