#pragma once
// Joints that hinder flow across them. A joint type with a barrier (barrier_permeability k_b,
// barrier_width b) is a layer of that width along each of its faces: the fluid mesh follows a
// strip of width b about each face, and the elements in it take k_b. The mesh's element edges
// run along both sides of the strip, so P1 elements carry flow across it as layers in series,
// exactly: the resistance per unit area is b / k_b whatever the elements' size (docs/flow.md,
// "Joints that hinder flow").

#include <string>
#include <vector>

#include "geometry/polygon.hpp"
#include "scenario/scenario.hpp"

namespace hydrodda::run {

struct BarrierStrip {
  std::string region;          // the mesh region it is meshed as: "barrier.<type>"
  geometry::Polygon polygon;   // counter-clockwise
  double permeability = 0.0;   // m²
};

// A strip for each fracture face (as cut) whose joint type has a barrier: the face widened by
// b / 2 to each side and lengthened by b / 2 at each end, so that strips meeting at a
// junction overlap there. None when no type has a barrier (then the domain is not cut again).
std::vector<BarrierStrip> find_barrier_strips(const scenario::Scenario& scenario);

}  // namespace hydrodda::run
