#pragma once
// [[geometry.tessellate]] applied to a cut domain: each block whose centroid lies in a
// tessellation's region (the first that holds it) replaced by its sub-blocks, in place, and
// every face between two sub-blocks a bond (docs/dda.md, "Bonds").

#include "run/model_geometry.hpp"

namespace hydrodda::run {

// Tessellates model.network's blocks as the scenario's tessellations ask, filling
// model.edge_bonds and model.bond_types; a sub-block's edge on its block's edge keeps that
// edge's fracture id. Throws a ScenarioError naming geometry.tessellate for a block it cannot
// tessellate (one that is not convex).
void tessellate_blocks(const scenario::Scenario& scenario, ModelGeometry& model);

}  // namespace hydrodda::run
