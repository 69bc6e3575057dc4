#include "analysis/surface_columns.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace plisse {

Vec3d closest_point_weights(const Vec3d& p, const Vec3d& a, const Vec3d& b, const Vec3d& c) {
  // Barycentric tests region by region; the closest point q is a vertex, on an edge or inside.
  const Vec3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return {1.0, 0.0, 0.0};  // vertex a
  const Vec3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return {0.0, 1.0, 0.0};  // vertex b
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {  // edge ab
    const double v = d1 / (d1 - d3);
    return {1.0 - v, v, 0.0};
  }
  const Vec3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return {0.0, 0.0, 1.0};  // vertex c
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {  // edge ac
    const double w = d2 / (d2 - d6);
    return {1.0 - w, 0.0, w};
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {  // edge bc
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {0.0, 1.0 - w, w};
  }
  const double denom = va + vb + vc;
  if (denom <= 0.0) {  // degenerate triangle: the nearest of its corners
    const double da = ap.squaredNorm(), db = bp.squaredNorm(), dc = cp.squaredNorm();
    if (da <= db && da <= dc) return {1.0, 0.0, 0.0};
    return db <= dc ? Vec3d(0.0, 1.0, 0.0) : Vec3d(0.0, 0.0, 1.0);
  }
  const double v = vb / denom, w = vc / denom;  // inside the face
  return {1.0 - v - w, v, w};
}

double point_triangle_distance(const Vec3d& p, const Vec3d& a, const Vec3d& b, const Vec3d& c) {
  const Vec3d w = closest_point_weights(p, a, b, c);
  return (p - (w[0] * a + w[1] * b + w[2] * c)).norm();
}

namespace {

/// Uniform grid of buckets over a box; each bucket lists the triangles whose bounding box meets
/// it (compressed rows).
class TriangleGrid {
 public:
  TriangleGrid(const std::vector<Vec3d>& nodes, const std::vector<std::array<int, 3>>& triangles)
      : nodes_(nodes), triangles_(triangles) {
    lo_ = Vec3d::Constant(1e300);
    Vec3d hi = Vec3d::Constant(-1e300);
    double edge_sum = 0.0;
    for (const auto& t : triangles) {
      for (int k = 0; k < 3; ++k) {
        const Vec3d& x = node(t[k]);
        lo_ = lo_.cwiseMin(x);
        hi = hi.cwiseMax(x);
        edge_sum += (node(t[(k + 1) % 3]) - x).norm();
      }
    }
    const double n_tri = static_cast<double>(triangles.size());
    const Vec3d extent = (hi - lo_).cwiseMax(1e-300);
    cell_ = std::max(edge_sum / (3.0 * n_tri), 1e-12 * extent.maxCoeff());
    // At most about 8 cells per triangle (plus a few), so a coarse surface in a large box does
    // not make an enormous empty grid.
    const double max_cells = 8.0 * n_tri + 64.0;
    const auto cells_for = [&](double h) {
      return std::ceil(extent.x() / h) * std::ceil(extent.y() / h) * std::ceil(extent.z() / h);
    };
    while (cells_for(cell_) > max_cells) cell_ *= 1.25;
    for (int i = 0; i < 3; ++i)
      dims_[i] = std::max(1, static_cast<int>(std::ceil(extent[i] / cell_)));
    const std::size_t n_cells = static_cast<std::size_t>(dims_[0]) * dims_[1] * dims_[2];
    start_.assign(n_cells + 1, 0);
    for (int pass = 0; pass < 2; ++pass) {  // pass 0 counts, pass 1 fills
      std::vector<int> fill;
      if (pass == 1) {
        for (std::size_t c = 0; c < n_cells; ++c) start_[c + 1] += start_[c];
        items_.resize(static_cast<std::size_t>(start_[n_cells]));
        fill.assign(start_.begin(), start_.end() - 1);
      }
      for (std::size_t t = 0; t < triangles.size(); ++t) {
        Vec3d tlo = node(triangles[t][0]), thi = tlo;
        for (int k = 1; k < 3; ++k) {
          tlo = tlo.cwiseMin(node(triangles[t][k]));
          thi = thi.cwiseMax(node(triangles[t][k]));
        }
        const std::array<int, 3> c0 = cell_of(tlo), c1 = cell_of(thi);
        for (int i = c0[0]; i <= c1[0]; ++i)
          for (int j = c0[1]; j <= c1[1]; ++j)
            for (int k = c0[2]; k <= c1[2]; ++k) {
              const std::size_t c = index(i, j, k);
              if (pass == 0)
                ++start_[c + 1];
              else
                items_[static_cast<std::size_t>(fill[c]++)] = static_cast<int>(t);
            }
      }
    }
  }

  /// Nearest triangle to p (lowest index on ties).
  int nearest(const Vec3d& p) const {
    const std::array<int, 3> c = cell_of(p);
    double best = 1e300;
    int best_t = -1;
    const int r_max = std::max({dims_[0], dims_[1], dims_[2]});
    for (int r = 0; r <= r_max; ++r) {
      for (int i = std::max(0, c[0] - r); i <= std::min(dims_[0] - 1, c[0] + r); ++i)
        for (int j = std::max(0, c[1] - r); j <= std::min(dims_[1] - 1, c[1] + r); ++j)
          for (int k = std::max(0, c[2] - r); k <= std::min(dims_[2] - 1, c[2] + r); ++k) {
            // Only the shell at Chebyshev distance r; inner cells were searched before.
            if (std::max({std::abs(i - c[0]), std::abs(j - c[1]), std::abs(k - c[2])}) != r)
              continue;
            const std::size_t cell = index(i, j, k);
            for (int q = start_[cell]; q < start_[cell + 1]; ++q) {
              const int t = items_[static_cast<std::size_t>(q)];
              const auto& tri = triangles_[static_cast<std::size_t>(t)];
              const double d = point_triangle_distance(p, node(tri[0]), node(tri[1]), node(tri[2]));
              if (d < best || (d == best && t < best_t)) {
                best = d;
                best_t = t;
              }
            }
          }
      // Cells at Chebyshev distance > r are at least r cells away from p (also when p lies
      // outside the grid and was clamped to its nearest cell).
      if (best_t >= 0 && best < r * cell_) break;
    }
    return best_t;
  }

 private:
  const Vec3d& node(int i) const { return nodes_[static_cast<std::size_t>(i)]; }
  std::array<int, 3> cell_of(const Vec3d& p) const {
    std::array<int, 3> c{};
    for (int i = 0; i < 3; ++i)
      c[i] = std::clamp(static_cast<int>(std::floor((p[i] - lo_[i]) / cell_)), 0, dims_[i] - 1);
    return c;
  }
  std::size_t index(int i, int j, int k) const {
    return (static_cast<std::size_t>(k) * dims_[1] + j) * dims_[0] + i;
  }

  const std::vector<Vec3d>& nodes_;
  const std::vector<std::array<int, 3>>& triangles_;
  Vec3d lo_;
  double cell_ = 1.0;
  std::array<int, 3> dims_{1, 1, 1};
  std::vector<int> start_, items_;
};

}  // namespace

namespace {

void check_triangles(std::size_t n_nodes, const std::vector<std::array<int, 3>>& triangles) {
  for (const auto& t : triangles)
    for (int a : t)
      PLISSE_CHECK(a >= 0 && static_cast<std::size_t>(a) < n_nodes,
                   "surface search: triangle node " << a << " out of range");
}

}  // namespace

std::vector<int> nearest_triangles(const std::vector<Vec3d>& nodes,
                                   const std::vector<std::array<int, 3>>& triangles,
                                   const std::vector<Vec3d>& points) {
  std::vector<int> nearest(points.size(), -1);
  if (points.empty()) return nearest;
  PLISSE_CHECK(!triangles.empty(), "surface search: no surface triangles");
  check_triangles(nodes.size(), triangles);
  const TriangleGrid grid(nodes, triangles);
  for (std::size_t i = 0; i < points.size(); ++i) nearest[i] = grid.nearest(points[i]);
  return nearest;
}

std::vector<int> assign_columns(const std::vector<Vec3d>& nodes,
                                const std::vector<std::array<int, 4>>& tets,
                                const std::vector<std::array<int, 3>>& triangles) {
  std::vector<int> column(tets.size(), -1);
  if (tets.empty()) return column;
  PLISSE_CHECK(!triangles.empty(), "surface columns: no surface triangles");
  const int n_nodes = static_cast<int>(nodes.size());
  check_triangles(nodes.size(), triangles);
  const TriangleGrid grid(nodes, triangles);
  for (std::size_t e = 0; e < tets.size(); ++e) {
    Vec3d centroid = Vec3d::Zero();
    for (int a : tets[e]) {
      PLISSE_CHECK(a >= 0 && a < n_nodes,
                   "surface columns: tetrahedron node " << a << " out of range");
      centroid += nodes[static_cast<std::size_t>(a)];
    }
    column[e] = grid.nearest(centroid / 4.0);
  }
  return column;
}

}  // namespace plisse
