#pragma once
// A map of a run as the paper draws it (its Figs. 6, 8, 11): the fluid mesh coloured by a
// field (or the blocks with coloured lines over them), head contours, the deformed blocks, and
// Darcy flux arrows (the largest 8% of the plot's width, under 1% of the largest hidden, a key
// arrow with its value); a colour bar labelled beside it, axes in metres, a title. PNG, SVG or
// PDF by file extension.

#include <array>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "geometry/point.hpp"
#include "geometry/polygon.hpp"

namespace hydrodda::output {

struct FieldFigure {
  std::string title;                         // the case; shrunk to fit the page
  std::string subtitle;                      // the quantity and state, under the title
  std::string warning;                       // in red under the title, e.g. "not converged"
  std::string field_label;                   // the colour bar's label, e.g. "head (m)"
  std::span<const geometry::Point> nodes;
  std::span<const std::array<int, 3>> triangles;
  std::vector<double> node_field;            // coloured and contoured (per node), or empty
  std::vector<double> element_field;         // coloured per element when node_field is empty
  bool logarithmic = false;                  // colour by log10 of the element field
  int contour_levels = 10;                   // head contours of node_field; 0 for none
  std::vector<geometry::Polygon> blocks;     // outlines drawn over the field
  bool faint_blocks = false;                 // thin grey outlines, so a field along the joints shows
  std::vector<geometry::Point> element_flux; // arrows at element centroids, or empty
  // Lines coloured by a value (e.g. fracture apertures) drawn over the blocks, which are then
  // filled light grey; the colour bar is theirs when there is no mesh field. Lines not
  // `highlighted` are drawn thin and grey (e.g. closed fractures).
  std::vector<std::array<geometry::Point, 2>> segments;
  std::vector<double> segment_values;
  std::vector<bool> segment_highlighted;
  // Lines drawn thick in black over the others and outside the colour scale, which their values
  // do not set (e.g. cracks broken from the start, on a figure coloured by when bonds broke).
  std::vector<bool> segment_marked;
  // Lines only: the colour scale starts at zero, their values being sizes (apertures); false: it
  // spans the values of the highlighted lines, as on a log scale (e.g. the loads bonds broke at).
  bool lines_scale_from_zero = true;
  // The values are counts (e.g. the pass a bond broke in): the bar is ticked at whole numbers.
  bool whole_numbers = false;
  std::string flux_unit = "m/s";             // of the key arrow's value
};

// Throws std::runtime_error naming the path when the file cannot be written.
void render_field_figure(const std::filesystem::path& path, const FieldFigure& figure);

// The points where a P1 field equals `level` inside one triangle: 0 or 2 points (a segment).
// Linear interpolation along the edges whose ends straddle the level.
std::vector<geometry::Point> contour_segment(const std::array<geometry::Point, 3>& corners,
                                             const std::array<double, 3>& values, double level);

}  // namespace hydrodda::output
