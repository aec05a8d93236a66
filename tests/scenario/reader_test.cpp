#include "scenario/reader.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <utility>

#include "parse_errors.hpp"
#include "scenario/diagnostics.hpp"

namespace hydrodda::scenario {
namespace {

const std::filesystem::path kSource = std::filesystem::path(HYDRODDA_SOURCE_DIR);

// One free 1 m block of rock, up to the [mechanics] header (on line 8): the cases below add
// the mechanics keys they are about.
const std::string kOneFreeBlock = R"([geometry]
[[geometry.block]]
vertices = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]
[material.rock]
density = 2500.0
young = 1.0e10
poisson = 0.25
[mechanics]
)";

using test_support::errors_of;

TEST(ScenarioReader, ReadsEveryKeyOfTheContract) {
  const Scenario s = read_scenario(kSource / "scenarios/examples/contract.toml");
  EXPECT_EQ(s.title, "Six-block asymmetric model: left-right shortening, flow right to left");
  ASSERT_TRUE(s.geometry);
  EXPECT_EQ(s.geometry->domain.size(), 4u);
  ASSERT_EQ(s.geometry->fractures.size(), 2u);
  EXPECT_EQ(s.geometry->fractures[0].from, (Point{0.0, 2.1}));
  EXPECT_EQ(s.geometry->fractures[1].to, (Point{2.0, 5.0}));
  EXPECT_EQ(s.geometry->welded.size(), 1u);
  EXPECT_DOUBLE_EQ(s.geometry->initial_aperture, 0.01);

  const BoundarySegment* incline = s.find_boundary("incline");
  ASSERT_NE(incline, nullptr);
  EXPECT_EQ(incline->segment.to, (Point{4.0, 2.0}));
  const BoundarySegment* top = s.find_boundary("top");
  ASSERT_NE(top, nullptr);
  EXPECT_TRUE(top->is_default);
  EXPECT_EQ(top->segment.from, (Point{0.0, 5.0}));
  EXPECT_EQ(top->segment.to, (Point{5.0, 5.0}));

  const MaterialDefinition* rock = s.find_material("rock");
  ASSERT_NE(rock, nullptr);
  EXPECT_DOUBLE_EQ(*rock->young, 1.0e10);
  EXPECT_DOUBLE_EQ(*rock->poisson, 0.35);
  EXPECT_DOUBLE_EQ(rock->matrix_porosity, 0.1);
  EXPECT_DOUBLE_EQ(s.joint.cohesion, 3.0e5);

  ASSERT_TRUE(s.mechanics);
  EXPECT_EQ(s.mechanics->analysis, dda::Analysis::static_);
  EXPECT_EQ(s.mechanics->plane, dda::Plane::strain);
  EXPECT_EQ(*s.mechanics->steps, 500);
  EXPECT_EQ(s.mechanics->contact, dda::ContactMethod::augmented_lagrangian);
  ASSERT_EQ(s.mechanics->displacements.size(), 1u);
  EXPECT_EQ(s.mechanics->displacements[0].boundary, "right");
  EXPECT_EQ(s.mechanics->displacements[0].value, (Point{-0.005, 0.0}));
  ASSERT_EQ(s.mechanics->tractions.size(), 1u);
  EXPECT_DOUBLE_EQ(s.mechanics->tractions[0].normal.value(0.0), -5.0e6);
  EXPECT_DOUBLE_EQ(s.mechanics->tractions[0].normal_end.value(0.0), -5.0e6);  // defaults to `normal`
  ASSERT_EQ(s.mechanics->measures.size(), 1u);
  EXPECT_EQ(s.mechanics->measures[0].name, "A");
  ASSERT_EQ(s.mechanics->rollers.size(), 1u);
  EXPECT_EQ(s.mechanics->rollers[0].boundary, "left");
  ASSERT_TRUE(s.mechanics->initial_stress);
  EXPECT_EQ(s.mechanics->initial_stress->stress, (std::array<double, 3>{-5.0e6, -1.0e7, 0.0}));
  EXPECT_EQ(s.mechanics->initial_stress->reference_y, 0.0);
  EXPECT_EQ(s.mechanics->initial_stress->gradient, (std::array<double, 3>{1.2e4, 2.4e4, 0.0}));

  ASSERT_TRUE(s.flow);
  EXPECT_EQ(s.flow->pressure, hydro::PressureConvention::overpressure);
  EXPECT_EQ(s.flow->permeability_law, coupling::PermeabilityLaw::kozeny_carman);
  ASSERT_EQ(s.flow->boundaries.size(), 2u);
  EXPECT_EQ(s.flow->boundaries[0].kind, hydro::BoundaryKind::head);
  EXPECT_DOUBLE_EQ(s.flow->boundaries[0].value.value(0.0), 20.0);
  ASSERT_EQ(s.flow->regions.size(), 1u);
  EXPECT_FALSE(s.flow->regions[0].permeability.has_value());

  ASSERT_TRUE(s.mesh);
  EXPECT_DOUBLE_EQ(s.mesh->fracture_size, 0.01);
  EXPECT_EQ(s.coupling.max_iterations, 50);
  EXPECT_EQ(s.output.directory, "out/six-block");
  EXPECT_EQ(s.output.figures, std::vector<std::string>{"png"});
}

