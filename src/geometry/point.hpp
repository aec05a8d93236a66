#pragma once
// A point (or vector) in the plane; the plain data every module passes around.

#include <cmath>

namespace hydrodda::geometry {

struct Point {
  double x = 0.0;
  double y = 0.0;

  friend constexpr Point operator+(Point a, Point b) { return {a.x + b.x, a.y + b.y}; }
  friend constexpr Point operator-(Point a, Point b) { return {a.x - b.x, a.y - b.y}; }
  friend constexpr Point operator*(double s, Point a) { return {s * a.x, s * a.y}; }
  friend constexpr Point operator*(Point a, double s) { return {s * a.x, s * a.y}; }
  friend constexpr Point operator/(Point a, double s) { return {a.x / s, a.y / s}; }
  constexpr Point& operator+=(Point b) { x += b.x; y += b.y; return *this; }
  constexpr Point& operator-=(Point b) { x -= b.x; y -= b.y; return *this; }
  friend constexpr bool operator==(Point a, Point b) = default;
};

constexpr double dot(Point a, Point b) { return a.x * b.x + a.y * b.y; }
// z-component of the 3D cross product: > 0 when b is counter-clockwise from a.
constexpr double cross(Point a, Point b) { return a.x * b.y - a.y * b.x; }
// Not std::hypot: its guard against overflow costs several times a square root, and no length
// in a model comes near the limits of a double (hypot was 4% of a DDA step, bench_dda).
inline double norm(Point a) { return std::sqrt(a.x * a.x + a.y * a.y); }
inline double distance(Point a, Point b) { return norm(b - a); }
// Twice the signed area of triangle abc: > 0 when a, b, c turn counter-clockwise.
constexpr double orient(Point a, Point b, Point c) { return cross(b - a, c - a); }

// Axis-aligned bounding box; empty until a point is added.
struct Box {
  Point lo{INFINITY, INFINITY};
  Point hi{-INFINITY, -INFINITY};

  constexpr void add(Point p) {
    lo.x = p.x < lo.x ? p.x : lo.x;
    lo.y = p.y < lo.y ? p.y : lo.y;
    hi.x = p.x > hi.x ? p.x : hi.x;
    hi.y = p.y > hi.y ? p.y : hi.y;
  }
  constexpr bool empty() const { return lo.x > hi.x; }
  constexpr bool overlaps(const Box& o) const {
    return lo.x <= o.hi.x && o.lo.x <= hi.x && lo.y <= o.hi.y && o.lo.y <= hi.y;
  }
  constexpr bool contains(Point p) const {
    return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y;
  }
  constexpr Box inflated(double d) const { return {{lo.x - d, lo.y - d}, {hi.x + d, hi.y + d}}; }
  constexpr double width() const { return hi.x - lo.x; }
  constexpr double height() const { return hi.y - lo.y; }
};

}  // namespace hydrodda::geometry
