#include "output/plot_axes.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace hydrodda::output {

std::array<double, 3> viridis(double t) {
  // Viridis (van der Walt & Smith, matplotlib), sampled at 9 equally spaced stops; linear
  // interpolation between them is within 1/255 of the full table.
  static constexpr std::array<std::array<double, 3>, 9> stops{{{0.267004, 0.004874, 0.329415},
                                                                {0.282623, 0.140926, 0.457517},
                                                                {0.253935, 0.265254, 0.529983},
                                                                {0.206756, 0.371758, 0.553117},
                                                                {0.163625, 0.471133, 0.558148},
                                                                {0.127568, 0.566949, 0.550556},
                                                                {0.134692, 0.658636, 0.517649},
                                                                {0.266941, 0.748751, 0.440573},
                                                                {0.993248, 0.906157, 0.143936}}};
  t = std::clamp(std::isfinite(t) ? t : 0.0, 0.0, 1.0);
  const double x = t * (stops.size() - 1);
  const std::size_t i = std::min<std::size_t>(static_cast<std::size_t>(x), stops.size() - 2);
  const double f = x - i;
  return {stops[i][0] + f * (stops[i + 1][0] - stops[i][0]), stops[i][1] + f * (stops[i + 1][1] - stops[i][1]),
          stops[i][2] + f * (stops[i + 1][2] - stops[i][2])};
}

double nice_step(double lo, double hi, int count) {
  const double raw = (hi - lo) / std::max(1, count);
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0})
    if (m * magnitude >= raw * (1.0 - 1e-12)) return m * magnitude;
  return 10.0 * magnitude;
}

std::vector<double> nice_ticks(double lo, double hi, int count) {
  if (!(hi > lo)) return {lo};
  const double step = nice_step(lo, hi, count);
  // Values as k * step, not by accumulation, so 0 is exactly 0 and no error builds up.
  std::vector<double> ticks;
  const double first = std::ceil(lo / step - 1e-9), last = std::floor(hi / step + 1e-9);
  for (double k = first; k <= last; k += 1.0) ticks.push_back(k == 0.0 ? 0.0 : k * step);
  return ticks;
}

std::vector<double> whole_number_ticks(double lo, double hi, int count) {
  const double first = std::ceil(lo - 1e-9), last = std::floor(hi + 1e-9);
  if (!(last >= first)) return {};
  const double step = std::max(1.0, nice_step(lo, hi, count));
  std::vector<double> ticks;
  for (double k = std::ceil(first / step); k * step <= last; k += 1.0) ticks.push_back(k * step);
  return ticks;
}

std::vector<double> log_ticks(double lo, double hi) {
  if (!(lo > 0.0) || !(hi > lo)) return {};
  const int first = static_cast<int>(std::ceil(std::log10(lo) - 1e-9));
  const int last = static_cast<int>(std::floor(std::log10(hi) + 1e-9));
  std::vector<double> ticks;
  if (last - first < 1) {
    // Less than a decade between two powers of ten: 1, 2 and 5 times them; a range too short
    // to hold two of those (5.5 to 9.9) gets the linear nice ticks inside it.
    for (int e = first - 1; e <= last; ++e)
      for (double m : {1.0, 2.0, 5.0})
        if (const double v = m * std::pow(10.0, e); v >= lo * (1 - 1e-9) && v <= hi * (1 + 1e-9)) ticks.push_back(v);
    if (ticks.size() < 2) ticks = nice_ticks(lo, hi, 5);
    return ticks;
  }
  const int stride = std::max(1, (last - first + 8) / 8);
  for (int e = first; e <= last; e += stride) ticks.push_back(std::pow(10.0, e));
  return ticks;
}

std::string format_tick(double value, double step) {
  const int decimals = std::max(0, -static_cast<int>(std::floor(std::log10(step) + 1e-9)));
  const double magnitude = std::max(std::abs(value), step);
  if (magnitude >= 1e5 || magnitude < 1e-3) return fmt::format("{:g}", value);
  return fmt::format("{:.{}f}", std::abs(value) < 1e-12 * step ? 0.0 : value, decimals);
}

std::vector<std::string> log_tick_labels(const std::vector<double>& ticks) {
  // Evenly spaced ticks are the linear ones of a range under a decade (log_ticks' fallback):
  // labelled by their step. The 1, 2, 5 ticks of wider ranges keep their shortest form.
  bool even = ticks.size() >= 2;
  for (std::size_t i = 2; even && i < ticks.size(); ++i)
    even = std::abs((ticks[i] - ticks[i - 1]) - (ticks[1] - ticks[0])) <= 1e-9 * (ticks[1] - ticks[0]);
  std::vector<std::string> labels;
  for (double v : ticks) {
    const double e = std::round(std::log10(v));
    if (std::abs(v - std::pow(10.0, e)) < 1e-9 * v)
      labels.emplace_back();
    else
      labels.push_back(even ? format_tick(v, ticks[1] - ticks[0]) : fmt::format("{:g}", v));
  }
  return labels;
}

bool is_flat_range(double lo, double hi) {
  return std::abs(hi - lo) <= kFlatSpread * std::max(std::abs(lo), std::abs(hi));
}

std::array<double, 2> one_value_range(double value, bool log_axis) {
  const double half = log_axis ? 0.5 : value == 0.0 ? 1.0 : 0.1 * std::abs(value);
  return {value - half, value + half};
}

std::array<double, 2> padded_range(double lo, double hi, bool log_axis, bool at_least_zero) {
  if (log_axis) {
    double a = std::log10(lo), b = std::log10(hi);
    if (is_flat_range(lo, hi)) {  // one value: a decade about it, not its round-off magnified
      const std::array<double, 2> unit = one_value_range(a, true);
      a = unit[0];
      b = unit[1];
    }
    const double pad = 0.04 * (b - a);
    return {std::pow(10.0, a - pad), std::pow(10.0, b + pad)};
  }
  const bool nonnegative = at_least_zero && lo >= 0.0;
  if (hi - lo <= 1e-12 * std::max(std::abs(lo), std::abs(hi))) {
    const std::array<double, 2> unit = one_value_range(lo, false);
    lo = unit[0];
    hi = unit[1];
  }
  const double pad = 0.04 * (hi - lo);
  std::array<double, 2> range{lo - pad, hi + pad};
  if (nonnegative) range[0] = std::max(range[0], -0.04 * range[1]);
  return range;
}

}  // namespace hydrodda::output
