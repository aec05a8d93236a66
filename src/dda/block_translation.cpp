// A rigid translation of blocks between steps: no strain, so no stress changes, and the
// contact records (keyed by vertex and edge) stay; the next step measures their gaps anew.

#include <stdexcept>
#include <string>

#include "dda/block_kernels.hpp"
#include "dda/system.hpp"

namespace hydrodda::dda {

void System::translate_blocks(std::span<const int> blocks, Point shift) {
  std::vector<char> moved(blocks_.size(), 0);
  for (int b : blocks) {
    if (b < 0 || b >= block_count()) throw std::invalid_argument("DDA: no block " + std::to_string(b) + " to move");
    if (blocks_[static_cast<std::size_t>(b)].dof < 0)
      throw std::invalid_argument("DDA: block " + std::to_string(b) + " is fixed and cannot be moved");
    moved[static_cast<std::size_t>(b)] = 1;
  }
  for (std::size_t b = 0; b < blocks_.size(); ++b) {
    if (!moved[b]) continue;
    Block& block = blocks_[b];
    for (Point& p : block.polygon) p += shift;
    block.material_centroid += shift;
    block.moments = compute_moments(block.polygon);
  }
  for (auto* list : {&fixed_points_, &load_points_, &displacement_points_, &measured_})
    for (TrackedPoint& tp : *list)
      if (moved[static_cast<std::size_t>(tp.block)]) tp.position += shift;
}

}  // namespace hydrodda::dda
