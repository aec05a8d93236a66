#pragma once
// What to mesh: a domain polygon with named boundary segments, refinement lines (the
// fractures) and region polygons that the mesh must honour.

#include <string>
#include <vector>

#include "geometry/polygon.hpp"
#include "mesh/triangle_mesh.hpp"

namespace hydrodda::mesh {

struct NamedSegment {
  std::string name;
  Point from;
  Point to;
};

struct Segment {
  Point from;
  Point to;
};

// A point the mesh is refined around: elements of `size` at it, growing linearly to the
// request's size at `radius` from it.
struct RefinePoint {
  Point point;
  double size = 0.0;
  double radius = 0.0;
};

struct NamedPolygon {
  std::string name;
  geometry::Polygon polygon;
};

struct MeshRequest {
  geometry::Polygon domain;              // simple polygon, either orientation
  std::vector<NamedSegment> boundaries;  // added to (and taking precedence over) the defaults
  std::vector<Segment> refinement_lines; // the mesh is refined along these (fractures)
  std::vector<NamedPolygon> regions;     // element edges follow their boundaries
  double size = 0.1;                     // element size far from the refinement lines (m)
  double fracture_size = 0.01;           // element size on the refinement lines (m)
  double refine_distance = 0.2;          // distance over which the size grows back (m)
  std::vector<RefinePoint> refinement_points;  // and around these (wedge tips)
  // Gmsh's 2D algorithm: 5 "Delaunay" (default: fastest measured, docs/performance.md),
  // 6 "Frontal-Delaunay", 1 "MeshAdapt".
  int algorithm = 5;
  // Triangles per surface Gmsh meshes: a request of ten times this many or more is cut into a
  // grid of rectangular tiles of about this many (gmsh_mesher.cpp: Gmsh's cost per triangle grows
  // with the triangles of a surface); 0 keeps the domain one surface.
  int tile_triangles = 5000;
  // Gmsh threads: Gmsh meshes surfaces (regions, tiles) in parallel, but the mesh itself then
  // varies from run to run (the 10^5-triangle seal over 20 tiles: 101,196 to 101,228
  // triangles on 2 threads, 101,194 every time on 1); 1 is reproducible.
  int threads = 1;
  // Processes meshing the tiles of a tiled request at once, each a fixed group of tiles
  // (gmsh_mesher.cpp); the run sets it to its thread count. The mesh is the same on any
  // number, so it is not part of the mesh cache's key.
  int processes = 2;
  // Passes of Gmsh's Laplacian smoothing (Mesh.Smoothing), which moves each node towards the
  // mean of its neighbours where that improves the triangles' angles; −1 chooses: one pass on
  // a mesh of one surface (every shipped scenario's), none on a tiled one. On a tiled mesh it
  // was half of Gmsh's time (the 1.09-million-triangle seal: 7.9–8.4 s meshing with it,
  // 3.3–4.0 s without) for triangles Delaunay refinement already makes well shaped: smallest
  // angle 30.2° without against 31.5° with, mean smallest angle 46.5° against 49.0°
  // (docs/scenario.md, "How many triangles"). Part of the mesh cache's key.
  int smoothing = -1;
  bool verbose = false;                  // let Gmsh print to the terminal
};

// Default boundary names: the sides of the domain's bounding box, restricted to where the
// domain boundary lies on them.
inline const std::vector<std::string> kDefaultBoundaryNames{"left", "right", "bottom", "top"};

// Names the boundary edges of `mesh` (which must have its triangles and nodes): an edge
// takes the first segment of `segments` that contains both its end points (within a relative
// 1e-9 of the domain size), else the first default side (left, right, bottom, top of `box`)
// it lies on, else stays unnamed. Several segments may share a name; a user segment named
// like a default side replaces that side. Sets mesh.boundary_edges and mesh.boundary_names
// (user names first, in order, then the defaults not redefined).
void name_boundary_edges(TriangleMesh& mesh, const std::vector<NamedSegment>& segments,
                         const geometry::Box& box);

// The element size at distance d from the nearest refinement line: Gmsh's Threshold field
// with DistMin = 0, i.e. fracture_size at the line, growing linearly to size at
// refine_distance and constant beyond.
double refined_size(const MeshRequest& request, double distance);
// The element size at p: the least of refined_size at `line_distance` (p's distance to the
// nearest refinement line) and, for each refinement point within its radius,
// size + d (request.size − size) / radius at distance d from it.
double refined_size(const MeshRequest& request, double line_distance, Point p);

// Meshes the request with Gmsh. Throws std::runtime_error on invalid input (non-simple
// domain, non-positive sizes) or when Gmsh fails.
TriangleMesh generate_mesh(const MeshRequest& request);

// Reads a Gmsh .msh file (any version Gmsh reads). Triangles take the 2D physical group of
// their entity as region (region 0 "domain" for none); boundary edges the 1D physical group
// that contains them. Errors name the file.
TriangleMesh read_msh(const std::string& path, bool verbose = false);

}  // namespace hydrodda::mesh
