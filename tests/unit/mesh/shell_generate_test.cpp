// Generated shell mid-surfaces (generate_shell_surface): nodes on the sphere, spheroid, cylinder
// or plane to round-off, every normal outward (or +z), the total area against the closed form
// with its O(h^2) faceting error, edge tags in their planes covering the surface's boundary
// exactly, surface tags and face sides, and the refused options.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <iostream>
#include <map>
#include <numbers>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "mesh/generate.hpp"
#include "mesh/shell_surface.hpp"
#include "mesh/spheroid_surface.hpp"
#include "mesh_test_util.hpp"

namespace plisse {
namespace {

Vec3d area_vector(const Mesh& mesh, std::size_t t) {
  const auto& n = mesh.triangles[t];
  const Vec3d& x0 = mesh.nodes[static_cast<std::size_t>(n[0])];
  return 0.5 * (mesh.nodes[static_cast<std::size_t>(n[1])] - x0)
                   .cross(mesh.nodes[static_cast<std::size_t>(n[2])] - x0);
}

double total_area(const Mesh& mesh) {
  double a = 0.0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) a += area_vector(mesh, t).norm();
  return a;
}

Vec3d centroid(const Mesh& mesh, std::size_t t) {
  Vec3d c = Vec3d::Zero();
  for (int n : mesh.triangles[t]) c += mesh.nodes[static_cast<std::size_t>(n)] / 3.0;
  return c;
}

std::pair<int, int> undirected(int a, int b) { return {std::min(a, b), std::max(a, b)}; }

/// The sides of exactly one triangle.
std::set<std::pair<int, int>> boundary_sides(const Mesh& mesh) {
  std::map<std::pair<int, int>, int> uses;
  for (const auto& tri : mesh.triangles)
    for (std::size_t i = 0; i < 3; ++i) ++uses[undirected(tri[i], tri[(i + 1) % 3])];
  std::set<std::pair<int, int>> out;
  for (const auto& [side, n] : uses)
    if (n == 1) out.insert(side);
  return out;
}

double edge_length(const Mesh& mesh, int e) {
  const auto& edge = mesh.edges[static_cast<std::size_t>(e)];
  return (mesh.nodes[static_cast<std::size_t>(edge[0])] -
          mesh.nodes[static_cast<std::size_t>(edge[1])])
      .norm();
}

/// What every generated shell satisfies: make_shell_surface ran (thickness, neighbours), the
/// surface tags `faces` list every triangle with their face sides, the edge tags are `edge_tags`
/// and lie in their planes (coordinate exactly the plane's value), and the edges of the planes
/// cover the boundary of the surface exactly, each boundary side once.
void expect_shell_conventions(const Mesh& mesh, double thickness,
                              const std::pair<std::string, std::string>& faces,
                              const std::map<std::string, std::pair<int, double>>& edge_tags) {
  ASSERT_TRUE(mesh.is_shell());
  EXPECT_TRUE(mesh.tets.empty());
  EXPECT_EQ(mesh.order(), 1);
  ASSERT_EQ(mesh.shell_thickness.size(), mesh.nodes.size());
  for (double t : mesh.shell_thickness) EXPECT_EQ(t, thickness);
  ASSERT_EQ(mesh.triangle_neighbours.size(), mesh.triangles.size());
  std::vector<int> all(mesh.triangles.size());
  for (std::size_t t = 0; t < all.size(); ++t) all[t] = static_cast<int>(t);
  EXPECT_EQ(mesh.surface_tags.size(), 2u);
  EXPECT_EQ(mesh.surface_tags.at(faces.first), all);
  EXPECT_EQ(mesh.surface_tags.at(faces.second), all);
  EXPECT_EQ(mesh.shell_face_side,
            (std::map<std::string, int>{{faces.first, -1}, {faces.second, 1}}));

  std::set<std::string> names;
  for (const auto& [name, edges] : mesh.edge_tags) names.insert(name);
  std::set<std::string> expected_names;
  for (const auto& [name, plane] : edge_tags) expected_names.insert(name);
  EXPECT_EQ(names, expected_names);
  // Each tag's edges in its plane; the union of the tags is the boundary, and the neighbours
  // that make_shell_surface left missing (-1) are those sides.
  std::set<std::pair<int, int>> tagged;
  for (const auto& [name, plane] : edge_tags) {
    const auto& edges = mesh.edge_tags.at(name);
    EXPECT_FALSE(edges.empty()) << name;
    for (int e : edges) {
      const auto& edge = mesh.edges[static_cast<std::size_t>(e)];
      for (int n : edge)
        EXPECT_EQ(mesh.nodes[static_cast<std::size_t>(n)][plane.first], plane.second) << name;
      tagged.insert(undirected(edge[0], edge[1]));
    }
  }
  const auto boundary = boundary_sides(mesh);
  EXPECT_EQ(tagged, boundary);
  EXPECT_EQ(mesh.edges.size(), boundary.size());  // every edge once
  std::size_t missing = 0;
  for (const auto& sides : mesh.triangle_neighbours)
    for (int n : sides) missing += n < 0 ? 1 : 0;
  EXPECT_EQ(missing, boundary.size());
}

/// The edge tags of a spheroid's cut planes for `symmetry`.
std::map<std::string, std::pair<int, double>> cut_edge_tags(Symmetry symmetry) {
  std::map<std::string, std::pair<int, double>> tags;
  const auto planes = cut_planes(symmetry);
  if (planes[0]) tags["sym_x"] = {0, 0.0};
  if (planes[1]) tags["sym_y"] = {1, 0.0};
  if (planes[2]) tags["sym_z"] = {2, 0.0};
  return tags;
}

/// The sheet 10 x 4 mm of 1 mm cells, 0.3 mm thick, as a shell's mid-surface.
MeshGenerationSpec small_sheet() {
  MeshGenerationSpec spec;
  spec.kind = "sheet";
  spec.length = 10.0;
  spec.width = 4.0;
  spec.thickness = 0.3;
  spec.element_size = 1.0;
  spec.layers = 0;  // ignored by a shell (out of the solid's range [1, 64])
  return spec;
}

TEST(GenerateShellSurface, SheetIsTheStructuredMidPlane) {
  const MeshGenerationSpec spec = small_sheet();
  const Mesh mesh = generate_shell_surface(spec);
  const int nx = 10, ny = 4;
  EXPECT_EQ(mesh.n_nodes(), (nx + 1) * (ny + 1));
  EXPECT_EQ(mesh.triangles.size(), static_cast<std::size_t>(2 * nx * ny));
  EXPECT_EQ(estimate_n_shell_triangles(spec), 2.0 * nx * ny);
  for (const auto& x : mesh.nodes) EXPECT_EQ(x.z(), 0.15);  // z = thickness / 2 exactly
  // Normals +z; the triangles tile the rectangle.
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Vec3d a = area_vector(mesh, t);
    EXPECT_GT(a.z(), 0.0);
    EXPECT_EQ(a.x(), 0.0);
    EXPECT_EQ(a.y(), 0.0);
  }
  EXPECT_NEAR(total_area(mesh), 40.0, 1e-12 * 40.0);
  expect_shell_conventions(mesh, 0.3, {"bottom", "top"},
                           {{"left", {0, 0.0}},
                            {"sym_x", {0, 0.0}},
                            {"right", {0, 10.0}},
                            {"front", {1, 0.0}},
                            {"sym_y", {1, 0.0}},
                            {"back", {1, 4.0}}});
  EXPECT_EQ(mesh.edge_tags.at("left").size(), static_cast<std::size_t>(ny));
  EXPECT_EQ(mesh.edge_tags.at("front").size(), static_cast<std::size_t>(nx));
  EXPECT_EQ(mesh.edge_tags.at("sym_x"), mesh.edge_tags.at("left"));
  EXPECT_EQ(mesh.edge_tags.at("sym_y"), mesh.edge_tags.at("front"));
  // The nodes are in-plane positions of the solid sheet's nodes (points of a case keep theirs).
  MeshGenerationSpec solid = spec;
  solid.layers = 2;
  std::set<std::pair<double, double>> in_plane;
  for (const auto& x : generate_mesh(solid).nodes) in_plane.emplace(x.x(), x.y());
  for (const auto& x : mesh.nodes) EXPECT_TRUE(in_plane.count({x.x(), x.y()})) << x.transpose();
  EXPECT_EQ(in_plane.size(), mesh.nodes.size());
}

