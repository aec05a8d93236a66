#include "scenario/transient_reading.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "geometry/polygon.hpp"
#include "scenario/bounds.hpp"

namespace hydrodda::scenario {

namespace {

// output_times: an array of finite numbers, increasing, in [0, end_time].
std::vector<double> read_output_times(ReadContext& ctx, const TableView& t, double end_time) {
  const toml::node* node = t.node("output_times");
  if (!node) return {};
  const std::string key = t.key_path("output_times");
  const toml::array* array = node->as_array();
  if (!array || array->empty()) {
    ctx.error(t.line_of_key("output_times"), key, "expected an array of times (s) such as [8.64e6, 3.15e7]");
    return {};
  }
  std::vector<double> times;
  for (const toml::node& item : *array) {
    const std::optional<double> value = item.is_number() ? item.value<double>() : std::nullopt;
    if (!value || !std::isfinite(*value)) {
      ctx.error(line_of(item), key, "each output time must be a finite number (s)");
      return {};
    }
    if (*value < 0.0 || (end_time > 0.0 && *value > end_time)) {
      ctx.error(line_of(item), key, fmt::format("{:g} s lies outside [0, end_time = {:g} s]", *value, end_time));
      return {};
    }
    if (!times.empty() && !(*value > times.back())) {
      ctx.error(line_of(item), key,
                fmt::format("the times must increase: {:g} s comes after {:g} s", *value, times.back()));
      return {};
    }
    times.push_back(*value);
  }
  return times;
}

// initial_head: a number (m) or "steady".
std::optional<double> read_initial_head(ReadContext& ctx, const TableView& t, double lowest, double highest) {
  const toml::node* node = t.node("initial_head");
  if (!node) {
    ctx.defaults.push_back({"flow.transient.initial_head", "\"steady\""});
    return std::nullopt;
  }
  if (const auto text = node->value<std::string>(); text && node->is_string()) {
    if (*text != "steady")
      ctx.error(t.line_of_key("initial_head"), t.key_path("initial_head"),
                fmt::format("expected a head (m) or \"steady\", got \"{}\"", *text));
    return std::nullopt;
  }
  const std::optional<double> head = t.number("initial_head");
  if (head)
    t.require("initial_head", std::isfinite(*head) && *head >= lowest && *head <= highest,
              fmt::format("must lie within {:g} m of the model's heights: a head farther off is a pressure past 10 GPa",
                          kMaxPressureHead));
  return head;
}

// Inside the polygon or on its outline (to 1e-12 of its size): a probe may sit on a boundary.
bool holds_or_borders(const Polygon& polygon, Point p) {
  if (geometry::contains(polygon, p)) return true;
  const geometry::Box box = geometry::bounding_box(polygon);
  const double size = std::max(box.width(), box.height());
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Point a = polygon[i], b = polygon[(i + 1) % polygon.size()];
    const double length = geometry::distance(a, b);
    const double along = geometry::dot(p - a, b - a) / (length * length);
    if (along >= 0.0 && along <= 1.0 && std::abs(geometry::orient(a, b, p)) <= 1e-12 * size * length) return true;
  }
  return false;
}

}  // namespace

void read_transient(ReadContext& ctx, const TableView& flow_table, double lowest_head, double highest_head,
                    FlowDefinition& flow) {
  const toml::table* table = flow_table.table("transient");
  if (!table) return;
  const TableView t(ctx, *table, "flow.transient",
                    {"end_time", "time_step", "max_time_step", "output_times", "initial_head"});
  TransientDefinition transient;
  transient.line = t.line();
  if (!t.has("end_time")) ctx.error(t.line(), "flow.transient.end_time", "required key is missing");
  transient.end_time = t.number("end_time").value_or(0.0);
  if (t.has("end_time"))
    t.require("end_time", std::isfinite(transient.end_time) && transient.end_time > 0.0, "must be > 0 (s)");
  const double end = transient.end_time > 0.0 && std::isfinite(transient.end_time) ? transient.end_time : 0.0;
  // The defaults: a first step of a thousandth of the run, growing to a twentieth.
  transient.time_step = t.number_or("time_step", end / 1000.0);
  transient.max_time_step = t.number_or("max_time_step", end / 20.0);
  if (end > 0.0) {
    t.require("time_step", transient.time_step > 0.0 && transient.time_step <= end,
              fmt::format("must lie in (0, end_time = {:g}] s", end));
    t.require("max_time_step", transient.max_time_step >= transient.time_step && transient.max_time_step <= end,
              fmt::format("must lie in [time_step = {:g}, end_time = {:g}] s", transient.time_step, end));
    t.require("max_time_step", !(transient.max_time_step > 0.0) || end / transient.max_time_step <= kMaxTransientSteps,
              fmt::format("end_time / max_time_step is {:g} steps; at most {:g}", end / transient.max_time_step,
                          kMaxTransientSteps));
  }
  transient.output_times = read_output_times(ctx, t, end);
  if (!t.has("output_times")) {
    transient.output_times = {end};
    ctx.defaults.push_back({"flow.transient.output_times", fmt::format("[{:g}]", end)});
  }
  transient.initial_head = read_initial_head(ctx, t, lowest_head, highest_head);
  flow.transient = std::move(transient);
}

