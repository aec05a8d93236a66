#pragma once
// A model's fields as NumPy arrays in dicts: the fluid mesh and its solution, the blocks, the
// contacts and the fractures. What hydrodda.Simulation shows between steps and what a run's
// result keeps of its model's last state. Call with the GIL held.

#include <pybind11/numpy.h>

#include <vector>

#include "dda/system.hpp"
#include "fractures/fracture_results.hpp"
#include "hydro/flow_solution.hpp"
#include "mesh/triangle_mesh.hpp"
#include "python/bindings.hpp"
#include "run/run.hpp"
#include "scenario/scenario.hpp"

namespace hydrodda::python {

// nodes (N, 2) m, triangles (T, 3) node indices, permeability (T) m²; once solved head and
// pressure (N) m and Pa, flux (T, 2) m/s; porosity (T) when given.
py::dict fluid_fields(const mesh::TriangleMesh& mesh, const hydro::FlowSolution* flow,
                      const std::vector<double>& permeability, const std::vector<double>* porosity = nullptr);
// polygons (a list of (n, 2) arrays, m), centroid and displacement (B, 2) m, rotation (B) rad,
// stress (B, 3) σxx, σyy, τxy Pa, area (B) m², material (B) str: its material's name as
// summary.json's blocks give it ("" where the scenario names no material).
py::dict block_fields(const dda::System& system, const scenario::Scenario& scenario);
// block_i, vertex, block_j, edge (vertex `vertex` of block_i against edge `edge` of block_j),
// state ("open", "sliding", "locked"), penetration (m, > 0 overlap), normal_force (N/m,
// compression positive).
py::dict contact_fields(const dda::System& system);
// One entry per fracture, as fractures.csv's columns: id, origin ("listed", "set", "file"),
// set (-1 unless from a set), number, length, open_length (m), open (bool), open_share, mean_aperture,
// max_aperture, max_shear (m), hydraulic_aperture (m), normal_stress (Pa), flow (m²/s, NaN
// where not computed).
py::dict fracture_fields(const fractures::FractureState& state);
// {"fluid", "blocks", "contacts", "fractures"} of a run's model at its end, each present when
// the kind of run has it (fractures: when the run measured them).
py::dict fields_at_end(const run::ModelAtEnd& end);

}  // namespace hydrodda::python
