// What the figures compute without drawing (contour crossings, the palettes), kept in the
// library: the drawing itself is in the figures plugin (figures_loader.cpp).
#include "output/field_figure.hpp"
#include "output/preview_figure.hpp"

#include <iterator>

namespace hydrodda::output {

using geometry::Point;

std::vector<Point> contour_segment(const std::array<Point, 3>& p, const std::array<double, 3>& v, double level) {
  std::vector<Point> out;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    const double a = v[i] - level, b = v[j] - level;
    if ((a < 0.0 && b >= 0.0) || (a >= 0.0 && b < 0.0)) {
      const double t = a / (a - b);
      out.push_back(p[i] + t * (p[j] - p[i]));
    }
  }
  if (out.size() != 2) out.clear();
  return out;
}

Rgb material_colour(int index) {
  static constexpr Rgb kPalette[] = {{0.65, 0.81, 0.89}, {0.99, 0.75, 0.44}, {0.70, 0.87, 0.54}, {0.98, 0.60, 0.60},
                                     {0.79, 0.70, 0.84}, {0.99, 0.93, 0.55}, {0.80, 0.80, 0.80}, {0.55, 0.83, 0.78}};
  return kPalette[static_cast<std::size_t>(index) % std::size(kPalette)];
}

Rgb joint_type_colour(int index) {
  static constexpr Rgb kPalette[] = {{0.80, 0.10, 0.10}, {0.10, 0.55, 0.10}, {0.45, 0.20, 0.65},
                                     {0.55, 0.34, 0.10}, {0.90, 0.45, 0.00}, {0.10, 0.10, 0.10}};
  return kPalette[static_cast<std::size_t>(index) % std::size(kPalette)];
}

}  // namespace hydrodda::output
