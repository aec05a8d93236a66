#pragma once
// The pore fluid, and the conversion from intrinsic permeability to hydraulic conductivity.

namespace hydrodda::hydro {

struct Fluid {
  double density = 1000.0;   // ρ_w, kg/m³
  double viscosity = 1.0e-3; // μ, Pa·s
  double gravity = 9.81;     // g, m/s²

  // K = k ρ_w g / μ: hydraulic conductivity (m/s) per unit intrinsic permeability (m²).
  double conductivity_per_permeability() const { return density * gravity / viscosity; }
  // ρ_w g: pressure (Pa) per metre of head.
  double unit_weight() const { return density * gravity; }
};

// An intrinsic permeability tensor (m²), symmetric: [[xx, xy], [xy, yy]].
struct PermeabilityTensor {
  double xx = 0.0;
  double xy = 0.0;
  double yy = 0.0;
  bool operator==(const PermeabilityTensor&) const = default;
};

}  // namespace hydrodda::hydro
