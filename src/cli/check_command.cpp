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
  // What only reading it shows: the user's mesh file is a triangle mesh Gmsh can read.
  if (scenario->mesh && scenario->mesh->file) {
    try {
      const mesh::TriangleMesh mesh = read_mesh_file(*scenario);
      spdlog::debug("mesh.file: {} nodes, {} triangles", mesh.node_count(), mesh.triangle_count());
    } catch (const scenario::ScenarioError& e) {
      for (const scenario::Diagnostic& d : e.diagnostics())
        std::fputs(fmt::format("error: {}\n", d.format()).c_str(), stderr);
      std::fputs(fmt::format("{}: {} error(s)\n", file.string(), e.diagnostics().size()).c_str(), stderr);
      return kBadInput;
    }
  }
  std::fputs(fmt::format("{}: OK ({})\n", file.string(), describe(*scenario)).c_str(), stdout);
  return kSuccess;
}

}  // namespace hydrodda::cli
