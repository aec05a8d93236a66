// Materials by region in a coupled run, on scenarios/examples/layered_seal.toml: each block
// takes the material whose region holds its centroid, and the fluid elements of a material that
// fixes its `permeability` have it after a pass (exactly: nothing but the value is stored), while
// the seal's take the porosity law's (along a joint, the material's value is the matrix's and
// the joint adds to it); a material of its own matrix (porosity, grain size) gives
// its elements away from the joints the cubic law's k_m = d² φ³ / (180 (1 − φ)²) of it
// (Kozeny–Carman, uncapped under the cubic law), to round-off (1e-12 relative).

#include <gtest/gtest.h>

#include <filesystem>

#include "mesh/triangle_mesh.hpp"
#include "run/coupled_model.hpp"
#include "run/model_building.hpp"
#include "scenario/reader.hpp"

namespace {

namespace fs = std::filesystem;

TEST(MaterialRegions, ACoupledRunsElementsTakeTheirMaterialsFixedPermeability) {
  const auto s =
      hydrodda::scenario::read_scenario(fs::path(HYDRODDA_SOURCE_DIR) / "scenarios/examples/layered_seal.toml");
  hydrodda::run::CoupledModel model(s);
  model.run_pass();
  const auto& mesh = model.mesh();
  const std::vector<double>& k = model.loop().permeability();
  ASSERT_TRUE(model.loop().joints().has_value());
  const std::vector<char>& along_a_joint = model.loop().joints()->zone();
  // Off the joints, exactly the material's value; along them its value is the matrix's, to which
  // the joint's transmissivity adds (docs/coupling.md, "One transmissivity per joint").
  const auto expect_material = [&](int t, double value) {
    if (along_a_joint[t]) EXPECT_GE(k[t], value) << "element " << t;
    else EXPECT_EQ(k[t], value) << "element " << t;
  };
  int reservoir = 0, overburden = 0, seal = 0, joint_zone = 0, overburden_carried_by_the_fault = 0;
  for (int t = 0; t < mesh.triangle_count(); ++t) {
    const double y = hydrodda::mesh::triangle_centroid(mesh, t).y;
    joint_zone += along_a_joint[t] ? 1 : 0;
    if (y < 10.0) {
      expect_material(t, 1.0e-13);
      ++reservoir;
    } else if (y > 30.0) {
      expect_material(t, 1.0e-17);
      overburden_carried_by_the_fault += k[t] > 1.0e-17 ? 1 : 0;
      ++overburden;
    } else {
      EXPECT_LT(k[t], 1.0e-13) << "element " << t;  // the seal's matrix, or a joint through it
      ++seal;
    }
  }
  EXPECT_GT(joint_zone, 0);
  EXPECT_GT(overburden_carried_by_the_fault, 0);  // the fault runs up through the overburden
  EXPECT_GT(reservoir, 100);
  EXPECT_GT(overburden, 100);
  EXPECT_GT(seal, 100);
}

TEST(MaterialRegions, ACoupledRunsElementsTakeTheirMaterialsOwnMatrix) {
  auto s = hydrodda::scenario::read_scenario(fs::path(HYDRODDA_SOURCE_DIR) / "scenarios/examples/layered_seal.toml");
  // The overburden as a matrix of φ = 0.2, d = 1e-5 m instead of a fixed permeability.
  hydrodda::scenario::MaterialDefinition& silt = s.materials[2];
  ASSERT_EQ(silt.name, "siltstone");
  silt.permeability.reset();
  silt.matrix_porosity = 0.2;
  silt.grain_diameter = 1e-5;
  const double k_silt = 1e-10 * 0.008 / (180.0 * 0.64);
  hydrodda::run::CoupledModel model(s);
  model.run_pass();
  const auto& mesh = model.mesh();
  const std::vector<double>& k = model.loop().permeability();
  const std::vector<double>& porosity = model.loop().porosity().porosity;
  int checked = 0;
  for (int t = 0; t < mesh.triangle_count(); ++t) {
    const auto c = hydrodda::mesh::triangle_centroid(mesh, t);
    if (c.y < 33.0 || c.x < 120.0) continue;  // away from the bedding joint at 30 m and the fault
    EXPECT_NEAR(k[t], k_silt, 1e-12 * k_silt) << "element " << t;
    EXPECT_NEAR(porosity[t], 0.2, 1e-12) << "element " << t;
    ++checked;
  }
  EXPECT_GT(checked, 20);
}

TEST(MaterialRegions, ARegionsCappedMatrixIsNamedInAWarning) {
  // Under Kozeny–Carman, a material with a region whose matrix (φ 0.3, d 0.018 m: 9.9e-8 m²) lies
  // above the cap is named, as the material without a region's would be.
  auto s = hydrodda::scenario::read_scenario(fs::path(HYDRODDA_SOURCE_DIR) / "scenarios/examples/layered_seal.toml");
  s.flow->permeability_law = hydrodda::coupling::PermeabilityLaw::kozeny_carman;
  EXPECT_FALSE(hydrodda::run::describe_capped_matrix(s).has_value());
  hydrodda::scenario::MaterialDefinition& silt = s.materials[2];
  silt.permeability.reset();
  silt.matrix_porosity = 0.3;
  silt.grain_diameter = 0.018;
  const auto warning = hydrodda::run::describe_capped_matrix(s);
  ASSERT_TRUE(warning.has_value());
  EXPECT_EQ(warning->rfind("material.siltstone: ", 0), 0u) << *warning;
}

}  // namespace
