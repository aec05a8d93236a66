#include "hydro/permeability_field.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace hydrodda::hydro {

PermeabilityField::PermeabilityField(PermeabilityView k) {
  if (k.isotropic()) {
    isotropic_.assign(k.scalars().begin(), k.scalars().end());
    return;
  }
  const std::span<const PermeabilityTensor> t = k.tensors();
  const bool isotropic =
      std::all_of(t.begin(), t.end(), [](const PermeabilityTensor& p) { return p.xy == 0.0 && p.xx == p.yy; });
  if (!isotropic) {
    tensors_.assign(t.begin(), t.end());
    return;
  }
  isotropic_.resize(t.size());
  for (std::size_t e = 0; e < t.size(); ++e) isotropic_[e] = t[e].xx;
}

std::vector<PermeabilityTensor> PermeabilityField::tensors() const {
  if (!tensors_.empty()) return tensors_;
  std::vector<PermeabilityTensor> out(isotropic_.size());
  for (std::size_t e = 0; e < out.size(); ++e) out[e] = {isotropic_[e], 0.0, isotropic_[e]};
  return out;
}

void check_permeability(PermeabilityView k) {
  const auto refuse = [](std::size_t t, const char* what) {
    throw std::runtime_error("permeability of triangle " + std::to_string(t) + " is not " + what);
  };
  if (k.isotropic()) {
    const std::span<const double> s = k.scalars();
    for (std::size_t t = 0; t < s.size(); ++t) {
      if (!std::isfinite(s[t])) refuse(t, "finite");
      if (!(s[t] > 0.0)) refuse(t, "positive");
    }
    return;
  }
  const std::span<const PermeabilityTensor> tensors = k.tensors();
  for (std::size_t t = 0; t < tensors.size(); ++t) {
    const PermeabilityTensor& p = tensors[t];
    if (!std::isfinite(p.xx) || !std::isfinite(p.xy) || !std::isfinite(p.yy)) refuse(t, "finite");
    if (!(p.xx > 0.0) || !(p.xx * p.yy - p.xy * p.xy > 0.0)) refuse(t, "positive (definite)");
  }
}

}  // namespace hydrodda::hydro
