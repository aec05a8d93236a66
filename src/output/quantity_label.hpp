#pragma once
// A scenario key or a summary.json path as a figure's axis title: the quantity, what it belongs
// to, and its unit. Shared by the sweep's and the breach's figures.

#include <string>
#include <string_view>
#include <vector>

namespace hydrodda::output {

struct Quantity {
  std::string name;  // "head at base"; the path itself when not known
  std::string_view unit;
};

// The quantity a path names: its last part names it, the unit is the scenario's (SI) or
// summary.json's; `boundary_names` (the scenario's [[flow.boundary]] names, in order) name what
// flow.boundary[i] belongs to.
Quantity name_quantity(const std::string& path, const std::vector<std::string>& boundary_names = {});

// "head at bottom (m)" for flow.boundary[0].head, "K_eff / K_matrix of fractured" for
// flow.regions.fractured.normalised_conductivity; the path itself when it is none of those.
std::string quantity_label(const std::string& path, const std::vector<std::string>& boundary_names = {});

}  // namespace hydrodda::output
