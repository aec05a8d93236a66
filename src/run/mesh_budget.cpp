#include "run/mesh_budget.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <cmath>

#include "mesh/mesh_estimate.hpp"
#include "scenario/diagnostics.hpp"

namespace hydrodda::run {

namespace {

// A coupled run's peak: 0.99 GB at 1,087,258 triangles (10 passes), 3.0 GB at about 4.3
// million (1 pass); 1,200 B leaves room for a longer run's history and the fields written.
constexpr double kBytesPerTriangle = 1200.0;
// Gmsh on a tiled mesh, two meshing processes on two cores: 3.3-4.8 s for 1,087,258 triangles
// and 18.1 s for about 4.3 million (the seal of docs/performance.md at 0.07 and 0.035 m).
constexpr double kTrianglesMeshedPerSecond = 240000.0;
constexpr double kReasonableMeshingSeconds = 60.0;

double physical_memory_bytes() {
  return static_cast<double>(::sysconf(_SC_PHYS_PAGES)) * static_cast<double>(::sysconf(_SC_PAGESIZE));
}

std::string count_text(double n) {
  if (n >= 1e6) return fmt::format("{:.3g} million", n / 1e6);
  const double rounded = n < 1000 ? std::round(n) : std::round(n / 100) * 100;
  return fmt::format("{:.0f}", rounded);
}

}  // namespace

std::string check_mesh_budget(const scenario::Scenario& s, const mesh::MeshRequest& request) {
  const mesh::TriangleEstimate estimate = mesh::estimate_triangle_count(request);
  const double n = estimate.total();
  std::string text = fmt::format("about {} triangles", count_text(n));
  const bool refined = estimate.near_lines > 0.0;
  if (refined)
    text += fmt::format(" ({} within mesh.refine_distance = {:g} m of the fractures, at mesh.fracture_size = {:g} m "
                        "there; {} elsewhere, at mesh.size = {:g} m)",
                        count_text(estimate.near_lines), request.refine_distance, request.fracture_size,
                        count_text(estimate.elsewhere), request.size);
  else
    text += fmt::format(" (at mesh.size = {:g} m)", request.size);
  const double bytes = n * kBytesPerTriangle, memory = physical_memory_bytes();
  const double seconds = n / kTrianglesMeshedPerSecond;
  // The keys to change: those of the part that holds most of the triangles.
  const std::string advice = refined && estimate.near_lines > estimate.elsewhere
                                 ? "make mesh.fracture_size larger or mesh.refine_distance smaller"
                                 : "make mesh.size larger";
  const std::string cost = fmt::format("a run of about {:.1f} GB and {:.0f} s of meshing", bytes / 1e9, seconds);
  if (bytes > memory)
    throw scenario::ScenarioError({{s.file.string(), 0, "mesh",
                                    fmt::format("the mesh would have {}: {}, more than this machine's {:.1f} GB of "
                                                "memory; {}",
                                                text, cost, memory / 1e9, advice)}});
  if (seconds > kReasonableMeshingSeconds || bytes > memory / 2)
    spdlog::warn("{}: mesh: {}: {} (this machine has {:.1f} GB); to mesh less, {}", s.file.string(), text, cost,
                 memory / 1e9, advice);
  return text;
}

}  // namespace hydrodda::run
