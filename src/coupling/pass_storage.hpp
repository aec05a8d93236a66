#pragma once
// The fluid's stiffness within a coupling pass: pseudo-transient continuation of the steady
// coupled problem (Kelley & Keyes 1998, "Convergence analysis of pseudo-transient
// continuation", SIAM J. Numer. Anal. 35(2)). Each pass's flow is a backward-Euler step of
//   S_s ∂h/∂τ − ∇·(K ∇h) = 0
// from the last pass's heads over a pseudo-time step Δτ: (A + Σ_e S_e M_e/Δτ) h = f + Σ_e
// S_e M_e h_prev/Δτ. Its fixed point is the steady one exactly (the storage term vanishes
// where h = h_prev), so the loop's convergence is judged on the steady solve's heads, never
// on the stepped ones (a small Δτ alone would make the passes' changes small).
//
// The storage is physical, that of the fixed-stress split (Kim, Tchelepi & Juanes 2011,
// CMAME 200: the drained compressibility α²/K_dr added to 1/M), per element in head (1/m):
//   S_e = ρ_w g [ 1/M_e + α_e²/K_dr,e + f_e c_w + Σ_{crossings c in e} (L_c/A_e)(C_c + a_c c_w) ]
// with f_e the element's open fraction, L_c a joint's length inside it, a_c its hydraulic
// aperture and C_c = da/dp its compliance, the inverse of the Barton–Bandis normal stiffness
// at its current stress (Bandis, Lumsden & Barton 1983):
//   a = a_r + V_m − σ V_m/(k_ni V_m + σ)  ⇒  C = dV/dσ = k_ni V_m²/(k_ni V_m + σ)²
//                                             = (a − a_r)²/(k_ni V_m²)  (σ eliminated),
// and 1/k_ni on an open crossing (σ = 0). A joint that opens answers its pressure within the
// pass: a drained joint's pressure falls only as fast as its stored water leaves it.
//
// The pseudo-time step grows as the passes settle by switched evolution relaxation (SER,
// Mulder & van Leer 1985; Kelley & Keyes 1998 eq. 1.5): Δτ_{k+1} = Δτ_k r_{k−1}/r_k, the
// ratio bounded to [1/2, 2] a pass, r the steady head change.

#include <span>
#include <vector>

#include "coupling/embedded_joints.hpp"

namespace hydrodda::coupling {

// The settings of the pseudo-time storage; absent (LoopSettings::pseudo_time unset): off.
struct PseudoTimeSettings {
  double first_step = 0.0;             // Δτ of pass 2 (s); pass 1 is the steady solve
  std::vector<double> matrix_storage;  // per element: 1/M + α²/K_dr (1/Pa)
  double fluid_compressibility = 4.5e-10;  // c_w (1/Pa)
  double unit_weight = 9810.0;             // ρ_w g (Pa/m)
};

// A crossing's compliance da/dp (m/Pa) at hydraulic aperture `aperture` by its law: 0 for a
// law with no closure.
double joint_compliance(const hydro::JointApertureLaw& law, double aperture);

// S_e (1/m) per element as above. `open_fraction` per element (empty: none); `joints` and
// `apertures` (one per crossing) may be absent.
std::vector<double> compute_pass_storage(const PseudoTimeSettings& settings, std::span<const double> element_areas,
                                         std::span<const double> open_fraction, const EmbeddedJoints* joints,
                                         std::span<const double> apertures);

// SER: the next Δτ from this one and the last two steady head changes.
double next_pseudo_time_step(double step, double change_before, double change_now);

}  // namespace hydrodda::coupling
