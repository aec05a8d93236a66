#pragma once
// The hydraulic aperture law of each fracture: the law of its joint type (hydro::JointApertureLaw,
// Barton–Bandis). A trace names its type; every face cut along it, every crossing of such a face
// with a fluid element and every piece the fracture meter measures on it take that type's law.

#include <span>
#include <vector>

#include "hydro/permeability_law.hpp"

namespace hydrodda::coupling {

class JointApertureLaws {
 public:
  // One law for every fracture (default: a_r = 0 and no closure, so an open joint carries its
  // opening and a closed one nothing). Implicit: where one law serves all, it is that law.
  JointApertureLaws(hydro::JointApertureLaw law = {});  // NOLINT(google-explicit-constructor)
  // `by_type[t]`: joint type t's law (type 0 the default); `fracture_types[f]`: fracture f's
  // type. Throws std::invalid_argument for a type with no law or no type at all.
  JointApertureLaws(std::vector<hydro::JointApertureLaw> by_type, std::vector<int> fracture_types);

  // Fracture f's law; f past the list is a caller's error (std::out_of_range) unless one law
  // serves every fracture.
  const hydro::JointApertureLaw& of_fracture(int fracture) const;
  std::span<const hydro::JointApertureLaw> by_type() const { return by_type_; }

 private:
  std::vector<hydro::JointApertureLaw> by_type_;
  std::vector<int> fracture_types_;  // empty: by_type_[0] for every fracture
};

}  // namespace hydrodda::coupling
