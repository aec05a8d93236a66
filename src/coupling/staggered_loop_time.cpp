// The staggered loop in time: a coupled transient run's steps by the fixed-stress split
// (fixed_stress_step.hpp), each pass an iteration of the step under way.
#include <stdexcept>

#include "coupling/local_aperture.hpp"
#include "coupling/staggered_loop.hpp"

namespace hydrodda::coupling {

// The porosity field of `blocks` (the clip, the boundary gaps taken out, the materials' matrix
// porosity), with the block pieces when asked for: what every pass computes first.
PorosityField StaggeredLoop::clip_blocks(const std::vector<geometry::Polygon>& blocks, BlockPieces* pieces) const {
  PorosityField field = porosity_mapper_.compute(blocks, settings_.permeability.matrix_porosity, pieces);
  // A block moved off the domain boundary leaves a strip that is no fracture (boundary_gaps.hpp).
  exclude_boundary_gaps(field, boundary_gaps_.compute_gap_areas(blocks), porosity_mapper_.element_areas(),
                        settings_.permeability.matrix_porosity);
  settings_.permeability.apply_element_matrix_porosity(field, porosity_mapper_.element_areas());
  return field;
}

std::vector<double> StaggeredLoop::block_volumetric_strains() const {
  std::vector<std::array<double, 3>> strains;
  strains.reserve(mechanics_.block_count());
  for (int b = 0; b < mechanics_.block_count(); ++b) strains.push_back(mechanics_.strain(b));
  return volumetric_strains(strains);
}

void StaggeredLoop::start_in_time(std::optional<hydro::FlowSolution> initial) {
  if (!settings_.fixed_stress) throw std::logic_error("start_in_time: the loop was not built for a transient run");
  if (completed_ > 0) throw std::logic_error("start_in_time: passes have run already");
  // The fields of the blocks as built, and with them (unless given) the steady heads of the
  // boundary values at t = 0.
  const std::vector<geometry::Polygon> blocks = current_blocks();
  porosity_ = clip_blocks(blocks, nullptr);
  std::vector<double> apertures;
  if (settings_.permeability.reads_apertures())
    apertures = compute_local_apertures(mesh_, porosity_.fracture_area, blocks, settings_.permeability.domain,
                                        settings_.permeability.aperture_reach);
  permeability_ = settings_.permeability.compute(porosity_, porosity_mapper_.element_areas(), apertures);
  const hydro::PermeabilityView k = update_permeability(blocks);
  if (!initial) initial = darcy_.solve(k);
  if (initial->head.size() != static_cast<std::size_t>(mesh_.node_count()))
    throw std::invalid_argument("start_in_time: the initial heads are not one per node");
  solution_ = std::move(*initial);
  previous_heads_ = solution_.head;
  previous_displacements_.assign(static_cast<std::size_t>(mechanics_.block_count()), Point{0.0, 0.0});
}

// ζ^n of the blocks as they are now (fixed_stress_step.hpp), from a clip of their own: the
// last pass's clip was of the blocks before its mechanics.
void StaggeredLoop::begin_time_step(double time_step) {
  if (!settings_.fixed_stress) throw std::logic_error("begin_time_step: the loop was not built for a transient run");
  if (!(time_step > 0.0)) throw std::invalid_argument("begin_time_step: the time step must be > 0");
  if (solution_.head.empty()) throw std::logic_error("begin_time_step: no heads yet (start_in_time first)");
  const std::vector<geometry::Polygon> blocks = current_blocks();
  BlockPieces pieces;
  const PorosityField field = clip_blocks(blocks, &pieces);
  std::vector<double> apertures;
  // With bonds, an intact bond's crossing is rock, as in every pass (compute_joint_apertures).
  if (joints_) apertures = compute_joint_apertures(blocks);
  const SkeletonVolumes start =
      compute_skeleton_volumes(*settings_.fixed_stress, porosity_mapper_.element_areas(), pieces,
                               block_volumetric_strains(), field.fracture_area, joints_ ? &*joints_ : nullptr, apertures);
  GapSecant gaps =
      start_gap_secant(mesh_.triangles, porosity_mapper_.element_areas(), field.fracture_area, solution_.head);
  time_level_ = TimeLevel{time_step, solution_.head, start.zeta, 0, std::move(gaps)};
}

// Iteration k's flow: (S + β)(h^k − h^n)/Δt − ∇·(K∇h^k) = −(ζ^{k−1} − ζ^n)/Δt + β(h^{k−1} − h^n)/Δt,
// ζ^{k−1} of the blocks this pass clipped (as the last mechanics left them), h^{k−1} the heads
// the last mechanics felt.
hydro::FlowSolution StaggeredLoop::step_in_time(hydro::PermeabilityView permeability) {
  TimeLevel& level = *time_level_;
  const std::span<const double> areas = porosity_mapper_.element_areas();
  SkeletonVolumes now =
      compute_skeleton_volumes(*settings_.fixed_stress, areas, pieces_, block_volumetric_strains(),
                               porosity_.fracture_area, joints_ ? &*joints_ : nullptr, joint_apertures_);
  // The open gaps' own β, from their change since the last iterate against its heads.
  update_gap_secant(level.gaps, mesh_.triangles, areas, porosity_.fracture_area, solution_.head, settings_.tolerance);
  for (std::size_t e = 0; e < now.stabilisation.size(); ++e) now.stabilisation[e] += level.gaps.beta[e];
  const StepHeads step =
      fold_step_heads(mesh_.triangles, areas, now, level.zeta, level.time_step, level.heads, solution_.head);
  return darcy_.solve_step(permeability, step.storage_over_step, hydro::MassMatrix::lumped, step.heads);
}

}  // namespace hydrodda::coupling
