#include "analysis/tension_field.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "analysis/surface_columns.hpp"
#include "analysis/wrinkle_rings.hpp"
#include "core/error.hpp"

namespace plisse {

namespace {

/// Key of a face: its sorted node triple.
std::array<int, 3> face_key(std::array<int, 3> f) {
  std::sort(f.begin(), f.end());
  return f;
}

/// In-plane principal values sigma_1 >= sigma_2 of P sigma P, P = I - n n (T2-T3), in the
/// orthonormal tangent basis t1 = (x1 - x0)/|x1 - x0|, t2 = n x t1 of the triangle.
std::array<double, 2> in_plane_principal(const Mat3d& sigma, const Vec3d& x0, const Vec3d& x1,
                                         const Vec3d& x2) {
  const Vec3d n = (x1 - x0).cross(x2 - x0).normalized();
  const Vec3d t1 = (x1 - x0).normalized();
  const Vec3d t2 = n.cross(t1);
  const double s11 = t1.dot(sigma * t1), s22 = t2.dot(sigma * t2);
  const double s12 = 0.5 * (t1.dot(sigma * t2) + t2.dot(sigma * t1));
  const double mean = 0.5 * (s11 + s22);
  const double radius = std::hypot(0.5 * (s11 - s22), s12);
  return {mean + radius, mean - radius};
}

/// Checks the tolerance options (T4).
void check_options(const TensionFieldSettings& options) {
  PLISSE_CHECK(
      !options.tolerance || (std::isfinite(*options.tolerance) && *options.tolerance >= 0.0),
      "tension field: tolerance must be >= 0");
  PLISSE_CHECK(std::isfinite(options.relative_tolerance) && options.relative_tolerance >= 0.0,
               "tension field: relative_tolerance must be >= 0");
}

/// The state of principal values (s1, s2) under tolerance tau (T4).
MembraneState classify(const std::array<double, 2>& principal, double tau) {
  const auto [s1, s2] = principal;
  return s2 > tau ? MembraneState::taut : s1 > tau ? MembraneState::wrinkled : MembraneState::slack;
}

}  // namespace

const char* to_string(MembraneState state) {
  switch (state) {
    case MembraneState::taut:
      return "taut";
    case MembraneState::wrinkled:
      return "wrinkled";
    case MembraneState::slack:
      return "slack";
  }
  return "?";
}

TensionField compute_tension_field(
    const std::vector<Vec3d>& nodes, const std::vector<std::array<int, 4>>& tets,
    const std::vector<std::array<int, 3>>& triangles, const std::vector<int>& column,
    const std::vector<Vec3d>& displacement, const std::vector<Mat3d>& cauchy_stress,
    const std::vector<double>& J, const TensionFieldSettings& options) {
  const std::size_t n_tets = tets.size(), n_tri = triangles.size();
  const int n_nodes = static_cast<int>(nodes.size());
  PLISSE_CHECK(column.size() == n_tets,
               "tension field: " << column.size() << " columns for " << n_tets << " tetrahedra");
  PLISSE_CHECK(displacement.size() == nodes.size(), "tension field: " << displacement.size()
                                                                      << " displacements for "
                                                                      << nodes.size() << " nodes");
  PLISSE_CHECK(cauchy_stress.size() == n_tets, "tension field: " << cauchy_stress.size()
                                                                 << " stresses for " << n_tets
                                                                 << " tetrahedra");
  PLISSE_CHECK(J.empty() || J.size() == n_tets,
               "tension field: " << J.size() << " values of J for " << n_tets << " tetrahedra");
  PLISSE_CHECK(
      !options.tolerance || (std::isfinite(*options.tolerance) && *options.tolerance >= 0.0),
      "tension field: tolerance must be >= 0");
  PLISSE_CHECK(std::isfinite(options.relative_tolerance) && options.relative_tolerance >= 0.0,
               "tension field: relative_tolerance must be >= 0");
  for (const auto& t : triangles)
    for (int a : t)
      PLISSE_CHECK(a >= 0 && a < n_nodes, "tension field: triangle node " << a << " out of range");
  const auto X = [&](int a) -> const Vec3d& { return nodes[static_cast<std::size_t>(a)]; };
  const auto x = [&](int a) {
    const auto i = static_cast<std::size_t>(a);
    return Vec3d(nodes[i] + displacement[i]);
  };

  // Volume-weighted column sums (T1): w_e = J_e V0_e (or V0_e).
  std::vector<Mat3d> sum(n_tri, Mat3d::Zero());
  std::vector<double> weight(n_tri, 0.0);
  for (std::size_t e = 0; e < n_tets; ++e) {
    const int c = column[e];
    PLISSE_CHECK(c >= 0 && c < static_cast<int>(n_tri),
                 "tension field: column " << c << " of tetrahedron " << e << " out of range");
    for (int a : tets[e])
      PLISSE_CHECK(a >= 0 && a < n_nodes,
                   "tension field: tetrahedron node " << a << " out of range");
    const auto& t = tets[e];
    const double V0 =
        std::abs((X(t[1]) - X(t[0])).dot((X(t[2]) - X(t[0])).cross(X(t[3]) - X(t[0])))) / 6.0;
    const double w = J.empty() ? V0 : J[e] * V0;
    sum[static_cast<std::size_t>(c)] += w * cauchy_stress[e];
    weight[static_cast<std::size_t>(c)] += w;
  }

  // Triangles without a column: the stress of the tetrahedron they are a face of.
  std::map<std::array<int, 3>, std::size_t> orphan;  // face key -> triangle
  for (std::size_t i = 0; i < n_tri; ++i)
    if (weight[i] <= 0.0) orphan.emplace(face_key(triangles[i]), i);
  if (!orphan.empty()) {
    for (std::size_t e = 0; e < n_tets && !orphan.empty(); ++e)
      for (int k = 0; k < 4; ++k) {
        const auto& t = tets[e];
        const auto it = orphan.find(face_key({t[(k + 1) % 4], t[(k + 2) % 4], t[(k + 3) % 4]}));
        if (it == orphan.end()) continue;
        sum[it->second] = cauchy_stress[e];
        weight[it->second] = 1.0;
        orphan.erase(it);
      }
    PLISSE_CHECK(
        orphan.empty(),
        "tension field: " << orphan.size() << " surface triangle(s) are no tetrahedron's face");
  }

  TensionField out;
  out.principal_stress.resize(n_tri);
  double largest = 0.0;
  for (std::size_t i = 0; i < n_tri; ++i) {
    const Mat3d mean = sum[i] / weight[i];
    const auto& t = triangles[i];
    out.principal_stress[i] = in_plane_principal(mean, x(t[0]), x(t[1]), x(t[2]));
    largest = std::max(largest, std::abs(out.principal_stress[i][0]));
  }
  out.tolerance = options.tolerance.value_or(options.relative_tolerance * largest);  // T4

  out.triangle_state.resize(n_tri);
  for (std::size_t i = 0; i < n_tri; ++i) {
    const auto [s1, s2] = out.principal_stress[i];
    const MembraneState s = s2 > out.tolerance   ? MembraneState::taut
                            : s1 > out.tolerance ? MembraneState::wrinkled
                                                 : MembraneState::slack;
    out.triangle_state[i] = s;
    ++out.n_triangles[static_cast<std::size_t>(s)];
  }
  out.element_state.resize(n_tets);
  for (std::size_t e = 0; e < n_tets; ++e) {
    const MembraneState s = out.triangle_state[static_cast<std::size_t>(column[e])];
    out.element_state[e] = s;
    ++out.n_elements[static_cast<std::size_t>(s)];
  }
  return out;
}

TensionField compute_shell_tension_field(const std::vector<Vec3d>& nodes,
                                         const std::vector<std::array<int, 3>>& elements,
                                         const std::vector<int>& surface,
                                         const std::vector<Vec3d>& displacement,
                                         const std::vector<Mat3d>& cauchy_stress,
                                         const TensionFieldSettings& options) {
  const std::size_t n_elements = elements.size();
  const int n_nodes = static_cast<int>(nodes.size());
  PLISSE_CHECK(displacement.size() == nodes.size(), "tension field: " << displacement.size()
                                                                      << " displacements for "
                                                                      << nodes.size() << " nodes");
  PLISSE_CHECK(cauchy_stress.size() == n_elements, "tension field: " << cauchy_stress.size()
                                                                     << " stresses for "
                                                                     << n_elements << " triangles");
  check_options(options);
  for (const auto& t : elements)
    for (int a : t)
      PLISSE_CHECK(a >= 0 && a < n_nodes, "tension field: triangle node " << a << " out of range");
  for (int e : surface)
    PLISSE_CHECK(e >= 0 && e < static_cast<int>(n_elements),
                 "tension field: surface triangle " << e << " out of range");
  const auto x = [&](int a) {
    const auto i = static_cast<std::size_t>(a);
    return Vec3d(nodes[i] + displacement[i]);
  };

  // Each triangle is its own column (T1s): its principal values in its deformed plane (T2-T3).
  std::vector<std::array<double, 2>> principal(n_elements);
  double largest = 0.0;
  for (std::size_t e = 0; e < n_elements; ++e) {
    const auto& t = elements[e];
    principal[e] = in_plane_principal(cauchy_stress[e], x(t[0]), x(t[1]), x(t[2]));
    largest = std::max(largest, std::abs(principal[e][0]));
  }
  TensionField out;
  out.tolerance = options.tolerance.value_or(options.relative_tolerance * largest);  // T4
  out.element_state.resize(n_elements);
  for (std::size_t e = 0; e < n_elements; ++e) {
    out.element_state[e] = classify(principal[e], out.tolerance);
    ++out.n_elements[static_cast<std::size_t>(out.element_state[e])];
  }
  out.triangle_state.reserve(surface.size());
  out.principal_stress.reserve(surface.size());
  for (int e : surface) {
    const MembraneState s = out.element_state[static_cast<std::size_t>(e)];
    out.triangle_state.push_back(s);
    out.principal_stress.push_back(principal[static_cast<std::size_t>(e)]);
    ++out.n_triangles[static_cast<std::size_t>(s)];
  }
  return out;
}

TensionField compute_tension_field(const Mesh& mesh, const std::vector<Vec3d>& displacement,
                                   const std::vector<Mat3d>& cauchy_stress,
                                   const std::vector<double>& J,
                                   const TensionFieldSettings& options,
                                   const std::string& outer_tag) {
  if (mesh.is_shell()) {
    const auto tag = mesh.surface_tags.find(outer_tag);
    PLISSE_CHECK(tag != mesh.surface_tags.end(),
                 "the mesh has no surface tag '" << outer_tag << "'");
    return compute_shell_tension_field(mesh.nodes, mesh.triangles, tag->second, displacement,
                                       cauchy_stress, options);
  }
  const auto triangles = tagged_triangles(mesh, outer_tag);
  const auto column = assign_columns(mesh.nodes, mesh.tets, triangles);
  return compute_tension_field(mesh.nodes, mesh.tets, triangles, column, displacement,
                               cauchy_stress, J, options);
}

}  // namespace plisse