class SphereShellSurface : public ::testing::TestWithParam<Symmetry> {};

TEST_P(SphereShellSurface, OnTheMidSphereOutwardWithCutEdges) {
  MeshGenerationSpec spec;
  spec.kind = "spherical-shell";
  spec.inner_radius = 10.0;
  spec.thickness = 1.0;
  spec.element_size = 1.0;
  spec.symmetry = GetParam();
  const Mesh mesh = generate_shell_surface(spec);
  const double R = 10.5;  // inner_radius + thickness / 2
  for (const auto& x : mesh.nodes) EXPECT_NEAR(x.norm(), R, 1e-13 * R);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    EXPECT_GT(area_vector(mesh, t).dot(centroid(mesh, t)), 0.0) << "triangle " << t;
  // Faceted: inscribed flat triangles, smaller than the sphere by O((h/R)^2).
  const double fraction = kept_fraction(spec.symmetry);
  const double exact = fraction * 4.0 * std::numbers::pi * R * R;
  const double deficit = 1.0 - total_area(mesh) / exact;
  EXPECT_GT(deficit, 0.0);
  EXPECT_LT(deficit, 0.5 * std::pow(spec.element_size / R, 2));
  const auto tags = cut_edge_tags(spec.symmetry);
  expect_shell_conventions(mesh, 1.0, {"inner", "outer"}, tags);
  // Each cut is an arc of the great circle in its plane, 4 pi R times the kept fraction (a
  // quarter of the circle for the octant); the chords fall short by O((h/R)^2).
  for (const auto& [name, plane] : tags) {
    double length = 0.0;
    for (int e : mesh.edge_tags.at(name)) length += edge_length(mesh, e);
    const double arc = 4.0 * std::numbers::pi * R * fraction;
    EXPECT_GT(length, arc * (1.0 - 0.1 * std::pow(spec.element_size / R, 2))) << name;
    EXPECT_LT(length, arc) << name;
  }
  for (const auto& x : mesh.nodes)
    for (int axis = 0; axis < 3; ++axis)
      if (cut_planes(spec.symmetry)[static_cast<std::size_t>(axis)]) {
        EXPECT_GE(x[axis], 0.0);
      }
  const double estimate =
      estimate_n_shell_triangles(spec) / static_cast<double>(mesh.triangles.size());
  EXPECT_GT(estimate, 0.5);
  EXPECT_LT(estimate, 2.0);
  std::cout << "sphere " << to_string(spec.symmetry) << ": " << mesh.triangles.size()
            << " triangles, area deficit " << deficit << ", estimate ratio " << estimate << "\n";
}

