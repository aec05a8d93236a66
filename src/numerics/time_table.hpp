#pragma once
// A value that changes in time: rows (t, v₁ … v_k), linear between rows and held at the first
// and last row's values before and after them. A constant is a table of one row, equal to it
// at every time, so that a load that may be a table is always one and is read the same way:
//   value(t) = v_0                                   t ≤ t_0
//            = v_i + (t − t_i)/(t_{i+1} − t_i) (v_{i+1} − v_i)   t_i ≤ t ≤ t_{i+1}
//            = v_{n−1}                               t ≥ t_{n−1}
// A constant's value is its number exactly, so a run whose loads are all constants gives the
// same results, bit for bit, as one that read plain numbers.

#include <cstddef>
#include <span>
#include <stdexcept>
#include <vector>

namespace hydrodda::numerics {

class TimeTable {
 public:
  // A constant of one column (implicit: a number stands for a constant table).
  TimeTable(double constant = 0.0) : times_{0.0}, values_{constant}, columns_(1) {}  // NOLINT
  // A constant of as many columns as `values`.
  static TimeTable constant(std::span<const double> values);
  // Rows of (time, `columns` values), the values row by row; throws std::invalid_argument unless
  // there are at least two rows, the times strictly increase and every number is finite.
  TimeTable(std::vector<double> times, std::vector<double> values, std::size_t columns = 1);

  bool is_constant() const { return times_.size() == 1; }
  std::size_t columns() const { return columns_; }
  std::size_t rows() const { return times_.size(); }
  const std::vector<double>& times() const { return times_; }
  double time(std::size_t row) const { return times_[row]; }
  double at(std::size_t row, std::size_t column = 0) const { return values_[row * columns_ + column]; }
  // The last row's time (0 for a constant).
  double end_time() const { return times_.back(); }

  // The least and greatest value of a column over all time (at its rows: linear between them).
  double lowest(std::size_t column = 0) const;
  double highest(std::size_t column = 0) const;

  // Column `column` at time t: linear between rows, held beyond the ends.
  double value(double t, std::size_t column = 0) const;

  // a(t) + s (b(t) − a(t)), the point a fraction s of the way from a to b, as a table of one
  // column (column 0 of each) on the union of their times: exact, both being linear between
  // those times. Two constants give the constant a + s (b − a).
  static TimeTable between(const TimeTable& a, const TimeTable& b, double s);

  friend bool operator==(const TimeTable&, const TimeTable&) = default;

 private:
  std::vector<double> times_;
  std::vector<double> values_;  // row by row
  std::size_t columns_ = 1;
};

}  // namespace hydrodda::numerics
