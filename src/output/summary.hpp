#pragma once
// summary.json: the run's results in one machine-readable file (docs/scenario.md, "The run folder").

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "fractures/refined_tip.hpp"

namespace hydrodda::output {

struct BlockSummary {
  int id = 0;
  std::array<double, 2> centroid{};
  std::array<double, 2> displacement{};
  double rotation = 0.0;
  std::array<double, 3> stress{};  // sxx, syy, sxy
  double area = 0.0;
  std::string material;  // its material's name; empty (left out) when not known
};

struct MeasureSummary {
  std::string name;
  std::array<double, 2> position{};
  std::array<double, 2> displacement{};
};

struct NamedValue {
  std::string name;
  double value = 0.0;
};

struct RegionSummary {
  std::string name;
  double flow = 0.0;
  // Measured along the head gradient the boundary conditions impose; none (null) where they
  // impose none (every head boundary at one head: still water).
  std::optional<double> effective_conductivity;
  std::optional<double> matrix_conductivity;      // the same region in the unfractured case
  std::optional<double> normalised_conductivity;  // effective / matrix
  std::optional<std::array<double, 2>> direction;  // the imposed head gradient's
  // The region's full effective conductivity tensor (m/s, region_tensor.hpp): xx, xy, yy, its
  // principal values (largest first) and their unit directions.
  std::array<double, 3> tensor{};
  std::array<double, 2> principal_values{};
  std::array<std::array<double, 2>, 2> principal_directions{};
  // A coupled run that did not converge: the least and largest normalised conductivity of its
  // last passes (up to 10), how far its answer still moved.
  struct PassRange {
    int passes = 0;
    double least = 0.0, largest = 0.0;
  };
  std::optional<PassRange> last_passes;
};

// How far the blocks had left the fluid mesh at the end of a coupled run.
struct OutsideMeshSummary {
  double largest_distance = 0.0;  // m: the block vertex farthest outside the mesh
  int block = -1;                 // its block, −1 when none is outside
  int blocks = 0;                 // blocks with a vertex outside
};

struct FlowSummary {
  std::vector<NamedValue> boundaries;  // outward flow per metre of thickness, m2/s
  double balance = 0.0;                // relative mass-balance error
  std::vector<RegionSummary> regions;
  // Coupled runs: the coupling iteration whose flow this is, the last that finished (of a run
  // that failed or was stopped, the one before the pass that did not finish).
  std::optional<int> iteration{};
  // Transient runs: the rate water goes into storage at the last step (m²/s per metre; < 0:
  // released), which the boundaries' flows balance with.
  std::optional<double> storage_rate{};
};

// One fracture's row (fractures.csv's columns at the run's last step).
struct FractureRow {
  int id = 0;
  std::string origin;           // "listed", "set", "file"
  std::optional<int> set;       // the joint set, for "set"
  int number = 0;
  std::string type;             // its joint type: [joint.NAME]'s NAME, "joint" for [joint]
  double length = 0.0, open_length = 0.0, mean_aperture = 0.0, max_aperture = 0.0, hydraulic_aperture = 0.0,
         normal_stress = 0.0, max_shear = 0.0, tip_opening_angle = 0.0;
  double open_share = 0.0;      // open_length / length
  bool open = false;            // open over at least fractures::kOpenShare of its length
  std::optional<double> flow;   // coupled runs
};

// The fractures at a glance: how many, which are open, the widest, and every row by id.
struct FractureSummary {
  std::vector<FractureRow> rows;  // by id
  // Cubic-law runs: the shortest wedge-tip length s* of the open joints and its fracture
  // (run::find_sharpest_wedge_tip); none without a sharp tip or under another law.
  std::optional<double> tip_length;
  std::optional<int> tip_length_id;
  // The longest edge of the fluid element at that tip (m; run::find_wedge_tip_element): under
  // s*/2 the mesh resolves the tip.
  std::optional<double> tip_element_size;
  std::vector<fractures::RefinedTip> refined_tips;  // in the order they were added
  std::optional<int> rounds;             // with mesh.refine_tips: the rounds run, 1 when none refined
};

// A run that found no equilibrium: the last state that held (the last step or pass after which
// no block was farther than its own size), as its message names it.
struct LastHeldSummary {
  std::string state;                               // "DDA step 28", "coupling iteration 3", "the blocks as built"
  long long step = 0;                              // the step or pass; 0: the blocks as built
  std::optional<std::vector<int>> open_fractures;  // ids; none measured (no traces): absent
  std::optional<int> broken_bonds;                 // a model with bonds: broken by then
};

struct RunSummary {
  std::string title;
  std::string scenario;          // the scenario file as given
  bool converged = false;
  int iterations = 0;
  std::string status = "ok";     // "ok", "stopped" (--stop-after), "interrupted", "no equilibrium" or "failed"
  std::string message;
  std::vector<BlockSummary> blocks;
  std::vector<MeasureSummary> measures;
  std::optional<FlowSummary> flow;
  std::optional<OutsideMeshSummary> outside_mesh;  // coupled runs
  std::optional<FractureSummary> fractures;  // runs of a domain cut by fractures
  std::vector<NamedValue> timings;  // seconds per phase
  std::optional<double> time;       // transient runs: the time reached (s)
  std::optional<LastHeldSummary> last_held;  // status "no equilibrium"
};

// The summary as JSON text, pretty-printed, full double precision.
std::string format_summary(const RunSummary& summary);

// The summary as format_summary writes it, and the summary.json paths of its values that are
// infinite or NaN (written as null), e.g. "flow.regions.core.effective_conductivity": a
// result that overflowed is no result. The JSON is built once for both.
struct CheckedSummary {
  std::string text;
  std::vector<std::string> non_finite;
};
CheckedSummary format_checked_summary(const RunSummary& summary);

}  // namespace hydrodda::output
