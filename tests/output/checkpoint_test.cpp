// The checkpoint codec: what is encoded decodes to the same values bit for bit, and a file cut
// short, damaged or of another kind is refused rather than read as something else.

#include "output/checkpoint.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

namespace hydrodda::output {
namespace {

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

RunCheckpoint make_checkpoint() {
  RunCheckpoint c;
  c.scenario_hash = hash_text("title = \"x\"\n");
  c.scenario_file = "/data/runs/seal.toml";
  c.input_files = {{"geometry.fractures_file", "/data/runs/traces.csv", hash_text("0,0,1,1\n")},
                   {"mesh.file", "/data/runs/seal.msh", 0xffffffffffffffffull}};
  c.converged = false;
  c.history = {{"1", "0.10000000000000001", "1"}, {"2", "0.20000000000000001", "0.5"}};
  c.measure = {{"1", "0.10000000000000001", "top", "0.5", "1", "0", "-1e-06"}};
  c.written_iterations = {1, 2};
  c.refined_tips = {8.0, 1.0073446173275367, 4.5e-4, 0.7477, 1.0};
  c.recent_tips = {41.0, 1.0, 11.9958, 1.0034, 5.5e-3, 0.72, 2.0, 42.0, 0.0};
  dda::SystemState::BlockState block;
  block.polygon = {{0.0, 0.0}, {1.0 / 3.0, 0.0}, {0.0, 0.1}};
  block.velocity = {1e-300, -0.0, std::numeric_limits<double>::denorm_min(), 4, 5, 6};
  block.stress = {-1.0e7, 2.0e6, 3.0};
  block.strain = {1e-6, -2e-6, 3e-7};
  block.rotation = 0.001;
  block.material_centroid = {0.1, 0.2};
  c.mechanics.blocks = {block, block};
  c.mechanics.time = 0.2;
  c.mechanics.time_step = 7.5e-4;
  dda::ContactRecord record;
  record.state = dda::ContactState::sliding;
  record.reference_ratio = 0.3;
  record.multiplier = 12.5;
  record.slide_sign = -1;
  record.normal_force = 1e5;
  record.penetration = -1e-5;
  dda::ContactRecord released;  // opened by the tension cutoff: closes only past the tolerance
  released.released = true;
  released.penetration = -2e-7;
  c.mechanics.contacts = {{{0, 1, 1, 2}, record}, {{1, 0, 0, 3}, released}};
  c.mechanics.fixed_points = {{0.0, 0.0}};
  c.mechanics.measured_points = {{0.5, 0.5}, {0.25, 0.75}};
  c.mechanics.vertex_forces = {{}, {{1.0, 2.0}, {3.0, 4.0}, {5.0, 6.0}}};
  c.coupling.iterations = 2;
  c.coupling.flow.head = {20.0, 10.0 / 3.0, 0.0};
  c.coupling.flow.pressure = {2e5, 1e5, 0.0};
  c.coupling.flow.flux = {{1e-7, -2e-7}};
  c.coupling.flow.boundary_flows = {{"left", 1e-6}, {"right", -1e-6}};
  c.coupling.flow.reference_head = 0.0;
  c.coupling.flow.balance_error = 1e-15;
  c.coupling.flow.refinement_steps = 1;
  c.coupling.previous_heads = c.coupling.flow.head;
  c.coupling.previous_displacements = {{1e-3, 0.0}, {0.0, -2e-3}};
  c.coupling.heads_two_back = {19.0, 3.0, 0.0};
  c.coupling.previous_update = {0.5, -0.25, 0.0};
  c.coupling.relaxation = 0.7;
  c.coupling.anderson_residuals = {{0.1, -0.2, 0.0, 1e3, -2e3, 0.0}, {0.05, -0.1, 0.0, 5e2, -1e3, 0.0}};
  c.coupling.anderson_images = {{20.1, 3.1, 0.0, 2.01e5, 0.99e5, 0.0}, {20.0, 3.3, 0.0, 2e5, 1e5, 0.0}};
  c.coupling.kept_factor_permeability = std::make_shared<const hydro::PermeabilityField>(
      std::vector<hydro::PermeabilityTensor>{{1e-15, 0.0, 1e-15}, {3.7e-9, -1.2e-10, 2.5e-11}});
  c.coupling.kept_factor_single_precision = true;
  c.coupling.porosity.fracture_area = {0.0, 1.25e-3};
  c.coupling.porosity.porosity = {0.1, 0.35};
  c.coupling.permeability = {1e-15, 3.7e-9};
  c.coupling.permeability_tensors = {{1e-15, 0.0, 1e-15}, {3.7e-9, -1.2e-10, 2.5e-11}};
  c.coupling.float_groups = {{{0, 1}, {0.0, 0.125}, {-1e-300, 2.5e-3}}, {{1}, {-0.0, 1e-3}, {0.0, -7.5}}};
  return c;
}

TEST(Checkpoint, DecodesToTheSameValuesBitForBit) {
  const RunCheckpoint c = make_checkpoint();
  const RunCheckpoint d = decode_checkpoint(encode_checkpoint(c));
  EXPECT_EQ(d.scenario_hash, c.scenario_hash);
  EXPECT_EQ(d.scenario_file, c.scenario_file);
  ASSERT_EQ(d.input_files.size(), c.input_files.size());
  for (std::size_t i = 0; i < c.input_files.size(); ++i) {
    EXPECT_EQ(d.input_files[i].key, c.input_files[i].key);
    EXPECT_EQ(d.input_files[i].path, c.input_files[i].path);
    EXPECT_EQ(d.input_files[i].hash, c.input_files[i].hash);
  }
  EXPECT_EQ(d.converged, c.converged);
  EXPECT_EQ(d.history, c.history);
  EXPECT_EQ(d.measure, c.measure);
  EXPECT_EQ(d.written_iterations, c.written_iterations);
  EXPECT_EQ(d.refined_tips, c.refined_tips);
  EXPECT_EQ(d.recent_tips, c.recent_tips);
  ASSERT_EQ(d.mechanics.blocks.size(), 2u);
  const auto& b = d.mechanics.blocks[1];
  const auto& e = c.mechanics.blocks[1];
  ASSERT_EQ(b.polygon.size(), 3u);
  EXPECT_TRUE(same_bits(b.polygon[1].x, e.polygon[1].x));
  for (int i = 0; i < 6; ++i) EXPECT_TRUE(same_bits(b.velocity[i], e.velocity[i])) << i;  // -0.0, denormals
  EXPECT_EQ(b.stress, e.stress);
  EXPECT_EQ(b.strain, e.strain);
  EXPECT_EQ(b.rotation, e.rotation);
  EXPECT_EQ(b.material_centroid.y, e.material_centroid.y);
  EXPECT_EQ(d.mechanics.time, 0.2);
  EXPECT_EQ(d.mechanics.time_step, 7.5e-4);
  ASSERT_EQ(d.mechanics.contacts.size(), 2u);
  EXPECT_EQ(d.mechanics.contacts[0].first, (dda::ContactKey{0, 1, 1, 2}));
  const dda::ContactRecord& r = d.mechanics.contacts[0].second;
  EXPECT_EQ(r.state, dda::ContactState::sliding);
  EXPECT_EQ(r.slide_sign, -1);
  EXPECT_EQ(r.multiplier, 12.5);
  EXPECT_EQ(r.penetration, -1e-5);
  EXPECT_FALSE(r.released);
  EXPECT_EQ(d.mechanics.contacts[1].second.state, dda::ContactState::open);
  EXPECT_TRUE(d.mechanics.contacts[1].second.released);
  EXPECT_EQ(d.mechanics.measured_points.size(), 2u);
  EXPECT_EQ(d.mechanics.load_points.size(), 0u);
  ASSERT_EQ(d.mechanics.vertex_forces.size(), 2u);
  EXPECT_TRUE(d.mechanics.vertex_forces[0].empty());
  EXPECT_EQ(d.mechanics.vertex_forces[1][2].y, 6.0);
  EXPECT_EQ(d.coupling.iterations, 2);
  EXPECT_EQ(d.coupling.flow.head, c.coupling.flow.head);
  EXPECT_EQ(d.coupling.flow.pressure, c.coupling.flow.pressure);
  EXPECT_EQ(d.coupling.flow.flux[0].y, -2e-7);
  ASSERT_EQ(d.coupling.flow.boundary_flows.size(), 2u);
  EXPECT_EQ(d.coupling.flow.boundary_flows[1].name, "right");
  EXPECT_EQ(d.coupling.flow.boundary_flow("left"), 1e-6);
  EXPECT_EQ(d.coupling.flow.balance_error, 1e-15);
  EXPECT_EQ(d.coupling.flow.refinement_steps, 1);
  EXPECT_EQ(d.coupling.previous_displacements[1].y, -2e-3);
  EXPECT_EQ(d.coupling.anderson_residuals, c.coupling.anderson_residuals);
  EXPECT_EQ(d.coupling.anderson_images, c.coupling.anderson_images);
  ASSERT_TRUE(d.coupling.kept_factor_permeability);
  EXPECT_EQ(d.coupling.kept_factor_permeability->tensors(), c.coupling.kept_factor_permeability->tensors());
  EXPECT_TRUE(d.coupling.kept_factor_single_precision);
  EXPECT_EQ(d.coupling.porosity.fracture_area, c.coupling.porosity.fracture_area);
  EXPECT_EQ(d.coupling.porosity.porosity, c.coupling.porosity.porosity);
  EXPECT_EQ(d.coupling.permeability, c.coupling.permeability);
  EXPECT_EQ(d.coupling.permeability_tensors, c.coupling.permeability_tensors);
  ASSERT_EQ(d.coupling.float_groups.size(), 2u);
  for (std::size_t g = 0; g < 2; ++g) {
    const auto &got = d.coupling.float_groups[g], &put = c.coupling.float_groups[g];
    EXPECT_EQ(got.group, put.group);
    for (const auto& [a, b] : {std::pair{got.start, put.start}, std::pair{got.rate, put.rate}}) {
      EXPECT_TRUE(same_bits(a.x, b.x)) << g;  // -0.0, denormals
      EXPECT_TRUE(same_bits(a.y, b.y)) << g;
    }
  }
}

TEST(Checkpoint, ACutOrDamagedFileIsRefused) {
  const std::string bytes = encode_checkpoint(make_checkpoint());
  // Every proper prefix is refused: lengths are checked against what is left.
  for (std::size_t n = 0; n < bytes.size(); n += 7)
    EXPECT_THROW(decode_checkpoint(std::string_view(bytes).substr(0, n)), CheckpointError) << n;
  EXPECT_THROW(decode_checkpoint(bytes + "x"), CheckpointError);
  EXPECT_THROW(decode_checkpoint("title = \"a scenario, not a checkpoint\"\n"), CheckpointError);
  std::string other_version = bytes;
  other_version[std::string_view("hydrodda checkpoint\n").size()] = 8;  // the format before this one
  EXPECT_THROW(decode_checkpoint(other_version), CheckpointError);
}

// Every single bit flipped anywhere is refused by the checksum: a flip in the payload's last
// fifth (a double of the loop's state) was decoded and resumed from, to a head change of 5.7e74.
TEST(Checkpoint, AnyFlippedBitIsRefused) {
  const std::string bytes = encode_checkpoint(make_checkpoint());
  for (std::size_t at = 0; at < bytes.size(); ++at) {
    for (int bit = 0; bit < 8; ++bit) {
      std::string damaged = bytes;
      damaged[at] = static_cast<char>(damaged[at] ^ (1 << bit));
      EXPECT_THROW(decode_checkpoint(damaged), CheckpointError) << "byte " << at << " bit " << bit;
    }
  }
}

TEST(Checkpoint, TheScenarioHashTellsAnEditedText) {
  EXPECT_EQ(hash_text("steps = 100\n"), hash_text("steps = 100\n"));
  EXPECT_NE(hash_text("steps = 100\n"), hash_text("steps = 101\n"));
  EXPECT_EQ(hash_text(""), 14695981039346656037ull);  // FNV-1a 64 offset basis
}

}  // namespace
}  // namespace hydrodda::output