INSTANTIATE_TEST_SUITE_P(AllSymmetries, SphereShellSurface,
                         ::testing::Values(Symmetry::full, Symmetry::half, Symmetry::quarter,
                                           Symmetry::octant),
                         [](const auto& info) { return to_string(info.param); });

TEST(GenerateShellSurface, SphereAreaErrorFallsAsHSquared) {
  MeshGenerationSpec spec;
  spec.kind = "spherical-shell";
  spec.inner_radius = 9.5;
  spec.thickness = 1.0;  // mid radius 10
  spec.symmetry = Symmetry::octant;
  const double exact = 4.0 * std::numbers::pi * 100.0 / 8.0;
  std::vector<double> deficit;
  for (double h : {1.0, 0.5, 0.25}) {
    spec.element_size = h;
    deficit.push_back(1.0 - total_area(generate_shell_surface(spec)) / exact);
    std::cout << "octant of R = 10, h = " << h << ": area deficit " << deficit.back() << "\n";
  }
  for (std::size_t i = 1; i < deficit.size(); ++i) {
    const double ratio = deficit[i - 1] / deficit[i];
    std::cout << "ratio " << ratio << "\n";
    EXPECT_GT(ratio, 3.0);
    EXPECT_LT(ratio, 5.0);
  }
}

