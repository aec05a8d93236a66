#pragma once
// Fluid pressure on the blocks' faces (the paper's §3.3, integrated exactly for the P1 field).
// A face of a block of Biot coefficient α (seepage_forces.hpp) feels the traction (1 − α) p n_in.
// The face is cut where it crosses the fluid elements; along each piece the P1 pressure is
// linear, so the edge a→b (length L, s from a) takes exactly its consistent end loads
//   F_a = (1 − α) ∫ (1 − s/L) p(s) ds n_in,   F_b = (1 − α) ∫ (s/L) p(s) ds n_in,
// which are DDA's ∫ Tᵀ t ds over the edge (T is linear along it). A uniform pressure gives no
// net force or moment and a linear one Archimedes' buoyancy, exactly, on any mesh.
//
// Outside the fluid mesh (a block moved partly off it) a point takes the pressure of the mesh's
// nearest point (FacePressureLoads::pressure_outside_mesh, the one place that rule lives). The
// seepage force is only found inside the mesh, so the part of a block outside it is loaded as
// that force would load it, by the divergence theorem: its faces outside the mesh take the whole
// pressure (not 1 − α of it), and the mesh boundary across the block, Γ, the traction α p n
// (n out of the mesh). Net force and moment then stay the same for every α.

#include <memory>
#include <span>
#include <vector>

#include "coupling/element_index.hpp"
#include "geometry/point.hpp"
#include "geometry/polygon.hpp"
#include "geometry/spatial_grid.hpp"
#include "mesh/triangle_mesh.hpp"

namespace hydrodda::coupling {

using geometry::Point;

// Keeps the fixed mesh's spatial index and boundary edges.
class FacePressureLoads {
 public:
  // Keeps a reference to the mesh, which must outlive it.
  explicit FacePressureLoads(const mesh::TriangleMesh& mesh);
  // The same over a shared index of the mesh's elements.
  FacePressureLoads(const mesh::TriangleMesh& mesh, std::shared_ptr<const ElementIndex> elements);

  // forces[b][v] on vertex v of block b (blocks counter-clockwise) from the nodal pressures;
  // biot[b] is the α of block b. `sealed[b][e]` nonzero: edge e of block b is no face the
  // fluid stands on (an intact bond between two sub-blocks: rock, its pore pressure acting
  // through the seepage force alone, as in the block it tessellates) and takes no load; empty
  // (or an empty entry): every edge is loaded.
  std::vector<std::vector<Point>> compute(std::span<const geometry::Polygon> blocks,
                                          std::span<const double> nodal_pressure, std::span<const double> biot,
                                          std::span<const std::vector<char>> sealed = {}) const;

  // The P1 pressure at p: the field of the element that holds p, or the rule outside the mesh.
  double pressure_at(Point p, std::span<const double> nodal_pressure) const;

  // ∫ (1 − s/L) p ds and ∫ (s/L) p ds along the segment a→b, exactly for the P1 field, over
  // its parts inside the mesh and outside it.
  struct SegmentIntegrals {
    double start_inside = 0.0, end_inside = 0.0;
    double start_outside = 0.0, end_outside = 0.0;
    bool leaves_mesh = false;
  };
  SegmentIntegrals integrate_along(Point a, Point b, std::span<const double> nodal_pressure) const;

 private:
  // Outside the fluid mesh (a block moved partly off it): the pressure of the P1 field at the
  // nearest point of the mesh boundary. Along a face part outside the mesh it is taken linear
  // between the cuts below.
  double pressure_outside_mesh(Point p, std::span<const double> nodal_pressure) const;
  // Parameters in [0, 1] along the segment a→b (outside the mesh) between which its nearest
  // mesh point stays on one boundary side, so that the rule's pressure is linear between them
  // (exactly so along a straight stretch of boundary).
  std::vector<double> cut_where_nearest_side_changes(Point a, Point b) const;

  const mesh::TriangleMesh& mesh_;
  std::shared_ptr<const ElementIndex> elements_;  // the elements' grid
  double chunk_length_ = 1.0;   // a face is searched in pieces about one grid cell long
  double tolerance_ = 0.0;      // distance within which a point counts as on an element's edge
  double area_tolerance_ = 0.0;  // the same in orient()'s unit, as mesh::PointLocator takes it
  struct BoundarySide {
    Point a, b;
    int triangle;
    Point outward;  // unit normal out of the mesh
  };
  std::vector<BoundarySide> boundary_;  // the mesh boundary's edges with their triangle
  geometry::SpatialGrid boundary_grid_;  // over their boxes
  double boundary_reach_ = 0.0;          // their mean length: the first search's reach
  static std::vector<BoundarySide> find_boundary(const mesh::TriangleMesh& mesh);

  // The traction α p n (n out of the mesh) on the mesh boundary's parts inside the polygon,
  // as vertex forces of the polygon.
  std::vector<Point> load_mesh_boundary_across(const geometry::Polygon& block, double alpha,
                                               std::span<const double> nodal_pressure) const;
};

}  // namespace hydrodda::coupling