// No closed contact pulls past the joint's strength unless the file asks for the hysteresis band.
TEST(ScenarioReader, TheTensionCutoffIsOnUnlessTurnedOff) {
  const std::string base = kOneFreeBlock + "analysis = \"dynamic\"\nsteps = 10\n";
  EXPECT_TRUE(parse_scenario(base, "case.toml").mechanics->tension_cutoff);
  EXPECT_FALSE(parse_scenario(base + "tension_cutoff = false\n", "case.toml").mechanics->tension_cutoff);
}

TEST(ScenarioReader, RecordsEveryDefaultItFillsIn) {
  const Scenario s = parse_scenario(R"(
[geometry]
domain = [[0.0, 0.0], [4.0, 0.0], [4.0, 2.0], [0.0, 2.0]]
[material.rock]
matrix_porosity = 0.2
grain_diameter = 1e-5
[flow]
[[flow.boundary]]
name = "left"
head = 1.0
)", "flow.toml");
  const auto has_default = [&](const std::string& key) {
    for (const auto& d : s.defaults_used)
      if (d.key == key) return true;
    return false;
  };
  EXPECT_TRUE(has_default("flow.pressure"));
  EXPECT_EQ(s.flow->pressure, hydro::PressureConvention::hydrostatic);  // p = ρ g (h − z) unless named
  EXPECT_TRUE(has_default("flow.permeability_law"));
  EXPECT_TRUE(has_default("mesh.size"));
  EXPECT_TRUE(has_default("output.directory"));
  EXPECT_TRUE(has_default("output.every"));
  EXPECT_EQ(s.output.every, 100);
  EXPECT_TRUE(s.output.fields.fluid && s.output.fields.blocks && s.output.fields.contacts && s.output.fields.fractures);
  // Mesh size defaults to 1/40 of the domain's larger side.
  EXPECT_DOUBLE_EQ(s.mesh->size, 0.1);
  EXPECT_DOUBLE_EQ(s.mesh->fracture_size, 0.01);
  EXPECT_EQ(s.output.directory, std::filesystem::path("out/flow"));
  EXPECT_FALSE(s.mechanics.has_value());
}