TEST(GenerateShellSurface, PoleRefinementMakesSmallTrianglesAtThePole) {
  MeshGenerationSpec spec;
  spec.kind = "spherical-shell";
  spec.inner_radius = 19.5;
  spec.thickness = 1.0;  // mid radius 20
  spec.element_size = 4.0;
  spec.symmetry = Symmetry::octant;
  const Mesh plain = generate_shell_surface(spec);
  spec.pole_element_size = 0.5;
  spec.pole_radius = 2.0;
  const Mesh refined = generate_shell_surface(spec);
  EXPECT_GT(refined.triangles.size(), plain.triangles.size());
  const Vec3d pole(0.0, 20.0, 0.0);
  double longest = 0.0;
  for (std::size_t t = 0; t < refined.triangles.size(); ++t) {
    if ((centroid(refined, t) - pole).norm() > 2.0) continue;
    const auto& n = refined.triangles[t];
    for (std::size_t i = 0; i < 3; ++i)
      longest = std::max(longest, (refined.nodes[static_cast<std::size_t>(n[i])] -
                                   refined.nodes[static_cast<std::size_t>(n[(i + 1) % 3])])
                                      .norm());
  }
  EXPECT_GT(longest, 0.0);
  // Within pole_radius the size is 0.5; a triangle there reaches out to where it grows by a
  // fifth of the distance. Without the refinement the edges there are about 4.
  EXPECT_LT(longest, 2.0 * 0.5) << "longest edge of a triangle within pole_radius of the pole";
  std::cout << "pole: " << plain.triangles.size() << " -> " << refined.triangles.size()
            << " triangles, longest edge near the pole " << longest << "\n";
  for (const auto& x : refined.nodes) EXPECT_NEAR(x.norm(), 20.0, 1e-13 * 20.0);
  expect_shell_conventions(refined, 1.0, {"inner", "outer"}, cut_edge_tags(Symmetry::octant));
}

class AirbagShellSurface : public ::testing::TestWithParam<Symmetry> {};

TEST_P(AirbagShellSurface, OnTheMidSpheroidOutward) {
  MeshGenerationSpec spec;
  spec.kind = "airbag";
  spec.radius = 20.0;
  spec.height = 10.0;
  spec.thickness = 0.5;
  spec.element_size = 1.0;
  spec.symmetry = GetParam();
  const Mesh mesh = generate_shell_surface(spec);
  const double a = 20.0, c = 5.0;
  const auto level = [&](const Vec3d& x) {
    return x.x() * x.x() / (a * a) + x.y() * x.y() / (c * c) + x.z() * x.z() / (a * a);
  };
  for (const auto& x : mesh.nodes) EXPECT_NEAR(level(x), 1.0, 1e-13);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Vec3d m = centroid(mesh, t);
    const Vec3d gradient(m.x() / (a * a), m.y() / (c * c), m.z() / (a * a));
    EXPECT_GT(area_vector(mesh, t).dot(gradient), 0.0) << "triangle " << t;
  }
  const double exact = kept_fraction(spec.symmetry) * spheroid_area(a, c);
  const double deficit = 1.0 - total_area(mesh) / exact;
  EXPECT_GT(deficit, 0.0);
  EXPECT_LT(deficit, 0.01);
  expect_shell_conventions(mesh, 0.5, {"inner", "outer"}, cut_edge_tags(spec.symmetry));
  std::cout << "airbag " << to_string(spec.symmetry) << ": " << mesh.triangles.size()
            << " triangles, area deficit " << deficit << "\n";
}

