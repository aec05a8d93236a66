#include "run/fracture_output.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <fstream>
#include <sstream>
#include <string>

#include "output/field_figure.hpp"
#include "output/vtk_writer.hpp"
#include "run/model_geometry.hpp"
#include "run/paraview_output.hpp"

namespace hydrodda::run {

using output::CsvTable;
using output::DataArray;

namespace {

std::vector<std::string> columns(bool with_flow, bool with_bonds = false) {
  std::vector<std::string> c{"step",          "time",          "fracture",     "origin",    "set",
                             "number",        "length",        "open_length",  "open",      "mean_aperture",
                             "max_aperture",  "hydraulic_aperture", "normal_stress", "max_shear",
                             "tip_opening_angle"};
  if (with_flow) c.push_back("flow");
  // Added last, so that the columns before them keep their places.
  c.push_back("type");
  c.push_back("open_share");
  if (with_bonds)
    for (const char* name : {"mode", "x1", "y1", "x2", "y2"}) c.push_back(name);
  return c;
}

}  // namespace

// The name of fracture `id`'s joint type; empty where none is known.
std::string type_of(const std::vector<std::string>& types, int id) {
  return id >= 0 && id < static_cast<int>(types.size()) ? types[static_cast<std::size_t>(id)] : std::string();
}

FractureOutput::FractureOutput(const output::RunFolder& folder, bool with_flow, std::vector<std::string> types)
    : folder_(folder), with_flow_(with_flow), types_(std::move(types)), table_(columns(with_flow)) {}

std::vector<std::string> fracture_type_names(const scenario::Scenario& s) {
  std::vector<std::string> names;
  if (!s.geometry || s.geometry->domain.empty()) return names;
  for (const geometry::FractureTrace& t : collect_fracture_traces(s)) {
    const std::string& name = s.joint_type(t.joint_type).name;
    names.push_back(name.empty() ? "joint" : name);
  }
  return names;
}

void FractureOutput::continue_from(int last_step, const std::vector<int>& written) {
  keep_rows_up_to(last_step);
  if (!series_) series_.emplace(folder_.file("fractures.pvd"));
  for (int step : written) list_if_present(*series_, folder_, step, fmt::format("fractures_{:04d}.vtu", step));
}

void FractureOutput::continue_in_time(int last_step, const std::vector<double>& written_times) {
  keep_rows_up_to(last_step);
  if (!series_) series_.emplace(folder_.file("fractures.pvd"));
  for (std::size_t i = 0; i < written_times.size(); ++i)
    list_if_present(*series_, folder_, written_times[i], fmt::format("fractures_{:04d}.vtu", i));
}

void FractureOutput::keep_rows_up_to(int last_step) {
  std::ifstream in(folder_.file("fractures.csv"));
  std::string line;
  std::getline(in, line);  // the header
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::stringstream fields(line);
    for (std::string cell; std::getline(fields, cell, ',');) cells.push_back(cell);
    // Rows of a pass after the checkpoint (written before the run stopped) are left out.
    if (cells.size() == columns(with_flow_, with_bonds_).size() && std::stoll(cells[0]) <= last_step) table_.add_row(cells);
  }
}

void FractureOutput::add_rows(long long step, double time, const fractures::FractureState& state) {
  for (const fractures::FractureResult& r : state.fractures) {
    const bool from_set = r.origin.source == geometry::TraceSource::joint_set;
    std::vector<std::string> row{CsvTable::cell(step),
                                 CsvTable::cell(time),
                                 CsvTable::cell(static_cast<long long>(r.id)),
                                 fractures::origin_name(r.origin.source),
                                 from_set ? CsvTable::cell(static_cast<long long>(r.origin.set)) : "",
                                 CsvTable::cell(static_cast<long long>(r.origin.number)),
                                 CsvTable::cell(r.length),
                                 CsvTable::cell(r.open_length),
                                 CsvTable::cell(static_cast<long long>(r.open ? 1 : 0)),
                                 CsvTable::cell(r.mean_aperture),
                                 CsvTable::cell(r.max_aperture),
                                 CsvTable::cell(r.hydraulic_aperture),
                                 CsvTable::cell(r.normal_stress),
                                 CsvTable::cell(r.max_shear),
                                 CsvTable::cell(r.tip_opening_angle)};
    if (with_flow_) row.push_back(r.flow ? CsvTable::cell(*r.flow) : "");
    row.push_back(type_of(types_, r.id));
    row.push_back(CsvTable::cell(r.open_share));
    if (with_bonds_) row.resize(row.size() + 5);
    table_.add_row(row);
  }
  folder_.write("fractures.csv", table_.text());
}

void FractureOutput::list_broken_bonds() {
  with_bonds_ = true;
  table_ = CsvTable(columns(with_flow_, true));
}

