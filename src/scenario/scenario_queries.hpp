#pragma once
// What the layers above scenario/ ask of a scenario once it is read: plain functions of the
// definition structs (no TOML).

#include <optional>

#include "scenario/scenario.hpp"

namespace hydrodda::scenario {

// Whether any material has a region (material_regions.cpp).
bool has_material_regions(const Scenario& scenario);

// The material (index into scenario.materials) whose region holds p, else the one material
// without a region; -1 when neither exists. Regions do not overlap (checked on reading), so at
// most one holds a point inside; on a border between two, the first listed (material_regions.cpp).
int find_material_at(const Scenario& scenario, Point p);

// The range of the heads the flow's boundaries fix, m; empty when it is not bounded (a flux
// through a boundary raises or lowers the heads inside beyond any fixed one) or not known (a
// pressure on a mesh file's curve, whose height is not known before the mesh is read)
// (rollers_and_initial_stress.cpp).
std::optional<double> find_boundary_head_range(const Scenario& scenario);

}  // namespace hydrodda::scenario