void read_probes(ReadContext& ctx, const TableView& flow_table, FlowDefinition& flow) {
  for (const toml::table* pt : flow_table.tables("probe")) {
    const TableView p(ctx, *pt, "flow.probe", {"name", "point"});
    ProbeDefinition probe;
    probe.line = p.line();
    probe.name = p.string("name").value_or("");
    if (!p.has("name")) ctx.error(p.line(), "flow.probe.name", "required key is missing");
    else if (probe.name.empty() || probe.name.find_first_of(",\"\n\r") != std::string::npos)
      ctx.error(p.line_of_key("name"), "flow.probe.name", "must be a name without commas, quotes or line breaks (it is a probes.csv cell)");
    for (const ProbeDefinition& other : flow.probes)
      if (!probe.name.empty() && other.name == probe.name)
        ctx.error(p.line_of_key("name"), "flow.probe.name",
                  fmt::format("\"{}\" is already used (line {})", probe.name, other.line));
    if (const auto point = p.point("point")) probe.point = *point;
    else if (!p.has("point")) ctx.error(p.line(), "flow.probe.point", "required key is missing");
    flow.probes.push_back(std::move(probe));
  }
}

void check_transient(ReadContext& ctx, const TableView&, const Scenario& s) {
  if (!s.flow) return;
  if (s.flow->transient) {
    const TransientDefinition& t = *s.flow->transient;
    // A coupled transient run steps by the fixed-stress split: each step's passes are its
    // iterations, which neither mix heads across steps nor step in pseudo-time.
    if (s.mechanics && s.coupling.acceleration != coupling::Acceleration::none)
      ctx.error(t.line, "coupling.acceleration",
                "a coupled transient run ([flow.transient]) iterates each time step by the fixed-stress split, "
                "without acceleration: remove coupling.acceleration");
    if (s.mechanics && s.coupling.pseudo_time_step > 0.0)
      ctx.error(t.line, "coupling.pseudo_time_step",
                "a coupled transient run ([flow.transient]) steps in real time: remove coupling.pseudo_time_step "
                "(it is for steady coupled runs)");
    // A storage refused where it was given is not also "absent". In a coupled run a block
    // with Biot's α > 0 stores water by its strain.
    const bool any_storage = std::any_of(s.materials.begin(), s.materials.end(), [&](const MaterialDefinition& m) {
      return m.storage > 0.0 || ctx.has_error("material." + m.name + ".storage") ||
             (s.mechanics && m.biot_coefficient > 0.0);
    });
    // Or the water of the open gaps between blocks, by its compressibility; in a coupled run
    // also that of the joints' hydraulic apertures (docs/coupling.md, "Coupled transient runs").
    const bool compressible = s.flow->fluid_compressibility > 0.0;
    const bool gaps_store = compressible && s.geometry && s.geometry->initial_aperture > 0.0;
    const bool has_joints = s.geometry && (!s.geometry->fractures.empty() || !s.geometry->joint_sets.empty() ||
                                           !s.geometry->file_fractures.empty() || !s.geometry->tessellations.empty() ||
                                           s.geometry->blocks.size() > 1);
    const bool joints_store = compressible && s.mechanics && s.any_joint_hydraulic() && has_joints;
    if (!any_storage && !gaps_store && !joints_store)
      ctx.error(t.line, "flow.transient",
                fmt::format("no material has a storage (every [material.NAME] storage is 0 or absent{}) and no {} "
                            "holds water ({}), so nothing stores water and the heads jump to the steady ones at once: "
                            "give storage (1/Pa) to the materials, or remove [flow.transient] for a steady run",
                            s.mechanics ? ", every biot_coefficient 0" : "",
                            s.mechanics ? "open gap or joint" : "open gap",
                            !compressible ? "the fluid is incompressible: flow.fluid.compressibility = 0"
                            : s.mechanics ? "geometry.initial_aperture is 0 and no joint type has a hydraulic aperture"
                                          : "geometry.initial_aperture is 0"));
  }
  for (const ProbeDefinition& probe : s.flow->probes) {
    if (s.mechanics && !s.flow->transient)
      ctx.error(probe.line, "flow.probe",
                "probes in a steady coupled run are not built yet (a coupled run with [flow.transient] has them)");
    if (s.geometry && s.geometry->domain.size() >= 3 && !holds_or_borders(s.geometry->domain, probe.point))
      ctx.error(probe.line, "flow.probe.point",
                fmt::format("({:g}, {:g}) lies outside geometry.domain", probe.point.x, probe.point.y));
  }
}

}  // namespace hydrodda::scenario
