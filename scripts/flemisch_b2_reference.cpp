// A reference for Flemisch et al. (2018) Benchmark 2 (regular fracture network), built
// independently of hydrodda's elements: cell-centred finite volumes with two-point fluxes on
// an N × N grid of the unit square whose cell faces carry the six fractures. Each fracture face
// is a cell of its own, of aperture a and permeability K_f (the hybrid-dimensional model of the
// benchmark): across, it links each of its two matrix cells through the half cell and half the
// aperture in series,
//   F_cf = h (p_c − p_f) / (h/2 / K + a/2 / K_f)        (face length h, K = 1 in the matrix),
// so that the two links in series are h / (h/K + a/K_f), exact for a thin layer of aperture a
// between the cells (the blocking case, K_f = 1e-4); along, it links the grid vertex at each of
// its ends through half its length, F = K_f a (p_f − p_v) / (h/2), and the vertices are the
// fracture network's nodes, where fractures meet and cross (the conductive case, K_f = 1e4,
// K_f a = 1). The matrix the fractures displace (a = 1e-4) is left out. Inflow 1 on the left
// (the matrix's faces), p = 1 on the right (F = 2 (p_i − 1) at the boundary face; a fracture
// ending there, F = 2 K_f a (p_f − 1) / h), no flow at the top and bottom and into the
// fractures' left ends. TPFA is exact for this grid's K = I, so the error is O(h²) (the
// sampling below keeps it so).
//
// Writes the pressure along the segment (x0, y0)–(x1, y1) at `samples` points as
// "arc_length,pressure" rows: each point takes its cell's value plus its cell's gradient from
// the neighbours not behind a fracture face (one-sided where a fracture bounds the cell).
//
//   g++ -O2 -std=c++20 -I/usr/include/eigen3 scripts/flemisch_b2_reference.cpp -o b2_reference
//   ./b2_reference N Kf [x0 y0 x1 y1 samples] > reference.csv
// (N a multiple of 8, so that x, y = 0.5, 0.625, 0.75 are cell faces; Kf = 1e-4 blocking,
// 1e4 conductive).
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCore>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <utility>
#include <vector>

