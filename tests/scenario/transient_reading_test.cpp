// Transient flow in the scenario file (docs/scenario.md, "Transient flow"): [flow.transient],
// [material.NAME] storage, fluid.compressibility and [[flow.probe]], their defaults, and each
// refusal with its file, line and key.

#include <gtest/gtest.h>

#include "parse_errors.hpp"
#include "scenario/diagnostics.hpp"
#include "scenario/reader.hpp"

namespace hydrodda::scenario {
namespace {

using test_support::errors_of;

// A flow-only strip: lines 1–9 here, the case's keys from line 10 on.
const std::string kHead = R"([geometry]
domain = [[0.0, 0.0], [10.0, 0.0], [10.0, 1.0], [0.0, 1.0]]
[material.rock]
permeability = 1.0e-13
storage = 1.0e-9
[flow]
[[flow.boundary]]
name = "left"
head = 1.0
)";

// The single diagnostic's line, key and a part of its message.
void expect_one_error(const std::string& text, int line, const std::string& key, const std::string& part) {
  const std::vector<Diagnostic> errors = errors_of(text);
  ASSERT_EQ(errors.size(), 1u) << (errors.empty() ? "no error" : errors[0].format() + " and more");
  EXPECT_EQ(errors[0].file, "case.toml");
  EXPECT_EQ(errors[0].line, line);
  EXPECT_EQ(errors[0].key, key);
  EXPECT_NE(errors[0].message.find(part), std::string::npos) << errors[0].message;
}

TEST(TransientReading, ReadsTheKeysAndFillsTheDefaults) {
  const Scenario s = parse_scenario(kHead + R"([flow.transient]
end_time = 100.0
[[flow.probe]]
name = "middle"
point = [5.0, 0.5]
[[flow.probe]]
name = "corner"
point = [10.0, 1.0]
)", "case.toml");
  ASSERT_TRUE(s.flow->transient);
  const TransientDefinition& t = *s.flow->transient;
  EXPECT_EQ(t.end_time, 100.0);
  EXPECT_EQ(t.time_step, 0.1);        // end_time / 1000
  EXPECT_EQ(t.max_time_step, 5.0);    // end_time / 20
  EXPECT_EQ(t.output_times, std::vector<double>{100.0});
  EXPECT_FALSE(t.initial_head);       // "steady"
  EXPECT_EQ(s.materials[0].storage, 1.0e-9);
  EXPECT_EQ(s.flow->fluid_compressibility, 4.5e-10);
  ASSERT_EQ(s.flow->probes.size(), 2u);
  EXPECT_EQ(s.flow->probes[1].name, "corner");  // on the domain's corner: inside
  EXPECT_EQ(s.flow->probes[0].point.x, 5.0);
  const auto listed = [&](const std::string& key) {
    return std::any_of(s.defaults_used.begin(), s.defaults_used.end(), [&](const DefaultUsed& d) { return d.key == key; });
  };
  EXPECT_TRUE(listed("flow.transient.time_step"));
  EXPECT_TRUE(listed("flow.transient.initial_head"));
  EXPECT_TRUE(listed("flow.transient.output_times"));
}

TEST(TransientReading, ReadsEveryKeyGiven) {
  const Scenario s = parse_scenario(kHead + R"([flow.transient]
end_time = 3.15e7
time_step = 3600.0
max_time_step = 8.64e5
output_times = [0.0, 8.64e6, 3.15e7]
initial_head = 2.5
[flow.fluid]
compressibility = 5.0e-10
)", "case.toml");
  const TransientDefinition& t = *s.flow->transient;
  EXPECT_EQ(t.time_step, 3600.0);
  EXPECT_EQ(t.max_time_step, 8.64e5);
  EXPECT_EQ(t.output_times, (std::vector<double>{0.0, 8.64e6, 3.15e7}));
  EXPECT_EQ(t.initial_head, 2.5);
  EXPECT_EQ(s.flow->fluid_compressibility, 5.0e-10);
}

TEST(TransientReading, RefusesANegativeStorage) {
  std::string text = kHead;
  text.replace(text.find("storage = 1.0e-9"), 16, "storage = -1.0e-9");
  expect_one_error(text, 5, "material.rock.storage", "must lie in [0");
}

TEST(TransientReading, RefusesAnEndTimeNotAfterTheStart) {
  expect_one_error(kHead + "[flow.transient]\nend_time = 0.0\n", 11, "flow.transient.end_time", "must be > 0");
  expect_one_error(kHead + "[flow.transient]\nend_time = -5.0\n", 11, "flow.transient.end_time", "must be > 0");
  expect_one_error(kHead + "[flow.transient]\ntime_step = 1.0\n", 10, "flow.transient.end_time", "required key is missing");
}

TEST(TransientReading, RefusesStepsOutsideTheRun) {
  expect_one_error(kHead + "[flow.transient]\nend_time = 10.0\ntime_step = 0.0\n", 12,
                   "flow.transient.time_step", "(0, end_time = 10]");
  expect_one_error(kHead + "[flow.transient]\nend_time = 10.0\ntime_step = 2.0\nmax_time_step = 1.0\n", 13,
                   "flow.transient.max_time_step", "[time_step = 2, end_time = 10]");
}

TEST(TransientReading, RefusesOutputTimesOutsideTheRunOrNotIncreasing) {
  expect_one_error(kHead + "[flow.transient]\nend_time = 10.0\noutput_times = [2.0, 12.0]\n", 12,
                   "flow.transient.output_times", "outside [0, end_time = 10 s]");
  expect_one_error(kHead + "[flow.transient]\nend_time = 10.0\noutput_times = [-1.0]\n", 12,
                   "flow.transient.output_times", "outside [0");
  expect_one_error(kHead + "[flow.transient]\nend_time = 10.0\noutput_times = [5.0, 5.0]\n", 12,
                   "flow.transient.output_times", "must increase");
  expect_one_error(kHead + "[flow.transient]\nend_time = 10.0\noutput_times = [6.0, 3.0]\n", 12,
                   "flow.transient.output_times", "must increase");
  expect_one_error(kHead + "[flow.transient]\nend_time = 10.0\noutput_times = []\n", 12,
                   "flow.transient.output_times", "expected an array");
}

TEST(TransientReading, RefusesAnInitialHeadThatIsNeitherAHeadNorSteady) {
  expect_one_error(kHead + "[flow.transient]\nend_time = 10.0\ninitial_head = \"hydrostatic\"\n", 12,
                   "flow.transient.initial_head", "expected a head (m) or \"steady\"");
}

TEST(TransientReading, RefusesATransientRunWithNoStorageAnywhere) {
  std::string text = kHead;
  text.replace(text.find("storage = 1.0e-9"), 16, "storage = 0.0");
  expect_one_error(text + "[flow.transient]\nend_time = 10.0\n", 10, "flow.transient", "no material has a storage");
  text.replace(text.find("storage = 0.0\n"), 14, "");
  expect_one_error(text + "[flow.transient]\nend_time = 10.0\n", 9, "flow.transient", "no material has a storage");
}

// The water of open gaps between blocks stores by its compressibility: a fractured model with an
// initial aperture needs no material storage, unless the fluid is incompressible.
TEST(TransientReading, OpenGapsStoreWaterByItsCompressibility) {
  const std::string fractured = R"([geometry]
domain = [[0.0, 0.0], [10.0, 0.0], [10.0, 2.0], [0.0, 2.0]]
fractures = [[[0.0, 1.0], [10.0, 1.0]]]
initial_aperture = 1.0e-4
[material.rock]
matrix_porosity = 0.01
grain_diameter = 1.0e-7
[flow]
[[flow.boundary]]
name = "left"
head = 1.0
[flow.transient]
end_time = 0.05
)";
  EXPECT_TRUE(errors_of(fractured).empty());
  expect_one_error(fractured + "[flow.fluid]\ncompressibility = 0.0\n", 12, "flow.transient", "no open gap holds water");
}

