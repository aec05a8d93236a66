#pragma once
// The result of one steady flow solve.

#include <string>
#include <vector>

#include "geometry/point.hpp"

namespace hydrodda::hydro {

struct BoundaryFlow {
  std::string name;
  double flow = 0.0;  // outward, m²/s per metre of thickness (< 0 is inflow)
};

// Wall-clock seconds of the stages of one solve.
struct SolveTimings {
  double assemble = 0.0;
  double factorize = 0.0;
  double solve = 0.0;
  double postprocess = 0.0;
};

struct FlowSolution {
  std::vector<double> head;               // h per node, m
  std::vector<double> pressure;           // p per node, Pa (by the pressure convention)
  std::vector<geometry::Point> flux;      // Darcy velocity q = −K ∇h per triangle, m/s
  std::vector<BoundaryFlow> boundary_flows;  // every named boundary of the mesh, in mesh order
  double reference_head = 0.0;            // h_ref of the over-pressure convention
  // A transient step's rate of water going into storage, Σ (S_s M (h − h_old))_i / Δt
  // (m²/s per metre of thickness; < 0: released); 0 for a steady solve.
  double storage_rate = 0.0;
  // |Σ boundary flows + storage rate| / max(total inflow, total outflow, |storage rate|); 0
  // when nothing flows.
  double balance_error = 0.0;
  int refinement_steps = 0;               // iterative-refinement steps the solve took
  bool factorised = true;                 // factored afresh (false: CG on a kept factor)
  int cg_iterations = 0;                  // CG iterations on the kept factor
  int corrected_elements = 0;             // elements the kept factor was corrected for (low rank)
  SolveTimings timings;

  // Outward flow through a named boundary; throws when the name is unknown.
  double boundary_flow(const std::string& name) const;
  double total_inflow() const;
};

}  // namespace hydrodda::hydro
