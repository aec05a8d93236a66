#include "numerics/time_table.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <string>

namespace hydrodda::numerics {

TimeTable TimeTable::constant(std::span<const double> values) {
  if (values.empty()) throw std::invalid_argument("a constant needs at least one value");
  TimeTable table;
  table.values_.assign(values.begin(), values.end());
  table.columns_ = values.size();
  return table;
}

TimeTable::TimeTable(std::vector<double> times, std::vector<double> values, std::size_t columns)
    : times_(std::move(times)), values_(std::move(values)), columns_(columns) {
  if (columns_ == 0) throw std::invalid_argument("a time table needs at least one value column");
  if (times_.size() < 2) throw std::invalid_argument("a time table needs at least two rows (time, value)");
  if (values_.size() != times_.size() * columns_)
    throw std::invalid_argument("a time table needs " + std::to_string(columns_) + " value(s) in every row");
  for (std::size_t i = 0; i < times_.size(); ++i) {
    if (!std::isfinite(times_[i])) throw std::invalid_argument("a time table's times must be finite numbers");
    if (i > 0 && !(times_[i] > times_[i - 1]))
      throw std::invalid_argument("a time table's times must increase from row to row (row " + std::to_string(i + 1) +
                                  " is not later than row " + std::to_string(i) + ")");
  }
  for (double v : values_)
    if (!std::isfinite(v)) throw std::invalid_argument("a time table's values must be finite numbers");
}

double TimeTable::lowest(std::size_t column) const {
  double v = at(0, column);
  for (std::size_t row = 1; row < rows(); ++row) v = std::min(v, at(row, column));
  return v;
}

double TimeTable::highest(std::size_t column) const {
  double v = at(0, column);
  for (std::size_t row = 1; row < rows(); ++row) v = std::max(v, at(row, column));
  return v;
}

double TimeTable::value(double t, std::size_t column) const {
  if (t <= times_.front()) return at(0, column);
  if (t >= times_.back()) return at(times_.size() - 1, column);
  // The row whose interval holds t: times_[i] ≤ t < times_[i + 1].
  const std::size_t i = static_cast<std::size_t>(std::upper_bound(times_.begin(), times_.end(), t) - times_.begin()) - 1;
  const double s = (t - times_[i]) / (times_[i + 1] - times_[i]);
  return at(i, column) + s * (at(i + 1, column) - at(i, column));
}

TimeTable TimeTable::between(const TimeTable& a, const TimeTable& b, double s) {
  const auto mix = [s](double va, double vb) { return va + s * (vb - va); };
  if (a.is_constant() && b.is_constant()) return TimeTable(mix(a.at(0), b.at(0)));
  std::vector<double> times;
  std::set_union(a.times_.begin(), a.times_.end(), b.times_.begin(), b.times_.end(), std::back_inserter(times));
  // A constant's time 0 is no corner of the other's path.
  if (a.is_constant() != b.is_constant()) {
    const TimeTable& path = a.is_constant() ? b : a;
    times = path.times_;
  }
  std::vector<double> values;
  for (double t : times) values.push_back(mix(a.value(t), b.value(t)));
  return TimeTable(std::move(times), std::move(values));
}

}  // namespace hydrodda::numerics
