#pragma once
// A look at a model before it runs (`hydrodda check FILE --figure PNG`): the domain, its blocks
// coloured by material (with a legend), the fracture traces coloured by joint type with their
// ids, each boundary with a condition named with it ("bottom: head = 125 m"), the flow regions
// outlined, the fixed, loaded and measured points, and a note of the mesh to expect. Drawn in
// the frame and style of the run's field figures; PNG, SVG or PDF by the file's extension.

#include <filesystem>
#include <string>
#include <vector>

#include "geometry/point.hpp"
#include "geometry/polygon.hpp"

namespace hydrodda::output {

struct PreviewFigure {
  std::string title;
  std::string subtitle;                     // what the model is: "31 blocks, 23 traces"
  std::string note;                         // under the plot: the mesh to expect
  geometry::Polygon domain;                 // empty for blocks given one by one
  std::vector<geometry::Polygon> blocks;
  std::vector<int> block_material;          // per block, index into materials
  std::vector<bool> block_fixed;            // per block
  std::vector<std::string> materials;
  // The traces as they remain after the cut (pieces between blocks), each with its fracture id
  // and its joint type (index into joint_types).
  struct Trace {
    geometry::Point from, to;
    int fracture = 0;
    int joint_type = 0;
  };
  std::vector<Trace> traces;
  std::vector<std::string> joint_types;
  // A boundary segment with its conditions, said in words.
  struct Boundary {
    geometry::Point from, to;
    std::string label;
  };
  std::vector<Boundary> boundaries;
  struct Region {
    geometry::Polygon polygon;
    std::string name;
  };
  std::vector<Region> flow_regions;
  struct Marker {
    geometry::Point point;
    std::string name;
  };
  std::vector<Marker> fixed_points, loads, measures;
};

// The colour a material (or joint type) of this index is drawn in, as RGB in [0, 1]: a fixed
// palette, so that a test can look for its pixels.
struct Rgb {
  double r = 0.0, g = 0.0, b = 0.0;
};
Rgb material_colour(int index);
Rgb joint_type_colour(int index);

// Throws std::runtime_error naming the path when the file cannot be written.
void render_preview_figure(const std::filesystem::path& path, const PreviewFigure& figure);

}  // namespace hydrodda::output
