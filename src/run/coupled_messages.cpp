#include "run/coupled_messages.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "numerics/distinct_digits.hpp"
#include "run/figures.hpp"

namespace hydrodda::run {

std::string describe_farthest(const std::vector<geometry::Point>& displacements) {
  std::vector<int> order(displacements.size());
  for (std::size_t b = 0; b < order.size(); ++b) order[b] = static_cast<int>(b);
  const auto distance = [&](int b) { return std::hypot(displacements[b].x, displacements[b].y); };
  const std::size_t named = std::min<std::size_t>(order.size(), 5);
  std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(named), order.end(),
                    [&](int a, int b) { return distance(a) > distance(b) || (distance(a) == distance(b) && a < b); });
  std::string text;
  for (std::size_t i = 0; i < named; ++i) {
    const int b = order[i];
    text += fmt::format("{}block {} moved {:.3g} m (ux {:.3g} m, uy {:.3g} m)", i == 0 ? "" : ", ", b, distance(b),
                        displacements[b].x, displacements[b].y);
  }
  return text;
}

namespace {

// Whether the block had bonds and has none left: a piece loose in its crack.
bool every_bond_broken(const dda::System& system, int block) {
  bool bonded = false;
  for (std::size_t e = 0; e < system.polygon(block).size(); ++e) {
    const int bond = system.bond_of_edge(block, static_cast<int>(e));
    if (bond < 0) continue;
    if (!system.is_bond_broken(bond)) return false;
    bonded = true;
  }
  return bonded;
}

}  // namespace

std::string describe_last_pass_movers(const coupling::StaggeredLoop::PassMotion& motion, const dda::System& system) {
  const std::size_t n = motion.after.size();
  if (motion.before.size() != n || n == 0) return "";
  std::vector<double> moved(n);
  for (std::size_t b = 0; b < n; ++b)
    moved[b] = std::hypot(motion.after[b].x - motion.before[b].x, motion.after[b].y - motion.before[b].y);
  std::vector<int> order(n);
  for (std::size_t b = 0; b < n; ++b) order[b] = static_cast<int>(b);
  const std::size_t ranked = std::min<std::size_t>(n, 4);
  std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(ranked), order.end(),
                    [&](int a, int b) { return moved[a] > moved[b] || (moved[a] == moved[b] && a < b); });
  // Named: the fewest leaders, up to three, the last of them more than twice as far as the next;
  // else the first alone, the rest not far behind.
  std::size_t named = 0;
  for (std::size_t k = 1; named == 0 && k < ranked; ++k)
    if (moved[order[k - 1]] > 2.0 * moved[order[k]]) named = k;
  const bool apart = named > 0;
  if (!apart) named = 1;
  std::string text = "in the last pass ";
  for (std::size_t i = 0; i < named; ++i) {
    const int b = order[i];
    const geometry::Point c = system.centroid(b);
    text += fmt::format("{}block {} ({:.3g} m²{}) at ({:.4g}, {:.4g}) moved {:.3g} m", i == 0 ? "" : ", ", b,
                        system.area(b), every_bond_broken(system, b) ? ", every bond broken" : "", c.x, c.y,
                        moved[b]);
  }
  if (named == n) return text;
  std::vector<geometry::Point> without = motion.after;
  for (std::size_t i = 0; i < named; ++i) without[order[i]] = motion.before[order[i]];
  text += fmt::format("; every other block at most {:.3g} m", moved[order[named]]);
  if (apart)
    text += fmt::format(", and without {} the displacement change would be {:.3g}",
                        named == 1 ? "it" : fmt::format("these {}", named),
                        coupling::displacement_change(without, motion.before, motion.reference_length));
  return text;
}

std::string describe_results_kept(int finished) {
  return finished > 0 ? fmt::format("summary.json and the figures hold coupling iteration {}, the last that finished",
                                    finished)
                      : "no coupling iteration finished: there are no results";
}

std::string describe_failure_for_figures(int pass, const std::string& message) {
  const std::string prefix = fmt::format("coupling iteration {} failed: ", pass);
  return describe_status_for_figures(fmt::format("failed at pass {}", pass),
                                     message.rfind(prefix, 0) == 0 ? message.substr(prefix.size()) : message);
}

std::string describe_last_passes(const std::vector<std::string>& columns,
                                 const std::vector<std::vector<std::string>>& rows, int ramp_passes,
                                 std::vector<output::RegionSummary>& regions) {
  const std::size_t loaded = rows.size() > static_cast<std::size_t>(ramp_passes) ? rows.size() - ramp_passes : 0;
  const std::size_t passes = std::min(kRangePasses, loaded);
  if (passes == 0) return {};
  std::string text;
  for (output::RegionSummary& r : regions) {
    const auto column = std::find(columns.begin(), columns.end(), "region_conductivity_" + r.name);
    if (column == columns.end() || !(r.matrix_conductivity.value_or(0.0) > 0.0)) continue;
    const auto at = static_cast<std::size_t>(column - columns.begin());
    output::RegionSummary::PassRange range{static_cast<int>(passes), std::numeric_limits<double>::infinity(),
                                           -std::numeric_limits<double>::infinity()};
    for (std::size_t k = rows.size() - passes; k < rows.size(); ++k) {
      if (at >= rows[k].size() || rows[k][at].empty()) continue;  // a region that held no element
      const double normalised = std::stod(rows[k][at]) / *r.matrix_conductivity;
      range.least = std::min(range.least, normalised);
      range.largest = std::max(range.largest, normalised);
    }
    if (!(range.least <= range.largest)) continue;  // no value in those passes
    r.last_passes = range;
    // A region whose answer did not move (its permeability fixed) is no news in the message.
    const double spread = (range.largest - range.least) / std::abs(*r.normalised_conductivity);
    if (!(spread > 1e-9)) continue;
    const std::array<std::string, 2> ends = numerics::format_apart(range.least, range.largest, 4);
    text += fmt::format("{}K_eff/K_m of region '{}' ranged from {} to {} ({}%)", text.empty() ? "" : ", ", r.name,
                        ends[0], ends[1],
                        spread >= 0.1 ? fmt::format("{:.0f}", 100.0 * spread) : fmt::format("{:.2g}", 100.0 * spread));
  }
  return text.empty() ? text : fmt::format("over the last {} passes {}", passes, text);
}

std::string describe_cut_steps(double shortest, double full) {
  return fmt::format(
      "its DDA steps were cut short (to {:.3g} s at the shortest, against mechanics.time_step = {:g} s) and its last "
      "one had not grown back: steps cut short move the blocks little however far they are from equilibrium, so a "
      "small change proves nothing. The contacts did not settle at the full step (their states or their forces): "
      "look for blocks thinner than the contact distance (set by mechanics.max_displacement_ratio), or give more "
      "mechanics.steps so that the step can grow back",
      shortest, full);
}

}  // namespace hydrodda::run
