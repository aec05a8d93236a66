// docs/tutorial_faulted_seal.md's steps through the program, and the numbers the page quotes
// (scenarios/examples/layered_faulted_seal.toml): the model `check` counts and draws, the run
// at 100 m of overpressure with the fault on its own hydraulic aperture law, the sweep of the
// fault's residual aperture, the sweep of the overpressure with the fractures that open, and
// the runs at 0.90 of the hand jacking head with the mesh halved once more, at 0.95 of it with
// the load at once and ramped (as the default ramp chooses), and at 0.97 of it ramped over 3 and 5 passes.
// Tolerances: counts and statuses exact; K_eff/K_m and flows within 0.5% of the page's values
// (printed to 3 or 4 figures); the change on halving the mesh under 2% (the bar its mesh is
// chosen by); the fault's hydraulic aperture within 1e-4 of its own law at its mean normal
// stress (its faces between the bedding carry different stresses, and the mean of the convex
// closure law lies above the law at the mean, Jensen's inequality: measured +1.1e-5 relative;
// [joint]'s law at that stress would give 12.5 µm, not 102.5).

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "result_files.hpp"
#include "run_program.hpp"

namespace fs = std::filesystem;
using hydrodda::testing::read_csv;
using hydrodda::testing::run_program;

namespace {

const std::string kScenario = std::string(HYDRODDA_SOURCE_DIR) + "/scenarios/examples/layered_faulted_seal.toml";

struct Folder : hydrodda::testing::TemporaryFolder {
  Folder() : TemporaryFolder("hydrodda-faulted-seal-tutorial-" + std::to_string(::getpid())) {}
};

nlohmann::json read_json(const fs::path& file) {
  std::ifstream in(file);
  return in ? nlohmann::json::parse(in) : nlohmann::json::object();
}

// The fractures open over some of their length (open_share > 0) in the last pass's rows of a
// fractures.csv, as "id:type".
std::set<std::string> opening_fractures(const fs::path& fractures_csv) {
  const auto rows = read_csv(fractures_csv);
  std::set<std::string> opening;
  if (rows.size() < 2) return opening;
  const auto column = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(rows[0].begin(), rows[0].end(), name) - rows[0].begin());
  };
  for (std::size_t r = 1; r < rows.size(); ++r)
    if (rows[r][0] == rows.back()[0] && std::stod(rows[r][column("open_share")]) > 0.0)
      opening.insert(rows[r][column("fracture")] + ":" + rows[r][column("type")]);
  return opening;
}

// Step 3: the counts `check` prints, no warning, and the preview drawn.
TEST(FaultedSealTutorial, CheckCountsTheModelAndDrawsIt) {
  Folder folder;
  fs::create_directories(folder.path);
  const fs::path preview = folder.path / "preview.png";
  const auto result = run_program("check " + kScenario + " --figure " + preview.string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("21 traces (3 listed, 3 from joint set 1, 15 from joint set 2), 73 blocks"),
            std::string::npos)
      << result.output;
  EXPECT_EQ(result.output.find("warning"), std::string::npos) << result.output;
  EXPECT_GT(fs::file_size(preview), 10000u);
}

