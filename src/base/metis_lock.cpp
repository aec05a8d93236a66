#include "base/metis_lock.hpp"

namespace hydrodda::base {

std::mutex& metis_lock() {
  static std::mutex lock;
  return lock;
}

}  // namespace hydrodda::base
