#include "output/summary.hpp"

#include <nlohmann/json.hpp>

#include <cmath>

namespace hydrodda::output {

namespace {

using nlohmann::json;

// count, open (how many are open over at least fractures::kOpenShare of their length), open_ids,
// open_length (m, theirs summed), the widest
// opening and its fracture, and `by_id`: each fracture's row as fractures.csv has it.
json format_fractures(const FractureSummary& f) {
  json by_id = json::object(), open_ids = json::array();
  double open_length = 0.0, widest = 0.0;
  json widest_id = nullptr;
  for (const FractureRow& r : f.rows) {
    json row = {{"origin", r.origin},
                {"number", r.number},
                {"length", r.length},
                {"open_length", r.open_length},
                {"open", r.open ? 1 : 0},
                {"open_share", r.open_share},
                {"mean_aperture", r.mean_aperture},
                {"max_aperture", r.max_aperture},
                {"hydraulic_aperture", r.hydraulic_aperture},
                {"normal_stress", r.normal_stress},
                {"max_shear", r.max_shear},
                {"tip_opening_angle", r.tip_opening_angle}};
    if (r.set) row["set"] = *r.set;
    if (!r.type.empty()) row["type"] = r.type;
    if (r.flow) row["flow"] = *r.flow;
    by_id[std::to_string(r.id)] = row;
    if (r.open) {
      open_ids.push_back(r.id);
      open_length += r.open_length;
    }
    if (r.max_aperture > widest) {
      widest = r.max_aperture;
      widest_id = r.id;
    }
  }
  json summary = {{"count", f.rows.size()},     {"open", open_ids.size()},  {"open_ids", open_ids},
                  {"open_length", open_length}, {"max_aperture", widest},   {"max_aperture_id", widest_id},
                  {"by_id", by_id}};
  if (f.tip_length) {
    summary["tip_length"] = *f.tip_length;
    summary["tip_length_id"] = *f.tip_length_id;
    if (f.tip_element_size) summary["tip_element_size"] = *f.tip_element_size;
  }
  if (f.rounds) summary["rounds"] = *f.rounds;
  if (!f.refined_tips.empty()) {
    json& refined = summary["refined_tips"] = json::array();
    for (const fractures::RefinedTip& t : f.refined_tips)
      refined.push_back({{"point", {t.x, t.y}}, {"size", t.size}, {"radius", t.radius},
                         {"round", t.round}});
  }
  return summary;
}

json to_json(const RunSummary& s) {
  // Each block's object filled in place: a json built from nested braces copies every
  // element it is made of (initializer lists hold constants), and a summary lists every block.
  json blocks = json::array();
  for (const BlockSummary& b : s.blocks) {
    json& block = blocks.emplace_back(json::object());
    block["id"] = b.id;
    block["centroid"] = b.centroid;
    block["displacement"] = b.displacement;
    block["rotation"] = b.rotation;
    block["stress"] = b.stress;
    block["area"] = b.area;
    if (!b.material.empty()) block["material"] = b.material;
  }
  json measure = json::object();
  for (const MeasureSummary& m : s.measures)
    measure[m.name] = {{"position", m.position}, {"displacement", m.displacement}};
  json timings = json::object();
  for (const NamedValue& t : s.timings) timings[t.name] = t.value;

  json out = {{"title", s.title},
              {"scenario", s.scenario},
              {"converged", s.converged},
              {"iterations", s.iterations},
              {"status", s.status},
              {"message", s.message},
              {"blocks", blocks},
              {"measure", measure},
              {"timings", timings}};
  if (s.flow) {
    json boundaries = json::object();
    for (const NamedValue& b : s.flow->boundaries) boundaries[b.name] = b.value;
    json regions = json::object();
    const auto or_null = [](const auto& value) { return value ? json(*value) : json(nullptr); };
    for (const RegionSummary& r : s.flow->regions) {
      regions[r.name] = {{"flow", r.flow},
                         {"effective_conductivity", or_null(r.effective_conductivity)},
                         {"matrix_conductivity", or_null(r.matrix_conductivity)},
                         {"normalised_conductivity", or_null(r.normalised_conductivity)},
                         {"direction", or_null(r.direction)},
                         {"conductivity_tensor",
                          {{"xx", r.tensor[0]},
                           {"xy", r.tensor[1]},
                           {"yy", r.tensor[2]},
                           {"principal_values", r.principal_values},
                           {"principal_directions", r.principal_directions}}}};
      if (r.last_passes)
        regions[r.name]["last_passes"] = {{"passes", r.last_passes->passes},
                                          {"least", r.last_passes->least},
                                          {"largest", r.last_passes->largest}};
    }
    out["flow"] = {{"boundaries", boundaries}, {"balance", s.flow->balance}, {"regions", regions}};
    if (s.flow->iteration) out["flow"]["iteration"] = *s.flow->iteration;
    if (s.flow->storage_rate) out["flow"]["storage_rate"] = *s.flow->storage_rate;
  }
  if (s.outside_mesh)
    out["outside_mesh"] = {{"largest_distance", s.outside_mesh->largest_distance},
                           {"block", s.outside_mesh->block},
                           {"blocks", s.outside_mesh->blocks}};
  if (s.fractures) out["fractures"] = format_fractures(*s.fractures);
  if (s.time) out["time"] = *s.time;
  if (s.last_held) {
    json held = {{"state", s.last_held->state}, {"step", s.last_held->step}};
    if (s.last_held->open_fractures) held["open_fractures"] = *s.last_held->open_fractures;
    if (s.last_held->broken_bonds) held["broken_bonds"] = *s.last_held->broken_bonds;
    out["last_held"] = held;
  }
  return out;
}

// One step of the path from the summary's root to a value: a key of an object, or else an
// index into an array.
struct PathStep {
  const std::string* key = nullptr;
  std::size_t index = 0;
};

// The path as find_non_finite_values names it: keys joined by '.', indices as "[i]".
std::string join_path(const std::vector<PathStep>& path) {
  std::string joined;
  for (const PathStep& step : path) {
    if (step.key) {
      if (!joined.empty()) joined += '.';
      joined += *step.key;
    } else {
      joined += '[' + std::to_string(step.index) + ']';
    }
  }
  return joined;
}

// The path is joined only for a value found: the walk visits every number of the summary.
void collect_non_finite(const json& value, std::vector<PathStep>& path, std::vector<std::string>& found) {
  if (value.is_number_float()) {
    if (!std::isfinite(value.get<double>())) found.push_back(join_path(path));
  } else if (value.is_object()) {
    for (auto item = value.begin(); item != value.end(); ++item) {
      path.push_back({&item.key(), 0});
      collect_non_finite(item.value(), path, found);
      path.pop_back();
    }
  } else if (value.is_array()) {
    for (std::size_t i = 0; i < value.size(); ++i) {
      path.push_back({nullptr, i});
      collect_non_finite(value[i], path, found);
      path.pop_back();
    }
  }
}

std::string dump(const json& summary) { return summary.dump(2) + "\n"; }

}  // namespace

std::string format_summary(const RunSummary& s) { return dump(to_json(s)); }

CheckedSummary format_checked_summary(const RunSummary& s) {
  const json summary = to_json(s);
  CheckedSummary checked;
  std::vector<PathStep> path;
  collect_non_finite(summary, path, checked.non_finite);
  checked.text = dump(summary);
  return checked;
}

}  // namespace hydrodda::output
