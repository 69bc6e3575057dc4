// Second-order generated meshes (`order: 2`): one shared node per edge, the corner mesh and tags of
// order 1, positive 10-node Jacobians, edge nodes on the true curved surfaces (sphere, offset
// spheroid), exact cut planes, and the volume of the quadratic sphere against 4/3 pi (Ro^3 - Ri^3).
#include "mesh/second_order.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <utility>

#include "core/error.hpp"
#include "element/quadrature.hpp"
#include "mesh/generate.hpp"
#include "mesh/quality.hpp"
#include "mesh/spheroid_surface.hpp"
#include "mesh/topology.hpp"
#include "mesh_test_util.hpp"

namespace plisse {
namespace {

/// Jacobian matrix d x / d xi of the 10-node map of tetrahedron `t` at barycentric coordinates
/// L = (1 - xi1 - xi2 - xi3, xi1, xi2, xi3). Shape functions: corner i L_i (2 L_i - 1), edge (i, j)
/// 4 L_i L_j; dL_0/dxi = (-1, -1, -1), dL_i/dxi_k = delta_ik.
Mat3d p2_jacobian(const Mesh& mesh, int t, const std::array<double, 4>& L) {
  const auto& corners = mesh.tets[static_cast<std::size_t>(t)];
  const auto& edges = mesh.tet_edge_nodes[static_cast<std::size_t>(t)];
  auto dL = [](int i) { return i == 0 ? Vec3d(-1.0, -1.0, -1.0) : Vec3d(Vec3d::Unit(i - 1)); };
  Mat3d J = Mat3d::Zero();
  for (int i = 0; i < 4; ++i) {
    const Vec3d grad = (4.0 * L[static_cast<std::size_t>(i)] - 1.0) * dL(i);
    J += mesh.nodes[static_cast<std::size_t>(corners[static_cast<std::size_t>(i)])] *
         grad.transpose();
  }
  for (std::size_t e = 0; e < 6; ++e) {
    const int i = kTetEdges[e][0], j = kTetEdges[e][1];
    const Vec3d grad =
        4.0 * (L[static_cast<std::size_t>(j)] * dL(i) + L[static_cast<std::size_t>(i)] * dL(j));
    J += mesh.nodes[static_cast<std::size_t>(edges[e])] * grad.transpose();
  }
  return J;
}

/// Volume of the 10-node geometry [mm^3]: each tetrahedron's |det J| integrated over the
/// reference tetrahedron (volume 1/6) by the degree-5 rule; det J is a cubic in xi, so exact.
double p2_volume(const Mesh& mesh) {
  double volume = 0.0;
  for (int t = 0; t < mesh.n_tets(); ++t)
    for (int q = 0; q < kTetQuadratureDegree5.n_points; ++q)
      volume += kTetQuadratureDegree5.weights[static_cast<std::size_t>(q)] / 6.0 *
                p2_jacobian(mesh, t, kTetQuadratureDegree5.points[static_cast<std::size_t>(q)])
                    .determinant();
  return volume;
}

using Edge = std::pair<int, int>;

Edge edge(int a, int b) { return {std::min(a, b), std::max(a, b)}; }

/// The edge nodes of `quadratic` by corner edge, after checking what every second-order generated
/// mesh must satisfy against its order-1 twin `linear`: same corner nodes (bit for bit),
/// tetrahedra, triangles and tags; one edge node per distinct edge, shared by all tetrahedra and
/// triangles on it, edge nodes numbered after the corners and each used; the 10-node Jacobian
/// positive at the four corners and the centroid of every tetrahedron; check_mesh clean.
std::map<Edge, int> expect_valid_second_order(const Mesh& linear, const Mesh& quadratic) {
  std::map<Edge, int> node_of;
  EXPECT_EQ(linear.order(), 1);
  EXPECT_EQ(quadratic.order(), 2);
  EXPECT_EQ(quadratic.tets, linear.tets);
  EXPECT_EQ(quadratic.triangles, linear.triangles);
  EXPECT_EQ(quadratic.surface_tags, linear.surface_tags);
  EXPECT_EQ(quadratic.volume_tags, linear.volume_tags);
  const int n = linear.n_nodes();
  EXPECT_GT(quadratic.n_nodes(), n);
  if (quadratic.n_nodes() <= n) return node_of;
  for (int i = 0; i < n; ++i)
    EXPECT_EQ(quadratic.nodes[static_cast<std::size_t>(i)],
              linear.nodes[static_cast<std::size_t>(i)])
        << "corner node " << i;
  EXPECT_EQ(quadratic.tet_edge_nodes.size(), quadratic.tets.size());
  EXPECT_EQ(quadratic.triangle_edge_nodes.size(), quadratic.triangles.size());

  int mismatches = 0;
  for (std::size_t t = 0; t < quadratic.tets.size(); ++t)
    for (std::size_t e = 0; e < 6; ++e) {
      const Edge key = edge(quadratic.tets[t][static_cast<std::size_t>(kTetEdges[e][0])],
                            quadratic.tets[t][static_cast<std::size_t>(kTetEdges[e][1])]);
      const int node = quadratic.tet_edge_nodes[t][e];
      const auto [it, inserted] = node_of.emplace(key, node);
      if (!inserted && it->second != node) ++mismatches;
    }
  EXPECT_EQ(mismatches, 0) << "tetrahedra sharing an edge with different edge nodes";
  // Distinct edges have distinct edge nodes, and the edge nodes are exactly n, n + 1, ...
  std::vector<int> seen(static_cast<std::size_t>(quadratic.n_nodes()), 0);
  for (const auto& [key, node] : node_of) {
    EXPECT_GE(node, n);
    EXPECT_LT(node, quadratic.n_nodes());
    if (node >= 0 && node < quadratic.n_nodes()) ++seen[static_cast<std::size_t>(node)];
  }
  EXPECT_EQ(node_of.size(), static_cast<std::size_t>(quadratic.n_nodes() - n));
  for (int i = n; i < quadratic.n_nodes(); ++i)
    EXPECT_EQ(seen[static_cast<std::size_t>(i)], 1) << "edge node " << i;
  int triangle_mismatches = 0;
  for (std::size_t f = 0; f < quadratic.triangles.size(); ++f)
    for (std::size_t e = 0; e < 3; ++e) {
      const auto it =
          node_of.find(edge(quadratic.triangles[f][e], quadratic.triangles[f][(e + 1) % 3]));
      if (it == node_of.end() || it->second != quadratic.triangle_edge_nodes[f][e])
        ++triangle_mismatches;
    }
  EXPECT_EQ(triangle_mismatches, 0) << "triangle edge nodes differ from their tetrahedron's";

  // Positive 10-node Jacobian at the corners and the centroid.
  const std::array<std::array<double, 4>, 5> points = {
      {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}, {0.25, 0.25, 0.25, 0.25}}};
  int non_positive = 0;
  double smallest = 1e300;
  for (int t = 0; t < quadratic.n_tets(); ++t)
    for (const auto& L : points) {
      const double det = p2_jacobian(quadratic, t, L).determinant();
      smallest = std::min(smallest, det / (6.0 * tet_signed_volume(quadratic, t)));
      if (!(det > 0.0)) ++non_positive;
    }
  EXPECT_EQ(non_positive, 0);
  // det J relative to that of the straight tetrahedron (6 V): far from 0 on these meshes.
  EXPECT_GT(smallest, 0.2);

