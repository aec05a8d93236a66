#pragma once
// [[geometry.tessellate]] applied to a cut domain: each block whose centroid lies in a
// tessellation's region (the first that holds it) replaced by its sub-blocks, in place, and
// every face between two sub-blocks a bond (docs/dda.md, "Bonds").

#include <vector>

#include "dda/definitions.hpp"
#include "run/model_geometry.hpp"

namespace hydrodda::run {

// Tessellates model.network's blocks as the scenario's tessellations ask, filling
// model.edge_bonds and model.bond_types; a sub-block's edge on its block's edge keeps that
// edge's fracture id. Throws a ScenarioError naming geometry.tessellate for a block it cannot
// tessellate (one that is not convex).
void tessellate_blocks(const scenario::Scenario& scenario, ModelGeometry& model);

// The bonds of `blocks` (as build_blocks makes them) that lie on a tessellation's `cracks`, in
// increasing order: they start broken (dda::ModelDefinition::broken_bonds).
std::vector<int> find_crack_bonds(const scenario::Scenario& scenario, const std::vector<dda::BlockDefinition>& blocks);

// The network as the flow's embedded joints see it (coupling::EmbeddedJoints): each bonded
// edge on fracture model.traces.size() + its bond, and each bond's face (its first sub-block's
// edge, as built) among the faces after the traces'. A bond's face is in the network from the
// start, intact or not: the fluid mesh is fixed, and the crossings of the faces with its
// elements are found once; a bond that breaks switches its crossings on.
geometry::BlockNetwork network_with_bond_faces(const ModelGeometry& model);

}  // namespace hydrodda::run
