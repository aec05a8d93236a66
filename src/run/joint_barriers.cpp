#include "run/joint_barriers.hpp"

#include "run/model_geometry.hpp"

namespace hydrodda::run {

std::vector<BarrierStrip> find_barrier_strips(const scenario::Scenario& s) {
  std::vector<BarrierStrip> strips;
  if (!s.any_joint_barrier() || !s.geometry || s.geometry->domain.empty()) return strips;
  const ModelGeometry model = build_model_geometry(s);
  for (const geometry::FractureFace& face : model.network.faces) {
    const int type = model.traces[static_cast<std::size_t>(face.fracture)].joint_type;
    const scenario::JointDefinition& joint = s.joint_type(type);
    if (!joint.barrier()) continue;
    const geometry::Point d = face.segment.to - face.segment.from;
    const double length = geometry::norm(d);
    if (!(length > 0.0)) continue;
    const double half = 0.5 * *joint.barrier_width;
    const geometry::Point e = d * (half / length);   // along the face
    const geometry::Point n{-e.y, e.x};              // across it, to its left
    const geometry::Point a = face.segment.from - e, b = face.segment.to + e;
    strips.push_back({"barrier." + (joint.name.empty() ? std::string("joint") : joint.name),
                      {a - n, b - n, b + n, a + n},
                      *joint.barrier_permeability});
  }
  return strips;
}

}  // namespace hydrodda::run
