#include "scenario/rollers_and_initial_stress.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "hydro/fluid.hpp"
#include "scenario/bounds.hpp"
#include "scenario/validation.hpp"

namespace hydrodda::scenario {

namespace {

// Three numbers [σxx, σyy, τxy] (or their gradients) at `key`, or empty with an error.
std::optional<std::array<double, 3>> read_tensor(ReadContext& ctx, const TableView& t, std::string_view key) {
  const toml::node* node = t.node(key);
  if (!node) return std::nullopt;
  const toml::array* a = node->as_array();
  std::array<double, 3> out{};
  bool valid = a && a->size() == 3;
  for (std::size_t i = 0; valid && i < 3; ++i) {
    const auto v = (*a)[i].value<double>();
    valid = v && std::isfinite(*v);
    if (valid) out[i] = *v;
  }
  if (!valid) {
    ctx.error(line_of(*node), t.key_path(key), "expected three numbers [xx, yy, xy]");
    return std::nullopt;
  }
  return out;
}

// The range of the heads the flow's boundaries fix, m; empty when it is not bounded (a flux
// through a boundary raises or lowers the heads inside beyond any fixed one) or not known (a
// pressure on a mesh file's curve, whose height is not known before the mesh is read).
std::optional<double> find_boundary_head_range(const Scenario& s) {
  const FlowDefinition& flow = *s.flow;
  hydro::Fluid fluid;
  fluid.density = flow.fluid_density;
  double lowest = std::numeric_limits<double>::infinity(), highest = -lowest;
  for (const FlowBoundaryCondition& bc : flow.boundaries)
    if (bc.kind == hydro::BoundaryKind::head)
      lowest = std::min(lowest, bc.value.lowest()), highest = std::max(highest, bc.value.highest());
  // Over all time: a table's values span its rows' (a range no smaller than at any one time).
  const double reference = std::isfinite(lowest) ? lowest : 0.0;  // the overpressure's h_ref
  for (const FlowBoundaryCondition& bc : flow.boundaries) {
    if (bc.kind == hydro::BoundaryKind::flux && (bc.value.lowest() != 0.0 || bc.value.highest() != 0.0)) return std::nullopt;
    if (bc.kind != hydro::BoundaryKind::pressure) continue;
    for (const double pressure_head : {bc.value.lowest() / fluid.unit_weight(), bc.value.highest() / fluid.unit_weight()}) {
      if (flow.pressure == hydro::PressureConvention::overpressure) {
        lowest = std::min(lowest, pressure_head + reference), highest = std::max(highest, pressure_head + reference);
        continue;
      }
      const BoundarySegment* segment = s.find_boundary(bc.name);
      if (!segment) return std::nullopt;
      for (double y : {segment->segment.from.y, segment->segment.to.y})
        lowest = std::min(lowest, pressure_head + y), highest = std::max(highest, pressure_head + y);
    }
  }
  return std::isfinite(lowest) ? highest - lowest : 0.0;
}

// The least mean dh/dy over the domain that heads within `head_range` can make: its integral
// is the outline's ∮ h n_y ds, at least −head_range times the length of the outline that faces
// down, projected on x (a counter-clockwise edge a→b faces down where b.x > a.x).
double find_least_mean_head_gradient(const Polygon& domain, double head_range) {
  double facing_down = 0.0;
  for (std::size_t i = 0; i < domain.size(); ++i)
    facing_down += std::max(0.0, domain[(i + 1) % domain.size()].x - domain[i].x);
  return -head_range * facing_down / geometry::signed_area(domain);
}

}  // namespace

void check_initial_stress_gradient(ReadContext& ctx, const Scenario& s) {
  if (!s.mechanics || !s.mechanics->initial_stress || s.materials.empty()) return;
  const double g = -s.mechanics->gravity.y;  // gravity pointing down: > 0
  if (!(g > 0.0)) return;
  const bool coupled = s.flow.has_value();
  const bool hydrostatic = coupled && s.flow->pressure == hydro::PressureConvention::hydrostatic;
  hydro::Fluid fluid;
  if (coupled) fluid.density = s.flow->fluid_density;
  // The lightest rock and the largest Biot coefficient: the least gradient any block may need.
  double weight = std::numeric_limits<double>::infinity(), biot = 0.0;
  for (const MaterialDefinition& m : s.materials) {
    if (!m.density) return;  // refused for it already
    weight = std::min(weight, (*m.density - (hydrostatic ? m.biot_coefficient * fluid.density : 0.0)) * g);
    biot = std::max(biot, m.biot_coefficient);
  }
  // The blocks carry the effective stress σ' = σ + α p: dσ'yy/dy = (ρ_r − α ρ_w) g + α ρ_w g dh/dy
  // (ρ_r g + α ρ_w g dh/dy in the overpressure convention, whose density is the buoyant one). An
  // upward seepage lowers it, and may turn it negative (scenarios/examples/jointed_seal.toml).
  double least = weight;
  if (coupled) {
    const std::optional<double> head_range = find_boundary_head_range(s);
    if (!head_range || !s.geometry || s.geometry->domain.size() < 3) return;
    least += biot * fluid.unit_weight() * find_least_mean_head_gradient(s.geometry->domain, *head_range);
  }
  const double allowed = std::min(0.0, least) - 0.01 * std::abs(weight);  // 1%: rounded input
  const double given = s.mechanics->initial_stress->gradient[1];
  if (given >= allowed) return;
  const std::string message =
      coupled ? fmt::format("dσyy/dy = {:g} Pa/m makes the stress less compressive downward than anything in the model "
                            "holds (compression is negative, the gradient per metre up): the rock's buoyant weight makes "
                            "it {:g} Pa/m, and the upward seepage the boundary heads can drive lowers that to no less than {:g} Pa/m",
                            given, weight, least)
              : fmt::format("dσyy/dy = {:g} Pa/m makes the stress less compressive downward: compression is negative "
                            "and the gradient per metre up, so under gravity pointing down it is >= 0 (the rock's "
                            "weight makes it {:g} Pa/m)", given, weight);
  ctx.error(s.mechanics->initial_stress->gradient_line, "mechanics.initial_stress.gradient", message);
}

void check_initial_stress_across_model(ReadContext& ctx, const Scenario& s) {
  if (!s.mechanics || !s.mechanics->initial_stress) return;
  const InitialStressDefinition& stress = *s.mechanics->initial_stress;
  const geometry::Box box = find_model_box(s);
  if (box.empty()) return;
  for (std::size_t i = 0; i < 3; ++i) {
    for (double y : {box.lo.y, box.hi.y}) {
      const double value = stress.stress[i] + stress.gradient[i] * (y - stress.reference_y);
      if (std::abs(stress.stress[i]) > kMaxStress || std::abs(value) <= kMaxStress) continue;  // the first: refused already
      ctx.error(stress.gradient_line, "mechanics.initial_stress.gradient",
                fmt::format("gives a stress of {:g} Pa at y = {:g} m in the model; each component must lie within "
                            "±{:g} Pa there: 10 GPa is beyond the strength of any rock", value, y, kMaxStress));
      return;
    }
  }
}

void read_rollers(ReadContext& ctx, const TableView& m, MechanicsDefinition& mech) {
  for (const toml::table* rt : m.tables("roller")) {
    const TableView r(ctx, *rt, "mechanics.roller", {"boundary"});
    RollerDefinition roller;
    roller.line = r.line();
    roller.boundary = r.string("boundary").value_or("");
    if (!r.has("boundary")) ctx.error(r.line(), "mechanics.roller.boundary", "required key is missing");
    mech.rollers.push_back(std::move(roller));
  }
}

void read_initial_stress(ReadContext& ctx, const TableView& m, MechanicsDefinition& mech) {
  const toml::table* table = m.table("initial_stress");
  if (!table) return;
  const TableView t(ctx, *table, "mechanics.initial_stress", {"stress", "reference_y", "gradient"});
  InitialStressDefinition stress;
  stress.line = t.line();
  if (auto s = read_tensor(ctx, t, "stress")) {
    stress.stress = *s;
    t.require("stress", std::all_of(s->begin(), s->end(), [](double v) { return std::abs(v) <= kMaxStress; }),
              fmt::format("each component must lie within ±{:g} Pa: 10 GPa is beyond the strength of any rock", kMaxStress));
  }
  else if (!t.has("stress")) ctx.error(t.line(), t.key_path("stress"), "required key is missing");
  stress.reference_y = t.number_or("reference_y", 0.0);
  stress.gradient_line = t.line_of_key("gradient");
  if (auto g = read_tensor(ctx, t, "gradient")) stress.gradient = *g;
  else if (!t.has("gradient")) ctx.defaults.push_back({t.key_path("gradient"), "[0, 0, 0]"});
  mech.initial_stress = stress;
}

}  // namespace hydrodda::scenario