INSTANTIATE_TEST_SUITE_P(AllSymmetries, AirbagShellSurface,
                         ::testing::Values(Symmetry::full, Symmetry::half, Symmetry::quarter,
                                           Symmetry::octant),
                         [](const auto& info) { return to_string(info.param); });

class TubeShellSurface : public ::testing::TestWithParam<Symmetry> {};

TEST_P(TubeShellSurface, OnTheCylinderOutwardWithEndAndCutEdges) {
  MeshGenerationSpec spec;
  spec.kind = "tube";
  spec.radius = 10.0;
  spec.length = 20.0;
  spec.thickness = 0.5;
  spec.element_size = 1.0;
  spec.symmetry = GetParam();
  const bool half = spec.symmetry == Symmetry::half;
  const Mesh mesh = generate_shell_surface(spec);
  const int nx = 20, na = half ? 31 : 62;  // round(pi 10 / 1) = 31 on the half tube
  EXPECT_EQ(mesh.n_nodes(), (nx + 1) * (half ? na + 1 : na));
  EXPECT_EQ(mesh.triangles.size(), static_cast<std::size_t>(2 * nx * na));
  EXPECT_EQ(estimate_n_shell_triangles(spec), 2.0 * nx * na);
  for (const auto& x : mesh.nodes) EXPECT_NEAR(std::hypot(x.y(), x.z()), 10.0, 1e-14 * 10.0);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Vec3d m = centroid(mesh, t);
    EXPECT_GT(area_vector(mesh, t).dot(Vec3d(0.0, m.y(), m.z())), 0.0) << "triangle " << t;
  }
  // The cells are flat rectangles of chord 2 R sin(dphi / 2): the area is exactly the
  // polygonal prism's, short of 2 pi R L (times the kept half) by about (dphi)^2 / 24.
  const double dphi = (half ? 1.0 : 2.0) * std::numbers::pi / na;
  const double polygonal = 20.0 * na * 2.0 * 10.0 * std::sin(0.5 * dphi);
  EXPECT_NEAR(total_area(mesh), polygonal, 1e-12 * polygonal);
  EXPECT_NEAR(1.0 - polygonal / ((half ? 1.0 : 2.0) * std::numbers::pi * 10.0 * 20.0),
              dphi * dphi / 24.0, 1e-3 * dphi * dphi);
  std::map<std::string, std::pair<int, double>> tags = {{"left", {0, 0.0}}, {"right", {0, 20.0}}};
  if (half) tags["sym_z"] = {2, 0.0};
  expect_shell_conventions(mesh, 0.5, {"inner", "outer"}, tags);
  EXPECT_EQ(mesh.edge_tags.at("left").size(), static_cast<std::size_t>(na));
  EXPECT_EQ(mesh.edge_tags.at("right").size(), static_cast<std::size_t>(na));
  if (half) {
    EXPECT_EQ(mesh.edge_tags.at("sym_z").size(), static_cast<std::size_t>(2 * nx));
  }
  // The nodes are those of the solid tube's layer of radius R (the middle one of two layers:
  // 9.75 + 0.5 / 2 is exactly 10).
  MeshGenerationSpec solid = spec;
  solid.layers = 2;
  solid.order = 1;
  std::set<std::array<double, 3>> solid_nodes;
  for (const auto& x : generate_mesh(solid).nodes) solid_nodes.insert({x.x(), x.y(), x.z()});
  for (const auto& x : mesh.nodes)
    EXPECT_TRUE(solid_nodes.count({x.x(), x.y(), x.z()})) << x.transpose();
}

INSTANTIATE_TEST_SUITE_P(FullAndHalf, TubeShellSurface,
                         ::testing::Values(Symmetry::full, Symmetry::half),
                         [](const auto& info) { return to_string(info.param); });

