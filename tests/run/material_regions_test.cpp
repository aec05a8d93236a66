// Materials by region in a coupled run, on scenarios/examples/layered_seal.toml: each block
// takes the material whose region holds its centroid, and the fluid elements of a material that
// fixes its `permeability` have it after a pass (exactly: nothing but the value is stored), while
// the seal's take the porosity law's.

#include <gtest/gtest.h>

#include <filesystem>

#include "mesh/triangle_mesh.hpp"
#include "run/coupled_model.hpp"
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
  int reservoir = 0, overburden = 0, seal = 0;
  for (int t = 0; t < mesh.triangle_count(); ++t) {
    const double y = hydrodda::mesh::triangle_centroid(mesh, t).y;
    if (y < 10.0) {
      EXPECT_EQ(k[t], 1.0e-13) << "element " << t;
      ++reservoir;
    } else if (y > 30.0) {
      EXPECT_EQ(k[t], 1.0e-17) << "element " << t;
      ++overburden;
    } else {
      EXPECT_LT(k[t], 1.0e-13) << "element " << t;  // the seal's matrix, or a joint through it
      ++seal;
    }
  }
  EXPECT_GT(reservoir, 100);
  EXPECT_GT(overburden, 100);
  EXPECT_GT(seal, 100);
}

}  // namespace
