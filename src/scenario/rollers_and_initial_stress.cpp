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

}  // namespace

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

namespace {

// The least mean dh/dy over the domain that heads within `head_range` can make: its integral
// is the outline's ∮ h n_y ds, at least −head_range times the length of the outline that faces
// down, projected on x (a counter-clockwise edge a→b faces down where b.x > a.x).
double find_least_mean_head_gradient(const Polygon& domain, double head_range) {
  double facing_down = 0.0;
  for (std::size_t i = 0; i < domain.size(); ++i)
    facing_down += std::max(0.0, domain[(i + 1) % domain.size()].x - domain[i].x);
  return -head_range * facing_down / geometry::signed_area(domain);
}

// vertical = "layers" with its horizontal_ratio (required) and column_x; the two others only with it.
void read_vertical_profile(ReadContext& ctx, const TableView& t, InitialStressDefinition& stress) {
  stress.vertical_line = t.line_of_key("vertical");
  if (const std::optional<std::string> vertical = t.string("vertical")) {
    stress.layers = *vertical == "layers";
    t.require("vertical", stress.layers,
              fmt::format("unknown value \"{}\": \"layers\" (dσyy/dy from each layer's density) is the one choice; "
                          "leave `vertical` out to give `gradient`", *vertical));
  }
  if (!stress.layers) {
    for (const char* key : {"horizontal_ratio", "column_x"})
      if (t.has(key)) ctx.error(t.line_of_key(key), t.key_path(key), "applies with vertical = \"layers\" only");
    return;
  }
  if (auto k0 = t.number("horizontal_ratio")) {
    stress.horizontal_ratio = *k0;
    t.require("horizontal_ratio", *k0 >= 0.0 && *k0 <= 10.0,
              "must lie in [0, 10]: σxx's increase over σyy's down through the layers (K0)");
  } else if (!t.has("horizontal_ratio")) {
    ctx.error(t.line(), t.key_path("horizontal_ratio"),
              "required with vertical = \"layers\": K0, the ratio of σxx's increase to σyy's with depth");
  }
  stress.column_x = t.number("column_x");
}

}  // namespace

void check_initial_stress_gradient(ReadContext& ctx, const Scenario& s) {
  if (!s.mechanics || !s.mechanics->initial_stress || s.materials.empty()) return;
  if (s.mechanics->initial_stress->layers) return;  // the layers' densities give it its sign
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
  if (s.mechanics->initial_stress->layers && !(s.geometry && s.geometry->domain.size() >= 3)) {
    ctx.error(s.mechanics->initial_stress->vertical_line, "mechanics.initial_stress.vertical",
              "\"layers\" reads the materials' layers down a vertical through geometry.domain: give a domain, or "
              "give `gradient` for blocks given one by one");
    return;
  }
  if (const auto x = s.mechanics->initial_stress->column_x) {
    const geometry::Box domain = geometry::bounding_box(s.geometry->domain);
    if (!(*x >= domain.lo.x && *x < domain.hi.x))
      ctx.error(s.mechanics->initial_stress->line, "mechanics.initial_stress.column_x",
                fmt::format("x = {:g} m misses geometry.domain, which spans x = {:g} to {:g} m", *x, domain.lo.x, domain.hi.x));
  }
  InitialStressDefinition stress = *s.mechanics->initial_stress;
  const geometry::Box box = find_model_box(s);
  if (box.empty()) return;
  if (stress.layers) {
    // The steepest the layers can make it: the densest material's weight all the way.
    double density = 0.0;
    for (const MaterialDefinition& m : s.materials) density = std::max(density, m.density.value_or(0.0));
    const Point g = s.mechanics->gravity;
    stress.gradient = {stress.horizontal_ratio * density * std::abs(g.y), density * std::abs(g.y), density * std::abs(g.x)};
  }
  for (std::size_t i = 0; i < 3; ++i) {
    for (double y : {box.lo.y, box.hi.y}) {
      const double value = stress.stress[i] + stress.gradient[i] * (y - stress.reference_y);
      if (std::abs(stress.stress[i]) > kMaxStress || std::abs(value) <= kMaxStress) continue;  // the first: refused already
      ctx.error(stress.layers ? stress.vertical_line : stress.gradient_line,
                stress.layers ? "mechanics.initial_stress.vertical" : "mechanics.initial_stress.gradient",
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
  const TableView t(ctx, *table, "mechanics.initial_stress",
                    {"stress", "reference_y", "gradient", "vertical", "horizontal_ratio", "column_x"});
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
  read_vertical_profile(ctx, t, stress);
  if (stress.layers) {
    if (t.has("gradient"))
      ctx.error(stress.gradient_line, t.key_path("gradient"),
                "vertical = \"layers\" integrates the gradient from each layer's density: leave `gradient` out, or "
                "leave `vertical` out to give the gradient yourself");
  } else if (auto g = read_tensor(ctx, t, "gradient")) {
    stress.gradient = *g;
  } else if (!t.has("gradient")) {
    ctx.defaults.push_back({t.key_path("gradient"), "[0, 0, 0]"});
  }
  mech.initial_stress = stress;
}

}  // namespace hydrodda::scenario