// A coupled scenario with [flow.transient] (fixed-stress steps) and a probe.
const std::string kCoupledTransient = R"([geometry]
domain = [[0.0, 0.0], [10.0, 0.0], [10.0, 1.0], [0.0, 1.0]]
[material.rock]
density = 2500.0
young = 1.0e10
poisson = 0.25
grain_diameter = 1.0e-5
storage = 1.0e-9
[mechanics]
analysis = "dynamic"
[flow]
[[flow.boundary]]
name = "left"
head = 1.0
[flow.transient]
end_time = 10.0
[[flow.probe]]
name = "p"
point = [1.0, 0.5]
)";

TEST(TransientReading, AcceptsTransientFlowAndProbesInACoupledRun) {
  EXPECT_TRUE(errors_of(kCoupledTransient).empty());
  // Without storage, a block with Biot's α > 0 stores water by its strain.
  std::string no_storage = kCoupledTransient;
  no_storage.replace(no_storage.find("storage = 1.0e-9\n"), 17, "");
  EXPECT_TRUE(errors_of(no_storage).empty());
}

// Coupled, with neither storage nor Biot's α: the water of the joints' hydraulic apertures
// stores by its compressibility (docs/coupling.md, "Coupled transient runs": Σ_c (L_c/A_e) a_c c_w),
// so joints with a hydraulic aperture make it a run; without them, or with an incompressible
// fluid, nothing stores and it is refused at [flow.transient]'s line.
TEST(TransientReading, ACoupledRunWithoutStorageOrBiotStoresInItsJointsOrIsRefused) {
  std::string rigid = kCoupledTransient;
  rigid.replace(rigid.find("storage = 1.0e-9\n"), 17, "biot_coefficient = 0.0\n");
  expect_one_error(rigid, 15, "flow.transient", "no open gap or joint holds water");
  const std::string jointed = std::string(R"([geometry]
fractures = [[[5.0, 0.0], [5.0, 1.0]]]
)") + rigid.substr(std::string("[geometry]\n").size());
  expect_one_error(jointed, 16, "flow.transient", "no joint type has a hydraulic aperture");
  const std::string hydraulic = jointed + "[joint]\nresidual_aperture = 1.0e-5\n";
  EXPECT_TRUE(errors_of(hydraulic).empty());
  expect_one_error(hydraulic + "[flow.fluid]\ncompressibility = 0.0\n", 16, "flow.transient",
                   "the fluid is incompressible");
  // Joint keys with no joint to carry them store nothing.
  expect_one_error(rigid + "[joint]\nresidual_aperture = 1.0e-5\n", 15, "flow.transient", "no open gap or joint");
}