std::string refusal(const MeshGenerationSpec& spec, std::string& key) {
  try {
    generate_shell_surface(spec);
  } catch (const InputError& e) {
    key = e.place().key;
    return e.rule();
  }
  return "";
}

class DiscShellSurface : public ::testing::TestWithParam<Symmetry> {};

// The flat panel of an airbag: every node in the plane y = 0, every triangle facing +y, the rim's
// nodes on the circle to round-off, the area of the inscribed polygon short of the disc's (kept
// part of pi R^2) by the O(h^2) of its chords, the rim's edges covering the kept arc.
TEST_P(DiscShellSurface, FlatFacingUpWithItsRimOnTheCircle) {
  MeshGenerationSpec spec;
  spec.kind = "disc";
  spec.radius = 30.0;
  spec.thickness = 0.2;
  spec.element_size = 2.0;
  spec.symmetry = GetParam();
  const Mesh mesh = generate_shell_surface(spec);
  for (const auto& x : mesh.nodes) {
    EXPECT_EQ(x.y(), 0.0);
    EXPECT_LE(std::hypot(x.x(), x.z()), 30.0 * (1.0 + 1e-15));
  }
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    EXPECT_GT(area_vector(mesh, t).y(), 0.0) << "triangle " << t;
  const double exact = kept_fraction(spec.symmetry) * std::numbers::pi * 30.0 * 30.0;
  const double deficit = 1.0 - total_area(mesh) / exact;
  EXPECT_GT(deficit, 0.0);
  EXPECT_LT(deficit, 2e-3);  // a chord of 2 on radius 30: (h/R)^2 / 12 of the area near the rim
  auto tags = cut_edge_tags(spec.symmetry);
  tags["rim"] = {1, 0.0};  // in the panel's plane
  expect_shell_conventions(mesh, 0.2, {"inner", "outer"}, tags);
  double rim = 0.0;
  for (int e : mesh.edge_tags.at("rim")) {
    for (int n : mesh.edges[static_cast<std::size_t>(e)]) {
      const Vec3d& x = mesh.nodes[static_cast<std::size_t>(n)];
      EXPECT_NEAR(std::hypot(x.x(), x.z()), 30.0, 1e-12 * 30.0);
    }
    rim += edge_length(mesh, e);
  }
  const double arc = kept_fraction(spec.symmetry) * 2.0 * std::numbers::pi * 30.0;
  EXPECT_GT(rim, arc * (1.0 - 1e-3));
  EXPECT_LT(rim, arc);
  const double estimate = estimate_n_shell_triangles(spec);
  EXPECT_NEAR(static_cast<double>(mesh.triangles.size()) / estimate, 1.0, 0.3);
  std::cout << "disc " << to_string(spec.symmetry) << ": " << mesh.triangles.size()
            << " triangles (estimate " << estimate << "), area deficit " << deficit << "\n";
}

INSTANTIATE_TEST_SUITE_P(Symmetries, DiscShellSurface,
                         ::testing::Values(Symmetry::full, Symmetry::half, Symmetry::quarter),
                         [](const auto& info) { return to_string(info.param); });

