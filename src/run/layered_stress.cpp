#include "run/layered_stress.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "hydro/fluid.hpp"

namespace hydrodda::run {

namespace {

using geometry::Point;
using geometry::Polygon;

// The heights at which the vertical x crosses the polygon's edges, increasing. An edge counts
// when its ends lie on either side of x by the half-open rule (a.x <= x) != (b.x <= x), so a
// vertex on the line counts once and an edge along it never: the column at x behaves as the one
// just right of it, and a column along the domain's left side still sees the domain.
std::vector<double> find_crossing_heights(const Polygon& polygon, double x) {
  std::vector<double> heights;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Point a = polygon[i], b = polygon[(i + 1) % polygon.size()];
    if ((a.x <= x) == (b.x <= x)) continue;
    heights.push_back(a.y + (x - a.x) / (b.x - a.x) * (b.y - a.y));
  }
  std::sort(heights.begin(), heights.end());
  return heights;
}

// Inside by parity: an odd number of crossings above y.
bool is_inside(const std::vector<double>& heights, double y) {
  const auto above = heights.end() - std::upper_bound(heights.begin(), heights.end(), y);
  return above % 2 == 1;
}

}  // namespace

std::vector<double> find_carried_densities(const scenario::Scenario& s) {
  const bool hydrostatic = s.flow && s.flow->pressure == hydro::PressureConvention::hydrostatic;
  std::vector<double> densities;
  for (const scenario::MaterialDefinition& m : s.materials)
    densities.push_back(m.density.value_or(0.0) - (hydrostatic ? m.biot_coefficient * s.flow->fluid_density : 0.0));
  return densities;
}

std::vector<ColumnPiece> find_density_column(const scenario::Scenario& s, double x, const std::vector<double>& densities) {
  const std::vector<double> domain = find_crossing_heights(s.geometry->domain, x);
  if (domain.size() < 2) return {};
  std::vector<std::vector<double>> regions;
  std::vector<double> cuts = domain;
  for (const scenario::MaterialDefinition& m : s.materials) {
    regions.push_back(find_crossing_heights(m.region, x));
    for (double y : regions.back())
      if (y > domain.front() && y < domain.back()) cuts.push_back(y);
  }
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  int rest = -1;  // the material without a region
  for (std::size_t i = 0; i < s.materials.size() && rest < 0; ++i)
    if (s.materials[i].region.empty()) rest = static_cast<int>(i);
  std::vector<ColumnPiece> column;
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    const double middle = 0.5 * (cuts[k] + cuts[k + 1]);
    int material = -1;
    if (is_inside(domain, middle)) {
      material = rest;
      for (std::size_t i = 0; i < regions.size(); ++i)
        if (!s.materials[i].region.empty() && is_inside(regions[i], middle)) { material = static_cast<int>(i); break; }
    }
    column.push_back({cuts[k], cuts[k + 1], material >= 0 ? densities[material] : 0.0});
  }
  return column;
}

namespace {

// ∫ from the column's bottom to y of the density, beyond its ends along the end pieces'.
double integrate_density(const std::vector<ColumnPiece>& column, double y) {
  double sum = 0.0;
  if (y < column.front().bottom) return (y - column.front().bottom) * column.front().density;
  for (const ColumnPiece& p : column) {
    sum += (std::min(y, p.top) - p.bottom) * p.density;
    if (y <= p.top) return sum;
  }
  return sum + (y - column.back().top) * column.back().density;
}

dda::StressField build_layered_stress(const scenario::Scenario& s) {
  const scenario::InitialStressDefinition& given = *s.mechanics->initial_stress;
  geometry::Box box;
  for (Point p : s.geometry->domain) box.add(p);
  const double x = given.column_x.value_or(0.5 * (box.lo.x + box.hi.x));
  const std::vector<ColumnPiece> column = find_density_column(s, x, find_carried_densities(s));
  if (column.empty()) throw std::logic_error("layered stress: the column misses the domain");
  std::vector<double> heights{given.reference_y};
  for (const ColumnPiece& p : column) heights.insert(heights.end(), {p.bottom, p.top});
  std::sort(heights.begin(), heights.end());
  const double tolerance = 1e-12 * std::max(box.width(), box.height());
  heights.erase(std::unique(heights.begin(), heights.end(), [&](double a, double b) { return b - a <= tolerance; }),
                heights.end());
  const Point g = s.mechanics->gravity;
  const double weight_at_reference = integrate_density(column, given.reference_y);
  dda::StressField field;
  field.at_reference = given.stress;
  field.reference_y = given.reference_y;
  for (double y : heights) {
    const double weight = integrate_density(column, y) - weight_at_reference;  // ∫_{y_ref}^{y} ρ' dη
    const double syy = given.stress[1] - g.y * weight;
    field.knots.push_back({y, {given.stress[0] + given.horizontal_ratio * (syy - given.stress[1]), syy,
                               given.stress[2] - g.x * weight}});
  }
  return field;
}

}  // namespace

dda::StressField build_initial_stress(const scenario::Scenario& s) {
  const scenario::InitialStressDefinition& i = *s.mechanics->initial_stress;
  if (!i.layers) return dda::StressField{i.stress, i.reference_y, i.gradient, {}};
  return build_layered_stress(s);
}

}  // namespace hydrodda::run
