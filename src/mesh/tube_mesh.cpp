#include "mesh/tube_mesh.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "core/error.hpp"
#include "mesh/boundary_tags.hpp"
#include "mesh/box_mesh.hpp"
#include "mesh/second_order.hpp"

namespace plisse {
namespace {

/// Unit directions (cos phi, sin phi) of the node rows about the axis, phi = sweep k / na: na + 1
/// rows over pi for the half tube, na over 2 pi for the full one. z is exactly 0 at phi = 0 and
/// phi = pi.
std::vector<std::array<double, 2>> directions_about_axis(int na, bool half) {
  const int rows = half ? na + 1 : na;
  const double sweep = half ? std::numbers::pi : 2.0 * std::numbers::pi;
  std::vector<std::array<double, 2>> direction(static_cast<std::size_t>(rows));
  for (int k = 0; k < rows; ++k) {
    const double phi = sweep * k / na;
    auto& d = direction[static_cast<std::size_t>(k)];
    const bool at_pi = half ? k == na : 2 * k == na;
    d = at_pi ? std::array<double, 2>{-1.0, 0.0}
              : std::array<double, 2>{std::cos(phi), std::sin(phi)};
  }
  return direction;
}

}  // namespace

namespace {

/// Phi(x) = the integral of 1 / h(s) ds of tube_stations' size function, and its inverse.
struct AxialGrading {
  double end_h, g, le;
  double phi_le = 0.0;  // set once phi can be called
  double size_after;
  bool flat;
  AxialGrading(double length, double h, double end_h_, double end_length)
      : end_h(end_h_),
        g((h - end_h_) / end_length),
        le(std::min(end_length, length)),
        size_after(end_h_ + g * le),
        flat(std::abs(g) < 1e-12) {
    phi_le = phi(le);
  }
  /// Logarithmic over the grading (the size linear in x), linear after it.
  double phi(double x) const {
    if (x > le) return phi_le + (x - le) / size_after;
    return flat ? x / end_h : std::log((end_h + g * x) / end_h) / g;
  }
  double x_of(double p) const {
    if (p > phi_le) return le + (p - phi_le) * size_after;
    return flat ? p * end_h : end_h * std::expm1(g * p) / g;
  }
};

}  // namespace

double tube_cells_along(double length, double h, double end_h, double end_length) {
  PLISSE_CHECK(length > 0.0 && h > 0.0 && end_h >= 0.0 && (end_h == 0.0 || end_length > 0.0),
               "tube_cells_along: needs length > 0, h > 0, and end_length > 0 with end_h > 0");
  const double n =
      end_h == 0.0 ? length / h : AxialGrading(length, h, end_h, end_length).phi(length);
  return std::max(1.0, std::round(n));
}

std::vector<double> tube_stations(double length, double h, double end_h, double end_length) {
  const int nx = static_cast<int>(tube_cells_along(length, h, end_h, end_length));
  std::vector<double> x(static_cast<std::size_t>(nx) + 1);
  if (end_h == 0.0) {
    for (int i = 0; i <= nx; ++i)
      x[static_cast<std::size_t>(i)] = i == nx ? length : length * i / nx;
    return x;
  }
  const AxialGrading grading(length, h, end_h, end_length);
  const double phi_l = grading.phi(length);
  for (int i = 0; i <= nx; ++i)
    x[static_cast<std::size_t>(i)] =
        i == nx ? length : std::min(grading.x_of(phi_l * i / nx), length);
  return x;
}

int tube_divisions_around(double radius, double h, bool half) {
  const int n = std::max(3, static_cast<int>(std::lround(std::numbers::pi * radius / h)));
  return half ? n : 2 * n;
}

Mesh make_tube_mesh(double radius, double length, double thickness, int layers, double h, bool half,
                    int order, std::vector<double> stations) {
  PLISSE_CHECK(radius > 0.5 * thickness && length > 0.0 && layers >= 1 && h > 0.0,
               "make_tube_mesh: needs radius > thickness / 2 > 0, length > 0, layers >= 1, h > 0");
  PLISSE_CHECK(order == 1 || order == 2, "make_tube_mesh: order must be 1 or 2");
  if (stations.empty()) stations = tube_stations(length, h);
  const int nx = static_cast<int>(stations.size()) - 1;
  const int na = tube_divisions_around(radius, h, half);
  // Node rows about the axis: na + 1 on the half tube (phi = 0 ... pi), na on the full one, whose
  // row na is row 0 again (the Kuhn cut is the same in every cell, so the seam is conforming).
  const int rows = half ? na + 1 : na;
  auto node = [&](int i, int k, int j) { return i + (nx + 1) * (k % rows + rows * j); };
  const auto direction = directions_about_axis(na, half);
  auto x_of = [&](int i) { return stations[static_cast<std::size_t>(i)]; };
  auto r_of = [&](int j) {
    const double inner = radius - 0.5 * thickness;
    return j == layers ? radius + 0.5 * thickness : inner + j * thickness / layers;
  };
  Mesh mesh;
  mesh.nodes.reserve(static_cast<std::size_t>((nx + 1) * rows * (layers + 1)));
  for (int j = 0; j <= layers; ++j)
    for (int k = 0; k < rows; ++k)
      for (int i = 0; i <= nx; ++i) {
        const auto& d = direction[static_cast<std::size_t>(k)];
        mesh.nodes.emplace_back(x_of(i), r_of(j) * d[0], r_of(j) * d[1]);
      }
  append_kuhn_tets(mesh, {nx, na, layers}, node);
  orient_generated_tets(mesh, "tube mesh");

  // Index (i, k, j) of a node, from its number.
  auto index = [&](int n) {
    return std::array<int, 3>{n % (nx + 1), (n / (nx + 1)) % rows, n / ((nx + 1) * rows)};
  };
  enum Side { kInner, kOuter, kLeft, kRight, kSymZ };
  tag_boundary(mesh, {{"inner"}, {"outer"}, {"left"}, {"right"}, {"sym_z"}},
               [&](const BoundaryFace& f) {
                 auto all = [&](int axis, int value) {
                   return std::all_of(f.nodes.begin(), f.nodes.end(), [&](int n) {
                     return index(n)[static_cast<std::size_t>(axis)] == value;
                   });
                 };
                 if (all(2, 0)) return static_cast<int>(kInner);
                 if (all(2, layers)) return static_cast<int>(kOuter);
                 if (all(0, 0)) return static_cast<int>(kLeft);
                 if (all(0, nx)) return static_cast<int>(kRight);
                 if (half && (all(1, 0) || all(1, na))) return static_cast<int>(kSymZ);
                 return -1;
               });
  if (!half) mesh.surface_tags.erase("sym_z");
  if (order == 2)
    add_edge_nodes(mesh, [&](int a, int b) {
      const auto ia = index(a), ib = index(b);
      const auto& da = direction[static_cast<std::size_t>(ia[1])];
      const auto& db = direction[static_cast<std::size_t>(ib[1])];
      const double dy = da[0] + db[0], dz = da[1] + db[1], norm = std::hypot(dy, dz);
      const double r = 0.5 * (r_of(ia[2]) + r_of(ib[2]));
      // Both ends on z = 0 (same row, phi = 0 or pi): dz is exactly 0, so z stays exactly 0.
      return Vec3d(0.5 * (x_of(ia[0]) + x_of(ib[0])), r * dy / norm, r * dz / norm);
    });
  return mesh;
}

Mesh make_tube_surface(double radius, double length, double h, bool half,
                       std::vector<double> stations) {
  PLISSE_CHECK(radius > 0.0 && length > 0.0 && h > 0.0,
               "make_tube_surface: needs radius > 0, length > 0, h > 0");
  if (stations.empty()) stations = tube_stations(length, h);
  const int nx = static_cast<int>(stations.size()) - 1;
  const int na = tube_divisions_around(radius, h, half);
  const int rows = half ? na + 1 : na;  // the full tube's row na is row 0
  auto node = [&](int i, int k) { return i + (nx + 1) * (k % rows); };
  const auto direction = directions_about_axis(na, half);
  Mesh mesh;
  mesh.nodes.reserve(static_cast<std::size_t>((nx + 1) * rows));
  for (int k = 0; k < rows; ++k)
    for (int i = 0; i <= nx; ++i) {
      const auto& d = direction[static_cast<std::size_t>(k)];
      mesh.nodes.emplace_back(stations[static_cast<std::size_t>(i)], radius * d[0], radius * d[1]);
    }
  // Counter-clockwise in (x, phi) runs the normal e_x x e_phi towards the axis: reversed.
  mesh.triangles.reserve(static_cast<std::size_t>(2 * nx * na));
  for (int k = 0; k < na; ++k)
    for (int i = 0; i < nx; ++i) {
      mesh.triangles.push_back({node(i, k), node(i + 1, k + 1), node(i + 1, k)});
      mesh.triangles.push_back({node(i, k), node(i, k + 1), node(i + 1, k + 1)});
    }
  std::vector<int> all(mesh.triangles.size());
  for (std::size_t t = 0; t < all.size(); ++t) all[t] = static_cast<int>(t);
  mesh.surface_tags["inner"] = all;
  mesh.surface_tags["outer"] = all;
  mesh.shell_face_side = {{"inner", -1}, {"outer", +1}};
  std::vector<EdgePlane> planes = {{{"left"}, 0, 0.0}, {{"right"}, 0, length}};
  if (half) planes.push_back({{"sym_z"}, 2, 0.0});
  tag_boundary_edges(mesh, planes);
  return mesh;
}

}  // namespace plisse
