#include "mesh/mesh_estimate.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace hydrodda::mesh {

namespace {

constexpr double kTrianglesPerSquareSize = 2.65;  // Gmsh's Delaunay: N h² / A, measured (header)
constexpr double kMaxCells = 4.0e6;               // a few tenths of a second at most

// Per row of cells, the spans [x_in, x_out) of the row's centre line inside the polygon
// (even-odd crossings).
std::vector<double> row_crossings(const geometry::Polygon& polygon, double y) {
  std::vector<double> xs;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Point a = polygon[i], b = polygon[(i + 1) % polygon.size()];
    if ((a.y <= y) != (b.y <= y)) xs.push_back(a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y));
  }
  std::sort(xs.begin(), xs.end());
  return xs;
}

}  // namespace

TriangleEstimate estimate_triangle_count(const MeshRequest& r) {
  TriangleEstimate estimate;
  const geometry::Box box = geometry::bounding_box(r.domain);
  const double width = box.hi.x - box.lo.x, height = box.hi.y - box.lo.y;
  if (!(width > 0.0 && height > 0.0 && r.size > 0.0)) return estimate;
  const bool refined = !r.refinement_lines.empty() && r.fracture_size > 0.0 && r.fracture_size < r.size &&
                       r.refine_distance > 0.0;
  double cell = refined ? std::min(r.size / 2, r.refine_distance / 4) : r.size / 2;
  cell = std::max(cell, std::sqrt(width * height / kMaxCells));
  const int nx = std::max(1, static_cast<int>(std::ceil(width / cell)));
  const int ny = std::max(1, static_cast<int>(std::ceil(height / cell)));
  const double cx = width / nx, cy = height / ny;
  const auto centre = [&](int i, int j) { return Point{box.lo.x + (i + 0.5) * cx, box.lo.y + (j + 0.5) * cy}; };

  // Distance from each cell's centre to the nearest line, for cells within reach of one.
  const double reach = r.refine_distance + cx + cy;
  std::vector<float> distance(static_cast<std::size_t>(nx) * ny, INFINITY);
  if (refined) {
    for (const Segment& s : r.refinement_lines) {
      const int j0 = std::max(0, static_cast<int>(std::floor((std::min(s.from.y, s.to.y) - reach - box.lo.y) / cy)));
      const int j1 = std::min(ny - 1, static_cast<int>(std::floor((std::max(s.from.y, s.to.y) + reach - box.lo.y) / cy)));
      for (int j = j0; j <= j1; ++j) {
        const double y = centre(0, j).y;
        // The part of the line within `reach` of this row, widened by `reach`.
        double x_lo = std::min(s.from.x, s.to.x), x_hi = std::max(s.from.x, s.to.x);
        const double dy = s.to.y - s.from.y;
        if (std::abs(dy) > 1e-12 * (width + height)) {
          double t0 = (y - reach - s.from.y) / dy, t1 = (y + reach - s.from.y) / dy;
          if (t0 > t1) std::swap(t0, t1);
          t0 = std::max(t0, 0.0);
          t1 = std::min(t1, 1.0);
          if (t0 > t1) continue;
          const double xa = s.from.x + t0 * (s.to.x - s.from.x), xb = s.from.x + t1 * (s.to.x - s.from.x);
          x_lo = std::min(xa, xb);
          x_hi = std::max(xa, xb);
        }
        const int i0 = std::max(0, static_cast<int>(std::floor((x_lo - reach - box.lo.x) / cx)));
        const int i1 = std::min(nx - 1, static_cast<int>(std::floor((x_hi + reach - box.lo.x) / cx)));
        for (int i = i0; i <= i1; ++i) {
          float& d = distance[static_cast<std::size_t>(j) * nx + i];
          d = std::min(d, static_cast<float>(geometry::distance_to_segment(centre(i, j), s.from, s.to)));
        }
      }
    }
  }

  // ∫ 1/h² over each cell inside the domain: the mean of 1/h² over the cell's distances
  // [d − w/2, d + w/2] (clipped at 0), exact for h linear in d (1/(h(a) h(b))), and 1/size²
  // beyond refine_distance.
  const double w = 0.5 * (cx + cy), cell_area = cx * cy;
  const double far = 1.0 / (r.size * r.size);
  for (int j = 0; j < ny; ++j) {
    const std::vector<double> xs = row_crossings(r.domain, centre(0, j).y);
    for (std::size_t k = 0; k + 1 < xs.size(); k += 2) {
      const int i0 = std::max(0, static_cast<int>(std::ceil((xs[k] - box.lo.x) / cx - 0.5)));
      const int i1 = std::min(nx - 1, static_cast<int>(std::floor((xs[k + 1] - box.lo.x) / cx - 0.5)));
      for (int i = i0; i <= i1; ++i) {
        const double d = distance[static_cast<std::size_t>(j) * nx + i];
        if (!(d < r.refine_distance + w / 2)) {
          estimate.elsewhere += cell_area * far;
          continue;
        }
        const double a = std::max(0.0, d - w / 2), b = d + w / 2;
        const double b_near = std::min(b, r.refine_distance);
        const double mean = ((b_near - a) / (refined_size(r, a) * refined_size(r, b_near)) + (b - b_near) * far) / (b - a);
        (d < r.refine_distance ? estimate.near_lines : estimate.elsewhere) += cell_area * mean;
      }
    }
  }
  estimate.near_lines *= kTrianglesPerSquareSize;
  estimate.elsewhere *= kTrianglesPerSquareSize;
  // Each refinement point adds, over the disc where it sets the size (h = s + g d, g = (H − s)
  // / radius, H = size), c ∫ 2π d dd / h² − the same at H, which is
  //   2π c / g² [ln(H / s) + s / H − 1] − c π radius² / H²
  // (a point nearer a line, or the domain's edge, than its radius is counted whole).
  for (const RefinePoint& p : r.refinement_points) {
    if (!(p.size > 0.0 && p.size < r.size && p.radius > 0.0)) continue;
    const double g = (r.size - p.size) / p.radius;
    estimate.near_points += kTrianglesPerSquareSize * (2.0 * std::numbers::pi / (g * g) * (std::log(r.size / p.size) + p.size / r.size - 1.0) -
                                                       std::numbers::pi * p.radius * p.radius / (r.size * r.size));
  }
  return estimate;
}

}  // namespace hydrodda::mesh
