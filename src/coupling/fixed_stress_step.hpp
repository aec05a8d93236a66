#pragma once
// The flow half of a coupled transient step by the fixed-stress split (Kim, Tchelepi & Juanes
// 2011, CMAME 200, "Stability and convergence of sequential methods for coupled flow and
// geomechanics: fixed-stress and fixed-strain splits"; Mikelić & Wheeler 2013, Comput. Geosci.
// 17, a contraction for β ≥ α²/(2 K_dr)). The mass balance of the water, in head (1/s):
//   S_s ∂h/∂t + ∂ζ/∂t − ∇·(K ∇h) = 0,
// S_s = ρ_w g S the storage at constant strain and ζ the volume of pore space and gap per unit
// volume that the skeleton's motion makes: α ε_v inside each block (ε_v its uniform strain's
// trace, plane strain), the open area between blocks (the porosity mapping's A_f) and the joint
// crossings' hydraulic apertures a L. Iteration k of the step n → n + 1 solves, by backward
// Euler with the storage lumped,
//   (S_s + β)(h^k − h^n)/Δt − ∇·(K ∇h^k) = −(ζ^{k−1} − ζ^n)/Δt + β (h^{k−1} − h^n)/Δt,
// ζ^{k−1} that of the blocks as the last mechanics left them, β = ρ_w g (α²/K_dr + C) the
// fixed-stress stabilisation (K_dr the block's drained bulk modulus in the plane, C a joint's
// Barton–Bandis compliance da/dp). At convergence h^k = h^{k−1} and β cancels: the fixed point
// is the fully coupled backward-Euler step.
//
// Per element e of area A_e (1/Pa before the factor ρ_w g), from the block pieces over it
// (porosity.hpp: block b's part of area A_be), its open area A_f and its joint crossings c
// (length L_c, aperture a_c):
//   S_e = Σ_b (A_be/A_e) S_b + (A_f/A_e) c_w + Σ_c (L_c/A_e) a_c c_w
//   β_e = Σ_b (A_be/A_e) α_b²/K_b + Σ_c (L_c/A_e) C_c
//   ζ_e = Σ_b (A_be/A_e) α_b ε_v,b + A_f/A_e + Σ_c (L_c/A_e) a_c
// With lumped storage the step is the solver's backward-Euler step (A + Σ_e c_e M_e) h =
// f + Σ_e c_e M_e h̃ with c_e = (S_e + β_e)/Δt and, per node i (m_i = Σ_{e∋i} A_e/3 c_e),
//   h̃_i = Σ_{e∋i} (A_e/3)(S_e h^n_i + β_e h^{k−1}_i − (ζ^{k−1}_e − ζ^n_e)) / (Δt m_i):
// exactly the equation above, node by node (fold_step_heads).

#include <array>
#include <span>
#include <vector>

#include "coupling/embedded_joints.hpp"
#include "coupling/porosity.hpp"

namespace hydrodda::coupling {

// The materials' part of the step, per block of the DDA system.
struct FixedStressSettings {
  std::vector<double> storage;          // S_b = 1/M of the block's material (1/Pa)
  std::vector<double> biot;             // α_b
  std::vector<double> drained_bulk;     // K_b in the plane (Pa): E/(2(1+ν)(1−2ν)) plane strain
  double fluid_compressibility = 0.0;   // c_w (1/Pa)
  double unit_weight = 9810.0;          // ρ_w g (Pa/m)
};

// What the blocks, gaps and joints hold of the water at one state of the skeleton, per element.
struct SkeletonVolumes {
  std::vector<double> zeta;           // ζ_e (-)
  std::vector<double> storage;        // ρ_w g S_e (1/m)
  std::vector<double> stabilisation;  // ρ_w g β_e (1/m)
};

// The sums above, from the pieces of the last clip (`pieces`), each block's ε_v, each element's
// open area (m²) and, with joints, each crossing's aperture (m). Throws std::invalid_argument
// when the sizes do not fit.
SkeletonVolumes compute_skeleton_volumes(const FixedStressSettings& settings, std::span<const double> element_areas,
                                         const BlockPieces& pieces, std::span<const double> volumetric_strain,
                                         std::span<const double> open_area, const EmbeddedJoints* joints,
                                         std::span<const double> apertures);

// Each block's ε_v = εx + εy, its uniform strain's trace (plane strain: εz = 0).
std::vector<double> volumetric_strains(std::span<const std::array<double, 3>> strains);

// The step's c_e = (S_e + β_e)/Δt (1/s) and the heads h̃ per node as above, on a mesh of
// `triangles` with `element_areas`. A node no storing element touches keeps h^n there (no
// storage: its heads are the steady ones, as the solver's row has no mass); throws
// std::runtime_error when a skeleton's change would have to go into such a node's water.
struct StepHeads {
  std::vector<double> storage_over_step;
  std::vector<double> heads;
};
StepHeads fold_step_heads(std::span<const std::array<int, 3>> triangles, std::span<const double> element_areas,
                          const SkeletonVolumes& now, std::span<const double> zeta_at_start, double time_step,
                          std::span<const double> heads_at_start, std::span<const double> heads_last_iterate);

}  // namespace hydrodda::coupling
