#include "run/in_situ_check.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "run/layered_stress.hpp"
#include "scenario/scenario_queries.hpp"

namespace hydrodda::run {

namespace {

using geometry::Point;

// What the boundaries put on the top point p: the normal stress of a traction along it, 0 for
// a free top, none where a roller or displacement holds it (unknown before the run).
std::optional<double> find_top_stress(const scenario::Scenario& s, Point p, double tolerance) {
  const scenario::MechanicsDefinition& m = *s.mechanics;
  const auto on = [&](const std::string& name) {
    const scenario::BoundarySegment* b = s.find_boundary(name);
    return b && geometry::distance_to_segment(p, b->segment.from, b->segment.to) <= tolerance ? b : nullptr;
  };
  for (const scenario::RollerDefinition& r : m.rollers)
    if (on(r.boundary)) return std::nullopt;
  for (const scenario::PrescribedDisplacement& d : m.displacements)
    if (!d.point && on(d.boundary)) return std::nullopt;
  for (const scenario::Traction& t : m.tractions) {
    const scenario::BoundarySegment* b = on(t.boundary);
    if (!b) continue;
    const Point along = b->segment.to - b->segment.from;
    const double f = std::clamp(dot(p - b->segment.from, along) / dot(along, along), 0.0, 1.0);
    // The traction the model starts under (time 0 of a table).
    const double from = t.normal.value(0.0), to = t.normal_end.value(0.0);
    return from + f * (to - from);
  }
  return 0.0;
}

// ∫ from y to the column's top of the density.
double weight_above(const std::vector<ColumnPiece>& column, double y) {
  double sum = 0.0;
  for (const ColumnPiece& p : column)
    if (p.top > y) sum += (p.top - std::max(p.bottom, y)) * p.density;
  return sum;
}

// How far a steady seepage may move the effective σyy off the still-water weight, Pa: a coupled
// run's blocks carry σ + α p, and the seepage force α ∇p the boundary heads drive adds at most
// α ρ_w g Δh to it anywhere (Δh the heads' range: the head falls by no more down any column).
// 0 without flow; empty where the heads are not bounded (nothing then to compare against).
std::optional<double> find_seepage_allowance(const scenario::Scenario& s) {
  if (!s.flow) return 0.0;
  const std::optional<double> range = scenario::find_boundary_head_range(s);
  if (!range) return std::nullopt;
  double biot = 0.0;
  for (const scenario::MaterialDefinition& m : s.materials) biot = std::max(biot, m.biot_coefficient);
  return biot * s.flow->fluid_density * std::abs(s.mechanics->gravity.y) * *range;
}

// The heads the pore pressure at the top point p may stand at, m, as the least and the largest:
// the head of a boundary through p that fixes one (at time 0, as the model starts), else the
// bounds of the boundaries' heads (a steady head lies within them); empty where none fixes one.
std::optional<std::pair<double, double>> find_top_heads(const scenario::Scenario& s, Point p, double tolerance) {
  double lowest = std::numeric_limits<double>::infinity(), highest = -lowest;
  for (const scenario::FlowBoundaryCondition& bc : s.flow->boundaries) {
    if (bc.kind != hydro::BoundaryKind::head) continue;
    const scenario::BoundarySegment* b = s.find_boundary(bc.name);
    if (b && geometry::distance_to_segment(p, b->segment.from, b->segment.to) <= tolerance)
      return std::pair{bc.value.value(0.0), bc.value.value(0.0)};
    lowest = std::min(lowest, bc.value.lowest()), highest = std::max(highest, bc.value.highest());
  }
  if (!std::isfinite(lowest)) return std::nullopt;
  return std::pair{lowest, highest};
}

// The fluid's share of the top's stress at the top point p, Pa, compression negative, as the
// least and the most compressive it may be: under hydrostatic pore pressure the top's face takes
// (1 − α) p_top from the fluid beside the traction (docs/coupling.md, "Fluid pressure on the
// blocks"), which the blocks' σ + α p carries below it (α that of the material at the top),
// p_top = ρ_w g (h − y_top). Zero under the overpressure convention (still water has none),
// at α = 1, or where no boundary fixes a head.
std::pair<double, double> find_top_fluid_share(const scenario::Scenario& s, Point p, double tolerance) {
  if (!s.flow || s.flow->pressure != hydro::PressureConvention::hydrostatic) return {0.0, 0.0};
  const int material = scenario::find_material_at(s, {p.x, p.y - tolerance});
  const double share = material >= 0 ? 1.0 - s.materials[material].biot_coefficient : 0.0;
  const std::optional<std::pair<double, double>> heads = find_top_heads(s, p, tolerance);
  if (share == 0.0 || !heads) return {0.0, 0.0};
  const double unit_weight = s.flow->fluid_density * std::abs(s.mechanics->gravity.y);
  return {-share * unit_weight * (heads->first - p.y), -share * unit_weight * (heads->second - p.y)};
}

}  // namespace

std::vector<InSituComparison> compare_in_situ_stress(const scenario::Scenario& s,
                                                      const std::vector<dda::BlockDefinition>& blocks,
                                                      const dda::StressField& field) {
  std::vector<InSituComparison> out;
  if (!s.geometry || s.geometry->domain.size() < 3 || !s.mechanics || !s.mechanics->initial_stress) return out;
  const double g_y = s.mechanics->gravity.y;
  const geometry::Box box = geometry::bounding_box(s.geometry->domain);
  const double tolerance = 1e-9 * std::max(box.width(), box.height());
  const std::vector<double> densities = find_carried_densities(s);
  const std::optional<double> seepage = find_seepage_allowance(s);
  if (!seepage) return out;
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    const Point c = geometry::centroid(blocks[b].polygon);
    const std::vector<ColumnPiece> column = find_density_column(s, c.x, densities);
    if (column.empty()) continue;
    const std::optional<double> top = find_top_stress(s, {c.x, column.back().top}, tolerance);
    if (!top) continue;
    const Point top_point{c.x, column.back().top};
    const auto [fluid_least, fluid_most] = find_top_fluid_share(s, top_point, tolerance);
    const double weight = *top + g_y * weight_above(column, c.y);
    // The expected σyy lies between the fluid's least and most; compared with the nearer.
    const double initial = field.at(c.y)[1];
    const double expected = std::clamp(initial, weight + std::min(fluid_least, fluid_most), weight + std::max(fluid_least, fluid_most));
    const double difference = std::max(0.0, std::abs(initial - expected) - *seepage);
    if (difference > kInSituTolerance * std::abs(expected) && difference > 1.0)
      out.push_back({static_cast<int>(b), c, initial, expected});
  }
  return out;
}