TEST(GenerateShellSurface, RimRefinementMakesSmallTrianglesAlongTheRim) {
  MeshGenerationSpec spec;
  spec.kind = "disc";
  spec.radius = 100.0;
  spec.thickness = 0.2;
  spec.element_size = 10.0;
  spec.symmetry = Symmetry::quarter;
  const Mesh plain = generate_shell_surface(spec);
  spec.rim_element_size = 2.0;
  spec.rim_width = 5.0;
  const Mesh refined = generate_shell_surface(spec);
  double longest_rim = 0.0;
  for (int e : refined.edge_tags.at("rim"))
    longest_rim = std::max(longest_rim, edge_length(refined, e));
  EXPECT_LT(longest_rim, 1.2 * 2.0) << "the rim's edges are rim_element_size";
  double longest_centre = 0.0;  // the middle keeps element_size
  for (std::size_t t = 0; t < refined.triangles.size(); ++t) {
    if (centroid(refined, t).norm() > 30.0) continue;
    const auto& n = refined.triangles[t];
    for (std::size_t i = 0; i < 3; ++i)
      longest_centre =
          std::max(longest_centre, (refined.nodes[static_cast<std::size_t>(n[i])] -
                                    refined.nodes[static_cast<std::size_t>(n[(i + 1) % 3])])
                                       .norm());
  }
  EXPECT_GT(longest_centre, 0.7 * 10.0);
  EXPECT_GT(refined.triangles.size(), plain.triangles.size());
  EXPECT_NEAR(static_cast<double>(refined.triangles.size()) / estimate_n_shell_triangles(spec), 1.0,
              0.3);
  std::cout << "rim: " << plain.triangles.size() << " -> " << refined.triangles.size()
            << " triangles, longest rim edge " << longest_rim << "\n";
}

// The node order is the order of every sum of the assembly, so it must not change between
// processes: Gmsh lists a surface's boundary nodes in an order that did (the quarter disc's three
// corners came last, in different orders, in two runs of one case). The generator takes them by
// increasing Gmsh tag, which puts the corner points, meshed first, first: the centre, then
// (r, 0, 0) and (0, 0, r). Generating the same disc again gives the same nodes and triangles.
TEST(GenerateShellSurface, TheDiscsNodesComeInGmshsTagOrderEveryTime) {
  MeshGenerationSpec spec;
  spec.kind = "disc";
  spec.radius = 350.0;
  spec.thickness = 0.35;
  spec.element_size = 40.0;
  spec.rim_element_size = 20.0;
  spec.rim_width = 40.0;
  spec.symmetry = Symmetry::quarter;
  const Mesh mesh = generate_shell_surface(spec);
  ASSERT_GE(mesh.nodes.size(), 3u);
  EXPECT_LT(mesh.nodes[0].norm(), 1e-9);
  EXPECT_LT((mesh.nodes[1] - Vec3d(350.0, 0.0, 0.0)).norm(), 1e-9);
  EXPECT_LT((mesh.nodes[2] - Vec3d(0.0, 0.0, 350.0)).norm(), 1e-9);
  for (int k = 0; k < 3; ++k) {
    const Mesh again = generate_shell_surface(spec);
    EXPECT_EQ(again.nodes, mesh.nodes);
    EXPECT_EQ(again.triangles, mesh.triangles);
  }
}

TEST(GenerateShellSurface, TheDiscIsAShellOnlyAndRefusesItsBadOptions) {
  std::string key;
  MeshGenerationSpec spec;
  spec.kind = "disc";
  spec.radius = 50.0;
  spec.element_size = 5.0;
  try {
    generate_mesh(spec);
    ADD_FAILURE() << "a solid disc was generated";
  } catch (const InputError& e) {
    EXPECT_NE(e.rule().find("shell's mid-surface only"), std::string::npos) << e.rule();
    EXPECT_EQ(e.place().key, "mesh.generate");
  }
  spec.symmetry = Symmetry::octant;
  EXPECT_NE(refusal(spec, key).find("not octant"), std::string::npos);
  EXPECT_EQ(key, "mesh.symmetry");
  spec.symmetry = Symmetry::quarter;
  spec.rim_width = 5.0;
  EXPECT_NE(refusal(spec, key).find("needs rim_element_size > 0"), std::string::npos);
  EXPECT_EQ(key, "mesh.rim_width");
  spec.rim_element_size = 6.0;
  EXPECT_NE(refusal(spec, key).find("must be <= element_size = 5 mm"), std::string::npos);
  EXPECT_EQ(key, "mesh.rim_element_size");
  spec.rim_element_size = 1.0;
  spec.rim_width = 60.0;
  EXPECT_NE(refusal(spec, key).find("must be <= radius = 50 mm"), std::string::npos);
  EXPECT_EQ(key, "mesh.rim_width");
  spec.rim_width = 5.0;
  spec.element_size = 60.0;
  spec.rim_element_size = 1.0;
  EXPECT_NE(refusal(spec, key).find("must be <= radius = 50 mm"), std::string::npos);
  EXPECT_EQ(key, "mesh.element_size");
}

