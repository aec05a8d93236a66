#include "run/sweep_results.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <fstream>

#include "output/csv_table.hpp"
#include "output/plot_line.hpp"
#include "output/summary_reading.hpp"

namespace hydrodda::run {

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

}  // namespace

SweepResults::SweepResults(std::vector<SweepAxis> axes, std::vector<std::vector<scenario::Override>> cases,
                           std::vector<std::string> columns, bool zipped)
    : axes_(std::move(axes)),
      cases_(std::move(cases)),
      columns_(std::move(columns)),
      zipped_(zipped),
      results_(cases_.size()) {}

void SweepResults::set_name(std::size_t index, std::string name) { results_[index].name = std::move(name); }

CaseResult read_case_result(const std::string& name, const std::filesystem::path& case_dir, int exit_code,
                            const std::vector<std::string>& columns) {
  CaseResult r;
  r.name = name;
  r.status = "failed";
  const std::filesystem::path summary = case_dir / "summary.json";
  if (std::filesystem::exists(summary)) {
    std::vector<std::string> paths{"status", "message", "converged", "iterations"};
    paths.insert(paths.end(), columns.begin(), columns.end());
    try {
      const auto values = output::read_summary_values(summary, paths);
      if (exit_code == 0 && values[0] == "ok") r.status = "ok";
      r.message = values[1].value_or("");
      r.converged = values[2].value_or("");
      r.iterations = values[3].value_or("");
      r.columns.assign(values.begin() + 4, values.end());
    } catch (const std::exception& e) {
      r.message = e.what();
    }
  }
  if (r.columns.empty()) r.columns.assign(columns.size(), std::nullopt);
  if (r.status == "failed" && r.message.empty()) {
    const std::string error = find_last_error(case_dir / "run.log");
    r.message = fmt::format("exit code {}{}; see {}", exit_code, error.empty() ? "" : ": " + error,
                            (case_dir / "run.log").string());
  }
  if (r.status == "ok")
    for (std::size_t c = 0; c < columns.size(); ++c)
      if (!r.columns[c]) spdlog::warn("{}: summary.json has no value at {}", r.name, columns[c]);
  return r;
}

void SweepResults::set_result(std::size_t index, CaseResult result) {
  result.name = results_[index].name;
  results_[index] = std::move(result);
}

void SweepResults::record_not_run(std::size_t index) {
  results_[index].status = "not run";
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
    if (r.status == "pending") continue;
    std::vector<std::string> row{r.name};
    for (const scenario::Override& o : cases_[i]) row.push_back(o.value);
    row.insert(row.end(), {r.status, r.converged, r.iterations});
    for (const auto& v : r.columns) row.push_back(v.value_or(""));
    row.push_back(r.message);
    table.add_row(row);
  }
  return table.text();
}

void SweepResults::plot(const std::filesystem::path& file, const std::string& title) const {
  if (columns_.empty() || axes_.empty()) {
    spdlog::info("no column to plot (choose one with --column): {} not drawn", file.string());
    return;
  }
  output::LinePlotSpec spec;
  spec.title = title;
  spec.x_label = axes_[0].key;
  spec.y_label = columns_[0];
  for (std::size_t i = 0; i < results_.size(); ++i) {
    const CaseResult& r = results_[i];
    const std::optional<double> x = to_number(cases_[i][0].value);
    if (!x) {
      spdlog::info("{} takes values that are not numbers: {} not drawn", axes_[0].key, file.string());
      return;
    }
    const std::optional<double> y = r.status == "ok" && r.columns[0] ? to_number(*r.columns[0]) : std::nullopt;
    if (!y) continue;
    std::string series;
    for (std::size_t k = 1; !zipped_ && k < cases_[i].size(); ++k)
      series += fmt::format("{}{} = {}", series.empty() ? "" : ", ", cases_[i][k].key, cases_[i][k].value);
    auto it = std::find_if(spec.series.begin(), spec.series.end(),
                           [&](const output::LineSeries& s) { return s.name == series; });
    if (it == spec.series.end()) it = spec.series.insert(spec.series.end(), output::LineSeries{series, {}, {}});
    it->x.push_back(*x);
    it->y.push_back(*y);
  }
  if (spec.series.empty()) {
    spdlog::warn("no case gave a number for {}: {} not drawn", columns_[0], file.string());
    return;
  }
  for (output::LineSeries& s : spec.series) {  // in x order, whatever order the values were given in
    std::vector<std::size_t> order(s.x.size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return s.x[a] < s.x[b]; });
    output::LineSeries sorted{s.name, {}, {}};
    for (std::size_t k : order) {
      sorted.x.push_back(s.x[k]);
      sorted.y.push_back(s.y[k]);
    }
    s = std::move(sorted);
  }
  output::render_line_plot(file, spec);
}

std::size_t SweepResults::count_not_ok() const {
  return static_cast<std::size_t>(
      std::count_if(results_.begin(), results_.end(), [](const CaseResult& r) { return r.status != "ok"; }));
}

}  // namespace hydrodda::run
