#pragma once
// What the cases of a sweep gave: one row per case in sweep.csv, and the response plot.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "run/sweep_plan.hpp"

namespace hydrodda::run {

struct CaseResult {
  std::string name;                // case_000
  std::string status = "pending";  // "ok", "failed" or "not run" once known
  std::string converged, iterations, message;
  std::vector<std::optional<std::string>> columns;  // the chosen summary.json values
};

class SweepResults {
 public:
  // `columns` are dotted paths into each case's summary.json; `zipped`: the keys moved
  // together (sweep --zip), so the plot draws one curve against the first.
  SweepResults(std::vector<SweepAxis> axes, std::vector<std::vector<scenario::Override>> cases,
               std::vector<std::string> columns, bool zipped = false);

  void set_name(std::size_t index, std::string name);
  // Reads the case's summary.json; a case is "ok" when its run exited with 0 and says so.
  const CaseResult& record_run(std::size_t index, const std::filesystem::path& case_dir, int exit_code);
  void record_not_run(std::size_t index);

  // case, each swept key, status, converged, iterations, the chosen columns, message; one row per
  // case with a result, in case order.
  std::string csv_text() const;
  // The first chosen column against the first swept key, one series per combination of the
  // other keys' values; cases without a number there are left out. Logs why when nothing can
  // be drawn.
  void plot(const std::filesystem::path& file, const std::string& title) const;
  std::size_t count_not_ok() const;

 private:
  std::vector<SweepAxis> axes_;
  std::vector<std::vector<scenario::Override>> cases_;
  std::vector<std::string> columns_;
  bool zipped_ = false;
  std::vector<CaseResult> results_;
};

}  // namespace hydrodda::run
