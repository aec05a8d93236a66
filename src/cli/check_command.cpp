#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <cstdio>

#include "cli/app.hpp"
#include "cli/commands.hpp"
#include "cli/model_building.hpp"
#include "cli/scenario_loading.hpp"
#include "scenario/diagnostics.hpp"

namespace hydrodda::cli {

int check_command(const std::filesystem::path& file) {
  const auto scenario = load_scenario(file);
  if (!scenario) return kBadInput;
  // What only building the model shows (a fixed point in no block, a boundary the mesh file
  // does not name), short of meshing and running.
  try {
    if (scenario->mechanics) build_mechanics_model(*scenario, build_blocks(*scenario));
    if (scenario->mesh && scenario->mesh->file) {
      const mesh::TriangleMesh mesh = read_mesh_file(*scenario);
      spdlog::debug("mesh.file: {} nodes, {} triangles", mesh.node_count(), mesh.triangle_count());
    }
  } catch (const scenario::ScenarioError& e) {
    print_scenario_errors(file, e);
    return kBadInput;
  }
  std::fputs(fmt::format("{}: OK ({})\n", file.string(), describe(*scenario)).c_str(), stdout);
  return kSuccess;
}

}  // namespace hydrodda::cli
