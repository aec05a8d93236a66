#include "numerics/kept_factor.hpp"

#include <algorithm>
#include <cmath>

namespace hydrodda::numerics {

long chebyshev_iterations(double c, double tolerance) {
  return static_cast<long>(std::ceil(std::log(0.5 * tolerance) / std::log((c - 1.0) / (c + 1.0))));
}

ReusePlan plan_factor_reuse(std::span<const double> spreads, bool correcting, const FactorReuseCosts& costs) {
  std::array<long, kReuseSpreads.size()> outside{};
  for (const double spread : spreads)
    for (std::size_t i = 0; i < kReuseSpreads.size() && !(spread <= kReuseSpreads[i]); ++i) ++outside[i];
  long bound = kNoReuseBound;
  double cost = INFINITY;
  int corrected_outside = -1;  // the ladder step whose outside parts are corrected
  for (std::size_t i = 0; i < kReuseSpreads.size(); ++i) {
    const long inside = chebyshev_iterations(kReuseSpreads[i], costs.tolerance);
    const long plain = costs.rank_per_part * outside[i] + inside;
    if (plain < cost) {
      cost = static_cast<double>(plain);
      bound = plain;
      corrected_outside = -1;
    }
    const double correction_cost = outside[i] / costs.corrected_per_iteration;
    const double with_correction = static_cast<double>(inside) + correction_cost;
    if (correcting && outside[i] > 0 && outside[i] <= costs.max_corrected_parts && inside <= costs.max_iterations &&
        correction_cost < costs.iterations_saved_by_keeping && with_correction < cost) {
      cost = with_correction;
      bound = inside;
      corrected_outside = static_cast<int>(i);
    }
  }
  ReusePlan plan{{}, static_cast<int>(std::min<long>(bound, kNoReuseBound))};
  if (corrected_outside >= 0)
    for (std::size_t p = 0; p < spreads.size(); ++p)
      if (!(spreads[p] <= kReuseSpreads[corrected_outside])) plan.corrected.push_back(static_cast<int>(p));
  return plan;
}

void KeptFactorPreconditioner::use_factor_alone() {
  corrected_.reset();
  factor_.keep_for_preconditioning();
}

bool KeptFactorPreconditioner::use_corrected_factor(const LowRankTerm& term) {
  const bool downdates = std::any_of(term.weight.begin(), term.weight.end(), [](double w) { return w < 0.0; });
  if (downdates && factor_.kept_for_preconditioning()) return false;
  try {
    corrected_ = factor_.correct(term);
  } catch (const SingularSystem&) {
    corrected_.reset();
  }
  return corrected_ != nullptr;
}

void KeptFactorPreconditioner::apply(const Eigen::VectorXd& r, Eigen::VectorXd& z) const {
  z = corrected_ ? corrected_->solve(r) : factor_.precondition(r);
}

}  // namespace hydrodda::numerics