TEST(TransientReading, RefusesProbesInASteadyCoupledRunAndAccelerationOrPseudoTimeInATransientOne) {
  std::string steady = kCoupledTransient;
  steady.replace(steady.find("[flow.transient]\nend_time = 10.0\n"), 33, "");
  expect_one_error(steady, 15, "flow.probe", "probes in a steady coupled run are not built yet");
  expect_one_error(kCoupledTransient + "[coupling]\nacceleration = \"aitken\"\n", 15, "coupling.acceleration",
                   "without acceleration");
  expect_one_error(kCoupledTransient + "[coupling]\npseudo_time_step = 1.0\n", 15, "coupling.pseudo_time_step",
                   "steps in real time");
}

TEST(TransientReading, RefusesProbesOutsideTheDomainUnnamedOrTwice) {
  expect_one_error(kHead + "[[flow.probe]]\nname = \"far\"\npoint = [11.0, 0.5]\n", 10, "flow.probe.point",
                   "lies outside geometry.domain");
  expect_one_error(kHead + "[[flow.probe]]\npoint = [1.0, 0.5]\n", 10, "flow.probe.name", "required key is missing");
  expect_one_error(kHead + "[[flow.probe]]\nname = \"a\"\npoint = [1.0, 0.5]\n[[flow.probe]]\nname = \"a\"\npoint = [2.0, 0.5]\n",
                   14, "flow.probe.name", "already used (line 10)");
  expect_one_error(kHead + "[[flow.probe]]\nname = \"a,b\"\npoint = [1.0, 0.5]\n", 11, "flow.probe.name", "without commas");
}

TEST(TransientReading, RefusesANegativeCompressibility) {
  expect_one_error(kHead + "[flow.fluid]\ncompressibility = -1.0\n", 11, "flow.fluid.compressibility", "must lie in [0");
}

}  // namespace
}  // namespace hydrodda::scenario
