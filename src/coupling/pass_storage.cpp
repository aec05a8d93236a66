#include "coupling/pass_storage.hpp"

#include <algorithm>
#include <stdexcept>

namespace hydrodda::coupling {

double joint_compliance(const hydro::JointApertureLaw& law, double aperture) {
  if (!(law.max_closure > 0.0) || !(law.normal_stiffness > 0.0)) return 0.0;
  if (aperture >= law.at_zero_stress()) return 1.0 / law.normal_stiffness;  // open: σ = 0
  const double above_residual = std::max(aperture - law.residual_aperture, 0.0);
  return above_residual * above_residual / (law.normal_stiffness * law.max_closure * law.max_closure);
}

std::vector<double> compute_pass_storage(const PseudoTimeSettings& settings, std::span<const double> element_areas,
                                         std::span<const double> open_fraction, const EmbeddedJoints* joints,
                                         std::span<const double> apertures) {
  const std::size_t n = element_areas.size();
  if (settings.matrix_storage.size() != n)
    throw std::invalid_argument("pass storage: one matrix storage per element is needed");
  std::vector<double> per_pascal(settings.matrix_storage);
  for (std::size_t e = 0; e < n && e < open_fraction.size(); ++e)
    per_pascal[e] += open_fraction[e] * settings.fluid_compressibility;
  if (joints) {
    const std::vector<JointCrossing>& crossings = joints->crossings();
    if (apertures.size() != crossings.size())
      throw std::invalid_argument("pass storage: one aperture per joint crossing is needed");
    for (std::size_t c = 0; c < crossings.size(); ++c) {
      const JointCrossing& x = crossings[c];
      const hydro::JointApertureLaw& law = joints->laws().of_fracture(x.face.fracture);
      const double held = joint_compliance(law, apertures[c]) + apertures[c] * settings.fluid_compressibility;
      per_pascal[static_cast<std::size_t>(x.element)] += x.length / element_areas[static_cast<std::size_t>(x.element)] * held;
    }
  }
  for (double& s : per_pascal) s *= settings.unit_weight;
  return per_pascal;
}

double next_pseudo_time_step(double step, double change_before, double change_now) {
  if (!(change_now > 0.0) || !(change_before > 0.0)) return 2.0 * step;
  return step * std::clamp(change_before / change_now, 0.5, 2.0);
}

}  // namespace hydrodda::coupling
