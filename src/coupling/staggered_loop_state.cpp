// Export and import of the staggered loop's state between passes (see LoopState).
#include <deque>
#include <stdexcept>

#include "coupling/staggered_loop.hpp"

namespace hydrodda::coupling {

LoopState StaggeredLoop::export_state() const {
  LoopState state{completed_,       solution_,   previous_heads_, heads_two_back_, previous_displacements_, growth_,
                  previous_update_, relaxation_, {},              {},              darcy_.kept_factor(),
                  darcy_.kept_factor_in_single_precision(), porosity_, permeability_,
                  permeability_tensors_,                   float_secant_.remembered()};
  state.ramp_passes = settings_.ramp_passes;
  for (const numerics::AndersonAccelerator::Pass& pass : anderson_.history()) {
    state.anderson_residuals.emplace_back(pass.residual.begin(), pass.residual.end());
    state.anderson_images.emplace_back(pass.image.begin(), pass.image.end());
  }
  return state;
}

void StaggeredLoop::import_state(LoopState state, const dda::SystemState& mechanics) {
  mechanics_.import_state(mechanics);
  const auto nodes = static_cast<std::size_t>(mesh_.node_count());
  const auto blocks = static_cast<std::size_t>(mechanics_.block_count());
  // A transient loop has its heads at t = 0 before any pass (start_in_time).
  const bool started = state.iterations > 0 || (settings_.fixed_stress && !state.flow.head.empty());
  if (state.iterations < 0) throw std::invalid_argument("coupling state: a negative iteration count");
  // A finished pass leaves a solution, heads and displacements of this mesh and system.
  const bool fits = started ? state.flow.head.size() == nodes && state.flow.pressure.size() == nodes &&
                                  state.flow.flux.size() == static_cast<std::size_t>(mesh_.triangle_count()) &&
                                  state.previous_heads.size() == nodes &&
                                  state.previous_displacements.size() == blocks &&
                                  (state.previous_update.empty() || state.previous_update.size() == nodes) &&
                                  (state.heads_two_back.empty() || state.heads_two_back.size() == nodes)
                            : state.flow.head.empty() && state.previous_heads.empty() &&
                                  state.previous_displacements.empty();
  bool anderson_fits = state.anderson_residuals.size() == state.anderson_images.size();
  for (std::size_t i = 0; anderson_fits && i < state.anderson_residuals.size(); ++i)
    anderson_fits = state.anderson_residuals[i].size() == 2 * nodes && state.anderson_images[i].size() == 2 * nodes;
  const std::size_t kept = state.kept_factor_permeability ? state.kept_factor_permeability->size() : 0;
  const auto per_element = [&](std::size_t n) { return n == 0 || n == static_cast<std::size_t>(mesh_.triangle_count()); };
  const bool fields_fit = per_element(state.porosity.porosity.size()) &&
                          per_element(state.porosity.fracture_area.size()) &&
                          per_element(state.permeability.size()) && per_element(state.permeability_tensors.size());
  if (!fits || !anderson_fits || !per_element(kept) || !fields_fit)
    throw std::invalid_argument("coupling state: sizes do not fit the mesh and the blocks");
  // The flow solver's kept factor, made again from its permeability: the next pass's solve
  // then starts from the very factor it had.
  float_secant_.restore(state.float_groups, mechanics_.block_count());
  darcy_.restore_kept_factor(std::move(state.kept_factor_permeability), state.kept_factor_single_precision);
  if (state.ramp_passes < 1) throw std::invalid_argument("coupling state: a ramp of fewer than one pass");
  if (state.iterations > 0) {  // the first pass has chosen the ramp
    settings_.ramp_passes = state.ramp_passes;
    settings_.ramp_if_moved = 0;
  }
  iteration_ = completed_ = state.iterations;
  solution_ = std::move(state.flow);
  previous_heads_ = std::move(state.previous_heads);
  heads_two_back_ = std::move(state.heads_two_back);
  previous_displacements_ = std::move(state.previous_displacements);
  pass_before_displacements_.clear();  // not a state's: the last pass's motion is told of passes run since
  growth_ = state.growth;
  previous_update_ = std::move(state.previous_update);
  relaxation_ = state.relaxation;
  porosity_ = std::move(state.porosity);
  permeability_ = std::move(state.permeability);
  permeability_tensors_ = std::move(state.permeability_tensors);
  std::deque<numerics::AndersonAccelerator::Pass> history;
  for (std::size_t i = 0; i < state.anderson_residuals.size(); ++i)
    history.push_back({Eigen::Map<const Eigen::VectorXd>(state.anderson_residuals[i].data(),
                                                         static_cast<Eigen::Index>(state.anderson_residuals[i].size())),
                       Eigen::Map<const Eigen::VectorXd>(state.anderson_images[i].data(),
                                                         static_cast<Eigen::Index>(state.anderson_images[i].size()))});
  anderson_.restore(std::move(history));
  last_mechanics_ = mechanics;
}

}  // namespace hydrodda::coupling
