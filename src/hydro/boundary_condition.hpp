#pragma once
// Flow boundary conditions on named boundary segments, and the pressure convention.

#include <string>

namespace hydrodda::hydro {

// How pressure follows from head (DESIGN.md §2.2):
//   over-pressure (the paper's): p = ρ_w g (h − h_ref), h_ref the smallest fixed-head value;
//   hydrostatic:                 p = ρ_w g (h − z), z the elevation (the y coordinate).
enum class PressureConvention { overpressure, hydrostatic };

// What is fixed on a named boundary; boundaries named by no condition are no-flow.
enum class BoundaryKind {
  head,      // h = value (m)
  pressure,  // p = value (Pa), turned into a head by the pressure convention
  flux,      // q·n = value (m/s), n the outward normal: > 0 is outflow
};

struct BoundaryCondition {
  std::string boundary;  // a name in TriangleMesh::boundary_names
  BoundaryKind kind = BoundaryKind::head;
  double value = 0.0;
};

}  // namespace hydrodda::hydro