TEST(GenerateShellSurface, RefusesTheCubeSecondOrderAndTooManyTriangles) {
  std::string key;
  MeshGenerationSpec spec;
  spec.kind = "cube";
  EXPECT_NE(refusal(spec, key).find("the cube is a solid and has no mid-surface"),
            std::string::npos);
  EXPECT_EQ(key, "mesh.generate");
  spec.kind = "spherical-shell";
  spec.order = 2;
  EXPECT_NE(refusal(spec, key).find("order must be 1 (got 2)"), std::string::npos);
  EXPECT_EQ(key, "mesh.order");
  spec.order = 1;
  spec.kind = "sheet";
  spec.length = spec.width = 1e4;
  spec.element_size = 1.0;  // 2e8 triangles
  EXPECT_NE(refusal(spec, key).find("about 2e+08 triangles, more than the limit of 2e+07"),
            std::string::npos)
      << refusal(spec, key);
  EXPECT_EQ(key, "mesh.element_size");
  // The solid's rules between options hold for its mid-surface too.
  spec = MeshGenerationSpec{};
  spec.kind = "airbag";
  spec.thickness = 5.0;  // radius 50, height 20: must be < 4
  EXPECT_NE(refusal(spec, key).find("must be < 2 (height/2)^2 / radius = 4 mm"), std::string::npos);
  EXPECT_EQ(key, "mesh.thickness");
}

}  // namespace
// A shell glued to a rigid part (clamp_to_rigid): the sheet 10 x 4 mm of 1 mm cells, its
// triangles left of x = 3 rigid. The 4 sides on the line x = 3 (one per row of cells) are cut
// out of both sides' patches and clamped on the deformable side: the half turn about the
// sheet's normal z through each side's midpoint, diag(-1, -1, 1). Done once: a second call finds
// no side between the two left.
TEST(GenerateShellSurface, ARigidPartClampsTheSidesItShares) {
  Mesh mesh = generate_shell_surface(small_sheet());
  std::vector<char> rigid(mesh.triangles.size(), 0);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    double x = 0.0;
    for (int v : mesh.triangles[t]) x += mesh.nodes[static_cast<std::size_t>(v)].x() / 3.0;
    rigid[t] = x < 3.0 ? 1 : 0;
  }
  const std::size_t mirrors_before = mesh.side_mirrors.size();
  EXPECT_EQ(clamp_to_rigid(mesh, rigid), 4);
  EXPECT_EQ(mesh.side_mirrors.size(), mirrors_before + 4);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int i = 0; i < 3; ++i) {
      const int a = mesh.triangle_adjacent[t][static_cast<std::size_t>(i)];
      if (a >= 0)
        EXPECT_EQ(rigid[t], rigid[static_cast<std::size_t>(a)]) << "triangle " << t;
      else
        EXPECT_EQ(mesh.triangle_neighbours[t][static_cast<std::size_t>(i)], -1);
    }
  int on_the_line = 0;
  for (const auto& [side, mirror] : mesh.side_mirrors) {
    if (mesh.nodes[static_cast<std::size_t>(side.first)].x() != 3.0 ||
        mesh.nodes[static_cast<std::size_t>(side.second)].x() != 3.0)
      continue;
    ++on_the_line;
    EXPECT_EQ(mirror.point.x(), 3.0);
    EXPECT_TRUE(mirror.map.isApprox(Vec3d(-1.0, -1.0, 1.0).asDiagonal().toDenseMatrix(), 1e-15));
  }
  EXPECT_EQ(on_the_line, 4);
  EXPECT_EQ(clamp_to_rigid(mesh, rigid), 0);
}

}  // namespace plisse
