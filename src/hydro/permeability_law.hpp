#pragma once
// Permeability from porosity, and the hydraulic aperture and transmissivity of a joint.

#include "geometry/point.hpp"
#include "hydro/fluid.hpp"

namespace hydrodda::hydro {

// The paper's eq. 9 (after Kozeny–Carman): k = d_g² φ³ / (180 (1 − φ)²), capped at k_max so
// that open fractures (φ → 1) stay finite (the paper caps at 1e5 mD = 9.869e-11 m²).
// φ in [0, 1]; d_g the grain diameter (m). φ = 1 gives the cap.
double kozeny_carman_permeability(double porosity, double grain_diameter, double cap);

// The cubic law's default cap on a fracture's permeability w²/12: a gap 1 cm wide,
// (1e-2 m)²/12 = 8.333e-6 m². Wider, a gap is an open channel whose flow at any gradient a seal
// holds is far past the laminar flow the cubic law describes (its Reynolds number
// ρ²gJw³/(12μ²) is 800 at a gradient J of 1e-3; Zimmerman et al. 2004, Int. J. Rock Mech.
// 41, 163, find it failing past about 20), and its contrast with a tight matrix (1e-19 m²: 8e13) stays inside the 1e16 that
// the flow solve's double precision resolves (the 0.7 m² of a layer lifted off by 2.9 m is not).
inline constexpr double kDefaultFracturePermeabilityCap = 1e-4 / 12.0;
inline constexpr double kNoFracturePermeabilityCap = 1e300;

// The cubic law: a fracture of aperture w carries the transmissivity w³/12 (m³). An element of
// width b across the fracture holding it has the equivalent permeability w³/(12 b) on top of
// its matrix permeability, k = k_m + (A_f/A_e) w²/12 with A_f/A_e = w/b, whatever b is.
// The fracture's own permeability w²/12 is capped at `fracture_cap` (m²):
//   k = k_m + (A_f/A_e) min(w²/12, k_cap),
// so that past the cap the transmissivity grows as w k_cap (docs/coupling.md, "The fracture
// permeability cap").
double cubic_law_permeability(double fracture_fraction, double aperture, double matrix_permeability,
                              double fracture_cap = kNoFracturePermeabilityCap);

// Whether the cubic law caps a fracture of aperture w: w²/12 > k_cap.
inline bool reaches_fracture_cap(double aperture, double fracture_cap) {
  return aperture * aperture / 12.0 > fracture_cap;
}

// The length over which a wedge tip exchanges flow with the matrix under the cubic law. A joint
// whose opening grows as w = α s from a tip carries α³ s² / 12 over a length s there, which is
// the matrix's k_m at
//   s* = √(12 k_m / α³);
// nearer the tip the matrix carries the flow, beyond it the joint. The head falls across s*,
// so a fluid mesh resolves the tip only with elements of a fraction of it (docs/coupling.md,
// "Wedge tips"). α > 0 (rad: dw/ds), k_m ≥ 0 (m²).
double cubic_law_tip_length(double opening_angle, double matrix_permeability);

// The hydraulic aperture of a joint (Barton, Bandis & Bakhtar 1985, the hyperbolic closure of
// Bandis et al. 1983). Closed under an effective normal stress σn ≥ 0 (compression positive):
//   a(σn) = a_r + V_m − σn V_m / (k_ni V_m + σn),
// from a_r + V_m at σn = 0 down to a_r as σn → ∞ (the closure σn V_m/(k_ni V_m + σn) tends to
// V_m, its initial slope is 1/k_ni). Open by a mechanical opening w: a(0) + w. Without a
// closure (V_m = 0) a closed joint keeps a_r at every stress.
// Where along a face between two blocks a joint is open to the flow (`[joint] hydraulic_opening`):
// `face`, a face that carries a compressive force is closed along its whole length under its mean
// stress; `local`, each point of a face is open where its own gap exceeds the tolerance.
enum class HydraulicOpening { face, local };

struct JointApertureLaw {
  double residual_aperture = 0.0;  // a_r, m
  double normal_stiffness = 0.0;   // k_ni, Pa/m (> 0 when max_closure > 0)
  double max_closure = 0.0;        // V_m, m
  HydraulicOpening opening = HydraulicOpening::face;

  double closed(double normal_stress) const;
  double at_zero_stress() const { return residual_aperture + max_closure; }
  double open(double opening) const { return at_zero_stress() + opening; }
  // At a point of a joint face between two blocks whose gap there is `gap` (m), the face
  // carrying a compressive effective normal force F (N/m) over its length L, of which
  // `closed_length` has a gap within `open_threshold`. `face`: a face that carries a force is
  // closed along its whole length, at closed(F / L), whatever gap its blocks' uniform strains
  // leave at one end; one that carries none is open(gap) where that exceeds the threshold,
  // closed(0) elsewhere. `local`: open(gap) where it exceeds the threshold, else
  // closed(F / closed_length).
  double on_face(double face_force, double face_length, double closed_length, double gap,
                 double open_threshold) const;
};

// A fracture of hydraulic aperture a embedded in an element (Lee, Lough & Jensen 2001; the
// embedded discrete fracture models): its transmissivity a³/12 (m³) along its direction t over
// the length L of it inside the element of area A, as the element permeability tensor
//   k = (a³/12)(L/A) t ⊗ t   (m²),
// which carries a³/12 × ∇h·t along the fracture whatever the element's size or shape.
PermeabilityTensor embedded_fracture_permeability(double aperture, double length, double area,
                                                  geometry::Point direction);

// An element whose open (unfilled) fraction f = A_f/A_e lies across it: open water, which
// resists nothing, in series with rock of permeability k_m over the rest of its width, the
// harmonic mean k_m / (1 − f), at most `cap` (and never under k_m). A joint opened as wide as
// the element is then no barrier across it, as a thin one (f → 0) leaves k_m unchanged; along
// an open joint the cubic law carries the flow, beside which the excess k_m f/(1 − f) is
// negligible (a²/12 ≫ k_m wherever a joint is open).
double permeability_across_open_fraction(double matrix_permeability, double open_fraction, double cap);

}  // namespace hydrodda::hydro