void FractureOutput::add_broken_bonds(long long step, const std::vector<BrokenBondRow>& rows) {
  for (const BrokenBondRow& b : rows) {
    std::vector<std::string> row{CsvTable::cell(step), CsvTable::cell(b.time), CsvTable::cell(static_cast<long long>(b.fracture)),
                                 "bond", "", CsvTable::cell(static_cast<long long>(b.bond)),
                                 CsvTable::cell(geometry::distance(b.from, b.to))};
    // open_length … tip_opening_angle (and flow): measured on traces only.
    row.resize(row.size() + 1, "");
    row.push_back("1");
    row.resize(row.size() + 6 + (with_flow_ ? 1 : 0), "");
    row.push_back(b.type);
    row.push_back("");  // open_share
    for (const std::string& cell : {b.mode, CsvTable::cell(b.from.x), CsvTable::cell(b.from.y), CsvTable::cell(b.to.x),
                                    CsvTable::cell(b.to.y)})
      row.push_back(cell);
    table_.add_row(row);
  }
  folder_.write("fractures.csv", table_.text());
}

void FractureOutput::write_series(int step, double time, const fractures::FractureState& state) {
  std::vector<std::array<geometry::Point, 2>> segments;
  DataArray fracture{"fracture", 1, {}}, aperture{"aperture", 1, {}}, shear{"shear", 1, {}}, open{"open", 1, {}},
      hydraulic{"hydraulic_aperture", 1, {}}, flow{"flow", 1, {}};
  std::vector<double> flow_of(state.fractures.empty() ? 0 : state.fractures.back().id + 1, 0.0);
  for (const fractures::FractureResult& r : state.fractures)
    if (r.flow) flow_of[r.id] = *r.flow;
  for (const fractures::FracturePiece& p : state.pieces) {
    segments.push_back(p.segment);
    fracture.values.push_back(p.fracture);
    aperture.values.push_back(p.aperture);
    shear.values.push_back(p.shear);
    open.values.push_back(p.open ? 1.0 : 0.0);
    hydraulic.values.push_back(p.hydraulic_aperture);
    flow.values.push_back(flow_of[p.fracture]);
  }
  std::vector<DataArray> cells{fracture, aperture, shear, open, hydraulic};
  if (with_flow_) cells.push_back(flow);
  const std::string name = fmt::format("fractures_{:04d}.vtu", step);
  output::write_vtu_segments(folder_.file(name), segments, cells);
  if (!series_) series_.emplace(folder_.file("fractures.pvd"));
  series_->add(time, name);
}

output::FractureSummary summarise_fractures(const fractures::FractureState& state, const std::vector<std::string>& types) {
  output::FractureSummary summary;
  for (const fractures::FractureResult& r : state.fractures) {
    output::FractureRow row;
    row.id = r.id;
    row.origin = fractures::origin_name(r.origin.source);
    if (r.origin.source == geometry::TraceSource::joint_set) row.set = r.origin.set;
    row.number = r.origin.number;
    row.type = type_of(types, r.id);
    row.length = r.length;
    row.open_length = r.open_length;
    row.open_share = r.open_share;
    row.open = r.open;
    row.mean_aperture = r.mean_aperture;
    row.max_aperture = r.max_aperture;
    row.hydraulic_aperture = r.hydraulic_aperture;
    row.normal_stress = r.normal_stress;
    row.max_shear = r.max_shear;
    row.tip_opening_angle = r.tip_opening_angle;
    row.flow = r.flow;
    summary.rows.push_back(row);
  }
  return summary;
}

void draw_aperture_figure(const scenario::Scenario& s, const output::RunFolder& folder,
                          std::span<const geometry::Polygon> blocks, const fractures::FractureState& state,
                          const FigureState& shown) {
  if (s.output.figures.empty() || state.pieces.empty()) return;
  spdlog::debug("figures: drawing in {}", folder.figures().string());
  output::FieldFigure figure;
  figure.title = s.title;
  figure.subtitle = "Fracture apertures (closed fractures in grey), " + shown.when;
  figure.warning = shown.status;
  figure.field_label = "mechanical aperture (mm)";
  figure.blocks.assign(blocks.begin(), blocks.end());
  for (const fractures::FracturePiece& p : state.pieces) {
    figure.segments.push_back(p.segment);
    figure.segment_values.push_back(p.aperture * 1e3);
    figure.segment_highlighted.push_back(p.open);
  }
  for (const std::string& format : s.output.figures)
    output::render_field_figure(folder.figures() / ("apertures." + format), figure);
  if (!s.any_joint_hydraulic()) return;
  // Joints that conduct while closed (a residual aperture, Barton–Bandis closure) are all grey
  // in the mechanical figure: this one colours every piece by the aperture the flow sees, on a
  // log scale, as closed ones carry micrometres and open ones millimetres.
  figure.subtitle = "Joint hydraulic apertures (closed joints by their closure law), " + shown.when;
  figure.field_label = "hydraulic aperture (µm, log scale)";
  figure.logarithmic = true;
  for (std::size_t k = 0; k < state.pieces.size(); ++k) {
    figure.segment_values[k] = state.pieces[k].hydraulic_aperture * 1e6;
    figure.segment_highlighted[k] = state.pieces[k].hydraulic_aperture > 0.0;
  }
  for (const std::string& format : s.output.figures)
    output::render_field_figure(folder.figures() / ("hydraulic_apertures." + format), figure);
}

}  // namespace hydrodda::run
