#include "sweep/results.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <csignal>
#include <fstream>

#include "output/csv_table.hpp"
#include "output/plot_line.hpp"
#include "output/quantity_label.hpp"
#include "output/summary_reading.hpp"

namespace hydrodda::sweep {

namespace {

std::optional<double> to_number(const std::string& text) {
  try {
    std::size_t used = 0;
    const double v = std::stod(text, &used);
    if (used == text.size()) return v;
  } catch (const std::exception&) {
  }
  return std::nullopt;
}

// The last line of a run's log that reports an error, for a case that left no summary.
std::string find_last_error(const std::filesystem::path& log) {
  std::ifstream in(log);
  std::string line, last;
  while (std::getline(in, line))
    if (line.rfind("error: ", 0) == 0) last = line.substr(7);
  return last;
}

// A child ended by SIGINT or SIGTERM before it could write its summary (128 + the signal).
bool ended_by_interrupt(int exit_code) { return exit_code == 128 + SIGINT || exit_code == 128 + SIGTERM; }

}  // namespace

std::string value_label(const scenario::Override& value, const std::vector<std::string>& boundary_names) {
  const output::Quantity q = output::name_quantity(value.key, boundary_names);
  return fmt::format("{} = {}{}", q.name, value.value, q.unit.empty() ? "" : fmt::format(" {}", q.unit));
}

std::string_view status_name(CaseStatus status) {
  switch (status) {
    case CaseStatus::pending: return "pending";
    case CaseStatus::ok: return "ok";
    case CaseStatus::not_converged: return "not converged";
    case CaseStatus::failed: return "failed";
    case CaseStatus::interrupted: return "interrupted";
    case CaseStatus::not_run: return "not run";
    case CaseStatus::no_equilibrium: return "no equilibrium";
  }
  return "pending";
}

CaseStatus status_from_name(std::string_view name) {
  for (std::size_t i = 0; i < kCaseStatuses; ++i)
    if (const auto status = static_cast<CaseStatus>(i); status_name(status) == name) return status;
  throw std::invalid_argument("not a case status: " + std::string(name));
}

SweepResults::SweepResults(std::vector<SweepAxis> axes, std::vector<std::vector<scenario::Override>> cases,
                           std::vector<std::string> columns, bool zipped)
    : axes_(std::move(axes)),
      cases_(std::move(cases)),
      columns_(std::move(columns)),
      zipped_(zipped),
      results_(cases_.size()) {}

void SweepResults::set_name(std::size_t index, std::string name) { results_[index].name = std::move(name); }

CaseResult read_case_result(const std::string& name, const std::filesystem::path& case_dir, int exit_code,
                            const std::vector<std::string>& columns, bool asked_to_stop) {
  CaseResult r;
  r.name = name;
  const std::filesystem::path summary = case_dir / "summary.json";
  const bool has_summary = std::filesystem::exists(summary);
  // A run interrupted while it builds its model ends at once with 1 and writes nothing.
  const bool stopped_while_building = asked_to_stop && exit_code == 1 && !has_summary;
  r.status = ended_by_interrupt(exit_code) || stopped_while_building ? CaseStatus::interrupted : CaseStatus::failed;
  if (stopped_while_building) r.message = find_last_error(case_dir / "run.log");
  if (has_summary) {
    std::vector<std::string> paths{"status", "message", "converged", "iterations"};
    paths.insert(paths.end(), columns.begin(), columns.end());
    try {
      const auto values = output::read_summary_values(summary, paths);
      r.message = values[1].value_or("");
      r.converged = values[2].value_or("");
      r.iterations = values[3].value_or("");
      r.columns.assign(values.begin() + 4, values.end());
      if (values[0] == "interrupted") {
        r.status = CaseStatus::interrupted;
      } else if (values[0] == "no equilibrium") {
        r.status = CaseStatus::no_equilibrium;
      } else if (exit_code == 0 && values[0] == "ok") {
        r.status = r.converged == "true" ? CaseStatus::ok : CaseStatus::not_converged;
        if (r.status == CaseStatus::not_converged && r.message.empty())
          r.message = fmt::format("the coupling loop did not converge in {} iteration(s)", r.iterations);
      }
    } catch (const std::exception& e) {
      r.message = e.what();
    }
  }
  // A case that failed or was interrupted has no result: its summary.json holds the last good
  // state it reached (the blocks as built, a pass before the one that failed), whose numbers
  // would read as the case's answer.
  if (r.columns.empty() || r.status == CaseStatus::failed || r.status == CaseStatus::interrupted ||
      r.status == CaseStatus::no_equilibrium)
    r.columns.assign(columns.size(), std::nullopt);
  if (r.status != CaseStatus::ok && r.message.empty()) {
    const std::string error = find_last_error(case_dir / "run.log");
    r.message = fmt::format("exit code {}{}; see {}", exit_code, error.empty() ? "" : ": " + error,
                            (case_dir / "run.log").string());
  }
  if (r.status == CaseStatus::ok)
    for (std::size_t c = 0; c < columns.size(); ++c)
      if (!r.columns[c]) spdlog::warn("{}: summary.json has no value at {}", r.name, columns[c]);
  return r;
}

void SweepResults::set_result(std::size_t index, CaseResult result) {
  result.name = results_[index].name;
  results_[index] = std::move(result);
}

void SweepResults::record_not_run(std::size_t index) {
  results_[index].status = CaseStatus::not_run;
  results_[index].message = "the sweep was interrupted before this case started";
  results_[index].columns.assign(columns_.size(), std::nullopt);
}

std::string SweepResults::csv_text() const {
  std::vector<std::string> header{"case"};
  for (const SweepAxis& a : axes_) header.push_back(a.key);
  header.insert(header.end(), {"status", "converged", "iterations"});
  header.insert(header.end(), columns_.begin(), columns_.end());
  header.push_back("message");
  output::CsvTable table(header);
  for (std::size_t i = 0; i < results_.size(); ++i) {
    const CaseResult& r = results_[i];
    if (r.status == CaseStatus::pending) continue;
    std::vector<std::string> row{r.name};
    for (const scenario::Override& o : cases_[i]) row.push_back(o.value);
    row.insert(row.end(), {std::string(status_name(r.status)), r.converged, r.iterations});
    for (const auto& v : r.columns) row.push_back(v.value_or(""));
    row.push_back(r.message);
    table.add_row(row);
  }
  return table.text();
}

SweepPlot SweepResults::plot_spec(const std::string& title) const {
  SweepPlot plot;
  if (columns_.empty() || axes_.empty()) {
    plot.why_not = "no column to plot (choose one with --column)";
    return plot;
  }
  output::LinePlotSpec& spec = plot.spec;
  spec.title = title;
  spec.x_label = output::quantity_label(axes_[0].key, boundary_names_);
  spec.y_label = output::quantity_label(columns_[0], boundary_names_);
  spec.open_label = "not converged";
  bool interrupted = false;  // some case marked as having no value was interrupted, not failed
  for (std::size_t i = 0; i < results_.size(); ++i) {
    const CaseResult& r = results_[i];
    const std::optional<double> x = to_number(cases_[i][0].value);
    if (!x) {
      plot.why_not = fmt::format("{} takes values that are not numbers", axes_[0].key);
      spec.series.clear();
      return plot;
    }
    const bool drawn = r.status == CaseStatus::ok || r.status == CaseStatus::not_converged;
    const std::optional<double> y = drawn && r.columns[0] ? to_number(*r.columns[0]) : std::nullopt;
    if (!y) {
      // A case that ran and gave no value is a cross on the x axis, not a gap in the line.
      if (r.status != CaseStatus::not_run && r.status != CaseStatus::pending) {
        spec.marks_x.push_back(*x);
        interrupted = interrupted || r.status == CaseStatus::interrupted;
      }
      continue;
    }
    std::string series;
    for (std::size_t k = 1; !zipped_ && k < cases_[i].size(); ++k)
      series += fmt::format("{}{}", series.empty() ? "" : ", ", value_label(cases_[i][k], boundary_names_));
    auto it = std::find_if(spec.series.begin(), spec.series.end(),
                           [&](const output::LineSeries& s) { return s.name == series; });
    if (it == spec.series.end()) it = spec.series.insert(spec.series.end(), output::LineSeries{series, {}, {}, {}});
    it->x.push_back(*x);
    it->y.push_back(*y);
    it->open.push_back(r.status == CaseStatus::not_converged);
  }
  if (!spec.marks_x.empty()) spec.marks_label = interrupted ? "failed or interrupted: no value" : "failed: no value";
  if (spec.series.empty() && spec.marks_x.empty()) {
    plot.why_not = fmt::format("no case gave a number for {}", columns_[0]);
    return plot;
  }
  // A lone series needs no legend entry (a second key with one value would name it).
  if (spec.series.size() == 1) spec.series[0].name.clear();
  for (output::LineSeries& s : spec.series) {  // in x order, whatever order the values were given in
    std::vector<std::size_t> order(s.x.size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return s.x[a] < s.x[b]; });
    output::LineSeries sorted{s.name, {}, {}, {}};
    for (std::size_t k : order) {
      sorted.x.push_back(s.x[k]);
      sorted.y.push_back(s.y[k]);
      sorted.open.push_back(s.open[k]);
    }
    s = std::move(sorted);
  }
  return plot;
}

