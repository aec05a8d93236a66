// Bonded triangle sub-blocks against the elastic continuum, through the program, each case at
// three sizes h (its scenario's and two coarser): the error against the analytic value falls at
// each halving of h, and the finest is within a stated tolerance. Triangles bonded along every
// face are the constant-strain triangles of the same mesh (docs/dda.md, "Bonds"), which converge
// to the continuum from the stiff side. Measurements at four sizes, and Voronoi cells beside:
// docs/studies/2026-11-30-bonds-against-the-continuum.md.
//
// - scenarios/verification/plate_with_hole.toml: a quarter of a plate with a hole of radius
//   a = 1 m under a tension σ = 1 MPa along y, its far edges loaded by Kirsch's own tractions, so
//   that the answer is Kirsch's (1898; Timoshenko & Goodier, Theory of Elasticity, §35) with no
//   correction for the plate's width. On the symmetry line y = 0,
//     σyy(x, 0) = σ (1 + a²/(2x²) + 3a⁴/(2x⁴)),
//   and the ligament from the hole's edge x = a to x = 2a carries ∫ σyy dx = 1.6875 σ a. Read
//   as the sum of the sub-blocks' uniform σyy times their faces' lengths on that line (a face's
//   own traction, as a bond reads it). h = 0.4, 0.2, 0.1 m about the hole (a/2.5 to a/10):
//   measured 0.6435, 0.9297, 0.9615 of Kirsch's; the finest within 5%.
// - scenarios/verification/bonded_cantilever.toml: a cantilever L = 8 m, depth d = 1 m, clamped
//   at x = 0 (bonded to a block held by three fixed points, so u = v = 0 along the whole clamped
//   end), sheared at its free end by P = 5 kN/m, plane stress. Timoshenko's beam:
//     δ = P L³/(3 E I) + P L/(κ G A), I = d³/12, A = d, κ = 5/6,
//   1.036 mm. The 2D solution of Timoshenko & Goodier (§21) puts the tip between P L³/(3 E I)
//   (the clamped end's axis held level) and that plus 1.5 P L/(G A) (its cross-section held
//   upright): 0.988 to 1.003 of δ, a band that the clamp's details decide. h = 0.5, 0.25, 0.125 m
//   (d/2 to d/8): measured 0.6236, 0.9217, 0.9790 of δ; the finest within 3%.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "coupled_runs.hpp"

