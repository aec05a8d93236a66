#include "run/coupled_transient_fractures.hpp"

#include <algorithm>
#include <stdexcept>

#include "output/csv_table.hpp"
#include "run/model_building.hpp"
#include "run/scenario_fractures.hpp"

namespace hydrodda::run {

using output::CsvTable;

FractureCounts count_fractures(const fractures::FractureState& state) {
  FractureCounts c;
  for (const fractures::FractureResult& f : state.fractures) {
    if (f.open) ++c.open;
    if (f.open_length > 0.0) ++c.partly_open;
    c.open_length += f.open_length;
    c.largest_opening = std::max(c.largest_opening, f.max_aperture);
    c.largest_hydraulic = std::max(c.largest_hydraulic, f.hydraulic_aperture);
  }
  return c;
}

std::vector<std::string> fracture_count_columns() {
  return {"open_fractures", "partly_open_fractures", "open_length", "largest_opening", "largest_hydraulic_aperture"};
}

std::vector<std::string> fracture_count_cells(const FractureCounts& c) {
  return {CsvTable::cell(static_cast<long long>(c.open)), CsvTable::cell(static_cast<long long>(c.partly_open)),
          CsvTable::cell(c.open_length), CsvTable::cell(c.largest_opening), CsvTable::cell(c.largest_hydraulic)};
}

output::LinePlotSpec plot_open_fractures(const std::vector<double>& times, const std::vector<FractureCounts>& counts) {
  if (times.size() != counts.size())
    throw std::invalid_argument("plot_open_fractures: one count per time is needed");
  output::LinePlotSpec plot;
  plot.x_label = "time (s)";
  plot.y_label = "open length of the fractures (m)";
  output::LineSeries open{"all fractures", times, {}, {}};
  for (const FractureCounts& c : counts) open.y.push_back(c.open_length);
  plot.series = {std::move(open)};
  return plot;
}

FracturesInTime::FracturesInTime(const RunContext& context, const CoupledModel& model)
    : context_(context),
      model_(model),
      meter_(make_fracture_meter(context.scenario)),
      joint_laws_(meter_ ? make_joint_aperture_laws(context.scenario, meter_->layout().traces)
                         : coupling::JointApertureLaws{}),
      flow_zones_(meter_ ? meter_->flow_zones(model.mesh()) : fractures::FractureMeter::FlowZones{}),
      output_(context.folder, /*with_flow=*/true, fracture_type_names(context.scenario)) {}

void FracturesInTime::record(long long step, double time) {
  if (!meter_) return;
  const dda::System& system = model_.mechanics();
  state_ = meter_->measure(model_.block_polygons(), system.penetration_tolerance(), system.contacts(), joint_laws_);
  meter_->add_flow(*state_, flow_zones_, model_.mesh(), model_.loop().flow());
  output_.add_rows(step, time, *state_);
  counts_.push_back(count_fractures(*state_));
}

void FracturesInTime::resume(int steps, const std::vector<double>& written_times, std::vector<FractureCounts> counts) {
  if (!meter_) {
    // Without traces fractures.csv holds only broken bonds' rows, if any: those up to `steps` kept.
    output_.continue_in_time(steps, {});
    return;
  }
  output_.continue_in_time(steps, written_times);
  counts_ = std::move(counts);
  const dda::System& system = model_.mechanics();
  state_ = meter_->measure(model_.block_polygons(), system.penetration_tolerance(), system.contacts(), joint_laws_);
  meter_->add_flow(*state_, flow_zones_, model_.mesh(), model_.loop().flow());
}

void FracturesInTime::write_series(int written, double time) {
  if (state_ && context_.scenario.output.fields.fractures) output_.write_series(written, time, *state_);
}

}  // namespace hydrodda::run
