#include "breach/breach_files.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <nlohmann/json.hpp>

#include "output/plot_line.hpp"
#include "output/quantity_label.hpp"
#include "output/summary_reading.hpp"
#include "output/summary.hpp"
#include "run/figures.hpp"
#include "run/fracture_output.hpp"

namespace hydrodda::breach {

namespace {

using output::CsvTable;

std::vector<std::string> region_names(const scenario::Scenario& s) {
  std::vector<std::string> names;
  if (s.flow)
    for (const auto& region : s.flow->regions) names.push_back(region.name);
  return names;
}

std::vector<std::string> columns_of(const std::vector<std::string>& regions, const std::optional<Limit>& limit,
                                    bool bonded) {
  std::vector<std::string> columns{"step", "load", "kind", "status", "passes", "largest_opening", "open_fractures"};
  for (const std::string& region : regions)
    for (const char* suffix : {"", "_least", "_largest"})
      columns.push_back(fmt::format("flow.regions.{}.normalised_conductivity{}", region, suffix));
  if (limit) columns.push_back(limit->path);
  if (bonded) columns.insert(columns.end(), {"broken_bonds", "broken_bonds_total"});
  columns.push_back("message");
  return columns;
}

bool is_state(StepStatus status) {
  return status == StepStatus::held || status == StepStatus::held_unsettled || status == StepStatus::beyond_limit;
}

std::string cell(const std::optional<double>& value) { return value ? CsvTable::cell(*value) : ""; }

nlohmann::json held_json(const HeldState& h, const std::vector<std::string>& regions, bool bonded) {
  nlohmann::json j{{"load", h.load}, {"largest_opening", h.largest_opening}, {"open_fractures", h.open_fractures}};
  nlohmann::json k = nlohmann::json::object();
  for (std::size_t r = 0; r < regions.size(); ++r)
    k[regions[r]] = h.conductivity[r] ? nlohmann::json(*h.conductivity[r]) : nlohmann::json(nullptr);
  j["normalised_conductivity"] = k;
  j["unsettled"] = h.unsettled;
  if (bonded) {
    j["broken_bonds"] = h.broken_bonds;
    j["broken_bonds_total"] = h.broken_bonds_total;
  }
  if (h.unsettled) {
    nlohmann::json ranges = nlohmann::json::object();
    for (std::size_t r = 0; r < regions.size() && r < h.ranges.size(); ++r)
      ranges[regions[r]] = h.ranges[r] ? nlohmann::json{{"least", h.ranges[r]->least}, {"largest", h.ranges[r]->largest}}
                                       : nlohmann::json(nullptr);
    j["normalised_conductivity_range"] = ranges;
  }
  return j;
}

}  // namespace

BreachFiles::BreachFiles(const output::RunFolder& folder, const scenario::Scenario& scenario, std::string key,
                         std::optional<Limit> limit, const dda::System& mechanics)
    : folder_(folder),
      scenario_(scenario),
      key_(std::move(key)),
      limit_(std::move(limit)),
      regions_(region_names(scenario)),
      table_(columns_of(regions_, limit_, mechanics.bond_count() > 0)),
      paraview_(folder, scenario.output.fields),
      fractures_(folder, true, run::fracture_type_names(scenario)) {
  if (mechanics.bond_count() == 0) return;
  fractures_.list_broken_bonds();
  bonds_.emplace(folder, scenario, mechanics, static_cast<int>(run::fracture_type_names(scenario).size()),
                 run::BondClock::load);
}

void BreachFiles::write_scenario(const std::string& text) const { folder_.write("scenario.toml", text); }

HeldState BreachFiles::measure(const SearchStep& step, const output::RunSummary& summary,
                               const std::vector<std::optional<ValueRange>>& ranges) const {
  HeldState h;
  h.load = step.load;
  h.beyond_limit = step.result.status == StepStatus::beyond_limit;
  h.unsettled = !summary.converged;  // held unsettled, beyond the limit or not
  for (const std::string& region : regions_) {
    std::optional<double> value;
    if (summary.flow && !h.unsettled)  // an unsettled answer is a range, not one number
      for (const output::RegionSummary& r : summary.flow->regions)
        if (r.name == region) value = r.normalised_conductivity;
    h.conductivity.push_back(value);
  }
  if (h.unsettled) h.ranges = ranges;
  h.ranges.resize(regions_.size());
  if (summary.fractures)
    for (const output::FractureRow& f : summary.fractures->rows) {
      h.largest_opening = std::max(h.largest_opening, f.max_aperture);
      if (f.open) h.open_fractures.push_back(f.id);  // as summary.json counts them (docs/output.md)
    }
  if (limit_) {
    const std::string text = output::format_summary(summary);
    if (const auto v = output::summary_values(text, {limit_->path})[0]) h.limit_value = std::stod(*v);
  }
  return h;
}

std::vector<std::string> BreachFiles::row_of(const SearchStep& step, const std::optional<HeldState>& held) const {
  std::vector<std::string> row{std::to_string(step.index), CsvTable::cell(step.load), step.bisection ? "bisection" : "step",
                               status_name(step.result.status), std::to_string(step.result.passes)};
  row.push_back(held ? CsvTable::cell(held->largest_opening) : "");
  row.push_back(held ? std::to_string(held->open_fractures.size()) : "");
  for (std::size_t r = 0; r < regions_.size(); ++r) {
    row.push_back(held ? cell(held->conductivity[r]) : "");
    const bool ranged = held && held->ranges[r].has_value();
    row.push_back(ranged ? CsvTable::cell(held->ranges[r]->least) : "");
    row.push_back(ranged ? CsvTable::cell(held->ranges[r]->largest) : "");
  }
  if (limit_) row.push_back(held ? cell(held->limit_value) : "");
  if (bonds_) {
    row.push_back(held ? std::to_string(held->broken_bonds.size()) : "");
    row.push_back(held ? std::to_string(held->broken_bonds_total) : "");
  }
  row.push_back(step.result.message);
  return row;
}

void BreachFiles::add_step(const SearchStep& step, const CoupledStepper& stepper, bool kept) {
  std::optional<HeldState> held;
  if (is_state(step.result.status)) {
    output::RunSummary summary = stepper.summary();
    summary.message = step.result.message;
    folder_.subfolder("steps");
    folder_.write(fmt::format("steps/step_{:03d}.json", step.index), output::format_summary(summary));
    held = measure(step, summary, stepper.unsettled_ranges());
    record_fractures(step, stepper, kept, *held);
    held_.push_back(*held);
    const run::CoupledModel& model = stepper.model();
    const auto& loop = model.loop();
    paraview_.write_fluid(step.index, step.load, model.mesh(), loop.flow(), loop.porosity().porosity, loop.permeability());
    paraview_.write_blocks(step.index, step.load, model.mechanics());
  }
  steps_.push_back(step);
  table_.add_row(row_of(step, held));
  folder_.write("breach.csv", table_.text());
}

void BreachFiles::record_fractures(const SearchStep& step, const CoupledStepper& stepper, bool kept, HeldState& held) {
  const dda::System& mechanics = stepper.model().mechanics();
  if (bonds_) {
    // The model stands at this step's state, reached from the last kept: the breaks past those
    // recorded are this step's (a step not kept leaves none behind: the model goes back).
    const std::vector<dda::BondBreak>& breaks = mechanics.bond_breaks();
    for (std::size_t k = static_cast<std::size_t>(bonds_listed_); k < breaks.size(); ++k)
      held.broken_bonds.push_back(breaks[k].bond);
    held.broken_bonds_total = static_cast<int>(breaks.size());
    if (kept) {  // recorded as a run records them; a state the search does not go on from is not
      bonds_listed_ += bonds_->add_breaks(step.index, mechanics, fractures_, step.load);
      bonds_->write_series(step.index, step.load, mechanics);
    }
  }
  if (const std::optional<fractures::FractureState> state = stepper.measure_fractures())
    fractures_.add_rows(step.index, step.load, *state);
}

void BreachFiles::write_last_held(double load, const CoupledStepper& stepper) {
  output::RunSummary summary = stepper.summary();
  folder_.write("last_held.json", output::format_summary(summary));
  if (scenario_.output.figures.empty()) return;
  const run::CoupledModel& model = stepper.model();
  const auto& loop = model.loop();
  const std::vector<geometry::Polygon> blocks = model.block_polygons();
  const std::string when = fmt::format("the last state that held, {} = {:.6g}", key_, load);
  try {
    run::draw_figures(scenario_, folder_,
                      {model.mesh(), loop.flow(), loop.porosity().porosity, loop.permeability(), blocks, when,
                       model.iterations()});
    if (const std::optional<fractures::FractureState> state = stepper.measure_fractures())
      run::draw_aperture_figure(scenario_, folder_, blocks, *state, {when, ""});
    if (bonds_) bonds_->draw_figure(scenario_, model.mechanics(), when);
  } catch (const std::exception& e) {
    spdlog::warn("the figures of the last state that held could not be drawn: {}", e.what());
  }
}

void BreachFiles::finish(const SearchResult& result, const std::string& verdict, const SearchSettings& settings) {
  nlohmann::json j{{"key", key_},          {"from", settings.from},           {"to", settings.to},
                   {"steps", settings.steps}, {"tolerance", settings.tolerance}, {"verdict", verdict},
                   {"interrupted", result.interrupted}, {"narrowed", result.narrowed}};
  j["held"] = result.held ? nlohmann::json(*result.held) : nlohmann::json(nullptr);
  j["broken"] = result.broken ? nlohmann::json(*result.broken) : nlohmann::json(nullptr);
  j["broken_status"] = result.broken_status ? nlohmann::json(status_name(*result.broken_status)) : nlohmann::json(nullptr);
  j["broken_message"] = nlohmann::json(nullptr);
  for (const SearchStep& step : steps_)
    if (result.broken && step.load == *result.broken && !holds(step.result.status, settings))
      j["broken_message"] = step.result.message;
  j["last_held"] = nlohmann::json(nullptr);
  for (const HeldState& h : held_)
    if (result.held && h.load == *result.held && !h.beyond_limit) j["last_held"] = held_json(h, regions_, bonds_.has_value());
  j["rule"] = settings.converged_only ? "converged only" : "mechanical";
  j["unsettled_held"] = result.unsettled_held;
  j["worst_unsettled_spread"] = nlohmann::json(nullptr);
  if (const std::optional<UnsettledSpread> worst = worst_unsettled_spread())
    j["worst_unsettled_spread"] = {{"spread", worst->spread}, {"load", worst->load}, {"region", worst->region}};
  folder_.write("breach.json", j.dump(2) + "\n");
  for (const std::string& format : scenario_.output.figures) {
    try {
      draw_curves(format);
    } catch (const std::exception& e) {
      spdlog::warn("the breach curves could not be drawn: {}", e.what());
    }
  }
}

std::optional<UnsettledSpread> BreachFiles::worst_unsettled_spread() const {
  std::optional<UnsettledSpread> worst;
  for (const HeldState& h : held_)
    for (std::size_t r = 0; h.unsettled && r < h.ranges.size(); ++r)
      if (h.ranges[r] && (!worst || h.ranges[r]->spread() > worst->spread))
        worst = UnsettledSpread{h.ranges[r]->spread(), h.load, regions_[r]};
  return worst;
}

void BreachFiles::draw_curves(const std::string& format) const {
  std::vector<HeldState> held = held_;
  std::sort(held.begin(), held.end(), [](const HeldState& a, const HeldState& b) { return a.load < b.load; });
  std::vector<double> broken;
  for (const SearchStep& step : steps_)
    if (!is_state(step.result.status)) broken.push_back(step.load);
  output::LinePlotSpec k;
  k.title = scenario_.title;
  std::vector<std::string> boundaries;  // what flow.boundary[i] names: "pressure at bottom (Pa)"
  if (scenario_.flow)
    for (const scenario::FlowBoundaryCondition& b : scenario_.flow->boundaries) boundaries.push_back(b.name);
  k.x_label = output::quantity_label(key_, boundaries);
  k.y_label = "K_eff / K_matrix";
  k.y_log = true;
  k.open_label = "beyond the limit";
  k.range_label = "unsettled (its last passes)";
  k.marks_x = broken;
  k.marks_label = "did not hold";
  for (std::size_t r = 0; r < regions_.size(); ++r) {
    output::LineSeries series{regions_[r], {}, {}, {}};
    std::vector<output::RangeBar> bars;
    for (const HeldState& h : held) {
      if (const std::optional<ValueRange>& range = h.ranges[r])
        bars.push_back({k.series.size(), h.load, range->least, range->largest});
      if (!h.conductivity[r]) continue;
      series.x.push_back(h.load);
      series.y.push_back(*h.conductivity[r]);
      series.open.push_back(h.beyond_limit);
    }
    if (series.x.empty() && bars.empty()) continue;
    k.series.push_back(std::move(series));
    k.range_bars.insert(k.range_bars.end(), bars.begin(), bars.end());
  }
  if (!k.series.empty()) output::render_line_plot(folder_.figures() / ("breach." + format), k);
  output::LinePlotSpec w = k;
  w.y_label = "largest fracture opening (mm)";
  w.y_log = false;
  w.y_at_least_zero = true;
  w.range_bars.clear();
  w.open_label = "beyond the limit, or held unsettled (its last pass)";
  w.series = {output::LineSeries{"largest opening", {}, {}, {}}};
  for (const HeldState& h : held) {
    w.series[0].x.push_back(h.load);
    w.series[0].y.push_back(1e3 * h.largest_opening);
    w.series[0].open.push_back(h.beyond_limit || h.unsettled);
  }
  if (!w.series[0].x.empty()) output::render_line_plot(folder_.figures() / ("breach_opening." + format), w);
}

}  // namespace hydrodda::breach
