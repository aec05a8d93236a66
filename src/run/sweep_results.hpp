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

// A finished case's result from its folder: "ok" when its run exited with 0 and summary.json
// says so, with the chosen columns (dotted paths into summary.json); else "failed" with what
// the summary or the end of run.log says. Warns of a column an ok case lacks.
CaseResult read_case_result(const std::string& name, const std::filesystem::path& case_dir, int exit_code,
                            const std::vector<std::string>& columns);

class SweepResults {
 public:
  // `columns` are dotted paths into each case's summary.json; `zipped`: the keys moved
  // together (sweep --zip), so the plot draws one curve against the first.
  SweepResults(std::vector<SweepAxis> axes, std::vector<std::vector<scenario::Override>> cases,
               std::vector<std::string> columns, bool zipped = false);

  void set_name(std::size_t index, std::string name);
  void record_not_run(std::size_t index);
  // A case's result, as read_case_result gives it (on this rank, or on another under MPI).
  void set_result(std::size_t index, CaseResult result);

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
