#pragma once
// The sanity of a model's in-situ state: per block cut from the domain, the initial σyy at its
// centroid against the weight of the layers above it and the traction on the domain's top,
//
//     σyy_expected(x, y) = t_n(x, y_top) + g_y ∫_{y}^{y_top} ρ'(x, η) dη
//
// along the vertical through the centroid (ρ' the density the blocks' stress carries:
// layered_stress.hpp; t_n the [[mechanics.traction]]'s normal stress where one acts on the top,
// 0 where the top is free). A block whose top is held by a roller or a prescribed
// displacement is not compared: what holds it there is not known before the run. In a coupled
// run the seepage the boundary heads drive may move it by up to α ρ_w g Δh (Δh the heads'
// range), which is allowed for; where the heads are not bounded nothing is compared. Under
// hydrostatic pore pressure the top's face also takes (1 − α) p_top from the fluid beside the
// traction (docs/coupling.md), which the blocks carry below it: p_top from the head of a boundary
// through the top, else anywhere within the boundary heads' bounds.

#include <optional>
#include <string>
#include <vector>

#include "dda/definitions.hpp"
#include "scenario/scenario.hpp"

namespace hydrodda::run {

// The relative difference beyond which the start is reported.
inline constexpr double kInSituTolerance = 0.05;

struct InSituComparison {
  int block = 0;
  geometry::Point centroid;
  double initial = 0.0;   // σyy of the field at the centroid, Pa
  double expected = 0.0;  // the weight above and the top traction, Pa
};

// Every block whose initial σyy differs from the expected one by more than kInSituTolerance of
// it (and 1 Pa); none without a domain, an initial stress or gravity.
std::vector<InSituComparison> compare_in_situ_stress(const scenario::Scenario& scenario,
                                                      const std::vector<dda::BlockDefinition>& blocks,
                                                      const dda::StressField& field);

// The warning for those blocks (the worst three named), naming the keys that set the start.
std::optional<std::string> describe_in_situ_mismatch(const scenario::Scenario& scenario,
                                                     const std::vector<InSituComparison>& mismatches);

}  // namespace hydrodda::run
