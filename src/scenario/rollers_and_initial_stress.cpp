#include "scenario/rollers_and_initial_stress.hpp"

#include <cmath>

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
  if (auto s = read_tensor(ctx, t, "stress")) stress.stress = *s;
  else if (!t.has("stress")) ctx.error(t.line(), t.key_path("stress"), "required key is missing");
  stress.reference_y = t.number_or("reference_y", 0.0);
  if (auto g = read_tensor(ctx, t, "gradient")) stress.gradient = *g;
  else if (!t.has("gradient")) ctx.defaults.push_back({t.key_path("gradient"), "[0, 0, 0]"});
  mech.initial_stress = stress;
}

}  // namespace hydrodda::scenario
