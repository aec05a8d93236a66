#include "run/mechanics_rest.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <vector>

#include "run/model_building.hpp"

namespace hydrodda::run {

namespace {

// A step within this share of time_step ran at it: the step that lands on end_time is
// end_time − t long, which rounding may leave a few ulps short.
constexpr double kFullStepShare = 1.0 - 1e-9;
constexpr std::size_t kBlocksNamed = 5;
// Itasca's local force ratio limit (UDEC, 3DEC: "Reaching Equilibrium"), per block: docs/dda.md,
// "At rest: the unbalanced force".
constexpr double kUnbalancedForceLimit = 1e-5;

// "block 3 at (0.5, 1.25) moved 2.1e-06 m, ..." for the blocks the last step moved past `still`,
// largest first; "and N more" beyond five.
std::string describe_moving_blocks(const dda::System& system, double still) {
  const std::vector<double>& motion = system.free_drift().motion;
  std::vector<int> moving;
  for (std::size_t b = 0; b < motion.size(); ++b)
    if (motion[b] > still) moving.push_back(static_cast<int>(b));
  std::stable_sort(moving.begin(), moving.end(), [&](int a, int b) { return motion[a] > motion[b]; });
  std::string text;
  for (std::size_t i = 0; i < std::min(moving.size(), kBlocksNamed); ++i) {
    const int b = moving[i];
    const geometry::Point c = system.centroid(b);
    text += fmt::format("{}block {} at ({:.4g}, {:.4g}) {:.3g} m", i == 0 ? "" : ", ", b, c.x, c.y, motion[b]);
  }
  if (moving.size() > kBlocksNamed) text += fmt::format(" and {} more", moving.size() - kBlocksNamed);
  return fmt::format("{} block(s) moved past it: {}", moving.size(), text);
}

}  // namespace

bool loads_change_between(const scenario::MechanicsDefinition& m, double t0, double t1) {
  const auto changes = [&](const numerics::TimeTable& table, std::size_t columns) {
    for (std::size_t c = 0; c < columns; ++c)
      if (table.value(t0, c) != table.value(t1, c)) return true;
    return false;
  };
  for (const scenario::Traction& t : m.tractions)
    if (changes(t.normal, 1) || changes(t.normal_end, 1) || changes(t.shear, 1) || changes(t.shear_end, 1)) return true;
  for (const scenario::PointLoad& load : m.loads)
    if (changes(load.force, 2)) return true;
  for (const scenario::PrescribedDisplacement& d : m.displacements)
    if (t0 < d.ramp_time.value_or(mechanics_duration(m)) && (d.value.x != 0.0 || d.value.y != 0.0)) return true;
  return false;
}

std::string describe_motion_at_end(const scenario::Scenario& scenario, const dda::System& system,
                                   const dda::StepReport& last, long long steps) {
  const scenario::MechanicsDefinition& m = *scenario.mechanics;
  if (loads_change_between(m, last.time - last.time_step, last.time)) return {};
  const bool by_end_time = !m.steps;
  const bool full = last.time_step >= kFullStepShare * system.full_time_step();
  const double still = system.at_rest_displacement();
  if (full && (last.max_displacement <= still || last.unbalanced_force_ratio <= kUnbalancedForceLimit)) return {};
  const std::string raise = by_end_time ? "raise mechanics.end_time (steps of time_step to rest)"
                                        : "raise mechanics.steps";
  if (!full)
    return fmt::format(
        "the blocks may not be at rest at the end: the last step (step {}) ran {:.4g} s, shorter than time_step "
        "{:.4g} s, and a step cut short moves little for being short, so rest cannot be told from motion (it moved "
        "a vertex by {:.3g} m, at rest below {:.3g} m){}; {}",
        steps, last.time_step, system.full_time_step(), last.max_displacement, still,
        by_end_time ? "; give mechanics.end_time a whole number of time steps" : "", raise);
  return fmt::format(
      "the blocks were not at rest at the end: the last step (step {}) still moved a vertex by {:.3g} m (at rest "
      "below {:.3g} m, 1e-9 of half the model's height) and left block {} an unbalanced force of {:.3g} of the "
      "forces on it (at rest below {:g}); {}; {}",
      steps, last.max_displacement, still, last.unbalanced_block, last.unbalanced_force_ratio, kUnbalancedForceLimit,
      describe_moving_blocks(system, still), raise);
}

}  // namespace hydrodda::run
