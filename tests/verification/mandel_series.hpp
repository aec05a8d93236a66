// Mandel's problem of scenarios/verification/mandel.toml by its series (Mandel 1953; Abousleiman,
// Cheng, Cui, Detournay & Roegiers 1996, Géotechnique 46(2); Cheng & Detournay 1988): a rectangle
// 2a × 2b between rigid frictionless plates, its sides x = ±a drained, squeezed at t = 0 by
// σ0 = F/a = 1 MPa; E = 1 GPa, ν = 0.25, α = 1, S = 1/M = 1e-10 1/Pa, k = 1e-15 m², μ = 1e-3 Pa·s,
// plane strain. With K = E/(3(1 − 2ν)), G = E/(2(1 + ν)), K_u = K + α² M, B = α M/K_u,
// ν_u = (3K_u − 2G)/(2(3K_u + G)), c = 2 (k/μ) B² G (1 − ν)(1 + ν_u)²/(9 (1 − ν_u)(ν_u − ν)):
//   p0 = σ0 B (1 + ν_u)/3,
//   p(x, t) = 2 p0 Σ_n sin α_n/(α_n − sin α_n cos α_n) (cos(α_n x/a) − cos α_n) exp(−α_n² c t/a²),
// α_n the positive roots of tan α = (1 − ν)/(ν_u − ν) α, one in each (nπ, nπ + π/2).
#pragma once

#include <cmath>
#include <numbers>
#include <vector>

namespace hydrodda::testing::mandel {

constexpr double kWidth = 1.0, kLoad = 1.0e6, kYoung = 1.0e9, kPoisson = 0.25, kBiot = 1.0, kStorage = 1.0e-10;
constexpr double kMobility = 1.0e-15 / 1.0e-3;  // k/μ (m²/(Pa s))
constexpr double kModulus = 1.0 / kStorage;     // M
constexpr double kBulk = kYoung / (3 * (1 - 2 * kPoisson));
constexpr double kShear = kYoung / (2 * (1 + kPoisson));
constexpr double kBulkUndrained = kBulk + kBiot * kBiot * kModulus;
constexpr double kSkempton = kBiot * kModulus / kBulkUndrained;
constexpr double kPoissonUndrained = (3 * kBulkUndrained - 2 * kShear) / (2 * (3 * kBulkUndrained + kShear));
constexpr double kDiffusivity = 2 * kMobility * kSkempton * kSkempton * kShear * (1 - kPoisson) *
                                (1 + kPoissonUndrained) * (1 + kPoissonUndrained) /
                                (9 * (1 - kPoissonUndrained) * (kPoissonUndrained - kPoisson));
constexpr double kP0 = kLoad * kSkempton * (1 + kPoissonUndrained) / 3;

// The first `count` roots of tan α = A α, A = (1 − ν)/(ν_u − ν) > 1, by bisection in each
// (nπ, nπ + π/2), where tan α − A α runs from below zero to +∞.
inline std::vector<double> roots(int count = 200) {
  const double slope = (1 - kPoisson) / (kPoissonUndrained - kPoisson);
  std::vector<double> out;
  for (int n = 0; n < count; ++n) {
    double lo = n * std::numbers::pi + 1e-12, hi = n * std::numbers::pi + std::numbers::pi / 2 - 1e-12;
    for (int i = 0; i < 200; ++i) {
      const double mid = 0.5 * (lo + hi);
      (std::tan(mid) - slope * mid > 0 ? hi : lo) = mid;
    }
    out.push_back(0.5 * (lo + hi));
  }
  return out;
}

inline double series_pressure(double x, double t) {
  static const std::vector<double> alphas = roots();
  double sum = 0.0;
  for (double a : alphas)
    sum += std::sin(a) / (a - std::sin(a) * std::cos(a)) * (std::cos(a * x / kWidth) - std::cos(a)) *
           std::exp(-a * a * kDiffusivity * t / (kWidth * kWidth));
  return 2 * kP0 * sum;
}

}  // namespace hydrodda::testing::mandel
