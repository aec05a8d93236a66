#include "scenario/material_regions.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

#include "scenario/validation.hpp"

namespace hydrodda::scenario {

bool has_material_regions(const Scenario& s) {
  return std::any_of(s.materials.begin(), s.materials.end(), [](const MaterialDefinition& m) { return !m.region.empty(); });
}

int find_material_at(const Scenario& s, Point p) {
  int rest = -1;
  for (std::size_t i = 0; i < s.materials.size(); ++i) {
    const Polygon& region = s.materials[i].region;
    if (region.empty()) {
      if (rest < 0) rest = static_cast<int>(i);
    } else if (geometry::contains(region, p)) {
      return static_cast<int>(i);
    }
  }
  return rest;
}

namespace {

// Regions given with [[geometry.block]] blocks, which name their own material: refused, so that
// no block silently takes a material other than the one it names.
bool refuse_regions_without_domain(ReadContext& ctx, const Scenario& s) {
  if (s.geometry && !s.geometry->domain.empty()) return false;
  for (const MaterialDefinition& m : s.materials)
    if (!m.region.empty())
      ctx.error(m.region_line, "material." + m.name + ".region",
                "a material region applies to blocks cut from geometry.domain; blocks given one by one "
                "([[geometry.block]]) name their material with `material`");
  return true;
}

void check_region_placement(ReadContext& ctx, const Scenario& s) {
  const Polygon& domain = s.geometry->domain;
  for (std::size_t i = 0; i < s.materials.size(); ++i) {
    const MaterialDefinition& m = s.materials[i];
    if (m.region.empty()) continue;
    const std::string key = "material." + m.name + ".region";
    if (domain.size() >= 3 && !polygons_overlap(m.region, domain)) {
      ctx.error(m.region_line, key, "the region lies wholly outside geometry.domain, so no block or element takes it");
      continue;
    }
    for (std::size_t j = 0; j < i; ++j) {
      if (s.materials[j].region.empty() || !polygons_overlap(m.region, s.materials[j].region)) continue;
      // Said at the later of the two in the file, naming the earlier.
      const bool later = m.region_line >= s.materials[j].region_line;
      const MaterialDefinition& at = later ? m : s.materials[j];
      const MaterialDefinition& other = later ? s.materials[j] : m;
      ctx.error(at.region_line, "material." + at.name + ".region",
                fmt::format("the region overlaps material.{}'s (line {}): a block or element in both would have "
                            "two materials; make them meet along a border",
                            other.name, other.region_line));
    }
  }
}

}  // namespace

void check_material_regions(ReadContext& ctx, const TableView& root, const Scenario& s) {
  if (refuse_regions_without_domain(ctx, s)) return;
  std::vector<std::string> without_region;
  for (const MaterialDefinition& m : s.materials)
    if (m.region.empty()) without_region.push_back(m.name);
  if (s.materials.size() > 1 && without_region.size() > 1)
    ctx.error(root.line_of_key("material"), "material",
              fmt::format("blocks cut from a domain take the material whose region holds their centroid, and the one "
                          "material without a region the rest; {} have none: give all but one a region",
                          fmt::join(without_region, ", ")));
  check_region_placement(ctx, s);
}

}  // namespace hydrodda::scenario
