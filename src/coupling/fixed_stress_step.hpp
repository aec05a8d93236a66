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
//   β_e = Σ_b (A_be/A_e) α_b²/K_b + Σ_c (L_c/A_e) C_c   (+ β_gap where a gap is or was: below)
//   ζ_e = Σ_b (A_be/A_e) α_b ε_v,b + A_f/A_e + Σ_c (L_c/A_e) a_c
// With lumped storage the step is the solver's backward-Euler step (A + Σ_e c_e M_e) h =
// f + Σ_e c_e M_e h̃ with c_e = (S_e + β_e)/Δt and, per node i (m_i = Σ_{e∋i} A_e/3 c_e),
//   h̃_i = Σ_{e∋i} (A_e/3)(S_e h^n_i + β_e h^{k−1}_i − (ζ^{k−1}_e − ζ^n_e)) / (Δt m_i):
// exactly the equation above, node by node (fold_step_heads).
//
// The open gaps between blocks have a stabilisation of their own, β_gap (GapSecant below). A
// gap's volume answers its pressure through the blocks' rigid motion, which no modulus bounds (a
// block on a film of water at fixed total stress is held by nothing), so the materials' β
// misses it: a gap that one iteration's mechanics closes shut loses its water at once, and
// without β_gap the next iteration's flow takes that water undrained (the source
// −(ζ^{k−1} − ζ^n)/Δt against the storage alone) and its pressure throws the blocks. The split is
// stable for β at least the compliance at fixed stress, and one larger only slows it
// (Castelletto, White & Tchelepi 2015, IJNAMG 39, "Accuracy and convergence properties of the
// fixed-stress iterative solution of two-way coupled poromechanics"; Girault, Kumar & Wheeler
// 2016, Comput. Geosci. 20, the same for a fracture's storage). β_gap is the compliance the
// iterations measured where a gap closed shut, the secant of its lost volume over its head:
//   s^k = max over e with ζgap^{k−1}_e = 0 < ζgap^{k−2}_e of
//         ζgap^{k−2}_e / max(|h̄^{k−1}_e − h̄^{k−2}_e|, τ (max h^{k−1} − min h^{k−1}))
//   β_gap^k = max(β_gap^{k−1}, s^k),   β_gap^1 = 0,   ζgap^0, h̄^0 those of the step's start,
// ζgap_e = A_f/A_e the gaps' share of element e, h̄_e its mean head, τ coupling.tolerance. A head
// change under what the loop resolves is no change: a gap shut while its head did not move has
// the compliance of its volume over the smallest head change the loop sees. The largest secant
// of the step is kept (the shut gap has no volume left to measure it by), and it is given to
// every element that holds a gap or held one in the step: a block's rigid motion moves every gap
// along it together, whatever the head at one element. Gaps that only open or narrow give no
// secant (a crack opening under its pressure is held by the rock's stiffness). β_e += β_gap
// there, on both sides: it cancels at convergence.

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

// The open gaps' secant within one time step: what the last iterate left, and β_gap so far.
struct GapSecant {
  std::vector<double> gap_share;  // ζgap_e = A_f/A_e of the last iterate's blocks
  std::vector<double> mean_head;  // h̄_e of the heads the last iterate's blocks were loaded with (m)
  std::vector<double> beta;       // ρ_w g β_gap,e (1/m): `largest` where a gap is or was, else 0
  std::vector<char> held_gap;     // the element held a gap at some iterate of the step
  double largest = 0.0;           // the largest secant of the step so far (1/m)
};

// The secant at a step's start: the gaps and heads of the step's start, β_gap = 0. Throws
// std::invalid_argument when the sizes do not fit.
GapSecant start_gap_secant(std::span<const std::array<int, 3>> triangles, std::span<const double> element_areas,
                           std::span<const double> open_area, std::span<const double> heads_at_start);

// Iteration k's update from the gaps (`open_area`, m²) and heads of iterate k − 1, with the
// loop's `tolerance` τ as above; the gaps and heads become the secant's last. Heads all alike
// give no scale for what the loop resolves: no secant is taken from them. Throws
// std::invalid_argument when the sizes do not fit.
void update_gap_secant(GapSecant& secant, std::span<const std::array<int, 3>> triangles,
                       std::span<const double> element_areas, std::span<const double> open_area,
                       std::span<const double> heads, double tolerance);

}  // namespace hydrodda::coupling
