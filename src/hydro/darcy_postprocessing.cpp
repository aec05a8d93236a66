#include "hydro/darcy_postprocessing.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace hydrodda::hydro {
namespace {

// Each boundary's flow from A h (DarcyAssembler::boundary_totals), and their balance: they
// add up to minus the sum of the free rows' residual, so the balance error is the solver's.
void compute_boundary_flows(const DarcyAssembler& system, FlowSolution& out) {
  const std::vector<double> flow = system.boundary_totals(system.compute_a_times_h(out.head));
  out.boundary_flows.clear();
  double sum = 0.0;
  for (std::size_t b = 0; b < flow.size(); ++b) {
    out.boundary_flows.push_back({system.mesh().boundary_names[b], flow[b]});
    sum += flow[b];
  }
  if (system.has_storage()) {  // a transient step: what the boundaries let in, storage takes
    out.storage_rate = system.storage_rate(out.head);
    sum += out.storage_rate;
  }
  const double scale = std::max(DarcyAssembler::net_boundary_flow(flow), std::abs(out.storage_rate));
  out.balance_error = scale > 0.0 ? std::abs(sum) / scale : 0.0;
}

}  // namespace

double FlowSolution::boundary_flow(const std::string& name) const {
  for (const BoundaryFlow& b : boundary_flows)
    if (b.name == name) return b.flow;
  throw std::runtime_error("flow solution has no boundary named '" + name + "'");
}

double FlowSolution::total_inflow() const {
  double inflow = 0.0;
  for (const BoundaryFlow& b : boundary_flows) inflow += std::max(-b.flow, 0.0);
  return inflow;
}

FlowSolution make_flow_solution(const DarcyAssembler& system, const Eigen::VectorXd& x, PermeabilityView permeability) {
  const mesh::TriangleMesh& mesh = system.mesh();
  const DarcyProblem& problem = system.problem();
  FlowSolution out;
  const int node_count = mesh.node_count();
  out.reference_head = system.reference_head();
  out.head = system.expand_heads(x);
  const double rho_g = problem.fluid.unit_weight();
  out.pressure.resize(node_count);
  for (int v = 0; v < node_count; ++v)
    out.pressure[v] = problem.pressure == PressureConvention::overpressure
                          ? rho_g * (out.head[v] - out.reference_head)  // p = ρg (h − h_ref)
                          : rho_g * (out.head[v] - mesh.nodes[v].y);    // p = ρg (h − z)
  out.flux.resize(mesh.triangles.size());
  const double factor = problem.fluid.conductivity_per_permeability();
  system.over_thread_shares(mesh.triangle_count(), [&](int first, int last) {
    for (int t = first; t < last; ++t) {
      const auto& tri = mesh.triangles[t];
      const auto g = compute_shape_gradients(mesh.nodes[tri[0]], mesh.nodes[tri[1]], mesh.nodes[tri[2]]);
      // ∇h = Σ h_i ∇φ_i;  q = −K ∇h
      const geometry::Point grad = out.head[tri[0]] * g[0] + out.head[tri[1]] * g[1] + out.head[tri[2]] * g[2];
      const Conductivity k = conductivity(permeability[t], factor);
      out.flux[t] = {-(k.xx * grad.x + k.xy * grad.y), -(k.xy * grad.x + k.yy * grad.y)};
    }
  });
  compute_boundary_flows(system, out);
  return out;
}

}  // namespace hydrodda::hydro