namespace {

int n_cells = 800;

// Whether the vertical face at x = i h (between cells i − 1 and i) in row j lies on a fracture.
bool vertical_fracture(int i, int j) {
  const double x = static_cast<double>(i) / n_cells, y = (j + 0.5) / n_cells;
  if (std::abs(x - 0.5) < 1e-12) return true;
  if (std::abs(x - 0.75) < 1e-12) return y > 0.5;
  if (std::abs(x - 0.625) < 1e-12) return y > 0.5 && y < 0.75;
  return false;
}

// The same for the horizontal face at y = j h in column i (the grid is symmetric in x and y).
bool horizontal_fracture(int i, int j) { return vertical_fracture(j, i); }

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s N Kf [x0 y0 x1 y1 samples]\n", argv[0]);
    return 2;
  }
  n_cells = std::atoi(argv[1]);
  const double kf = std::atof(argv[2]), aperture = 1e-4, h = 1.0 / n_cells;
  const double x0 = argc > 7 ? std::atof(argv[3]) : 0.0, y0 = argc > 7 ? std::atof(argv[4]) : 0.1;
  const double x1 = argc > 7 ? std::atof(argv[5]) : 0.9, y1 = argc > 7 ? std::atof(argv[6]) : 1.0;
  const int samples = argc > 7 ? std::atoi(argv[7]) : 901;
  const int n = n_cells;
  const auto id = [n](int i, int j) { return j * n + i; };
  // Unknowns: the n² cells, then the grid's (n + 1)² vertices (the fracture network's nodes;
  // a vertex no fracture face reaches is an isolated unknown fixed at 0 below), then one per
  // fracture face, numbered as met.
  const int cells = n * n, vertices = (n + 1) * (n + 1);
  const auto vertex = [n, cells](int i, int j) { return cells + j * (n + 1) + i; };
  std::vector<Eigen::Triplet<double>> a;
  std::vector<double> f(cells + vertices, 0.0);
  std::vector<bool> reached(vertices, false);
  int unknowns = cells + vertices;
  const auto link = [&](int p, int q, double t) {
    a.emplace_back(p, p, t);
    a.emplace_back(q, q, t);
    a.emplace_back(p, q, -t);
    a.emplace_back(q, p, -t);
  };
  const double across = h / (h / 2 + aperture / 2 / kf), along = kf * aperture / (h / 2);
  // A fracture face between the cells c0 and c1 (−1: none) and the vertices v0 and v1.
  const auto fracture_face = [&](int c0, int c1, int vi0, int vj0, int vi1, int vj1) {
    const int face = unknowns++;
    f.push_back(0.0);
    if (c0 >= 0) link(c0, face, across);
    if (c1 >= 0) link(c1, face, across);
    for (const auto& [vi, vj] : {std::pair{vi0, vj0}, std::pair{vi1, vj1}}) {
      if (vi == n) {  // on the right side: p = 1
        a.emplace_back(face, face, along);
        f[face] += along;
        continue;
      }
      link(face, vertex(vi, vj), along);
      reached[vj * (n + 1) + vi] = true;
    }
  };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      if (i + 1 < n) {
        if (vertical_fracture(i + 1, j)) fracture_face(id(i, j), id(i + 1, j), i + 1, j, i + 1, j + 1);
        else link(id(i, j), id(i + 1, j), 1.0);
      }
      if (j + 1 < n) {
        if (horizontal_fracture(i, j + 1)) fracture_face(id(i, j), id(i, j + 1), i, j + 1, i + 1, j + 1);
        else link(id(i, j), id(i, j + 1), 1.0);
      }
    }
  for (int v = 0; v < vertices; ++v)
    if (!reached[v]) a.emplace_back(cells + v, cells + v, 1.0);
  for (int j = 0; j < n; ++j) {
    f[id(0, j)] += h;                                  // inflow 1 through the left face
    a.emplace_back(id(n - 1, j), id(n - 1, j), 2.0);  // h / (h / 2) to p = 1 on the right
    f[id(n - 1, j)] += 2.0;
  }
  Eigen::SparseMatrix<double> matrix(unknowns, unknowns);
  matrix.setFromTriplets(a.begin(), a.end());
  Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper, Eigen::IncompleteCholesky<double>> cg;
  cg.setTolerance(1e-13);
  cg.setMaxIterations(100000);
  cg.compute(matrix);
  const Eigen::VectorXd p = cg.solve(Eigen::Map<const Eigen::VectorXd>(f.data(), unknowns));
  std::fprintf(stderr, "N %d: %ld CG iterations, relative residual %.2e\n", n, static_cast<long>(cg.iterations()), cg.error());

  std::printf("arc_length,pressure\n");
  const double length = std::hypot(x1 - x0, y1 - y0);
  for (int s = 0; s < samples; ++s) {
    const double t = static_cast<double>(s) / (samples - 1);
    const double x = x0 + t * (x1 - x0), y = y0 + t * (y1 - y0);
    const int i = std::min(n - 1, static_cast<int>(x / h)), j = std::min(n - 1, static_cast<int>(y / h));
    const double dx = x - (i + 0.5) * h, dy = y - (j + 0.5) * h;
    // One-sided or central differences towards the neighbours no fracture face separates.
    const auto slope = [&](bool back_ok, bool ahead_ok, double back, double here, double ahead, double offset) {
      if (back_ok && ahead_ok) return (ahead - back) / (2 * h);
      if (ahead_ok) return (ahead - here) / h;
      if (back_ok) return (here - back) / h;
      (void)offset;
      return 0.0;
    };
    const double here = p[id(i, j)];
    const bool left = i > 0 && !vertical_fracture(i, j), right = i + 1 < n && !vertical_fracture(i + 1, j);
    const bool below = j > 0 && !horizontal_fracture(i, j), above = j + 1 < n && !horizontal_fracture(i, j + 1);
    const double gx = slope(left, right, left ? p[id(i - 1, j)] : 0, here, right ? p[id(i + 1, j)] : 0, dx);
    const double gy = slope(below, above, below ? p[id(i, j - 1)] : 0, here, above ? p[id(i, j + 1)] : 0, dy);
    std::printf("%.10g,%.10g\n", t * length, here + gx * dx + gy * dy);
  }
  return 0;
}