TEST(ScenarioReader, OutputFieldsPickTheSeries) {
  const Scenario s = parse_scenario(R"(
[geometry]
domain = [[0.0, 0.0], [4.0, 0.0], [4.0, 2.0], [0.0, 2.0]]
[material.rock]
matrix_porosity = 0.2
grain_diameter = 1e-5
[flow]
[[flow.boundary]]
name = "left"
head = 1.0
[output]
every = 7
fields = ["contacts", "fluid"]
)", "flow.toml");
  EXPECT_EQ(s.output.every, 7);
  EXPECT_TRUE(s.output.fields.fluid);
  EXPECT_FALSE(s.output.fields.blocks);
  EXPECT_TRUE(s.output.fields.contacts);
  EXPECT_FALSE(s.output.fields.fractures);
}

TEST(ScenarioReader, MalformedTomlNamesTheLine) {
  const auto errors = errors_of("title = \"ok\"\n[geometry\n");
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].line, 2);
  EXPECT_NE(errors[0].message.find("malformed TOML"), std::string::npos);
}

TEST(ScenarioReader, ErrorsAreSortedByLine) {
  const auto errors = errors_of(R"([geometry]
[[geometry.block]]
vertices = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]
[material.rock]
density = -2.0
young = 0.0
poisson = 0.7
[mechanics]
steps = 0
analysis = "dynamic"
)");
  ASSERT_EQ(errors.size(), 4u);
  for (std::size_t i = 1; i < errors.size(); ++i) EXPECT_LE(errors[i - 1].line, errors[i].line);
  EXPECT_EQ(errors[0].key, "material.rock.density");
  EXPECT_EQ(errors[3].key, "mechanics.steps");
  EXPECT_EQ(errors[3].format(), "case.toml:9: mechanics.steps: must be a whole number from 1 to 100000000, got 0");
}

// Item 18 of the robustness list: a value that is there but not a number (nan, inf) is one
// error, that value's; it had also been reported missing ("required by [mechanics]").
TEST(ScenarioReader, ANonFiniteValueIsOneErrorNotAlsoAMissingKey) {
  for (const char* value : {"nan", "inf", "-inf"}) {
    SCOPED_TRACE(value);
    const auto errors = errors_of(std::string(R"([geometry]
[[geometry.block]]
vertices = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]
fixed = true
[material.rock]
density = 2500.0
young = )") + value + R"(
poisson = 0.25
[mechanics]
steps = 1
)");
    ASSERT_EQ(errors.size(), 1u) << errors.back().format();
    EXPECT_EQ(errors[0].format(), "case.toml:7: material.rock.young: must be a finite number");
  }
}

// Compression is negative and the gradient per metre up: a stress that grows less compressive
// downward under gravity was run without a word.
TEST(ScenarioReader, AnInSituStressLessCompressiveDownwardIsRefused) {
  const std::string held = kOneFreeBlock + "[[mechanics.fixed]]\npoint = [0.5, 0.0]\n[mechanics.initial_stress]\n"
                                           "stress = [-1.0e6, -1.0e6, 0.0]\n";
  EXPECT_TRUE(errors_of(held + "gradient = [0.0, 24525.0, 0.0]\n").empty());
  const auto errors = errors_of(held + "gradient = [0.0, -24525.0, 0.0]\n");
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].line, 13);
  EXPECT_EQ(errors[0].key, "mechanics.initial_stress.gradient");
  EXPECT_NE(errors[0].message.find("dσyy/dy = -24525 Pa/m makes the stress less compressive downward"), std::string::npos)
      << errors[0].message;
  // With gravity pointing up the sign turns.
  EXPECT_TRUE(errors_of(kOneFreeBlock + "gravity = [0.0, 9.81]\n" + held.substr(kOneFreeBlock.size()) +
                        "gradient = [0.0, -24525.0, 0.0]\n").empty());
}

