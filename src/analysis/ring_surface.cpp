#include "analysis/ring_surface.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "core/error.hpp"

namespace plisse {

namespace {

/// Area-weighted unit vertex normals: n_a ~ sum over the triangles at a of (x1 - x0) x (x2 - x0)
/// (twice the area times the unit normal), normalised (wrinkles.md, W5).
std::vector<Vec3d> vertex_normals(const std::vector<Vec3d>& x,
                                  const std::vector<std::array<int, 3>>& triangles) {
  std::vector<Vec3d> n(x.size(), Vec3d::Zero());
  for (const auto& t : triangles) {
    const Vec3d c = (x[t[1]] - x[t[0]]).cross(x[t[2]] - x[t[0]]);
    for (int a : t) n[static_cast<std::size_t>(a)] += c;
  }
  for (auto& v : n) {
    const double norm = v.norm();
    if (norm > 0.0) v /= norm;
  }
  return n;
}

}  // namespace

RingSurface::RingSurface(const std::vector<Vec3d>& nodes,
                         const std::vector<std::array<int, 3>>& triangles,
                         const std::vector<Vec3d>& displacement) {
  PLISSE_CHECK(
      displacement.empty() || displacement.size() == nodes.size(),
      "ring surface: " << displacement.size() << " displacements for " << nodes.size() << " nodes");
  // Local numbering of the surface nodes.
  std::unordered_map<int, int> local;
  std::vector<std::array<int, 3>> local_triangles;
  local_triangles.reserve(triangles.size());
  for (const auto& t : triangles) {
    std::array<int, 3> lt{};
    for (int k = 0; k < 3; ++k) {
      PLISSE_CHECK(
          t[k] >= 0 && t[k] < static_cast<int>(nodes.size()),
          "ring surface: triangle node " << t[k] << " out of range [0, " << nodes.size() << ")");
      const auto [it, inserted] = local.try_emplace(t[k], static_cast<int>(X_.size()));
      if (inserted) {
        const auto i = static_cast<std::size_t>(t[k]);
        X_.push_back(nodes[i]);
        x_.push_back(displacement.empty() ? nodes[i] : Vec3d(nodes[i] + displacement[i]));
      }
      lt[k] = it->second;
    }
    local_triangles.push_back(lt);
  }
  n_ = vertex_normals(x_, local_triangles);
  n0_ = vertex_normals(X_, local_triangles);
  edges_.reserve(3 * local_triangles.size());
  for (const auto& t : local_triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      edges_.push_back({std::min(a, b), std::max(a, b)});
    }
  std::sort(edges_.begin(), edges_.end());
  edges_.erase(std::unique(edges_.begin(), edges_.end()), edges_.end());
}

std::vector<RingPoint> RingSurface::sample(const CylindricalFrame& frame, double phi0) const {
  const std::size_t n = X_.size();
  std::vector<double> f(n);
  std::vector<char> on_cone(n);
  for (std::size_t a = 0; a < n; ++a) {
    f[a] = frame.cone_function(X_[a], phi0);
    // A node on the cone within round-off of its distance to the centre.
    on_cone[a] = std::abs(f[a]) <= 1e-12 * (X_[a] - frame.center()).norm();
  }
  const auto normalised = [](const Vec3d& v) {
    const double norm = v.norm();
    return norm > 0.0 ? Vec3d(v / norm) : v;
  };
  std::vector<RingPoint> points;
  for (std::size_t a = 0; a < n; ++a)
    if (on_cone[a]) points.push_back({X_[a], x_[a], n_[a], n0_[a]});
  for (const auto& [a, b] : edges_) {
    const auto ia = static_cast<std::size_t>(a), ib = static_cast<std::size_t>(b);
    if (on_cone[ia] || on_cone[ib] || (f[ia] > 0.0) == (f[ib] > 0.0)) continue;
    // Bisection on s in [0, 1] for f(X_a + s (X_b - X_a)) = 0: f is not linear along the edge
    // (rho is not), and 60 halvings reach round-off.
    double lo = 0.0, hi = 1.0;
    const bool a_above = f[ia] > 0.0;
    for (int it = 0; it < 60; ++it) {
      const double mid = 0.5 * (lo + hi);
      const double fm = frame.cone_function(X_[ia] + mid * (X_[ib] - X_[ia]), phi0);
      if ((fm > 0.0) == a_above)
        lo = mid;
      else
        hi = mid;
    }
    const double s = 0.5 * (lo + hi);
    points.push_back({X_[ia] + s * (X_[ib] - X_[ia]), x_[ia] + s * (x_[ib] - x_[ia]),
                      normalised((1.0 - s) * n_[ia] + s * n_[ib]),
                      normalised((1.0 - s) * n0_[ia] + s * n0_[ib])});
  }
  return points;
}

}  // namespace plisse
