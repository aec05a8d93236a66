// Terzaghi's consolidation of scenarios/verification/terzaghi_consolidation.toml by its series
// (Verruijt, Theory and Problems of Poroelasticity, ch. 2; Wang 2000, §6.2): a 10 m column
// between rollers, drained at its top, loaded by σ = 1 MPa at t = 0; E = 1 GPa, ν = 0.25, α = 1,
// S = 1e-10 1/Pa, k = 1e-15 m², μ = 1e-3 Pa·s. With K_v = E(1 − ν)/((1 + ν)(1 − 2ν)) the
// constrained modulus in plane strain, c_v = k/(μ (S + α²/K_v)), T = c_v t/H², z the depth:
//   p(z, t) = p0 Σ_m (2/M) sin(M z/H) exp(−M² T),   M = (2m + 1)π/2,  p0 = α σ/(α² + S K_v),
//   s(t) = s0 + (s∞ − s0) [1 − Σ_m (2/M²) exp(−M² T)],  s0 = (σ − α p0) H/K_v,  s∞ = σ H/K_v.
#pragma once

#include <cmath>
#include <numbers>

namespace hydrodda::testing::terzaghi {

constexpr double kLoad = 1.0e6, kHeight = 10.0, kStorage = 1.0e-10;
constexpr double kConstrained = 1.0e9 * 0.75 / (1.25 * 0.5);                 // K_v (Pa)
constexpr double kCv = 1.0e-15 / 1.0e-3 / (kStorage + 1.0 / kConstrained);  // m²/s
constexpr double kP0 = kLoad / (1.0 + kStorage * kConstrained);
constexpr double kS0 = (kLoad - kP0) * kHeight / kConstrained, kSinf = kLoad * kHeight / kConstrained;

// Σ_m f(M) exp(−M² T) over the first 400 terms (M = (2m + 1)π/2).
template <class Term>
double series(double t, Term term) {
  double sum = 0.0;
  for (int m = 0; m < 400; ++m) {
    const double big_m = (2 * m + 1) * std::numbers::pi / 2;
    sum += term(big_m) * std::exp(-big_m * big_m * kCv * t / (kHeight * kHeight));
  }
  return sum;
}

inline double series_pressure(double depth, double t) {
  return kP0 * series(t, [depth](double big_m) { return 2 / big_m * std::sin(big_m * depth / kHeight); });
}

inline double series_settlement(double t) {
  return kS0 + (kSinf - kS0) * (1 - series(t, [](double big_m) { return 2 / (big_m * big_m); }));
}

}  // namespace hydrodda::testing::terzaghi
