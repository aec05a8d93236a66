#pragma once
// The preview of a model before it runs (`hydrodda check FILE --figure PATH`): the blocks cut
// exactly as a run cuts them, what loads and holds them, where fluid enters and leaves, and the
// mesh to expect (output/preview_figure.hpp).

#include <filesystem>
#include <string>

#include "numerics/time_table.hpp"
#include "output/preview_figure.hpp"
#include "scenario/scenario.hpp"

namespace hydrodda::run {

// A value as the preview says it: "125 m", "-5 MPa", or for a time table its first and last
// values, "125 → 175 m (table)".
std::string describe_load(const numerics::TimeTable& value, const std::string& unit);

// The figure's content, built as `run` builds the model (the same cut, the same sliver
// merging); the scenario must have passed check_model. Throws scenario::ScenarioError as the
// building does.
output::PreviewFigure build_preview(const scenario::Scenario& scenario);

// Why a figure cannot be written at `path`, or "" when it can be tried: a folder, a folder that
// does not exist, an extension that names no figure format (.png, .svg, .pdf).
std::string find_figure_path_problem(const std::filesystem::path& path);

// build_preview drawn into `path` (PNG, SVG or PDF by its extension). Throws std::runtime_error
// naming the path when it cannot be written.
void draw_preview(const scenario::Scenario& scenario, const std::filesystem::path& path);

}  // namespace hydrodda::run
