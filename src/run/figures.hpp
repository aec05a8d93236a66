#pragma once
// The figures a run draws into figures/, in each format output.figures asks for.

#include <functional>
#include <string>
#include <vector>

#include "geometry/polygon.hpp"
#include "hydro/flow_solution.hpp"
#include "mesh/triangle_mesh.hpp"
#include "output/run_folder.hpp"
#include "scenario/scenario.hpp"

namespace hydrodda::run {

struct FlowPicture {
  const mesh::TriangleMesh& mesh;
  const hydro::FlowSolution& flow;
  const std::vector<double>& porosity;      // per element; may be empty
  const std::vector<double>& permeability;  // per element
  const std::vector<geometry::Polygon>& blocks;
  // How a coupled run ended, when not converged ("not converged after 40 passes", "failed at
  // pass 6: ..."): every figure says so in red under its title. Empty: nothing to say.
  std::string status{};
  int iterations = 0;  // of a coupled run; 0 for a flow-only run
  // Asked before each figure: true leaves the rest undrawn (the run reports the interrupt).
  std::function<bool()> stop_requested{};
};

// The relative changes of a coupled run's passes, as history.csv lists them.
struct ConvergenceHistory {
  std::vector<double> iteration, head_change, displacement_change;
  double tolerance = 0.0;
  std::string status{};  // as FlowPicture's
};

// head.* (heads with contours, blocks, flux arrows under 1% of the largest hidden, as the
// paper's Fig. 6), porosity.* (when given) and permeability.* (both log scale, so that the
// joints show), each titled with the scenario's title.
void draw_figures(const scenario::Scenario& scenario, const output::RunFolder& folder, const FlowPicture& picture);

// A stopped run's status line on its figures: `head` ("failed at pass 6", "interrupted at step
// 40"), then, when `message` is not empty, ": " and its first clause (up to its first ':' or
// ';'), cut to part of a line: the figures shrink a long line to their width.
std::string describe_status_for_figures(const std::string& head, const std::string& message);

// convergence.*: head and displacement change (log scale) against coupling iteration, with the
// tolerance both must fall below.
void draw_convergence(const scenario::Scenario& scenario, const output::RunFolder& folder,
                      const ConvergenceHistory& history);

}  // namespace hydrodda::run
