#pragma once
// Permeability from porosity.

namespace hydrodda::hydro {

// The paper's eq. 9 (after Kozeny–Carman): k = d_g² φ³ / (180 (1 − φ)²), capped at k_max so
// that open fractures (φ → 1) stay finite (the paper caps at 1e5 mD = 9.869e-11 m²).
// φ in [0, 1]; d_g the grain diameter (m). φ = 1 gives the cap.
double kozeny_carman_permeability(double porosity, double grain_diameter, double cap);

// The cubic law: a fracture of aperture w carries the transmissivity w³/12 (m³). An element of
// width b across the fracture holding it has the equivalent permeability w³/(12 b) on top of
// its matrix permeability, k = k_m + (A_f/A_e) w²/12 with A_f/A_e = w/b, whatever b is.
double cubic_law_permeability(double fracture_fraction, double aperture, double matrix_permeability);

}  // namespace hydrodda::hydro