// In a coupled run the blocks carry the effective stress, whose gradient an upward seepage
// lowers: the jointed seal's is negative (100 m of head across its 6 m), and stands; with the
// heads 1 m apart the same gradient is refused.
TEST(ScenarioReader, AnEffectiveStressGradientMayBeAsLowAsTheSeepageMakesIt) {
  const std::filesystem::path seal = kSource / "scenarios/examples/jointed_seal.toml";
  std::ifstream in(seal);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_NO_THROW(parse_scenario(text.str(), seal));
  std::string weak = text.str();
  weak.replace(weak.find("head = 106.0"), 12, "head = 7.0");
  try {
    parse_scenario(weak, seal);
    ADD_FAILURE() << "a gradient the heads cannot hold was accepted";
  } catch (const ScenarioError& e) {
    ASSERT_EQ(e.diagnostics().size(), 1u) << e.what();
    EXPECT_EQ(e.diagnostics()[0].key, "mechanics.initial_stress.gradient") << e.what();
    EXPECT_NE(e.diagnostics()[0].message.find("-149766 Pa/m"), std::string::npos) << e.what();
  }
}

TEST(ScenarioReader, BlocksTakeTheOnlyMaterial) {
  const Scenario s = parse_scenario(R"([geometry]
[[geometry.block]]
vertices = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]
fixed = true
[[geometry.block]]
vertices = [[0.0, 1.0], [1.0, 1.0], [0.5, 2.0]]
[material.granite]
density = 2700.0
young = 5.0e10
poisson = 0.2
[mechanics]
steps = 3
)", "two.toml");
  ASSERT_EQ(s.geometry->blocks.size(), 2u);
  EXPECT_EQ(s.geometry->blocks[0].material, "granite");
  EXPECT_TRUE(s.geometry->blocks[0].fixed);
  EXPECT_FALSE(s.geometry->blocks[1].fixed);
  EXPECT_EQ(s.geometry->blocks[1].line, 5);
}

TEST(ScenarioReader, TouchingBlocksAreNotOverlapping) {
  // Two blocks sharing an edge, and one touching at a corner only: valid.
  EXPECT_TRUE(errors_of(R"([geometry]
[[geometry.block]]
vertices = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]
fixed = true
[[geometry.block]]
vertices = [[1.0, 0.0], [2.0, 0.0], [2.0, 1.0], [1.0, 1.0]]
[[geometry.block]]
vertices = [[2.0, 1.0], [3.0, 1.0], [3.0, 2.0]]
[material.rock]
density = 2500.0
young = 1.0e10
poisson = 0.25
[mechanics]
steps = 1
)").empty());
}

TEST(ScenarioReader, IdenticalBlocksOverlap) {
  const auto errors = errors_of(R"([geometry]
[[geometry.block]]
vertices = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]
[[geometry.block]]
vertices = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]
[material.rock]
density = 2500.0
young = 1.0e10
poisson = 0.25
[mechanics]
steps = 1
analysis = "dynamic"
)");
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_NE(errors[0].message.find("overlaps"), std::string::npos);
}

TEST(ScenarioReader, StaticAnalysisNeedsASupport) {
  // One free block under gravity, static: nothing holds it. A fixed block, a fixed point, a
  // prescribed displacement or dynamic analysis each make the model well posed.
  const std::string blocks = kOneFreeBlock + "steps = 1\n";
  const auto errors = errors_of(blocks);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].key, "mechanics.analysis");
  EXPECT_EQ(errors[0].line, 8);
  EXPECT_TRUE(errors_of(blocks + "analysis = \"dynamic\"\n").empty());
  EXPECT_TRUE(errors_of(blocks + "[[mechanics.fixed]]\npoint = [0.5, 0.0]\n").empty());
  EXPECT_TRUE(errors_of(blocks + "[[mechanics.displacement]]\nboundary = \"bottom\"\nvalue = [0.0, 0.0]\n").empty());
}

