#pragma once
// The two ends of a range as messages print them: to `digits` significant figures (printf's
// %g), or as many more, up to 9, as tell them apart. A range whose ends agree to the usual
// figures ("from 2.29e+05 to 2.29e+05 (0.031%)") reads as no range at all.

#include <array>
#include <cstdio>
#include <string>

namespace hydrodda::numerics {

inline std::array<std::string, 2> format_apart(double low, double high, int digits) {
  std::array<std::string, 2> text;
  for (int d = digits; d <= 9; ++d) {
    char a[40], b[40];
    std::snprintf(a, sizeof a, "%.*g", d, low);
    std::snprintf(b, sizeof b, "%.*g", d, high);
    text = {a, b};
    if (low == high || text[0] != text[1]) break;
  }
  return text;
}

}  // namespace hydrodda::numerics
