#include "run/model_geometry.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <stdexcept>

#include "geometry/joint_sets.hpp"
#include "output/item_list.hpp"
#include "run/sub_blocks.hpp"
#include "scenario/diagnostics.hpp"

namespace hydrodda::run {

namespace {

using geometry::FractureTrace;
using geometry::TraceSource;

std::string plural(std::size_t count, const char* one, const char* many) {
  return fmt::format("{} {}", count, count == 1 ? one : many);
}

}  // namespace

std::vector<FractureTrace> collect_fracture_traces(const scenario::Scenario& s) {
  const scenario::GeometryDefinition& g = *s.geometry;
  std::vector<FractureTrace> traces;
  // A name that names no type is refused by the reader; the default type stands in for it here.
  const auto type = [&](const std::string& name) { return std::max(0, s.joint_type_index(name)); };
  for (std::size_t i = 0; i < g.fractures.size(); ++i)
    traces.push_back({{g.fractures[i].from, g.fractures[i].to},
                      {TraceSource::listed, -1, static_cast<int>(i)},
                      i < g.fracture_joints.size() ? type(g.fracture_joints[i].name) : 0});
  for (std::size_t k = 0; k < g.joint_sets.size(); ++k) {
    const scenario::JointSetDefinition& d = g.joint_sets[k];
    geometry::JointSet set;
    set.angle = d.angle;
    set.spacing = d.spacing;
    set.angle_spread = d.angle_spread;
    set.spacing_spread = d.spacing_spread;
    set.length = d.length;
    set.length_spread = d.length_spread;
    set.gap = d.gap;
    set.gap_spread = d.gap_spread;
    set.offset = d.offset;
    set.region = d.region.empty() ? g.domain : d.region;
    set.seed = d.seed;
    std::vector<geometry::Segment2> generated;
    try {
      generated = geometry::generate_joint_traces(set);
    } catch (const std::invalid_argument& e) {
      throw scenario::ScenarioError({{s.file.string(), d.line, "geometry.joint_set.spacing", e.what()}});
    }
    for (std::size_t j = 0; j < generated.size(); ++j)
      traces.push_back({generated[j], {TraceSource::joint_set, static_cast<int>(k), static_cast<int>(j)}, type(d.joint.name)});
  }
  for (const scenario::FileFracture& f : g.file_fractures)
    traces.push_back({{f.segment.from, f.segment.to}, {TraceSource::file, -1, f.line}, type(f.joint)});
  return traces;
}

ModelGeometry build_model_geometry(const scenario::Scenario& s) {
  const scenario::GeometryDefinition& g = *s.geometry;
  const std::string file = s.file.string();
  ModelGeometry model;
  model.traces = collect_fracture_traces(s);
  try {
    model.network = geometry::build_block_network(
        {g.domain, model.traces, g.welded, g.min_block_area.value_or(0.0), g.initial_aperture});
  } catch (const geometry::BlockNetworkError& e) {
    const bool aperture = e.cause() == geometry::BlockNetworkError::Cause::aperture;
    throw scenario::ScenarioError({{file, aperture ? g.initial_aperture_line : 0,
                                    aperture ? "geometry.initial_aperture" : "geometry.fractures", e.what()}});
  }
  const geometry::BlockNetwork& net = model.network;

  // Pieces that cut nothing: one warning naming the listed fractures by their ids, those of
  // the preview, fractures.csv and the other warnings (a few of them: a line is read, a
  // hundred numbers are not), a count per joint set and for the file, whose loose ends are
  // expected (a trace ending inside a block).
  std::vector<int> dropped_per_set(g.joint_sets.size(), 0);
  int dropped_file = 0;
  std::vector<std::string> dropped_listed;
  for (int f : net.dropped_from) {
    const geometry::TraceOrigin& o = model.traces[f].origin;
    if (o.source == TraceSource::listed) dropped_listed.push_back(std::to_string(f));
    else if (o.source == TraceSource::joint_set) ++dropped_per_set[o.set];
    else ++dropped_file;
  }
  if (dropped_listed.size() == 1)
    model.warnings.push_back(fmt::format("{}: geometry.fractures: fracture {}: a piece of it separates no blocks and is dropped",
                                         file, dropped_listed.front()));
  else if (!dropped_listed.empty())
    model.warnings.push_back(fmt::format("{}: geometry.fractures: fractures {}: a piece of each separates no blocks and is dropped",
                                         file, output::list_items(dropped_listed, nullptr, "")));
  std::vector<int> per_set(g.joint_sets.size(), 0);
  for (const FractureTrace& t : model.traces)
    if (t.origin.source == TraceSource::joint_set) ++per_set[t.origin.set];
  for (std::size_t k = 0; k < g.joint_sets.size(); ++k)
    if (dropped_per_set[k] > 0)
      model.notes.push_back(fmt::format("{}:{}: geometry.joint_set: {} of {} traces have pieces that separate no blocks (dropped)",
                                        file, g.joint_sets[k].line, dropped_per_set[k], per_set[k]));
  if (dropped_file > 0)
    model.notes.push_back(fmt::format("{}: geometry.fractures_file: {} of {} traces have pieces that separate no blocks (dropped)",
                                      g.fractures_file->string(), dropped_file, g.file_fractures.size()));
  if (net.merged_small > 0)
    model.warnings.push_back(fmt::format("{}: geometry.min_block_area: {} smaller than {:.3g} m2 merged into a neighbour",
                                         file, plural(net.merged_small, "block", "blocks"), net.min_block_area));
  if (net.unmerged_small > 0)
    model.warnings.push_back(fmt::format("{}: geometry.min_block_area: {} smaller than {:.3g} m2 with no neighbour to merge into, kept",
                                         file, plural(net.unmerged_small, "block", "blocks"), net.min_block_area));
  if (net.merged_thin > 0)
    model.warnings.push_back(fmt::format("{}:{}: geometry.initial_aperture: {} too thin for {:g} m merged into a neighbour",
                                         file, g.initial_aperture_line, plural(net.merged_thin, "block", "blocks"),
                                         g.initial_aperture));

  std::vector<std::string> sources;
  if (!g.fractures.empty()) sources.push_back(fmt::format("{} listed", g.fractures.size()));
  for (std::size_t k = 0; k < g.joint_sets.size(); ++k) sources.push_back(fmt::format("{} from joint set {}", per_set[k], k + 1));
  if (!g.file_fractures.empty()) sources.push_back(fmt::format("{} from {}", g.file_fractures.size(), g.fractures_file->filename().string()));
  model.summary = plural(model.traces.size(), "trace", "traces");
  if (!sources.empty()) model.summary += fmt::format(" ({})", fmt::join(sources, ", "));
  model.summary += ", " + plural(net.blocks.size(), "block", "blocks");
  const int merged = net.merged_small + net.merged_thin;
  if (merged > 0) model.summary += fmt::format(" ({} merged)", plural(static_cast<std::size_t>(merged), "sliver", "slivers"));
  tessellate_blocks(s, model);
  return model;
}

}  // namespace hydrodda::run
