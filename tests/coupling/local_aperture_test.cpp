// The local aperture of the cubic law (local_aperture.hpp) at chosen element centroids: the gap
// between two parallel faces wherever the centroid lies, the gap a block leaves against the
// domain boundary, and, along the boundary next to a closed fracture, the sliver a block left
// when it moved a little off the boundary rather than the distance to the block behind it.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "coupling/local_aperture.hpp"

namespace hydrodda::coupling {
namespace {

using geometry::Point;
using geometry::Polygon;

std::vector<double> apertures_at(const std::vector<Point>& centroids, const std::vector<Polygon>& blocks,
                                 const Polygon& domain, double reach) {
  const std::vector<double> open(centroids.size(), 1.0);  // every element has open area
  return compute_local_apertures(centroids, open, blocks, domain, reach);
}

const Polygon kDomain{{0, 0}, {1, 0}, {1, 2}, {0, 2}};

TEST(LocalAperture, ParallelFacesGiveTheGapWhereverTheCentroidLies) {
  // A horizontal fracture of w = 1 mm at y = 1: in the gap, in either block, near the mouth.
  const double w = 1e-3;
  const std::vector<Polygon> blocks{{{0, 0}, {1, 0}, {1, 1 - w / 2}, {0, 1 - w / 2}},
                                    {{0, 1 + w / 2}, {1, 1 + w / 2}, {1, 2}, {0, 2}}};
  const std::vector<Point> centroids{{0.5, 1.0}, {0.5, 1.0 + 0.3 * w}, {0.5, 1.02}, {0.5, 0.97}, {1e-4, 1.0}};
  const auto a = apertures_at(centroids, blocks, kDomain, 0.05);
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], w, 1e-12) << "centroid " << i;
}

TEST(LocalAperture, InclinedParallelFacesGiveTheGap) {
  // A fracture through (0, 0.8) at 30° to the x axis, w = 2 mm normal to it.
  const double w = 2e-3, t = std::tan(M_PI / 6), h = 0.5 * w / std::cos(M_PI / 6);  // vertical half-gap
  const std::vector<Polygon> blocks{{{0, 0}, {1, 0}, {1, 0.8 + t - h}, {0, 0.8 - h}},
                                    {{0, 0.8 + h}, {1, 0.8 + t + h}, {1, 2}, {0, 2}}};
  const std::vector<Point> centroids{{0.5, 0.8 + 0.5 * t}, {0.5, 0.8 + 0.5 * t + 0.01}, {0.4, 0.8 + 0.4 * t - 0.03}};
  const auto a = apertures_at(centroids, blocks, kDomain, 0.1);
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], w, 1e-12) << "centroid " << i;
}

TEST(LocalAperture, ABlockPulledOffTheBoundaryLeavesItsGap) {
  // One block 1 cm from the left side and no other block within reach: the boundary is the
  // second wall.
  const std::vector<Polygon> blocks{{{0.01, 0}, {1, 0}, {1, 2}, {0.01, 2}}};
  const auto a = apertures_at({{0.005, 1.0}, {0.02, 1.0}}, blocks, kDomain, 0.05);
  EXPECT_NEAR(a[0], 0.01, 1e-12);
  EXPECT_NEAR(a[1], 0.01, 1e-12);
}

TEST(LocalAperture, ASliverAlongTheBoundaryIsNotTheFractureBehindIt) {
  // A closed fracture at y = 1 (the blocks touch); the upper block has moved 1e-7 m right,
  // off the left side. Centroids inside the upper block, 2.5 mm from the left side and up to
  // 4 cm above the fracture, have the 1e-7 m sliver as their gap; the two nearest blocks (the
  // upper one's left face, the lower one below) do not face each other. Their signed
  // distances would sum to the height above the fracture less 2.5 mm, up to 3.75 cm.
  const double shift = 1e-7;
  const std::vector<Polygon> blocks{{{0, 0}, {1, 0}, {1, 1}, {0, 1}},
                                    {{shift, 1}, {1 + shift, 1}, {1 + shift, 2}, {shift, 2}}};
  const std::vector<Point> centroids{{0.0025, 1.003}, {0.0025, 1.01}, {0.0025, 1.023}, {0.0025, 1.04}};
  const auto a = apertures_at(centroids, blocks, kDomain, 0.05);
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], shift, 1e-12) << "centroid " << i;
  // Nearer the fracture than the side, the centroid's nearest faces are the closed fracture's.
  EXPECT_NEAR(apertures_at({{0.01, 1.002}}, blocks, kDomain, 0.05)[0], 0.0, 1e-12);
}

}  // namespace
}  // namespace hydrodda::coupling
