#include "geometry/trace_crossings.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace hydrodda::geometry {

double estimate_crossings(std::span<const Segment2> traces, const Box& region) {
  const double area = region.width() * region.height();
  if (!(area > 0.0)) return 0.0;
  constexpr int kBins = 180;
  std::array<double, kBins> length{};  // per 1° of direction in [0°, 180°)
  for (const Segment2& t : traces) {
    const Point d = t.to - t.from;
    double degrees = std::atan2(d.y, d.x) * 180.0 / std::numbers::pi;
    if (degrees < 0.0) degrees += 180.0;
    length[static_cast<std::size_t>(std::min(kBins - 1, static_cast<int>(degrees)))] += std::hypot(d.x, d.y);
  }
  double sum = 0.0;  // Σ over pairs of bins b < c: L_b L_c |sin(θ_c − θ_b)|
  for (int b = 0; b < kBins; ++b)
    for (int c = b + 1; c < kBins; ++c)
      sum += length[b] * length[c] * std::sin((c - b) * std::numbers::pi / kBins);
  return sum / area;
}

}  // namespace hydrodda::geometry