namespace hydrodda::testing::coupled {
namespace {

// A static run of `scenario` at rest: its summary and its blocks before and after.
struct StaticRun {
  nlohmann::json summary = nlohmann::json::object();
  std::string initial_blocks;  // blocks_0000.vtu: the sub-blocks as built
  std::string final_blocks;    // the last blocks_NNNN.vtu: their stresses at rest
};

StaticRun run_static(const std::string& scenario, const std::string& name) {
  const fs::path out = fs::temp_directory_path() / ("hydrodda-bonded-continuum-" + name);
  const fs::path file = out.string() + ".toml";
  fs::remove_all(out);
  std::ofstream(file) << scenario;
  const auto result = run_program("run " + file.string() + " -o " + out.string() + " --threads 1");
  EXPECT_EQ(result.exit_code, 0) << result.output;
  StaticRun r;
  if (std::ifstream in(out / "summary.json"); in) r.summary = nlohmann::json::parse(in);
  if (r.summary.contains("iterations")) {
    char last[32];
    std::snprintf(last, sizeof last, "blocks_%04d.vtu", r.summary["iterations"].get<int>());
    r.initial_blocks = read_file_bytes(out / "blocks_0000.vtu");
    r.final_blocks = read_file_bytes(out / last);
  }
  fs::remove_all(out);
  fs::remove(file);
  return r;
}

// `text` with its first line "size = <from>" made "size = <to>".
std::string with_size(std::string text, const std::string& from, double to) {
  const std::string key = "\nsize = " + from + "\n";
  const std::size_t at = text.find(key);
  EXPECT_NE(at, std::string::npos) << key;
  if (at == std::string::npos) return text;
  return text.replace(at, key.size(), "\nsize = " + std::to_string(to) + "\n");
}

// ∫ σyy dx over [x0, x1] of the line y = 0: each sub-block's face on the line (in its shape as
// built) times the block's uniform σyy at rest.
double force_on_symmetry_line(const StaticRun& r, double x0, double x1) {
  const std::vector<double> xyz = read_vtu_array(r.initial_blocks, "Points");
  const std::vector<std::int64_t> connectivity = read_vtu_int64_array(r.initial_blocks, "connectivity");
  const std::vector<std::int64_t> offsets = read_vtu_int64_array(r.initial_blocks, "offsets");
  const std::vector<double> stress = read_vtu_array(r.final_blocks, "stress");
  EXPECT_EQ(stress.size(), 3 * offsets.size());
  if (stress.size() != 3 * offsets.size()) return 0.0;
  double force = 0.0;
  std::int64_t start = 0;
  for (std::size_t c = 0; c < offsets.size(); ++c) {
    const std::int64_t n = offsets[c] - start;
    for (std::int64_t k = 0; k < n; ++k) {
      const auto p = static_cast<std::size_t>(connectivity[static_cast<std::size_t>(start + k)]);
      const auto q = static_cast<std::size_t>(connectivity[static_cast<std::size_t>(start + (k + 1) % n)]);
      if (std::abs(xyz[3 * p + 1]) > 1e-9 || std::abs(xyz[3 * q + 1]) > 1e-9) continue;
      const double lo = std::max(std::min(xyz[3 * p], xyz[3 * q]), x0);
      const double hi = std::min(std::max(xyz[3 * p], xyz[3 * q]), x1);
      if (hi > lo) force += stress[3 * c + 1] * (hi - lo);
    }
    start = offsets[c];
  }
  return force;
}

// The error falls strictly at each halving of h (errors listed coarsest first).
void expect_falling(const std::array<double, 3>& error) {
  EXPECT_LT(error[1], error[0]) << "errors " << error[0] << ", " << error[1] << ", " << error[2];
  EXPECT_LT(error[2], error[1]);
}

TEST(BondedContinuumVerification, APlateWithAHoleOfBondedTrianglesCarriesKirschsLigamentForce) {
  constexpr double kHole = 1.0;      // a (m)
  constexpr double kTension = 1.0e6;  // σ (Pa)
  constexpr double kKirsch = 1.6875 * kTension * kHole;  // ∫ σyy dx from a to 2a
  const std::string shipped = read_text(kVerification / "plate_with_hole.toml");
  const std::array<double, 3> sizes{0.4, 0.2, 0.1};  // about the hole; the next ring 2 h
  std::array<double, 3> error{};
  for (std::size_t k = 0; k < sizes.size(); ++k) {
    const std::string text = with_size(with_size(shipped, "0.1", sizes[k]), "0.2", 2.0 * sizes[k]);
    const StaticRun r = run_static(text, "plate-" + std::to_string(k));
    ASSERT_FALSE(r.final_blocks.empty());
    EXPECT_EQ(r.summary["converged"], true) << "h = " << sizes[k];
    error[k] = std::abs(force_on_symmetry_line(r, kHole, 2.0 * kHole) / kKirsch - 1.0);
  }
  expect_falling(error);
  EXPECT_LT(error[2], 0.05) << "h = a/10";  // measured 0.0385
}

TEST(BondedContinuumVerification, ACantileverOfBondedTrianglesDeflectsAsTimoshenkosBeam) {
  constexpr double kLoad = 5.0e3, kLength = 8.0, kDepth = 1.0;  // P (N/m), L, d (m)
  constexpr double kYoung = 1.0e10, kPoisson = 0.25;
  constexpr double kShearModulus = kYoung / (2.0 * (1.0 + kPoisson));
  const double beam = kLoad * std::pow(kLength, 3) / (3.0 * kYoung * std::pow(kDepth, 3) / 12.0) +
                      kLoad * kLength / (5.0 / 6.0 * kShearModulus * kDepth);
  const std::string shipped = read_text(kVerification / "bonded_cantilever.toml");
  const std::array<double, 3> sizes{0.5, 0.25, 0.125};
  std::array<double, 3> error{};
  for (std::size_t k = 0; k < sizes.size(); ++k) {
    const StaticRun r = run_static(with_size(shipped, "0.125", sizes[k]), "cantilever-" + std::to_string(k));
    ASSERT_TRUE(r.summary.contains("measure"));
    EXPECT_EQ(r.summary["converged"], true) << "h = " << sizes[k];
    const double tip = -r.summary["measure"]["tip"]["displacement"][1].get<double>();
    error[k] = std::abs(tip / beam - 1.0);
  }
  expect_falling(error);
  EXPECT_LT(error[2], 0.03) << "h = d/8";  // measured 0.021
}

// Voronoi cells are zoned: each fanned from its centroid into the triangles `triangles` makes of
// it, the faces within a cell holding for good (docs/dda.md, "Bonds"). So the same seeds' cells
// bend as their triangles do until a face breaks: the tip within 1e-6 of the triangles' (the same
// sub-blocks and locked faces, numbered otherwise), and so within 3% of Timoshenko's at d/8.
// Uniform-strain cells bonded along their faces locked: 0.105 of δ at d/16 (the study above).
TEST(BondedContinuumVerification, ACantileverOfZonedVoronoiCellsBendsAsItsTriangles) {
  const std::string shipped = read_text(kVerification / "bonded_cantilever.toml");
  const std::string key = "kind = \"triangles\"";
  std::string voronoi = shipped;
  ASSERT_NE(voronoi.find(key), std::string::npos);
  voronoi.replace(voronoi.find(key), key.size(), "kind = \"voronoi\"");
  const StaticRun cells = run_static(voronoi, "cantilever-voronoi");
  const StaticRun triangles = run_static(shipped, "cantilever-triangles");
  ASSERT_TRUE(cells.summary.contains("measure") && triangles.summary.contains("measure"));
  EXPECT_EQ(cells.summary["converged"], true);
  const double tip = cells.summary["measure"]["tip"]["displacement"][1].get<double>();
  const double expected = triangles.summary["measure"]["tip"]["displacement"][1].get<double>();
  EXPECT_NEAR(tip / expected, 1.0, 1e-6) << "the tip " << tip << " m, its triangles' " << expected << " m";
}

}  // namespace
}  // namespace hydrodda::testing::coupled