// Step 4: converged; K_eff/K_m 783; nothing open; the fault of type "fault" at its own law's
// aperture a_r + V_m − σn V_m/(k_ni V_m + σn) (a_r = 1e-4 m its own, V_m = 5e-5 m and
// k_ni = 2e10 Pa/m [joint]'s), 102.5 µm at 19.2 MPa; joint 13 at [joint]'s, 12.7 µm; the fault
// carrying 2.11e-6 of the top's 2.53e-6 m²/s. No warning of the fracture permeability cap: two
// elements along the bedding at the left roller hold a sliver of open area (2e-9 of their area)
// whose local aperture, taken at their centroids inside the blocks, comes out past the cap's
// 10 mm, but along the joints the porosity law gives way to the joints' own transmissivity.
TEST(FaultedSealTutorial, RunsWithTheFaultOnItsOwnAperture) {
  Folder folder;
  const fs::path out = folder.path / "run";
  const auto result = run_program("-q run " + kScenario + " -o " + out.string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_EQ(result.output.find("fracture_permeability_cap"), std::string::npos) << result.output;
  const nlohmann::json s = read_json(out / "summary.json");
  ASSERT_TRUE(s.contains("flow")) << result.output;
  EXPECT_TRUE(s["converged"].get<bool>());
  EXPECT_NEAR(s["flow"]["regions"]["seal"]["normalised_conductivity"].get<double>(), 783.0, 0.005 * 783.0);
  EXPECT_EQ(s["fractures"]["open"].get<int>(), 0);
  const auto& fault = s["fractures"]["by_id"]["2"];
  EXPECT_EQ(fault["type"].get<std::string>(), "fault");
  const double sigma = fault["normal_stress"].get<double>();
  EXPECT_NEAR(sigma, 19.2e6, 0.005 * 19.2e6);
  const double own_law = 1.0e-4 + 5.0e-5 - sigma * 5.0e-5 / (2.0e10 * 5.0e-5 + sigma);
  EXPECT_NEAR(fault["hydraulic_aperture"].get<double>(), own_law, 1e-4 * own_law);
  EXPECT_NEAR(fault["hydraulic_aperture"].get<double>(), 102.5e-6, 0.05e-6);
  EXPECT_NEAR(s["fractures"]["by_id"]["13"]["hydraulic_aperture"].get<double>(), 12.7e-6, 0.05e-6);
  EXPECT_NEAR(fault["flow"].get<double>(), 2.11e-6, 0.005 * 2.11e-6);
  EXPECT_NEAR(s["flow"]["boundaries"]["top"].get<double>(), 2.53e-6, 0.005 * 2.53e-6);
}

// A sweep of one key of the tutorial's scenario (`set`: KEY=V1,V2,...) gathering the seal's
// K_eff/K_m: every case converged, each K_eff/K_m within 0.5% of `expected` (the page's, printed
// to 3 or 4 figures); the sweep.csv rows, the header first.
std::vector<std::vector<std::string>> expect_converged_sweep(const fs::path& out, const std::string& set,
                                                             const std::vector<double>& expected) {
  const auto result = run_program("-q sweep " + kScenario + " --set '" + set + "' --threads 1" +
                                  " --column flow.regions.seal.normalised_conductivity -o " + out.string());
  EXPECT_EQ(result.exit_code, 0) << result.output;
  const auto sweep = read_csv(out / "sweep.csv");
  EXPECT_EQ(sweep.size(), expected.size() + 1);
  for (std::size_t c = 0; c < expected.size() && c + 1 < sweep.size(); ++c) {
    EXPECT_EQ(sweep[c + 1][3], "true") << "case " << c;
    EXPECT_NEAR(std::stod(sweep[c + 1][5]), expected[c], 0.005 * expected[c]) << "case " << c;
  }
  return sweep;
}

// Step 4's sweep of the fault's residual aperture: K_eff/K_m 29.0, 783, 16,546.
TEST(FaultedSealTutorial, TheSealFollowsTheFaultsAperture) {
  Folder folder;
  expect_converged_sweep(folder.path / "fault-aperture", "joint.fault.residual_aperture=1e-5,1e-4,3e-4",
                         {29.0, 783.0, 16546.0});
}

// Step 5: the overpressure sweep's table, each case's overpressure ramped over 3 passes from the
// in-situ state (the default ramp: the load at once moves the blocks): converged up to 2300 m with
// K_eff/K_m 783 … 899 rising at every step, nothing open up to 2100 m, and the seal's base
// (bedding 0) alone from 2200 m, over a hundredth of its length, then a twenty-fifth.
TEST(FaultedSealTutorial, TheOverpressureSweepOpensTheFracturesItLists) {
  Folder folder;
  const fs::path out = folder.path / "fault-sweep";
  const auto result = run_program("-q sweep " + kScenario +
                                   " --set 'flow.boundary[0].head=1940,2340,2840,3340,3740,3790,3840,3890,3940,4040,4140'" +
                                  " --column flow.regions.seal.normalised_conductivity -o " + out.string());
  EXPECT_EQ(result.exit_code, 0) << result.output;
  const auto sweep = read_csv(out / "sweep.csv");
  ASSERT_EQ(sweep.size(), 12u);
  const double conductivity[] = {782.7, 794.4, 812.8, 836.6, 863.3, 867.1, 871.0, 875.2, 879.5, 888.5, 898.7};
  const std::vector<std::set<std::string>> opening{{}, {}, {}, {}, {}, {}, {}, {}, {}, {"0:bedding"}, {"0:bedding"}};
  for (int c = 0; c < 11; ++c) {
    const std::string name = c < 10 ? "case_00" + std::to_string(c) : "case_0" + std::to_string(c);
    EXPECT_EQ(sweep[c + 1][3], "true") << "case " << c;
    EXPECT_NEAR(std::stod(sweep[c + 1][5]), conductivity[c], 0.005 * conductivity[c]) << "case " << c;
    EXPECT_EQ(opening_fractures(out / name / "fractures.csv"), opening[c]) << "case " << c;
  }
}

// Step 5, near the breach: at 2308 m of overpressure (0.90 of the hand jacking head
// H* = 2564 m) a run from the in-situ state converges at default settings (7 passes), K_eff/K_m
// 900.1 (0.5%, as the table's), the seal's base alone partly open. The same run on the mesh
// halved once more (mesh.size 1 m, mesh.fracture_size 0.25 m) moves K_eff/K_m by under 2%
// (measured −0.21%, 898.3: the shipped mesh is fine enough here;
// docs/studies/2026-11-30-in-situ-ramp.md).
TEST(FaultedSealTutorial, TheLoopConvergesAtDefaultsAt090OfTheJackingHeadOnAMeshThatHalvingMovesUnder2Percent) {
  Folder folder;
  const fs::path quartered = hydrodda::testing::edited_scenario(
      kScenario, "hydrodda-faulted-seal-quartered-" + std::to_string(::getpid()),
      {{"\nsize = 2.0 ", "\nsize = 1.0 "}, {"fracture_size = 0.5 ", "fracture_size = 0.25 "}});
  double conductivity[2] = {0.0, 0.0};
  for (int mesh = 0; mesh < 2; ++mesh) {
    const fs::path out = folder.path / (mesh == 0 ? "shipped" : "quartered");
    const std::string scenario = mesh == 0 ? kScenario : quartered.string();
    const auto result = run_program("-q sweep " + scenario + " --set 'flow.boundary[0].head=4148' --threads 1" +
                                    " --column flow.regions.seal.normalised_conductivity -o " + out.string());
    EXPECT_EQ(result.exit_code, 0) << result.output;
    const auto sweep = read_csv(out / "sweep.csv");
    ASSERT_EQ(sweep.size(), 2u);
    EXPECT_EQ(sweep[1][3], "true") << "0.90 H*: the loop converges, mesh " << mesh;
    conductivity[mesh] = std::stod(sweep[1][5]);
    EXPECT_EQ(opening_fractures(out / "case_000" / "fractures.csv"), std::set<std::string>{"0:bedding"})
        << "mesh " << mesh;
  }
  fs::remove(quartered);
  EXPECT_NEAR(conductivity[0], 900.1, 0.005 * 900.1);
  EXPECT_LT(std::abs(conductivity[1] - conductivity[0]), 0.02 * conductivity[0]);
}

// Step 5, near the breach at default settings: from the in-situ state, its first pass at once
// moving the blocks and run again with the overpressure ramped over 3 passes (the default ramp),
// the seal converges at 0.92, 0.95 and 0.97 of the hand jacking head (7, 8 and 7 passes),
// K_eff/K_m 905.9, 917.3 and 926.9 (0.5%, as the table's) rising with the load, the seal's base
// alone opening, over more of its length at each (0.24, 0.58, 0.69). With the whole load at once
// the same runs swing or drift for their 30 passes (AtOnceThe095CaseSaysToRampItsLoadAndRampedItConverges).
TEST(FaultedSealTutorial, TheLoopConvergesAtDefaultsUpTo097OfTheJackingHead) {
  Folder folder;
  const fs::path out = folder.path / "near-breach";
  const auto sweep = expect_converged_sweep(out, "flow.boundary[0].head=4199,4276,4327", {905.9, 917.3, 926.9});
  ASSERT_EQ(sweep.size(), 4u);
  for (int c = 0; c < 3; ++c) {
    if (c > 0) {
      EXPECT_GT(std::stod(sweep[c + 1][5]), std::stod(sweep[c][5])) << "case " << c;
    }
    EXPECT_EQ(opening_fractures(out / ("case_00" + std::to_string(c)) / "fractures.csv"),
              std::set<std::string>{"0:bedding"})
        << "case " << c;
  }
}

// Step 5, the load ramped: at 2487 m (0.97 H*) a run from the in-situ state whose fluid load
// rises over its first passes (coupling.ramp_passes = 3, what the default chooses here, or 5) converges (7 and
// 9 passes), where the whole load at once drifts; the fault stays shut and the seal's base alone opens, over
// 68–74% of its length; K_eff/K_m 927.7, the same for either ramp within 0.5% (measured 0.003%:
// once ramped, the state does not depend on the ramp's length).
TEST(FaultedSealTutorial, TheLoopConvergesAt097OfTheJackingHeadWithTheFluidLoadRamped) {
  Folder folder;
  const fs::path out = folder.path / "ramped";
  const auto result = run_program("-q sweep " + kScenario + " --set 'flow.boundary[0].head=4327'" +
                                  " --set 'coupling.ramp_passes=3,5' --threads 1" +
                                  " --column flow.regions.seal.normalised_conductivity -o " + out.string());
  EXPECT_EQ(result.exit_code, 0) << result.output;
  const auto sweep = read_csv(out / "sweep.csv");
  ASSERT_EQ(sweep.size(), 3u);
  for (int c = 0; c < 2; ++c) {
    EXPECT_EQ(sweep[c + 1][4], "true") << "0.97 H*, ramp case " << c;
    EXPECT_NEAR(std::stod(sweep[c + 1][6]), 927.7, 0.005 * 927.7) << "ramp case " << c;
    EXPECT_EQ(opening_fractures(out / ("case_00" + std::to_string(c)) / "fractures.csv"),
              std::set<std::string>{"0:bedding"})
        << "ramp case " << c;
  }
  EXPECT_NEAR(std::stod(sweep[1][6]), std::stod(sweep[2][6]), 0.005 * std::stod(sweep[1][6]));
}

// Step 5, the load at once and ramped, with each point of the joints open by its own gap
// (`joint.hydraulic_opening = "local"`): at 2436 m (0.95 H*) the run that puts the whole load on
// at once (coupling.ramp_passes = 1) ends unconverged after its 30 passes and says to try
// coupling.ramp_passes = 3; so ramped, as by default, it converges (8 passes, K_eff/K_m 917.3 within 0.5%). The overburden's 4 cm is the
// whole column swelling as the pore pressure rises, which both paths share: the top block
// (72) at 41.7 mm at once and 40.9 mm ramped, asserted within 5% of each other and above 35 mm
// (docs/studies/2026-11-29-default-ramp.md: the sudden load's first pass lifts it to 49 mm and
// leaves the joints it opened chattering, where ramped none opens before the full load); its
// message tells those joints opening and shutting from pass to pass.
TEST(FaultedSealTutorial, AtOnceThe095CaseSaysToRampItsLoadAndRampedItConverges) {
  Folder folder;
  const fs::path out = folder.path / "at-once-and-ramped";
  const auto result = run_program("-q sweep " + kScenario + " --set 'flow.boundary[0].head=4276'" +
                                  " --set 'joint.hydraulic_opening=local' --set 'coupling.ramp_passes=1,3' --threads 1" +
                                  " --column flow.regions.seal.normalised_conductivity -o " + out.string());
  EXPECT_NE(result.exit_code, 0) << "one case does not converge: " << result.output;
  const nlohmann::json at_once = read_json(out / "case_000" / "summary.json");
  const nlohmann::json ramped = read_json(out / "case_001" / "summary.json");
  ASSERT_TRUE(at_once.contains("message") && ramped.contains("flow")) << result.output;
  EXPECT_EQ(at_once["converged"], false);
  EXPECT_EQ(at_once["iterations"], 30);
  EXPECT_NE(at_once["message"].get<std::string>().find(
                "the whole fluid load went on at once in the first pass (coupling.ramp_passes = 1): try "
                "coupling.ramp_passes = 3"),
            std::string::npos)
      << at_once["message"];
  EXPECT_NE(at_once["message"].get<std::string>().find("the joints open and shut from pass to pass"),
            std::string::npos)
      << at_once["message"];
  EXPECT_EQ(ramped["converged"], true);
  EXPECT_EQ(ramped["iterations"], 8);
  EXPECT_NEAR(ramped["flow"]["regions"]["seal"]["normalised_conductivity"].get<double>(), 917.3, 0.005 * 917.3);
  const double top_at_once = at_once["blocks"][72]["displacement"][1].get<double>();
  const double top_ramped = ramped["blocks"][72]["displacement"][1].get<double>();
  EXPECT_GT(top_ramped, 0.035);
  EXPECT_NEAR(top_at_once, top_ramped, 0.05 * top_ramped);
}

// The same at once by default, where a joint face that carries a force is closed along its whole
// length under its mean stress (docs/coupling.md, "Joint hydraulic apertures"): the gaps the
// blocks' uniform strains leave at a face's end no longer open and shut from pass to pass, and
// the loop converges with the load at once (measured: 6 passes, K_eff/K_m 933.7 against the
// ramped path's 917.2, friction keeping what each path did), the top block lifted as on the
// ramped path (within 5%, as above).
TEST(FaultedSealTutorial, ByDefaultThe095CaseConvergesWithTheLoadAtOnce) {
  Folder folder;
  const fs::path out = folder.path / "at-once";
  const auto result = run_program("-q sweep " + kScenario + " --set 'flow.boundary[0].head=4276'" +
                                  " --set 'coupling.ramp_passes=1' --threads 1 -o " + out.string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const nlohmann::json at_once = read_json(out / "case_000" / "summary.json");
  EXPECT_EQ(at_once["converged"], true) << at_once["message"];
  EXPECT_LE(at_once["iterations"].get<int>(), 10);
  EXPECT_NEAR(at_once["blocks"][72]["displacement"][1].get<double>(), 0.0409, 0.05 * 0.0409);
}

}  // namespace
