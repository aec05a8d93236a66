#include "hydro/permeability_law.hpp"

#include <cmath>
#include <stdexcept>

namespace hydrodda::hydro {

double kozeny_carman_permeability(double porosity, double grain_diameter, double cap) {
  if (!(porosity >= 0.0 && porosity <= 1.0))
    throw std::invalid_argument("Kozeny-Carman: porosity must lie in [0, 1]");
  if (porosity >= 1.0) return cap;
  const double one_minus = 1.0 - porosity;
  const double k = grain_diameter * grain_diameter * porosity * porosity * porosity / (180.0 * one_minus * one_minus);
  return std::min(k, cap);
}

double cubic_law_permeability(double fracture_fraction, double aperture, double matrix_permeability,
                              double fracture_cap) {
  if (!(fracture_fraction >= 0.0 && fracture_fraction <= 1.0))
    throw std::invalid_argument("cubic law: the fracture fraction must lie in [0, 1]");
  if (reaches_fracture_cap(aperture, fracture_cap)) return matrix_permeability + fracture_fraction * fracture_cap;
  return matrix_permeability + fracture_fraction * aperture * aperture / 12.0;  // as ever, to the last bit
}

double cubic_law_tip_length(double opening_angle, double matrix_permeability) {
  if (!(opening_angle > 0.0) || !(matrix_permeability >= 0.0))
    throw std::invalid_argument("cubic law tip length: the opening angle must be positive, k_m not negative");
  return std::sqrt(12.0 * matrix_permeability / (opening_angle * opening_angle * opening_angle));
}

double JointApertureLaw::closed(double normal_stress) const {
  const double sigma = std::max(normal_stress, 0.0);  // a joint in tension is not squeezed
  if (!(max_closure > 0.0)) return residual_aperture;
  return residual_aperture + max_closure - sigma * max_closure / (normal_stiffness * max_closure + sigma);
}

// A DDA block has one uniform strain. Where the effective stress changes across a block (the
// seepage force of a steep head gradient), two blocks' faces cannot follow each other: a face in
// compression stands open at one end by some (Δσ / M) × the block's size and presses harder at
// the other. That wedge is the discretisation's, not the joint's; the force across the face, which
// equilibrium sets, is what the joint carries, so the face is closed under its mean stress. The
// law is continuous as the force vanishes: closed(0) = a(0), from which an open face's a(0) + w
// starts.
double JointApertureLaw::on_face(double face_force, double face_length, double closed_length, double gap,
                                 double open_threshold) const {
  if (opening == HydraulicOpening::face && face_force > 0.0 && face_length > 0.0) return closed(face_force / face_length);
  if (gap > open_threshold) return open(gap);
  return closed(face_force > 0.0 && closed_length > 0.0 ? face_force / closed_length : 0.0);
}

PermeabilityTensor embedded_fracture_permeability(double aperture, double length, double area,
                                                  geometry::Point direction) {
  if (!(area > 0.0)) throw std::invalid_argument("embedded fracture: the element area must be positive");
  const double t2 = geometry::dot(direction, direction);
  const double scale = aperture * aperture * aperture / 12.0 * length / area / t2;  // t normalised
  return {scale * direction.x * direction.x, scale * direction.x * direction.y, scale * direction.y * direction.y};
}

double permeability_across_open_fraction(double matrix_permeability, double open_fraction, double cap) {
  const double bound = std::max(cap, matrix_permeability);
  if (!(open_fraction > 0.0)) return matrix_permeability;
  if (open_fraction >= 1.0) return bound;
  return std::min(matrix_permeability / (1.0 - open_fraction), bound);
}

}  // namespace hydrodda::hydro