// A prescribed displacement's ramp_time is read as given; unset, the run's duration stands (the
// model building's default); zero, negative or not finite, it is an error naming its line.
TEST(ScenarioReader, APrescribedDisplacementTakesItsRampTime) {
  const std::string base =
      kOneFreeBlock + "steps = 10\n[[mechanics.displacement]]\nboundary = \"bottom\"\nvalue = [0.0, -0.01]\n";
  EXPECT_FALSE(parse_scenario(base, "case.toml").mechanics->displacements.at(0).ramp_time.has_value());
  const Scenario ramped = parse_scenario(base + "ramp_time = 2.5\n", "case.toml");
  EXPECT_EQ(ramped.mechanics->displacements.at(0).ramp_time, 2.5);
  for (const char* bad : {"0.0", "-1.0", "inf", "nan"}) {
    const auto errors = errors_of(base + "ramp_time = " + bad + "\n");
    ASSERT_EQ(errors.size(), 1u) << bad;
    EXPECT_EQ(errors[0].key, "mechanics.displacement.ramp_time") << bad;
    EXPECT_EQ(errors[0].line, 13) << bad;
  }
}

// coupling.settle is on by default in a static analysis, with or without a [coupling] table,
// and off in a dynamic one; asked of a dynamic analysis it is refused, naming its line.
TEST(ScenarioReader, SettlingPassesAreForStaticAnalysis) {
  const std::string base = kOneFreeBlock + "steps = 10\n";
  const std::string supported = base + "[[mechanics.fixed]]\npoint = [0.5, 0.0]\n";
  EXPECT_FALSE(parse_scenario(base + "analysis = \"dynamic\"\n", "case.toml").coupling.settle);
  EXPECT_FALSE(parse_scenario(base + "analysis = \"dynamic\"\n[coupling]\ntolerance = 1e-3\n", "case.toml").coupling.settle);
  EXPECT_TRUE(parse_scenario(supported, "case.toml").coupling.settle);
  EXPECT_TRUE(parse_scenario(supported + "[coupling]\ntolerance = 1e-3\n", "case.toml").coupling.settle);
  EXPECT_FALSE(parse_scenario(supported + "[coupling]\nsettle = false\n", "case.toml").coupling.settle);
  const auto errors = errors_of(base + "analysis = \"dynamic\"\n[coupling]\nsettle = true\n");
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].key, "coupling.settle");
  EXPECT_EQ(errors[0].line, 12);
}

// coupling.ramp_passes: in a steady coupled model that starts in an in-situ stress it is left to
// the first pass (ramp_if_moved 3: at once, or ramped over 3 passes if that moves the blocks;
// over the passes before the last where max_iterations leaves fewer, none where it leaves one);
// one that starts unstressed, or a transient run (which ramps nothing), takes the load at once;
// a value given stands, and nothing is left to the first pass.
TEST(ScenarioReader, AModelInAnInSituStressLeavesItsRampToItsFirstPass) {
  std::ifstream in(kSource / "scenarios/examples/jointed_seal.toml");
  std::stringstream text;
  text << in.rdbuf();
  const std::string seal = text.str();
  const auto coupling = [&](const std::string& max_iterations, const std::string& more = "") {
    std::string edited = seal;
    edited.replace(edited.find("max_iterations = 10"), 19, "max_iterations = " + max_iterations + more);
    const Scenario s = parse_scenario(edited, "seal.toml");
    return std::pair{s.coupling.ramp_passes, s.coupling.ramp_if_moved};
  };
  EXPECT_EQ(coupling("10"), std::pair(1, 3));
  EXPECT_EQ(coupling("3"), std::pair(1, 2));
  EXPECT_EQ(coupling("2"), std::pair(1, 0));
  EXPECT_EQ(coupling("10", "\nramp_passes = 1"), std::pair(1, 0));
  EXPECT_EQ(coupling("10", "\nramp_passes = 5"), std::pair(5, 0));
  std::string no_table = seal;
  no_table.erase(no_table.find("[coupling]"), no_table.find("max_iterations = 10") + 19 - no_table.find("[coupling]"));
  EXPECT_EQ(parse_scenario(no_table, "seal.toml").coupling.ramp_if_moved, 3);
  for (const char* file : {"scenarios/paper/six_block_ud_rl.toml", "scenarios/examples/seal_leaking_in_time.toml"}) {
    const Scenario s = read_scenario(kSource / file);
    EXPECT_EQ(s.coupling.ramp_passes, 1) << file;
    EXPECT_EQ(s.coupling.ramp_if_moved, 0) << file;
  }
}

