#include "coupling/fixed_stress_step.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "coupling/pass_storage.hpp"

namespace hydrodda::coupling {

SkeletonVolumes compute_skeleton_volumes(const FixedStressSettings& settings, std::span<const double> element_areas,
                                         const BlockPieces& pieces, std::span<const double> volumetric_strain,
                                         std::span<const double> open_area, const EmbeddedJoints* joints,
                                         std::span<const double> apertures) {
  const std::size_t n = element_areas.size();
  const std::size_t blocks = settings.biot.size();
  if (open_area.size() != n) throw std::invalid_argument("fixed-stress step: one open area per element is needed");
  if (volumetric_strain.size() != blocks || settings.storage.size() != blocks || settings.drained_bulk.size() != blocks)
    throw std::invalid_argument("fixed-stress step: one strain, storage, α and K_dr per block are needed");
  const double c_w = settings.fluid_compressibility;
  SkeletonVolumes v;
  v.zeta.assign(n, 0.0);
  v.storage.assign(n, 0.0);
  v.stabilisation.assign(n, 0.0);
  // The blocks' pieces, in element order (any thread count: the same sums).
  for (const std::vector<BlockPiece>& list : pieces.lists())
    for (const BlockPiece& piece : list) {
      const auto e = static_cast<std::size_t>(piece.element);
      const auto b = static_cast<std::size_t>(piece.block);
      const double share = piece.area / element_areas[e];
      const double alpha = settings.biot[b];
      v.zeta[e] += share * alpha * volumetric_strain[b];
      v.storage[e] += share * settings.storage[b];
      if (settings.drained_bulk[b] > 0.0) v.stabilisation[e] += share * alpha * alpha / settings.drained_bulk[b];
    }
  // The open gaps between blocks: their area, its water by its compressibility.
  for (std::size_t e = 0; e < n; ++e) {
    const double share = open_area[e] / element_areas[e];
    v.zeta[e] += share;
    v.storage[e] += share * c_w;
  }
  // The joints' crossings: their aperture, its water, and their compliance as stabilisation.
  if (joints) {
    const std::vector<JointCrossing>& crossings = joints->crossings();
    if (apertures.size() != crossings.size())
      throw std::invalid_argument("fixed-stress step: one aperture per joint crossing is needed");
    for (std::size_t c = 0; c < crossings.size(); ++c) {
      const JointCrossing& x = crossings[c];
      const auto e = static_cast<std::size_t>(x.element);
      const double share = x.length / element_areas[e];
      v.zeta[e] += share * apertures[c];
      v.storage[e] += share * apertures[c] * c_w;
      v.stabilisation[e] += share * joint_compliance(joints->laws().of_fracture(x.face.fracture), apertures[c]);
    }
  }
  for (std::size_t e = 0; e < n; ++e) {
    v.storage[e] *= settings.unit_weight;
    v.stabilisation[e] *= settings.unit_weight;
  }
  return v;
}

std::vector<double> volumetric_strains(std::span<const std::array<double, 3>> strains) {
  std::vector<double> trace;
  trace.reserve(strains.size());
  for (const std::array<double, 3>& s : strains) trace.push_back(s[0] + s[1]);
  return trace;
}

StepHeads fold_step_heads(std::span<const std::array<int, 3>> triangles, std::span<const double> element_areas,
                          const SkeletonVolumes& now, std::span<const double> zeta_at_start, double time_step,
                          std::span<const double> heads_at_start, std::span<const double> heads_last_iterate) {
  const std::size_t n = triangles.size();
  if (element_areas.size() != n || now.zeta.size() != n || zeta_at_start.size() != n)
    throw std::invalid_argument("fixed-stress step: one area and volume per element are needed");
  if (heads_last_iterate.size() != heads_at_start.size())
    throw std::invalid_argument("fixed-stress step: the heads of the step's start and of the last iterate differ in size");
  if (!(time_step > 0.0)) throw std::invalid_argument("fixed-stress step: the time step must be > 0");
  const std::size_t nodes = heads_at_start.size();
  std::vector<double> mass(nodes, 0.0), held(nodes, 0.0), change(nodes, 0.0);
  StepHeads step;
  step.storage_over_step.resize(n);
  for (std::size_t e = 0; e < n; ++e) {
    const double third = element_areas[e] / 3.0;  // the lumped ∫ φ_i over the element
    step.storage_over_step[e] = (now.storage[e] + now.stabilisation[e]) / time_step;
    for (int corner : triangles[e]) {
      const auto i = static_cast<std::size_t>(corner);
      mass[i] += third * (now.storage[e] + now.stabilisation[e]);
      held[i] += third * (now.storage[e] * heads_at_start[i] + now.stabilisation[e] * heads_last_iterate[i]);
      change[i] += third * (now.zeta[e] - zeta_at_start[e]);
    }
  }
  step.heads.resize(nodes);
  for (std::size_t i = 0; i < nodes; ++i) {
    if (mass[i] > 0.0) {
      step.heads[i] = (held[i] - change[i]) / mass[i];
      continue;
    }
    if (change[i] != 0.0)
      throw std::runtime_error("fixed-stress step: the skeleton's volume changes at node " + std::to_string(i) +
                               ", where no element stores water (no material storage, no Biot coefficient, no "
                               "fluid compressibility): give the fluid a compressibility");
    step.heads[i] = heads_at_start[i];
  }
  return step;
}

namespace {

std::vector<double> gap_shares(std::span<const double> element_areas, std::span<const double> open_area) {
  if (open_area.size() != element_areas.size())
    throw std::invalid_argument("gap secant: one open area per element is needed");
  std::vector<double> share(element_areas.size());
  for (std::size_t e = 0; e < share.size(); ++e) share[e] = open_area[e] / element_areas[e];
  return share;
}

std::vector<double> mean_heads(std::span<const std::array<int, 3>> triangles, std::span<const double> heads) {
  std::vector<double> mean(triangles.size());
  for (std::size_t e = 0; e < triangles.size(); ++e) {
    const std::array<int, 3>& t = triangles[e];
    mean[e] = (heads[static_cast<std::size_t>(t[0])] + heads[static_cast<std::size_t>(t[1])] +
               heads[static_cast<std::size_t>(t[2])]) / 3.0;
  }
  return mean;
}

}  // namespace

GapSecant start_gap_secant(std::span<const std::array<int, 3>> triangles, std::span<const double> element_areas,
                           std::span<const double> open_area, std::span<const double> heads_at_start) {
  if (triangles.size() != element_areas.size())
    throw std::invalid_argument("gap secant: one area per element is needed");
  GapSecant secant{gap_shares(element_areas, open_area), mean_heads(triangles, heads_at_start), {}, {}, 0.0};
  secant.beta.assign(triangles.size(), 0.0);
  secant.held_gap.assign(triangles.size(), 0);
  return secant;
}

// s = the largest ζgap^{k−2}_e / max(|Δh̄_e|, τ × range of the heads) of the elements whose gap
// closed shut; the largest of the step, given to every element that holds a gap or held one in
// the step (header).
void update_gap_secant(GapSecant& secant, std::span<const std::array<int, 3>> triangles,
                       std::span<const double> element_areas, std::span<const double> open_area,
                       std::span<const double> heads, double tolerance) {
  const std::size_t n = triangles.size();
  if (element_areas.size() != n || heads.empty() || secant.gap_share.size() != n || secant.beta.size() != n ||
      secant.held_gap.size() != n)
    throw std::invalid_argument("gap secant: one area and one secant per element are needed");
  std::vector<double> share = gap_shares(element_areas, open_area);
  std::vector<double> mean = mean_heads(triangles, heads);
  const auto [low, high] = std::minmax_element(heads.begin(), heads.end());
  const double resolved = tolerance * (*high - *low);
  // Heads all alike give no scale for a change the loop resolves: no secant is taken then.
  if (resolved > 0.0)
    for (std::size_t e = 0; e < n; ++e) {
      const bool closed_shut = share[e] == 0.0 && secant.gap_share[e] > 0.0;
      if (!closed_shut) continue;
      const double head_change = std::max(std::abs(mean[e] - secant.mean_head[e]), resolved);
      secant.largest = std::max(secant.largest, secant.gap_share[e] / head_change);
    }
  for (std::size_t e = 0; e < n; ++e) {
    if (share[e] > 0.0 || secant.gap_share[e] > 0.0) secant.held_gap[e] = 1;
    secant.beta[e] = secant.held_gap[e] ? secant.largest : 0.0;
  }
  secant.gap_share = std::move(share);
  secant.mean_head = std::move(mean);
}

}  // namespace hydrodda::coupling
