#pragma once
// The in-situ stress a scenario starts in ([mechanics.initial_stress]), and the weight of the
// material layers above a point, which a layered stress integrates and the in-situ check
// (in_situ_check.hpp) compares the start against.
//
// Layered (vertical = "layers"): along the vertical x = column_x (default: the middle of the
// domain's width), the materials' regions cut the column into pieces of one density each; with
// ρ' each material's density as the blocks carry it (ρ − α ρ_w under a hydrostatic pore
// pressure in a coupled run, whose blocks carry the effective stress σ + α p; ρ otherwise):
//
//     σyy(y) = σyy(y_ref) − g_y ∫_{y_ref}^{y} ρ'(x, η) dη      (dσyy/dy = −ρ' g_y)
//     τxy(y) = τxy(y_ref) − g_x ∫_{y_ref}^{y} ρ'(x, η) dη
//     σxx(y) = σxx(y_ref) + K0 (σyy(y) − σyy(y_ref))           (K0 = horizontal_ratio)
//
// piecewise linear in y, exactly what a stack of horizontal layers needs to be in equilibrium
// (∇·σ + ρ' g = 0 in each, σ·n continuous across each border).

#include <optional>
#include <vector>

#include "dda/definitions.hpp"
#include "scenario/scenario.hpp"

namespace hydrodda::run {

// A piece of a vertical column, of one density (kg/m3; 0 where the column leaves the domain).
struct ColumnPiece {
  double bottom = 0.0;  // m
  double top = 0.0;     // m
  double density = 0.0;
};

// Per material, the density its blocks' stress carries the weight of (ρ − α ρ_w in a coupled
// run under hydrostatic pore pressure, ρ otherwise).
std::vector<double> find_carried_densities(const scenario::Scenario& scenario);

// The column x = `x` through the domain, bottom to top, in pieces of one material each (the
// region holding the piece, else the material without one). Empty where x misses the domain.
std::vector<ColumnPiece> find_density_column(const scenario::Scenario& scenario, double x,
                                             const std::vector<double>& densities);

// The stress field of [mechanics.initial_stress]: linear (stress, reference_y, gradient), or
// integrated through the layers (above).
dda::StressField build_initial_stress(const scenario::Scenario& scenario);

}  // namespace hydrodda::run
