#include "coupling/seepage_forces.hpp"

#include <stdexcept>

namespace hydrodda::coupling {

std::vector<std::vector<Point>> compute_seepage_forces(std::span<const geometry::Polygon> blocks,
                                                       const BlockPieces& pieces,
                                                       std::span<const Point> pressure_gradients,
                                                       std::span<const double> biot) {
  if (biot.size() != blocks.size())
    throw std::invalid_argument("seepage forces: one Biot coefficient per block is needed");
  std::vector<ForceMoments> moments(blocks.size());
  for (std::size_t b = 0; b < blocks.size(); ++b) moments[b].origin = vertex_mean(blocks[b]);
  for (const std::vector<BlockPiece>& list : pieces.lists())
    for (const BlockPiece& piece : list) {
      if (piece.block < 0 || piece.block >= static_cast<int>(blocks.size()) || piece.element < 0 ||
          piece.element >= static_cast<int>(pressure_gradients.size()))
        throw std::invalid_argument("seepage forces: a piece names a missing block or element");
      // −α ∇p over the piece: a force −α A ∇p at its centroid.
      const double alpha = biot[piece.block];
      if (alpha == 0.0) continue;
      moments[piece.block].add(piece.centroid, (-alpha * piece.area) * pressure_gradients[piece.element]);
    }
  std::vector<std::vector<Point>> forces(blocks.size());
  for (std::size_t b = 0; b < blocks.size(); ++b)
    forces[b] = biot[b] == 0.0 ? std::vector<Point>(blocks[b].size()) : distribute_to_vertices(blocks[b], moments[b]);
  return forces;
}

}  // namespace hydrodda::coupling
