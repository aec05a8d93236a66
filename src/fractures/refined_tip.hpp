#pragma once
// A refined wedge tip as plain data, for summary.json and the checkpoint as well as the rounds
// of mesh.refine_tips (tip_refinement.hpp).

namespace hydrodda::fractures {

// A wedge tip a run refined its fluid mesh around (mesh.refine_tips): a [[mesh.refine]] point
// it added when a round ended with the tip unresolved.
struct RefinedTip {
  double x = 0.0, y = 0.0;  // m
  double size = 0.0;        // m: s*/4 of the tip
  double radius = 0.0;      // m
  int round = 0;            // the round that found it: 1 on the scenario's own mesh
};

}  // namespace hydrodda::fractures