std::optional<std::string> describe_in_situ_mismatch(const scenario::Scenario& s,
                                                     const std::vector<InSituComparison>& mismatches) {
  if (mismatches.empty()) return std::nullopt;
  std::vector<InSituComparison> worst = mismatches;
  const auto off = [](const InSituComparison& m) { return std::abs(m.initial - m.expected) / std::max(std::abs(m.expected), 1.0); };
  std::stable_sort(worst.begin(), worst.end(), [&](const auto& a, const auto& b) { return off(a) > off(b); });
  std::string named;
  for (std::size_t i = 0; i < std::min<std::size_t>(worst.size(), 3); ++i)
    named += fmt::format("{}block {} at ({:.4g}, {:.4g}): σyy = {:.4g} Pa against {:.4g} Pa", i ? "; " : "", worst[i].block,
                         worst[i].centroid.x, worst[i].centroid.y, worst[i].initial, worst[i].expected);
  const scenario::InitialStressDefinition& i = *s.mechanics->initial_stress;
  return fmt::format(
      "{}:{}: mechanics.initial_stress: the initial σyy of {} block(s) differs by more than {:g}% from the weight "
      "of the layers above (each material's density{}) plus the [[mechanics.traction]] on the top: {}. The blocks "
      "start out of equilibrium and move at the first step; check mechanics.initial_stress's stress, reference_y and "
      "{}, the materials' densities and the top's traction",
      s.file.string(), i.line, mismatches.size(), 100.0 * kInSituTolerance,
      s.flow && s.flow->pressure == hydro::PressureConvention::hydrostatic ? ", less α ρ_w under hydrostatic pore pressure" : "",
      named, i.layers ? "vertical (column_x)" : "gradient");
}

}  // namespace hydrodda::run