// coupling.pseudo_time_step (s): off (0) when left out, read when given, and a value ≤ 0 is
// refused naming its line and key.
TEST(ScenarioReader, PseudoTimeStepIsOffUnlessGivenAndPositive) {
  const std::string base = kOneFreeBlock + "steps = 10\n[[mechanics.fixed]]\npoint = [0.5, 0.0]\n";
  EXPECT_EQ(parse_scenario(base, "case.toml").coupling.pseudo_time_step, 0.0);
  EXPECT_EQ(parse_scenario(base + "[coupling]\npseudo_time_step = 1e5\n", "case.toml").coupling.pseudo_time_step, 1e5);
  const auto errors = errors_of(base + "[coupling]\npseudo_time_step = 0.0\n");
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].key, "coupling.pseudo_time_step");
  EXPECT_EQ(errors[0].line, 13);
}

// [[mesh.refine]]: a point, a size (at most mesh.size) and a radius (by default where a size
// growing by a fifth of the distance reaches mesh.size); each bad value is an error naming its
// line and key.
TEST(ScenarioReader, MeshRefinePointsAreReadAndChecked) {
  const std::string mesh = "[mesh]\nsize = 0.1\nrefine_distance = 0.3\n";
  const std::string good = "[[mesh.refine]]\npoint = [0.5, 0.25]\nsize = 0.001\n"
                           "[[mesh.refine]]\npoint = [0.2, 0.7]\nsize = 0.002\nradius = 0.05\n";
  const std::string bad = "[[mesh.refine]]\nsize = 0.001\n"                          // line 21: no point
                          "[[mesh.refine]]\npoint = [0.5, 0.5]\nsize = 0.2\n"       // 23–25: above mesh.size
                          "[[mesh.refine]]\npoint = [0.5, 0.5]\nsize = 0.001\nradius = -1.0\n";  // 26–29
  const auto refine_errors = [](const std::vector<Diagnostic>& errors) {
    std::vector<std::string> found;
    for (const Diagnostic& e : errors)
      if (e.key.rfind("mesh.refine", 0) == 0) found.push_back(e.format());
    return found;
  };
  const std::string header = kOneFreeBlock + "steps = 1\nanalysis = \"dynamic\"\n" + mesh;  // [mesh] on line 10
  EXPECT_TRUE(refine_errors(errors_of(header + good)).empty());
  const std::vector<std::string> found = refine_errors(errors_of(header + good + bad));
  ASSERT_EQ(found.size(), 3u);
  EXPECT_EQ(found[0], "case.toml:21: mesh.refine.point: required key is missing");
  EXPECT_EQ(found[1], "case.toml:25: mesh.refine.size: must be <= mesh.size");
  EXPECT_EQ(found[2], "case.toml:29: mesh.refine.radius: must be > 0");
  try {
    const Scenario scenario = parse_scenario(header + good, "case.toml");
    ASSERT_TRUE(scenario.mesh);
    ASSERT_EQ(scenario.mesh->refine_points.size(), 2u);
    EXPECT_EQ(scenario.mesh->refine_points[0].point, (Point{0.5, 0.25}));
    EXPECT_DOUBLE_EQ(scenario.mesh->refine_points[0].radius, (0.1 - 0.001) / 0.2);  // grows by a fifth
    EXPECT_DOUBLE_EQ(scenario.mesh->refine_points[1].size, 0.002);
    EXPECT_DOUBLE_EQ(scenario.mesh->refine_points[1].radius, 0.05);
  } catch (const ScenarioError& e) {
    ADD_FAILURE() << e.diagnostics().front().format();
  }
}

