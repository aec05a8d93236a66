#include "geometry/convex_decomposition.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "geometry/polygon.hpp"

namespace hydrodda::geometry {

namespace {

bool is_convex(std::span<const Point> polygon, const std::vector<int>& piece) {
  const std::size_t n = piece.size();
  for (std::size_t k = 0; k < n; ++k)
    if (!turns_left_or_straight(polygon[static_cast<std::size_t>(piece[k])],
                                polygon[static_cast<std::size_t>(piece[(k + 1) % n])],
                                polygon[static_cast<std::size_t>(piece[(k + 2) % n])]))
      return false;
  return true;
}

// Whether p lies in the closed triangle abc (counter-clockwise).
bool in_closed_triangle(Point p, Point a, Point b, Point c) {
  return orient(a, b, p) >= 0.0 && orient(b, c, p) >= 0.0 && orient(c, a, p) >= 0.0;
}

std::vector<std::vector<int>> clip_ears(std::span<const Point> polygon) {
  std::vector<int> remaining(polygon.size());
  for (std::size_t k = 0; k < remaining.size(); ++k) remaining[k] = static_cast<int>(k);
  const auto at = [&](int i) { return polygon[static_cast<std::size_t>(i)]; };
  std::vector<std::vector<int>> triangles;
  while (remaining.size() > 3) {
    const std::size_t m = remaining.size();
    bool cut = false;
    for (std::size_t k = 0; k < m && !cut; ++k) {
      const int a = remaining[(k + m - 1) % m], b = remaining[k], c = remaining[(k + 1) % m];
      if (!(orient(at(a), at(b), at(c)) > 0.0)) continue;
      const bool empty = std::none_of(remaining.begin(), remaining.end(), [&](int i) {
        return i != a && i != b && i != c && in_closed_triangle(at(i), at(a), at(b), at(c));
      });
      if (!empty) continue;
      triangles.push_back({a, b, c});
      remaining.erase(remaining.begin() + static_cast<std::ptrdiff_t>(k));
      cut = true;
    }
    if (!cut) throw std::invalid_argument("convex pieces: the polygon has no ear left (it is not simple)");
  }
  triangles.push_back(remaining);
  return triangles;
}

// The union of pieces p and q across their shared edge, p's u → v being q's v → u: p from v
// round to u, then q past u round to before v. Empty when they share no edge.
std::vector<int> join_across(const std::vector<int>& p, const std::vector<int>& q) {
  for (std::size_t k = 0; k < p.size(); ++k) {
    const int u = p[k], v = p[(k + 1) % p.size()];
    for (std::size_t m = 0; m < q.size(); ++m) {
      if (q[m] != v || q[(m + 1) % q.size()] != u) continue;
      std::vector<int> out;
      for (std::size_t j = 1; j <= p.size(); ++j) out.push_back(p[(k + j) % p.size()]);
      for (std::size_t j = 2; j < q.size(); ++j) out.push_back(q[(m + j) % q.size()]);
      return out;
    }
  }
  return {};
}

}  // namespace

std::vector<std::vector<int>> convex_pieces(std::span<const Point> polygon) {
  if (polygon.size() < 3 || signed_area(polygon) <= 0.0)
    throw std::invalid_argument("convex pieces: the polygon must be counter-clockwise");
  std::vector<std::vector<int>> pieces = clip_ears(polygon);
  // Every pair tried, a grown piece again against all: each diagonal that convexity does not
  // need goes.
  for (std::size_t p = 0; p < pieces.size(); ++p)
    for (std::size_t q = p + 1; q < pieces.size(); ++q) {
      if (pieces[p].empty() || pieces[q].empty()) continue;
      std::vector<int> joined = join_across(pieces[p], pieces[q]);
      if (joined.empty() || !is_convex(polygon, joined)) continue;
      pieces[p] = std::move(joined);
      pieces[q].clear();
      q = p;  // the grown piece may now join one tried before
    }
  std::erase_if(pieces, [](const std::vector<int>& piece) { return piece.empty(); });
  return pieces;
}

}  // namespace hydrodda::geometry
