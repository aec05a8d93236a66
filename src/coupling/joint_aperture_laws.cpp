#include "coupling/joint_aperture_laws.hpp"

#include <stdexcept>
#include <string>

namespace hydrodda::coupling {

JointApertureLaws::JointApertureLaws(hydro::JointApertureLaw law) : by_type_{law} {}

JointApertureLaws::JointApertureLaws(std::vector<hydro::JointApertureLaw> by_type, std::vector<int> fracture_types)
    : by_type_(std::move(by_type)), fracture_types_(std::move(fracture_types)) {
  if (by_type_.empty()) throw std::invalid_argument("joint aperture laws: no joint type given");
  for (std::size_t f = 0; f < fracture_types_.size(); ++f)
    if (fracture_types_[f] < 0 || fracture_types_[f] >= static_cast<int>(by_type_.size()))
      throw std::invalid_argument("joint aperture laws: fracture " + std::to_string(f) + " is of type " +
                                  std::to_string(fracture_types_[f]) + ", " + std::to_string(by_type_.size()) +
                                  " types have a law");
}

const hydro::JointApertureLaw& JointApertureLaws::of_fracture(int fracture) const {
  if (fracture_types_.empty()) return by_type_.front();
  return by_type_[static_cast<std::size_t>(fracture_types_.at(static_cast<std::size_t>(fracture)))];
}

}  // namespace hydrodda::coupling
