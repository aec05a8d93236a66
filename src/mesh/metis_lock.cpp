#include "mesh/metis_lock.hpp"

namespace hydrodda::mesh {

std::mutex& metis_lock() {
  static std::mutex lock;
  return lock;
}

}  // namespace hydrodda::mesh
