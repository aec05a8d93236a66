// Joint types through the program (scenarios/verification/incline_joint_types.toml): on a 30°
// incline, a block on a fault of no cohesion slides as Mohr–Coulomb friction alone allows,
//   d(t) = ½ g (sin θ − cos θ tan φ) t²   (θ = 30°, φ = 20°: 0.906407 m at 1 s),
// within 1% (as the engine's own sliding-block verification), while a block of the same
// friction on a joint of 100 kPa cohesion holds: it moves less than 1e-4 m. fractures.csv and
// summary.json name each fracture's type.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "../cli/run_program.hpp"

namespace {

namespace fs = std::filesystem;
using hydrodda::testing::read_csv;
using hydrodda::testing::run_program;

TEST(JointTypes, AFaultWithoutCohesionSlidesWhileAJointWithCohesionHolds) {
  const fs::path scenario = fs::path(HYDRODDA_SOURCE_DIR) / "scenarios/verification/incline_joint_types.toml";
  const fs::path out = fs::temp_directory_path() / ("hydrodda-joint-types-" + std::to_string(::getpid()));
  fs::remove_all(out);
  const auto result = run_program("run " + scenario.string() + " -o " + out.string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  std::ifstream in(out / "summary.json");
  const nlohmann::json s = nlohmann::json::parse(in);
  const auto csv = read_csv(out / "fractures.csv");
  fs::remove_all(out);

  const double theta = 30.0 * M_PI / 180.0, phi = 20.0 * M_PI / 180.0;
  const double expected = 0.5 * 9.81 * (std::sin(theta) - std::cos(theta) * std::tan(phi));
  const auto& fault = s["measure"]["fault-block"]["displacement"];
  const double slid = std::hypot(fault[0].get<double>(), fault[1].get<double>());
  EXPECT_NEAR(slid, expected, 0.01 * expected);
  EXPECT_LT(fault[0].get<double>(), 0.0);  // downhill
  const auto& joint = s["measure"]["joint-block"]["displacement"];
  EXPECT_LT(std::hypot(joint[0].get<double>(), joint[1].get<double>()), 1e-4);

  // The types by fracture id, as the scenario lists them.
  const auto& by_id = s["fractures"]["by_id"];
  EXPECT_EQ(by_id["0"]["type"], "fault");
  EXPECT_EQ(by_id["1"]["type"], "joint");
  EXPECT_EQ(by_id["2"]["type"], "side");
  ASSERT_GE(csv.size(), 4u);
  const auto type_column = std::find(csv[0].begin(), csv[0].end(), "type") - csv[0].begin();
  ASSERT_LT(static_cast<std::size_t>(type_column), csv[0].size());
  EXPECT_EQ(csv[1][type_column], "fault");
  EXPECT_EQ(csv[2][type_column], "joint");
  EXPECT_EQ(csv[3][type_column], "side");
}

}  // namespace
