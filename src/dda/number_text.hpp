#pragma once
// A number as the DDA's messages print it: three significant digits (printf's %.3g).

#include <cstdio>
#include <string>

namespace hydrodda::dda {

inline std::string format_number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", v);
  return text;
}

}  // namespace hydrodda::dda
