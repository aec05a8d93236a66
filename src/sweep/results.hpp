#pragma once
// What the cases of a sweep gave: one row per case in sweep.csv, and the response plot.

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "output/plot_line.hpp"
#include "sweep/cases.hpp"

namespace hydrodda::sweep {

// What became of a case. Only `ok` is a result: `not_converged` ran to its end without meeting
// the coupling tolerance, `failed` stopped on an error (or left no summary), `interrupted`
// stopped at a signal, `not_run` never started because the sweep was interrupted.
enum class CaseStatus { pending, ok, not_converged, failed, interrupted, not_run, no_equilibrium };
inline constexpr std::size_t kCaseStatuses = 7;

// As sweep.csv writes it: "ok", "not converged", "failed", "interrupted", "not run", "no equilibrium".
std::string_view status_name(CaseStatus status);
// The status of that name; std::invalid_argument for any other text.
CaseStatus status_from_name(std::string_view name);

struct CaseResult {
  std::string name;  // case_000
  CaseStatus status = CaseStatus::pending;
  std::string converged, iterations, message;
  std::vector<std::optional<std::string>> columns;  // the chosen summary.json values
};

// What sweep.png draws; no series when nothing can be drawn, and `why_not` says why.
struct SweepPlot {
  output::LinePlotSpec spec;
  std::string why_not;
};

// A swept value in words, for titles and legends: "head at base = 5 m".
std::string value_label(const scenario::Override& value, const std::vector<std::string>& boundary_names = {});

// A finished case's result from its folder: "ok" when its run exited with 0, its summary.json
// says "ok" and it converged; "not converged" when it exited with 0 but did not converge;
// "interrupted" when it says so, when a signal ended it (exit code 130 or 143) before it wrote
// one, or when it was `asked_to_stop` (the sweep passed an interrupt on) and exited with 1
// without one (interrupted while building its model, which leaves nothing); otherwise
// "failed", with what the summary or the end of run.log says. Warns of a column an ok case
// lacks.
CaseResult read_case_result(const std::string& name, const std::filesystem::path& case_dir, int exit_code,
                            const std::vector<std::string>& columns, bool asked_to_stop = false);

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
  // other keys' values; a case that did not converge is a hollow marker off the line (legend
  // "not converged"); a failed or interrupted case (which has no value) a red cross on the x
  // axis at its value (legend "failed: no value"); unstarted cases are left out. Logs why when
  // nothing can be drawn.
  void plot(const std::filesystem::path& file, const std::string& title) const;
  SweepPlot plot_spec(const std::string& title) const;
  // The [[flow.boundary]] names, for the axis titles (output::quantity_label).
  void set_boundary_names(std::vector<std::string> names) { boundary_names_ = std::move(names); }

  // How many cases ended each way, indexed by CaseStatus.
  std::array<std::size_t, kCaseStatuses> count_by_status() const;
  // The cases that gave no converged result (every status but ok and pending).
  std::size_t count_not_ok() const;
  // "1 not converged, 1 failed": each status other than ok that some case has, in the order
  // of CaseStatus; empty when none.
  std::string describe_not_ok() const;

 private:
  std::vector<SweepAxis> axes_;
  std::vector<std::vector<scenario::Override>> cases_;
  std::vector<std::string> columns_;
  bool zipped_ = false;
  std::vector<CaseResult> results_;
  std::vector<std::string> boundary_names_;
};

}  // namespace hydrodda::sweep
