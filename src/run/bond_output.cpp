#include "run/bond_output.hpp"

#include <fmt/format.h>

#include "output/field_figure.hpp"
#include "output/vtk_writer.hpp"
#include "run/paraview_output.hpp"

namespace hydrodda::run {

namespace {

const char* mode_name(dda::BondFailure mode) { return mode == dda::BondFailure::shear ? "shear" : "tension"; }

}  // namespace

BrokenBondRow broken_bond_row(const scenario::Scenario& s, const dda::System& system, const dda::BondBreak& b,
                              int trace_count, double time) {
  const std::string& name = s.joint_type(system.bond_joint_type(b.bond)).name;
  return {trace_count + b.bond, b.bond, time, mode_name(b.mode), name.empty() ? "joint" : name, b.from, b.to};
}

BondOutput::BondOutput(const output::RunFolder& folder, const scenario::Scenario& s, const dda::System& system,
                       int trace_count, BondClock clock)
    : folder_(folder), clock_(clock), trace_count_(trace_count) {
  const auto n = static_cast<std::size_t>(system.bond_count());
  for (int b = 0; b < system.bond_count(); ++b) {
    const std::string& name = s.joint_type(system.bond_joint_type(b)).name;
    type_names_.push_back(name.empty() ? "joint" : name);
    broken_.push_back(system.is_bond_broken(b) ? 1 : 0);
  }
  broken_at_.assign(n, -1.0);
  mode_.assign(n, 0);
  // Broken by a step, not from the start (a resumed run's earlier breaks): listed by continue_from.
  for (const dda::BondBreak& b : system.bond_breaks()) broken_[static_cast<std::size_t>(b.bond)] = 0;
}

int BondOutput::add_breaks(long long step, const dda::System& system, FractureOutput& fractures, double pass_time) {
  const std::vector<dda::BondBreak>& breaks = system.bond_breaks();
  std::vector<BrokenBondRow> rows;
  for (std::size_t k = listed_; k < breaks.size(); ++k) {
    const dda::BondBreak& b = breaks[k];
    const bool by_pass = clock_ == BondClock::pass;
    const double row_time = clock_ == BondClock::time ? b.time : pass_time;
    const double when = by_pass ? static_cast<double>(step) : row_time;
    rows.push_back({trace_count_ + b.bond, b.bond, row_time, mode_name(b.mode),
                    type_names_.at(static_cast<std::size_t>(b.bond)), b.from, b.to});
    const auto bond = static_cast<std::size_t>(b.bond);
    broken_[bond] = 1;
    broken_at_[bond] = when;
    mode_[bond] = b.mode == dda::BondFailure::shear ? 2 : 1;
  }
  listed_ = breaks.size();
  if (!rows.empty()) fractures.add_broken_bonds(step, rows);
  return static_cast<int>(rows.size());
}

template <class When>
void BondOutput::list_earlier_breaks(const dda::System& system, std::span<const int> broken_per_group, When when) {
  const std::vector<dda::BondBreak>& breaks = system.bond_breaks();
  std::size_t k = 0;
  for (std::size_t group = 0; group < broken_per_group.size(); ++group)
    for (int i = 0; i < broken_per_group[group] && k < breaks.size(); ++i, ++k) {
      const auto bond = static_cast<std::size_t>(breaks[k].bond);
      broken_[bond] = 1;
      broken_at_[bond] = when(group);
      mode_[bond] = breaks[k].mode == dda::BondFailure::shear ? 2 : 1;
    }
  listed_ = k;
}

void BondOutput::continue_from(const dda::System& system, std::span<const int> broken_per_pass,
                               std::span<const int> written) {
  list_earlier_breaks(system, broken_per_pass, [](std::size_t pass) { return static_cast<double>(pass + 1); });
  if (!series_) series_.emplace(folder_.file("bonds.pvd"));
  for (int pass : written) list_if_present(*series_, folder_, pass, fmt::format("bonds_{:04d}.vtu", pass));
}

void BondOutput::continue_in_time(const dda::System& system, std::span<const int> broken_per_step,
                                  std::span<const double> step_times, std::span<const double> written_times) {
  list_earlier_breaks(system, broken_per_step, [step_times](std::size_t step) { return step < step_times.size() ? step_times[step] : -1.0; });
  if (!series_) series_.emplace(folder_.file("bonds.pvd"));
  for (std::size_t i = 0; i < written_times.size(); ++i)
    list_if_present(*series_, folder_, written_times[i], fmt::format("bonds_{:04d}.vtu", i));
}

void BondOutput::write_series(int step, double time, const dda::System& system) {
  std::vector<std::array<geometry::Point, 2>> faces;
  output::DataArray bond{"bond", 1, {}}, broken{"broken", 1, {}}, mode{"mode", 1, {}}, broken_at{"broken_at", 1, {}};
  for (int b = 0; b < system.bond_count(); ++b) {
    const auto k = static_cast<std::size_t>(b);
    faces.push_back(system.bond_face(b));
    bond.values.push_back(b);
    broken.values.push_back(broken_[k] ? 1.0 : 0.0);
    mode.values.push_back(mode_[k]);
    broken_at.values.push_back(broken_at_[k]);
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
  // Bonds the system holds broken that were never listed: broken in the step (or pass) that failed.
  int unlisted = 0;
  for (int b = 0; b < system.bond_count(); ++b)
    if (system.is_bond_broken(b) && !broken_[static_cast<std::size_t>(b)]) ++unlisted;
  const char* unit = clock_ == BondClock::pass ? "pass" : clock_ == BondClock::time_step ? "time step" : "step";
  // The cracks broken from the start broke at no load, pass or time: drawn in black, outside the
  // colour scale, which spans the breaks listed.
  const auto broken_from_start = [&](std::size_t k) { return broken_[k] != 0 && broken_at_[k] < 0.0; };
  int from_start = 0;
  for (std::size_t k = 0; k < broken_.size(); ++k) from_start += broken_from_start(k) ? 1 : 0;
  figure.subtitle = fmt::format("Broken bonds ({} of {}; intact in grey{}), {}{}", listed_, system.bond_count(),
                                from_start > 0 ? fmt::format(", {} broken from the start in black", from_start) : "",
                                when,
                                unlisted > 0 ? fmt::format("; {} more in the failed {}, not drawn", unlisted, unit)
                                             : std::string());
  figure.field_label = clock_ == BondClock::pass ? "broke in pass" : clock_ == BondClock::load ? "broke at the load" : "broke at (s)";
  figure.lines_scale_from_zero = false;
  figure.whole_numbers = clock_ == BondClock::pass;
  for (int b = 0; b < system.block_count(); ++b) figure.blocks.push_back(system.polygon(b));
  for (int b = 0; b < system.bond_count(); ++b) {
    const auto k = static_cast<std::size_t>(b);
    figure.segments.push_back(system.bond_face(b));
    figure.segment_values.push_back(broken_at_[k] < 0.0 ? 0.0 : broken_at_[k]);
    figure.segment_highlighted.push_back(broken_[k] != 0 && !broken_from_start(k));
    figure.segment_marked.push_back(broken_from_start(k));
  }
  for (const std::string& format : s.output.figures)
    output::render_field_figure(folder_.figures() / ("cracks." + format), figure);
}

}  // namespace hydrodda::run
