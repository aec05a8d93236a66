#include "run/bond_output.hpp"

#include <fmt/format.h>

#include "output/field_figure.hpp"
#include "output/vtk_writer.hpp"

namespace hydrodda::run {

namespace {

const char* mode_name(dda::BondFailure mode) { return mode == dda::BondFailure::shear ? "shear" : "tension"; }

}  // namespace

BondOutput::BondOutput(const output::RunFolder& folder, const scenario::Scenario& s, const dda::System& system,
                       int trace_count)
    : folder_(folder), trace_count_(trace_count) {
  for (int b = 0; b < system.bond_count(); ++b) {
    const std::string& name = s.joint_type(system.bond_joint_type(b)).name;
    type_names_.push_back(name.empty() ? "joint" : name);
  }
}

int BondOutput::add_breaks(long long step, const dda::System& system, FractureOutput& fractures) {
  const std::vector<dda::BondBreak>& breaks = system.bond_breaks();
  std::vector<BrokenBondRow> rows;
  for (std::size_t k = listed_; k < breaks.size(); ++k) {
    const dda::BondBreak& b = breaks[k];
    rows.push_back({trace_count_ + b.bond, b.bond, b.time, mode_name(b.mode),
                    type_names_.at(static_cast<std::size_t>(b.bond)), b.from, b.to});
  }
  listed_ = breaks.size();
  if (!rows.empty()) fractures.add_broken_bonds(step, rows);
  return static_cast<int>(rows.size());
}

void BondOutput::write_series(int step, double time, const dda::System& system) {
  std::vector<std::array<geometry::Point, 2>> faces;
  output::DataArray bond{"bond", 1, {}}, broken{"broken", 1, {}}, mode{"mode", 1, {}}, broken_at{"broken_at", 1, {}};
  for (int b = 0; b < system.bond_count(); ++b) {
    faces.push_back(system.bond_face(b));
    bond.values.push_back(b);
    broken.values.push_back(system.is_bond_broken(b) ? 1.0 : 0.0);
    mode.values.push_back(0.0);
    broken_at.values.push_back(-1.0);
  }
  for (const dda::BondBreak& b : system.bond_breaks()) {
    mode.values[static_cast<std::size_t>(b.bond)] = b.mode == dda::BondFailure::shear ? 2.0 : 1.0;
    broken_at.values[static_cast<std::size_t>(b.bond)] = b.time;
  }
  const std::vector<output::DataArray> cells{bond, broken, mode, broken_at};
  const std::string name = fmt::format("bonds_{:04d}.vtu", step);
  output::write_vtu_segments(folder_.file(name), faces, cells);
  if (!series_) series_.emplace(folder_.file("bonds.pvd"));
  series_->add(time, name);
}

void BondOutput::draw_figure(const scenario::Scenario& s, const dda::System& system, const std::string& when) const {
  if (s.output.figures.empty()) return;
  output::FieldFigure figure;
  figure.title = s.title;
  figure.subtitle = fmt::format("Broken bonds ({} of {}; intact in grey), {}", system.bond_breaks().size(),
                                system.bond_count(), when);
  figure.field_label = "broke at (s)";
  for (int b = 0; b < system.block_count(); ++b) figure.blocks.push_back(system.polygon(b));
  std::vector<double> broken_at(static_cast<std::size_t>(system.bond_count()), 0.0);
  for (const dda::BondBreak& b : system.bond_breaks()) broken_at[static_cast<std::size_t>(b.bond)] = b.time;
  for (int b = 0; b < system.bond_count(); ++b) {
    figure.segments.push_back(system.bond_face(b));
    figure.segment_values.push_back(broken_at[static_cast<std::size_t>(b)]);
    figure.segment_highlighted.push_back(system.is_bond_broken(b));
  }
  for (const std::string& format : s.output.figures)
    output::render_field_figure(folder_.figures() / ("cracks." + format), figure);
}

}  // namespace hydrodda::run