// mesh.refine_tips: read where the run can act on it (a coupled run of a [geometry] domain,
// the cubic law, a generated mesh), refused with the key's line elsewhere.
TEST(ScenarioReader, RefineTipsIsReadWhereARunCanRefineTips) {
  std::ifstream in(kSource / "scenarios/paper/symmetric_flexure_20m.toml");
  std::stringstream text;
  text << in.rdbuf();
  const std::string flexure = text.str();
  const auto edited = [&](const std::vector<std::pair<std::string, std::string>>& edits) {
    std::string scenario = flexure;
    for (const auto& [from, to] : edits) {
      const auto at = scenario.find(from);
      EXPECT_NE(at, std::string::npos) << from;
      if (at != std::string::npos) scenario.replace(at, from.size(), to);
    }
    return scenario;
  };
  const std::pair<std::string, std::string> cubic{"permeability_law = \"kozeny-carman\"", "permeability_law = \"cubic\""};
  const std::pair<std::string, std::string> asked{"[mesh]\n", "[mesh]\nrefine_tips = true\n"};
  // The line of refine_tips in a scenario.
  const auto line_of_key = [](const std::string& scenario) {
    return 1 + static_cast<int>(std::count(scenario.begin(), scenario.begin() + static_cast<std::ptrdiff_t>(
                                                                                  scenario.find("refine_tips")),
                                           '\n'));
  };
  EXPECT_FALSE(parse_scenario(edited({cubic}), "case.toml").mesh->refine_tips);
  EXPECT_TRUE(parse_scenario(edited({cubic, asked}), "case.toml").mesh->refine_tips);
  const auto refine_tips_error = [&](const std::string& scenario) {
    for (const Diagnostic& e : errors_of(scenario))
      if (e.key == "mesh.refine_tips") return e.format();
    return std::string("no mesh.refine_tips error");
  };
  const std::string kozeny_carman = edited({asked});
  EXPECT_EQ(refine_tips_error(kozeny_carman),
            "case.toml:" + std::to_string(line_of_key(kozeny_carman)) +
                ": mesh.refine_tips: refines around the wedge tips of the cubic law; needs flow.permeability_law = "
                "\"cubic\"");
  const std::string from_file =
      edited({cubic, {"[mesh]\n", "[mesh]\nrefine_tips = true\nfile = \"" + (kSource / "README.md").string() + "\"\n"}});
  EXPECT_EQ(refine_tips_error(from_file),
            "case.toml:" + std::to_string(line_of_key(from_file)) +
                ": mesh.refine_tips: refines a mesh the run generates; mesh.file gives one: refine the file");
  const std::string flow_only = R"([geometry]
domain = [[0.0, 0.0], [4.0, 0.0], [4.0, 2.0], [0.0, 2.0]]
[material.rock]
matrix_porosity = 0.2
grain_diameter = 1e-5
[flow]
permeability_law = "cubic"
[[flow.boundary]]
name = "left"
head = 1.0
[mesh]
refine_tips = true
)";
  EXPECT_EQ(refine_tips_error(flow_only),
            "case.toml:12: mesh.refine_tips: needs a coupled run of a [geometry] domain cut by fractures");
}

TEST(NearestKey, SuggestsTyposOnly) {
  const std::vector<std::string> keys{"density", "young", "poisson", "matrix_porosity"};
  EXPECT_EQ(suggest_nearest("poison", keys), "poisson");
  EXPECT_EQ(suggest_nearest("Young", keys), "young");
  EXPECT_EQ(suggest_nearest("matrix_porostiy", keys), "matrix_porosity");
  EXPECT_EQ(suggest_nearest("temperature", keys), "");
}

}  // namespace
}  // namespace hydrodda::scenario
