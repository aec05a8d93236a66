#pragma once
// Boundary gaps are not fractures. The fluid mesh is fixed, so a block that moves off the
// domain boundary leaves an open strip between its face and the boundary, which the porosity
// clip counts as open area: a channel along the boundary that no fracture makes. Here every
// block face that lay on the domain boundary as built is followed; the strip between the face
// as it is now and the boundary line it came from,
//   gap(a′, b′) = quadrilateral a′, b′, b′ − d_b n, a′ − d_a n   (d = (x − p)·n, n inward),
// (only its part inside the domain: a face crossing the boundary is cut where d = 0), and at a
// block corner that lay on a domain corner the rectangle between the corner and the vertex,
// and, below the mouth of a joint that was closed where it met the boundary (two boundary
// faces of different blocks whose ends met there as built), the quadrilateral between the two
// ends as they are now and the boundary, p′, q′, q′ − d_q n, p′ − d_p n, when the ends have
// moved apart along it (a layer lifted off its base opens such a mouth: without it the sliver
// between the two strips would read as a fracture as tall as the lift),
// is taken out of the open area of the elements it covers (exclude_boundary_gaps). What the
// strip then is:
//   - along a head or pressure boundary it belongs to that boundary's reservoir: its fluid is
//     at the boundary's head (the boundary's nodes hold it; the strip adds no conductance of
//     its own, so the head reaches the rock face through the matrix of that element only);
//   - along a no-flow boundary it carries no flow along the boundary.
// Either way it is no fracture: the element keeps the open area of the real fractures over it.

#include <array>
#include <memory>
#include <span>
#include <vector>

#include "coupling/element_index.hpp"
#include "coupling/porosity.hpp"
#include "geometry/point.hpp"
#include "geometry/polygon.hpp"
#include "geometry/spatial_grid.hpp"

namespace hydrodda::coupling {

// How far the blocks have left the fluid domain: the vertex farthest outside it.
struct MeshExcursion {
  double distance = 0.0;  // m, 0 when every vertex lies inside (or on) the domain
  int block = -1;         // the block of that vertex, −1 when none is outside
  int blocks_outside = 0;  // blocks with at least one vertex outside
};

class BoundaryGaps {
 public:
  // `domain`: the fluid domain (a simple polygon, either orientation); `blocks_as_built`: the
  // blocks in the vertex order that later calls keep (an empty domain: no face is followed and
  // no vertex is outside). A block face counts as a boundary face
  // when both its ends lie within 1e-9 of the domain's size of one domain edge. `nodes` and
  // `triangles` must outlive the object (its ElementIndex keeps views of them).
  BoundaryGaps(std::span<const Point> nodes, std::span<const std::array<int, 3>> triangles,
               const geometry::Polygon& domain, std::span<const geometry::Polygon> blocks_as_built);
  // The same over a shared index of the mesh's elements.
  BoundaryGaps(std::shared_ptr<const ElementIndex> elements, const geometry::Polygon& domain,
               std::span<const geometry::Polygon> blocks_as_built);

  // Per element: the area of the boundary gaps over it (m²), for the blocks as they are now.
  std::vector<double> compute_gap_areas(std::span<const geometry::Polygon> blocks) const;

  // The gap polygons themselves (for tests and figures), for the blocks as they are now.
  std::vector<geometry::Polygon> find_gaps(std::span<const geometry::Polygon> blocks) const;

  MeshExcursion find_excursion(std::span<const geometry::Polygon> blocks) const;

  int boundary_face_count() const { return static_cast<int>(faces_.size()); }

 private:
  struct BoundaryFace {
    int block, vertex;  // the face runs from vertex to vertex + 1
    int side;           // the domain edge it lay on
  };
  struct Corner {
    int block, vertex;
    int side_before, side_after;  // the domain edges of the faces ending and starting there
    Point corner;                 // the domain corner the vertex lay on
  };
  struct Side {
    Point a, b;
    Point inward;  // unit normal into the domain
  };
  // The mouth of a joint closed as built: the end of face `before` met the start of face
  // `after` (of another block) on one side; `along` is the faces' direction as built.
  struct Mouth {
    int block_before, vertex_before;  // the end of the face before
    int block_after, vertex_after;    // the start of the face after
    int side;
    Point along;
  };

  std::shared_ptr<const ElementIndex> elements_;
  geometry::Polygon domain_;
  std::vector<Side> sides_;
  std::vector<BoundaryFace> faces_;
  std::vector<Corner> corners_;
  std::vector<Mouth> mouths_;
};

// Takes the gap area out of each element's open area (never below 0) and recomputes its
// porosity by the paper's eq. 8, φ = (A_f / A_e)(1 − φ_m) + φ_m.
void exclude_boundary_gaps(PorosityField& field, std::span<const double> gap_area,
                           std::span<const double> element_areas, double matrix_porosity);

}  // namespace hydrodda::coupling