void SweepResults::plot(const std::filesystem::path& file, const std::string& title) const {
  const SweepPlot plot = plot_spec(title);
  if (plot.spec.series.empty() && plot.spec.marks_x.empty()) {
    if (columns_.empty()) spdlog::info("{}: {} not drawn", plot.why_not, file.string());
    else spdlog::warn("{}: {} not drawn", plot.why_not, file.string());
    return;
  }
  output::render_line_plot(file, plot.spec);
}

std::array<std::size_t, kCaseStatuses> SweepResults::count_by_status() const {
  std::array<std::size_t, kCaseStatuses> counts{};
  for (const CaseResult& r : results_) ++counts[static_cast<std::size_t>(r.status)];
  return counts;
}

std::size_t SweepResults::count_not_ok() const {
  const auto counts = count_by_status();
  return results_.size() - counts[static_cast<std::size_t>(CaseStatus::ok)] -
         counts[static_cast<std::size_t>(CaseStatus::pending)];
}

std::string SweepResults::describe_not_ok() const {
  const auto counts = count_by_status();
  std::string text;
  for (CaseStatus s : {CaseStatus::not_converged, CaseStatus::no_equilibrium, CaseStatus::failed,
                       CaseStatus::interrupted, CaseStatus::not_run})
    if (const std::size_t n = counts[static_cast<std::size_t>(s)])
      text += fmt::format("{}{} {}", text.empty() ? "" : ", ", n, status_name(s));
  return text;
}

}  // namespace hydrodda::sweep
