#include "run/no_equilibrium.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>

#include "output/item_list.hpp"
#include "scenario/spellings.hpp"

namespace hydrodda::run {

std::vector<coupling::EscapingBlock> find_escaping_blocks(const dda::System& system) {
  std::vector<coupling::EscapingBlock> beyond;
  for (int b = 0; b < system.block_count(); ++b) {
    const geometry::Point u = system.displacement(b);
    const double distance = std::hypot(u.x, u.y);
    const double size = std::sqrt(std::abs(geometry::signed_area(system.polygon(b))));
    if (distance > size) beyond.push_back({b, distance, size});
  }
  std::stable_sort(beyond.begin(), beyond.end(),
                   [](const coupling::EscapingBlock& a, const coupling::EscapingBlock& b) { return a.distance > b.distance; });
  return beyond;
}

std::vector<EscapedBlock> locate_escaping_blocks(std::span<const coupling::EscapingBlock> escaping,
                                                 std::span<const geometry::Polygon> blocks) {
  std::vector<EscapedBlock> located;
  for (const coupling::EscapingBlock& b : escaping) {
    const bool known = b.block >= 0 && static_cast<std::size_t>(b.block) < blocks.size();
    located.push_back({b, known ? geometry::centroid(blocks[b.block]) : geometry::Point{}});
  }
  return located;
}

namespace {

// A load's value: a constant as it is, a table by the highest value it reaches, or by its value
// at `time` where given.
std::string describe_table(const numerics::TimeTable& table, std::optional<double> time, std::size_t column = 0) {
  if (table.is_constant()) return fmt::format("{:.4g}", table.value(0.0, column));
  if (time) return fmt::format("{:.4g}", table.value(*time, column));
  return fmt::format("up to {:.4g} (a table)", table.highest(column));
}

// A traction's value along its boundary: one value, or "a to b" where it varies.
std::string describe_along(const numerics::TimeTable& from, const numerics::TimeTable& to, std::optional<double> time) {
  const std::string a = describe_table(from, time), b = describe_table(to, time);
  return a == b ? a : a + " to " + b;
}


// A flow boundary's fixed value as the scenario writes it; a table by the highest value it reaches.
std::string describe_boundary(const scenario::FlowBoundaryCondition& b, std::optional<double> time) {
  const std::string value = describe_table(b.value, time);
  return b.kind == hydro::BoundaryKind::head ? fmt::format("\"{}\" head = {} m", b.name, value)
                                             : fmt::format("\"{}\" pressure = {} Pa", b.name, value);
}

// The fluid pressure's drive: the head and pressure boundaries, the highest pressure head
// (p/ρg, or h; a table's highest, or its value at `time`) first, the one that lifts, as one item.
std::vector<std::string> describe_flow_loads(const scenario::Scenario& s, std::optional<double> time) {
  std::vector<const scenario::FlowBoundaryCondition*> fixed;
  if (!s.flow) return {};
  for (const scenario::FlowBoundaryCondition& b : s.flow->boundaries)
    if (b.kind != hydro::BoundaryKind::flux) fixed.push_back(&b);
  const double rho_g = s.flow->fluid_density * 9.81;
  const auto height = [rho_g, time](const scenario::FlowBoundaryCondition* b) {
    const double value = time ? b->value.value(*time) : b->value.highest();
    return b->kind == hydro::BoundaryKind::head ? value : value / rho_g;
  };
  std::stable_sort(fixed.begin(), fixed.end(), [&](auto* a, auto* b) { return height(a) > height(b); });
  // The highest (all of them where several share it) drive; the rest are what they drive against.
  std::string driving, against;
  for (const scenario::FlowBoundaryCondition* b : fixed) {
    std::string& text = height(b) == height(fixed.front()) ? driving : against;
    text += (text.empty() ? "" : " and ") + describe_boundary(*b, time);
  }
  if (driving.empty()) return {};
  return {fmt::format("flow.boundary {}{}", driving, against.empty() ? "" : ", against " + against)};
}

}  // namespace

std::string describe_driving_load(const scenario::Scenario& s, std::optional<double> time) {
  std::vector<std::string> loads = describe_flow_loads(s, time);
  if (s.mechanics) {
    for (const scenario::Traction& t : s.mechanics->tractions)
      loads.push_back(fmt::format("mechanics.traction \"{}\" normal = {} Pa, shear = {} Pa", t.boundary,
                                  describe_along(t.normal, t.normal_end, time),
                                  describe_along(t.shear, t.shear_end, time)));
    for (const scenario::PointLoad& l : s.mechanics->loads)
      loads.push_back(fmt::format("mechanics.load at ({:.4g}, {:.4g}) force = [{}, {}] N/m", l.point.x, l.point.y,
                                  describe_table(l.force, time, 0), describe_table(l.force, time, 1)));
  }
  if (loads.empty()) return "gravity alone";
  std::string text;
  const std::size_t named = std::min<std::size_t>(loads.size(), 5);
  for (std::size_t i = 0; i < named; ++i) text += (i == 0 ? "" : ", ") + loads[i];
  if (loads.size() > named) text += fmt::format(" and {} more", loads.size() - named);
  return text;
}

output::LastHeldSummary summarise_held_state(const HeldState& held) {
  output::LastHeldSummary summary{held.name, held.step, std::nullopt, held.broken_bonds};
  if (held.fractures_known) summary.open_fractures = held.open_fractures;
  return summary;
}

void take_open_fractures(const fractures::FractureState& state, HeldState& held) {
  held.open_fractures.clear();
  held.fractures_known = !state.fractures.empty();
  for (const fractures::FractureResult& r : state.fractures)
    if (r.open) held.open_fractures.push_back(r.id);
}

namespace {

// "fractures 2, 5 were open and 14 bonds had broken", what the last state that held knew of.
std::string describe_held_fractures(const HeldState& held) {
  std::vector<std::string> parts;
  if (held.fractures_known) {
    std::vector<std::string> ids;
    for (int f : held.open_fractures) ids.push_back(std::to_string(f));
    parts.push_back(ids.empty() ? "no fracture was open"
                                : fmt::format("fracture{} {} {} open", ids.size() == 1 ? "" : "s",
                                              output::list_items(ids, nullptr, ""), ids.size() == 1 ? "was" : "were"));
  }
  if (held.broken_bonds) {
    const int n = *held.broken_bonds;
    const int later = held.broken_bonds_later;
    std::string bonds;
    if (n == 0)
      bonds = later == 0 ? "no bond had broken"
                         : fmt::format("no bond had broken ({} broke after it: fractures.csv's bond rows)", later);
    else
      bonds = fmt::format("{} bond{} had broken (fractures.csv's bond rows to then{})", n, n == 1 ? "" : "s",
                          later == 0 ? "" : fmt::format("; {} more after it", later));
    parts.push_back(bonds);
  }
  if (parts.empty()) return "";
  return fmt::format("; in the last state that held ({}) {}", held.name, fmt::join(parts, " and "));
}

}  // namespace

std::string describe_no_equilibrium(const scenario::Scenario& s, std::span<const EscapedBlock> blocks,
                                    const HeldState& held, const std::string& kept, const output::RunFolder* folder,
                                    std::optional<double> load_time) {
  std::vector<std::string> named;
  for (const EscapedBlock& b : blocks)
    named.push_back(fmt::format("block {} at ({:.4g}, {:.4g}) (moved {:.3g} m, size {:.3g} m)", b.escape.block,
                                b.centroid.x, b.centroid.y, b.escape.distance, b.escape.size));
  return fmt::format(
      "no mechanical equilibrium under {}{}: {} block(s) moved farther than their own size (the square root of their "
      "area) and the load still moves them: {}{}; the load exceeds what the blocks' weight, their contacts and the "
      "supports can hold (summary.json, history.csv and the figures are of {})",
      describe_driving_load(s, load_time), load_time ? fmt::format(" (the loads at t = {:g} s)", *load_time) : "",
      blocks.size(), output::list_items(named, folder, "escaping_blocks.txt"),
      describe_held_fractures(held), kept);
}

}  // namespace hydrodda::run
