#pragma once
// A permeability per triangle as the Darcy solver reads it: isotropic scalars or tensors.
//
// PermeabilityView borrows either kind; PermeabilityField owns a copy, as scalars wherever
// every tensor is isotropic ({k, 0, k}): at a million triangles that is 8 MB against 24 MB.

#include <span>
#include <vector>

#include "hydro/fluid.hpp"

namespace hydrodda::hydro {

class PermeabilityView {
 public:
  PermeabilityView() = default;
  PermeabilityView(std::span<const double> isotropic) : isotropic_(isotropic), isotropic_only_(true) {}
  PermeabilityView(std::span<const PermeabilityTensor> tensors) : tensors_(tensors) {}
  PermeabilityView(const std::vector<double>& isotropic) : PermeabilityView(std::span<const double>(isotropic)) {}
  PermeabilityView(const std::vector<PermeabilityTensor>& tensors)
      : PermeabilityView(std::span<const PermeabilityTensor>(tensors)) {}

  std::size_t size() const { return isotropic_only_ ? isotropic_.size() : tensors_.size(); }
  bool isotropic() const { return isotropic_only_; }
  PermeabilityTensor operator[](std::size_t t) const {
    if (isotropic_only_) return {isotropic_[t], 0.0, isotropic_[t]};
    return tensors_[t];
  }
  std::span<const double> scalars() const { return isotropic_; }
  std::span<const PermeabilityTensor> tensors() const { return tensors_; }

 private:
  std::span<const double> isotropic_;
  std::span<const PermeabilityTensor> tensors_;
  bool isotropic_only_ = false;
};

class PermeabilityField {
 public:
  PermeabilityField() = default;
  // A copy of `k`, as scalars when every value is isotropic.
  explicit PermeabilityField(PermeabilityView k);

  bool empty() const { return isotropic_.empty() && tensors_.empty(); }
  std::size_t size() const { return view().size(); }
  PermeabilityView view() const {
    return tensors_.empty() ? PermeabilityView(std::span<const double>(isotropic_))
                            : PermeabilityView(std::span<const PermeabilityTensor>(tensors_));
  }
  // Every value as a tensor (an isotropic k as {k, 0, k}).
  std::vector<PermeabilityTensor> tensors() const;
  void clear() {
    isotropic_ = {};
    tensors_ = {};
  }

 private:
  std::vector<double> isotropic_;
  std::vector<PermeabilityTensor> tensors_;
};

// Throws std::runtime_error naming the first triangle whose permeability is not finite or not
// positive definite (k_xx > 0 and det k > 0).
void check_permeability(PermeabilityView k);

}  // namespace hydrodda::hydro