  const MeshReport report = check_mesh(quadratic);
  for (const auto& e : report.errors) ADD_FAILURE() << "check_mesh error: " << e;
  for (const auto& w : report.warnings) ADD_FAILURE() << "check_mesh warning: " << w;
  return node_of;
}

MeshGenerationSpec with_order(MeshGenerationSpec spec, int order) {
  spec.order = order;
  return spec;
}

TEST(SecondOrder, CubeAndSheetEdgeNodesAreExactMidpoints) {
  MeshGenerationSpec cube;
  cube.kind = "cube";
  cube.edge = 2.5;
  cube.divisions = 3;
  MeshGenerationSpec sheet;
  sheet.kind = "sheet";
  sheet.length = 6.0;
  sheet.width = 4.0;
  sheet.thickness = 0.3;
  sheet.layers = 2;
  sheet.element_size = 1.0;
  for (const auto& spec : {cube, sheet}) {
    const Mesh linear = generate_mesh(spec);
    const Mesh quadratic = generate_mesh(with_order(spec, 2));
    const auto node_of = expect_valid_second_order(linear, quadratic);
    for (const auto& [key, node] : node_of)
      EXPECT_EQ(quadratic.nodes[static_cast<std::size_t>(node)],
                Vec3d(0.5 * (linear.nodes[static_cast<std::size_t>(key.first)] +
                             linear.nodes[static_cast<std::size_t>(key.second)])));
    // Edges of the structured box: the grid lines along x, y and z, one diagonal per grid face
    // and one main diagonal per cell.
    const int nx = spec.kind == "cube" ? 3 : 6, ny = spec.kind == "cube" ? 3 : 4,
              nz = spec.kind == "cube" ? 3 : 2;
    const int lines =
        nx * (ny + 1) * (nz + 1) + ny * (nx + 1) * (nz + 1) + nz * (nx + 1) * (ny + 1);
    const int faces = nx * ny * (nz + 1) + nx * nz * (ny + 1) + ny * nz * (nx + 1);
    EXPECT_EQ(node_of.size(), static_cast<std::size_t>(lines + faces + nx * ny * nz)) << spec.kind;
    // The straight 10-node geometry tiles the box exactly.
    const double volume = spec.kind == "cube" ? 2.5 * 2.5 * 2.5 : 6.0 * 4.0 * 0.3;
    EXPECT_NEAR(p2_volume(quadratic), volume, 1e-12 * volume);
  }
}

class SecondOrderShell : public ::testing::TestWithParam<Symmetry> {};

TEST_P(SecondOrderShell, EdgeNodesOnTheSpheresAndCutPlanes) {
  MeshGenerationSpec spec;
  spec.kind = "spherical-shell";
  spec.inner_radius = 10.0;
  spec.thickness = 1.0;
  spec.layers = 2;
  spec.element_size = 2.5;
  spec.symmetry = GetParam();
  const Mesh linear = generate_mesh(spec);
  const Mesh quadratic = generate_mesh(with_order(spec, 2));
  const auto node_of = expect_valid_second_order(linear, quadratic);
  const int n_surface = linear.n_nodes() / (spec.layers + 1);
  ASSERT_EQ(n_surface * (spec.layers + 1), linear.n_nodes());
  const double R = spec.inner_radius, t = spec.thickness;
  int on_sphere = 0, through_wall = 0;
  for (const auto& [key, node] : node_of) {
    const Vec3d& x = quadratic.nodes[static_cast<std::size_t>(node)];
    const int j1 = key.first / n_surface, j2 = key.second / n_surface;
    if (j1 == j2) {
      // Within one layer sphere (inner, middle, outer): on that sphere.
      const double r = R + j1 * t / spec.layers;
      EXPECT_NEAR(x.norm(), r, 1e-12 * r) << "edge " << key.first << "-" << key.second;
      ++on_sphere;
    } else if (key.first % n_surface == key.second % n_surface) {
      // Along one ray through the wall: the straight midpoint.
      const Vec3d mid = 0.5 * (linear.nodes[static_cast<std::size_t>(key.first)] +
                               linear.nodes[static_cast<std::size_t>(key.second)]);
      EXPECT_NEAR((x - mid).norm(), 0.0, 1e-12 * R);
      ++through_wall;
    }
  }
  EXPECT_GT(on_sphere, 0);
  EXPECT_EQ(through_wall, n_surface * spec.layers);
  // Edge nodes of the triangles on a cut plane: that coordinate exactly 0.
  for (int axis = 0; axis < 3; ++axis) {
    const std::string name = std::string("sym_") + "xyz"[axis];
    if (!quadratic.has_surface(name)) continue;
    for (int f : quadratic.surface_tags.at(name))
      for (int node : quadratic.triangle_edge_nodes[static_cast<std::size_t>(f)])
        EXPECT_EQ(quadratic.nodes[static_cast<std::size_t>(node)][axis], 0.0) << name;
  }
}

INSTANTIATE_TEST_SUITE_P(Symmetries, SecondOrderShell,
                         ::testing::Values(Symmetry::full, Symmetry::quarter, Symmetry::octant),
                         [](const auto& info) { return to_string(info.param); });

TEST(SecondOrder, ShellVolumeConvergesFasterThanLinear) {
  // Octant of a shell R = 10, t = 1 (2 layers) at element sizes h = 1 and 0.5, the effective size
  // ratio taken from the triangle counts, h1/h2 = sqrt(N2/N1) (Gmsh's sizes are only targets).
  // The linear mesh's flat facets lose a volume fraction of order (h/R)^2; the quadratic patches
  // interpolate the sphere to O(h^3) in position and their volume error falls as h^4.
  // Measured (relative volume errors): h = 1 (402 inner triangles): linear 3.48e-3, quadratic
  // 1.48e-6; h = 0.5 (1582): linear 8.80e-4, quadratic 9.47e-8; rates 2.0 and 4.0
  // (h = 0.25, 6017 triangles: 2.29e-4 and 6.43e-9, rates 2.0 and 4.0 again).
  MeshGenerationSpec spec;
  spec.kind = "spherical-shell";
  spec.inner_radius = 10.0;
  spec.thickness = 1.0;
  spec.layers = 2;
  spec.symmetry = Symmetry::octant;
  const double R = 10.0, Ro = 11.0;
  const double exact = 4.0 / 3.0 * std::numbers::pi * (Ro * Ro * Ro - R * R * R) / 8.0;
  std::array<double, 2> linear_error{}, quadratic_error{}, n_triangles{};
  const std::array<double, 2> sizes = {1.0, 0.5};
  for (std::size_t i = 0; i < 2; ++i) {
    spec.element_size = sizes[i];
    const Mesh quadratic = generate_mesh(with_order(spec, 2));
    n_triangles[i] = static_cast<double>(quadratic.surface_tags.at("inner").size());
    linear_error[i] = std::abs(test::mesh_volume(quadratic) / exact - 1.0);
    quadratic_error[i] = std::abs(p2_volume(quadratic) / exact - 1.0);
    std::cout << "shell octant h = " << sizes[i] << " (" << n_triangles[i]
              << " inner triangles): relative volume error linear " << linear_error[i]
              << ", quadratic " << quadratic_error[i] << "\n";
  }
  const double size_ratio = std::sqrt(n_triangles[1] / n_triangles[0]);
  const double linear_rate = std::log(linear_error[0] / linear_error[1]) / std::log(size_ratio);
  const double quadratic_rate =
      std::log(quadratic_error[0] / quadratic_error[1]) / std::log(size_ratio);
  std::cout << "size ratio " << size_ratio << ", rates: linear " << linear_rate << ", quadratic "
            << quadratic_rate << "\n";
  EXPECT_NEAR(linear_rate, 2.0, 0.3);
  EXPECT_GT(quadratic_rate, 3.5);
  EXPECT_LT(quadratic_error[0], 1e-3 * linear_error[0]);
}

/// Signed distance of `x` from the spheroid x^2/a^2 + y^2/c^2 + z^2/a^2 = 1 (positive outside),
/// through the closest point: in the meridian plane of x, (rho, y) = (hypot(x, z), y), the foot
/// (a cos s, c sin s) solves (c^2 - a^2) sin s cos s + a rho sin s - c y cos s = 0 (the offset is
/// along the normal), found by Newton's method from the radial projection.
double spheroid_distance(const Vec3d& x, double a, double c) {
  const double rho = std::hypot(x.x(), x.z()), y = x.y();
  double s = std::atan2(y / c, rho / a);
  for (int it = 0; it < 50; ++it) {
    const double f =
        (c * c - a * a) * std::sin(s) * std::cos(s) + a * rho * std::sin(s) - c * y * std::cos(s);
    const double df =
        (c * c - a * a) * std::cos(2.0 * s) + a * rho * std::cos(s) + c * y * std::sin(s);
    const double step = f / df;
    s -= step;
    if (std::abs(step) < 1e-16) break;
  }
  const double d = std::hypot(rho - a * std::cos(s), y - c * std::sin(s));
  return rho * rho / (a * a) + y * y / (c * c) >= 1.0 ? d : -d;
}

class SecondOrderAirbag : public ::testing::TestWithParam<Symmetry> {};

TEST_P(SecondOrderAirbag, EdgeNodesOnTheOffsetSurfaces) {
  // Edge node of an edge in layer j: m + o_j n(m), m on the mid-surface and n(m) its normal. The
  // closest point of the mid-surface to it is m itself, since |o_j| <= t/2 is below the smallest
  // radius of curvature (c^2/a = 1.6 mm): its distance is o_j exactly, and the test measures it
  // independently by the closest-point iteration. Coordinates are of size a = 10 mm and computed
  // in a few operations, so round-off stays near 1e-15 a; tolerance 1e-12 a.
  MeshGenerationSpec spec;
  spec.kind = "airbag";
  spec.radius = 10.0;
  spec.height = 8.0;
  spec.thickness = 0.4;
  spec.layers = 2;
  spec.element_size = 1.0;
  spec.symmetry = GetParam();
  const double a = 10.0, c = 4.0, t = 0.4;
  const Mesh linear = generate_mesh(spec);
  const Mesh quadratic = generate_mesh(with_order(spec, 2));
  const auto node_of = expect_valid_second_order(linear, quadratic);
  const int n_surface = linear.n_nodes() / (spec.layers + 1);
  ASSERT_EQ(n_surface * (spec.layers + 1), linear.n_nodes());
  int checked = 0, through_wall = 0;
  double worst = 0.0;
  for (const auto& [key, node] : node_of) {
    const Vec3d& x = quadratic.nodes[static_cast<std::size_t>(node)];
    const int j1 = key.first / n_surface, j2 = key.second / n_surface;
    if (j1 == j2) {
      const double offset = -0.5 * t + j1 * t / spec.layers;  // -t/2 (inner), 0, +t/2 (outer)
      const double error = std::abs(spheroid_distance(x, a, c) - offset);
      worst = std::max(worst, error);
      EXPECT_LT(error, 1e-12 * a) << "edge " << key.first << "-" << key.second;
      ++checked;
    } else if (key.first % n_surface == key.second % n_surface) {
      const Vec3d mid = 0.5 * (linear.nodes[static_cast<std::size_t>(key.first)] +
                               linear.nodes[static_cast<std::size_t>(key.second)]);
      EXPECT_NEAR((x - mid).norm(), 0.0, 1e-12 * a);
      ++through_wall;
    }
  }
  std::cout << "airbag " << to_string(spec.symmetry) << ": " << checked
            << " in-layer edge nodes, largest distance error " << worst << " mm\n";
  EXPECT_GT(checked, 0);
  EXPECT_EQ(through_wall, n_surface * spec.layers);
  for (int axis = 0; axis < 3; ++axis) {
    const std::string name = std::string("sym_") + "xyz"[axis];
    if (!quadratic.has_surface(name)) continue;
    for (int f : quadratic.surface_tags.at(name))
      for (int node : quadratic.triangle_edge_nodes[static_cast<std::size_t>(f)])
        EXPECT_EQ(quadratic.nodes[static_cast<std::size_t>(node)][axis], 0.0) << name;
  }
  // The quadratic wall volume against Steiner's t A + pi t^3 / 3 (times the kept fraction): far
  // closer than the linear mesh's chordal error (measured: 9.8e-6 against 8.3e-3).
  const double exact = kept_fraction(spec.symmetry) *
                       (t * spheroid_area(a, c) + t * t * t / 12.0 * 4.0 * std::numbers::pi);
  const double linear_error = std::abs(test::mesh_volume(linear) / exact - 1.0);
  const double quadratic_error = std::abs(p2_volume(quadratic) / exact - 1.0);
  std::cout << "airbag " << to_string(spec.symmetry) << ": relative volume error linear "
            << linear_error << ", quadratic " << quadratic_error << "\n";
  EXPECT_LT(quadratic_error, 0.01 * linear_error);
}

INSTANTIATE_TEST_SUITE_P(Symmetries, SecondOrderAirbag,
                         ::testing::Values(Symmetry::octant, Symmetry::half),
                         [](const auto& info) { return to_string(info.param); });

TEST(SecondOrder, AddEdgeNodesRefusesSecondOrderAndForeignTriangles) {
  Mesh mesh;
  mesh.nodes = {Vec3d(0, 0, 0), Vec3d(1, 0, 0), Vec3d(0, 1, 0), Vec3d(0, 0, 1), Vec3d(1, 1, 1)};
  mesh.tets = {{0, 1, 2, 3}};
  mesh.triangles = {{0, 2, 1}};
  add_straight_edge_nodes(mesh);
  EXPECT_EQ(mesh.n_nodes(), 5 + 6);
  // Edge nodes in increasing (a, b): 01, 02, 03, 12, 13, 23 -> nodes 5..10; Gmsh order of the tet
  // (01, 12, 20, 30, 32, 31) and of the triangle (02, 21, 10).
  EXPECT_EQ(mesh.tet_edge_nodes[0], (std::array<int, 6>{5, 8, 6, 7, 10, 9}));
  EXPECT_EQ(mesh.triangle_edge_nodes[0], (std::array<int, 3>{6, 8, 5}));
  EXPECT_EQ(mesh.nodes[9], Vec3d(0.5, 0.0, 0.5));
  EXPECT_THROW(add_straight_edge_nodes(mesh), Error);
  Mesh foreign;
  foreign.nodes = mesh.nodes;
  foreign.nodes.resize(5);
  foreign.tets = {{0, 1, 2, 3}};
  foreign.triangles = {{1, 2, 4}};
  EXPECT_THROW(add_straight_edge_nodes(foreign), Error);
}

}  // namespace
}  // namespace plisse
