#pragma once
// The clipping oracle of the tests: Boost.Geometry's intersection area of a triangle and a
// polygon (either orientation), in plain floating point as our kernels work (DESIGN.md §5).

#define BOOST_GEOMETRY_NO_ROBUSTNESS
#include <boost/geometry.hpp>
#include <boost/geometry/geometries/multi_polygon.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/geometries/polygon.hpp>

#include <array>
#include <span>

#include "geometry/point.hpp"

namespace hydrodda::geometry::testing {

namespace bg = boost::geometry;
using BoostPoint = bg::model::d2::point_xy<double>;
using BoostPolygon = bg::model::polygon<BoostPoint, false>;  // counter-clockwise
using BoostMulti = bg::model::multi_polygon<BoostPolygon>;

inline BoostPolygon to_boost(std::span<const Point> polygon) {
  BoostPolygon out;
  for (Point p : polygon) bg::append(out.outer(), BoostPoint(p.x, p.y));
  bg::correct(out);
  return out;
}

inline double oracle_area(const std::array<Point, 3>& t, std::span<const Point> polygon) {
  BoostMulti result;
  bg::intersection(to_boost(t), to_boost(polygon), result);
  return bg::area(result);
}

// The centroid of triangle ∩ polygon: the area-weighted mean of its pieces' centroids.
inline Point oracle_centroid(const std::array<Point, 3>& t, std::span<const Point> polygon) {
  BoostMulti result;
  bg::intersection(to_boost(t), to_boost(polygon), result);
  Point moment{};
  for (const BoostPolygon& piece : result) {
    BoostPoint c(0.0, 0.0);
    bg::centroid(piece, c);
    moment += bg::area(piece) * Point{c.x(), c.y()};
  }
  return moment / bg::area(result);
}

}  // namespace hydrodda::geometry::testing
