// The tube generator (the air beam's mesh): counts, tags on their planes and cylinders, exact
// cut plane, a seam that closes the full tube conformingly, the wall volume against the exact
// polygonal annulus (linear) and the true annulus (quadratic, error falling as h^4), and the
// refused options.
#include "mesh/tube_mesh.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "core/error.hpp"
#include "element/taylor_hood_geometry.hpp"
#include "mesh/generate.hpp"
#include "mesh/quality.hpp"
#include "mesh_test_util.hpp"

namespace plisse {
namespace {

using test::mesh_volume;
using test::tag_nodes;

MeshGenerationSpec tube_spec(Symmetry symmetry, int order) {
  MeshGenerationSpec spec;
  spec.kind = "tube";
  spec.radius = 10.0;
  spec.length = 12.0;
  spec.thickness = 0.5;
  spec.layers = 2;
  spec.element_size = 1.5;
  spec.symmetry = symmetry;
  spec.order = order;
  return spec;
}

double radial(const Vec3d& x) { return std::hypot(x.y(), x.z()); }

/// Volume of a 10-node mesh [mm^3]: the sum of the elements' quadrature weights w_q det J / 6.
double p2_volume(const Mesh& mesh) {
  double volume = 0.0;
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    std::array<Vec3d, taylor_hood::kNodes> X;
    for (std::size_t a = 0; a < 4; ++a)
      X[a] = mesh.nodes[static_cast<std::size_t>(mesh.tets[t][a])];
    for (std::size_t e = 0; e < 6; ++e)
      X[4 + e] = mesh.nodes[static_cast<std::size_t>(mesh.tet_edge_nodes[t][e])];
    volume += taylor_hood::compute_geometry(X).volume;
  }
  return volume;
}

class TubeMesh : public ::testing::TestWithParam<Symmetry> {};

TEST_P(TubeMesh, CountsTagsRadiiAndPolygonVolume) {
  const bool half = GetParam() == Symmetry::half;
  const auto spec = tube_spec(GetParam(), 1);
  const Mesh mesh = generate_mesh(spec);
  const double R = 10.0, t = 0.5, L = 12.0, ri = R - t / 2, ro = R + t / 2;
  const int nx = 8, around = half ? 21 : 42;  // round(12 / 1.5), round(pi 10 / 1.5) = 21
  EXPECT_EQ(tube_divisions_around(R, 1.5, half), around);
  EXPECT_EQ(mesh.n_tets(), 6 * nx * around * 2);
  EXPECT_EQ(mesh.n_nodes(), (nx + 1) * (half ? around + 1 : around) * 3);
  EXPECT_EQ(mesh.surface_tags.at("inner").size(), static_cast<std::size_t>(2 * nx * around));
  EXPECT_EQ(mesh.surface_tags.at("outer").size(), static_cast<std::size_t>(2 * nx * around));
  EXPECT_EQ(mesh.surface_tags.at("left").size(), static_cast<std::size_t>(2 * around * 2));
  EXPECT_EQ(mesh.surface_tags.at("right").size(), static_cast<std::size_t>(2 * around * 2));
  EXPECT_EQ(mesh.has_surface("sym_z"), half);
  if (half) {
    EXPECT_EQ(mesh.surface_tags.at("sym_z").size(), static_cast<std::size_t>(2 * 2 * nx * 2));
  }
  // Every node on one of the layer cylinders r = ri, (ri + ro)/2, ro; the tags on theirs.
  for (const auto& x : mesh.nodes) {
    const double r = radial(x);
    EXPECT_LT(std::min({std::abs(r - ri), std::abs(r - R), std::abs(r - ro)}), 1e-12 * R) << r;
    if (half) {
      EXPECT_GE(x.z(), 0.0);
    }
  }
  for (int n : tag_nodes(mesh, "inner"))
    EXPECT_NEAR(radial(mesh.nodes[static_cast<std::size_t>(n)]), ri, 1e-12 * R);
  for (int n : tag_nodes(mesh, "outer"))
    EXPECT_NEAR(radial(mesh.nodes[static_cast<std::size_t>(n)]), ro, 1e-12 * R);
  for (int n : tag_nodes(mesh, "left")) EXPECT_EQ(mesh.nodes[static_cast<std::size_t>(n)].x(), 0.0);
  for (int n : tag_nodes(mesh, "right")) EXPECT_EQ(mesh.nodes[static_cast<std::size_t>(n)].x(), L);
  if (half) {
    for (int n : tag_nodes(mesh, "sym_z"))
      EXPECT_EQ(mesh.nodes[static_cast<std::size_t>(n)].z(), 0.0);
  }
  // The tetrahedra tile the prism over the polygonal annulus exactly: N sectors of a full turn,
  // each (ro^2 - ri^2) sin(2 pi / N) / 2.
  const int sectors = 2 * tube_divisions_around(R, 1.5, true);
  const double polygon = L * (half ? 0.5 : 1.0) * sectors * 0.5 *
                         std::sin(2.0 * std::numbers::pi / sectors) * (ro * ro - ri * ri);
  EXPECT_NEAR(mesh_volume(mesh), polygon, 1e-12 * polygon);
  std::vector<std::string> tags = {"inner", "outer", "left", "right"};
  if (half) tags.push_back("sym_z");
  const MeshReport report = check_mesh(mesh, tags);  // also: the full tube's seam is conforming
  for (const auto& e : report.errors) ADD_FAILURE() << "check_mesh error: " << e;
  for (const auto& w : report.warnings) ADD_FAILURE() << "check_mesh warning: " << w;
}

TEST_P(TubeMesh, SecondOrderNodesOnTheCylindersAndVolumeError) {
  const bool half = GetParam() == Symmetry::half;
  const double R = 10.0, t = 0.5, L = 12.0, ri = R - t / 2, ro = R + t / 2;
  const double exact = (half ? 0.5 : 1.0) * std::numbers::pi * (ro * ro - ri * ri) * L;
  // The chords of N sectors lose a fraction 1 - sin(2 pi/N) / (2 pi/N) ~ (2 pi/N)^2 / 6 of the
  // annulus; quadratic arcs through the chord's midpoint on the circle err by O((2 pi/N)^4). So
  // halving the element size must cut the quadratic error about 16 times (order > 3.5) and leave
  // it far below the linear one.
  std::array<double, 2> error{};
  for (std::size_t level = 0; level < 2; ++level) {
    auto spec = tube_spec(GetParam(), 2);
    spec.element_size = level == 0 ? 1.5 : 0.75;
    const Mesh quadratic = generate_mesh(spec);
    ASSERT_EQ(quadratic.order(), 2);
    for (int n : tag_nodes(quadratic, "inner"))
      EXPECT_NEAR(radial(quadratic.nodes[static_cast<std::size_t>(n)]), ri, 1e-12 * R);
    for (const auto& tri : quadratic.surface_tags.at("outer"))
      for (int n : quadratic.triangle_edge_nodes[static_cast<std::size_t>(tri)])
        EXPECT_NEAR(radial(quadratic.nodes[static_cast<std::size_t>(n)]), ro, 1e-12 * R);
    if (half) {
      for (const auto& tri : quadratic.surface_tags.at("sym_z"))
        for (int n : quadratic.triangle_edge_nodes[static_cast<std::size_t>(tri)])
          EXPECT_EQ(quadratic.nodes[static_cast<std::size_t>(n)].z(), 0.0);
    }
    error[level] = std::abs(p2_volume(quadratic) / exact - 1.0);
    const double linear = std::abs(mesh_volume(quadratic) / exact - 1.0);
    EXPECT_LT(error[level], 0.01 * linear);
  }
  EXPECT_GT(std::log2(error[0] / error[1]), 3.5) << error[0] << " " << error[1];
}

INSTANTIATE_TEST_SUITE_P(Symmetries, TubeMesh, ::testing::Values(Symmetry::full, Symmetry::half));

TEST(TubeMesh, RefusesQuarterThickWallsAndCoarseSizes) {
  auto rule_for = [](MeshGenerationSpec spec, const std::string& expected_key) {
    try {
      generate_mesh(spec);
    } catch (const InputError& e) {
      EXPECT_EQ(e.place().key, expected_key);
      return e.rule();
    }
    ADD_FAILURE() << "accepted";
    return std::string();
  };
  auto spec = tube_spec(Symmetry::quarter, 1);
  EXPECT_NE(rule_for(spec, "mesh.symmetry").find("full or half"), std::string::npos);
  spec = tube_spec(Symmetry::half, 1);
  spec.thickness = 20.0;
  EXPECT_NE(rule_for(spec, "mesh.thickness").find("< 2 radius"), std::string::npos);
  spec = tube_spec(Symmetry::half, 1);
  spec.element_size = 11.0;
  EXPECT_NE(rule_for(spec, "mesh.element_size").find("<= radius"), std::string::npos);
  // The grading from the end x = 0 needs both its keys, within the tube.
  spec = tube_spec(Symmetry::half, 1);
  spec.end_element_size = 0.3;
  EXPECT_NE(rule_for(spec, "mesh.end_element_size").find("needs end_length > 0"),
            std::string::npos);
  spec.end_element_size = 0.0;
  spec.end_length = 3.0;
  EXPECT_NE(rule_for(spec, "mesh.end_length").find("needs end_element_size > 0"),
            std::string::npos);
  spec.end_element_size = 0.3;
  spec.end_length = 13.0;
  EXPECT_NE(rule_for(spec, "mesh.end_length").find("<= length"), std::string::npos);
}

/// Phi(x) = the integral of 1 / h(s) from 0 to x, by Simpson's rule on 20 000 intervals: an
/// independent sum of the size function tube_stations integrates in closed form.
double phi_by_quadrature(double x, double h, double end_h, double end_length) {
  const auto size = [&](double s) { return end_h + (h - end_h) * std::min(s / end_length, 1.0); };
  const int n = 20000;
  const double dx = x / n;
  double sum = 1.0 / size(0.0) + 1.0 / size(x);
  for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) / size(i * dx);
  return sum * dx / 3.0;
}

// Cells graded from the clamp: 100 mm long, 0.5 mm at x = 0 growing to 4 mm over 20 mm. The count
// is round(Phi(L)) and each station splits Phi evenly (Phi summed by quadrature, to 1e-6 of a
// cell: Simpson's error on the kink at 20 mm); the cells grow monotonically up to the grading's
// end and are equal after it, from about the end size to about element_size.
TEST(TubeMesh, StationsFollowTheGradedSizeFromTheEnd) {
  const double L = 100.0, h = 4.0, end_h = 0.5, end_length = 20.0;
  const std::vector<double> x = tube_stations(L, h, end_h, end_length);
  const double phi_l = phi_by_quadrature(L, h, end_h, end_length);
  const int n = static_cast<int>(x.size()) - 1;
  EXPECT_EQ(n, static_cast<int>(std::lround(phi_l))) << phi_l;
  EXPECT_EQ(tube_cells_along(L, h, end_h, end_length), n);
  EXPECT_EQ(x.front(), 0.0);
  EXPECT_EQ(x.back(), L);
  for (int i = 1; i < n; ++i)
    EXPECT_NEAR(phi_by_quadrature(x[i], h, end_h, end_length), phi_l * i / n, 1e-6) << i;
  for (int i = 1; i <= n; ++i) {
    const double cell = x[i] - x[i - 1];
    EXPECT_GT(cell, 0.0);
    if (x[i] <= end_length) {
      EXPECT_GE(cell, x[i - 1] - (i > 1 ? x[i - 2] : 0.0) - 1e-12) << "growing, cell " << i;
    }
  }
  std::printf("graded stations: %d cells, first %.4f mm, last %.4f mm\n", n, x[1] - x[0],
              x[n] - x[n - 1]);
  // The size grows by (h - end_h) / end_length = 0.175 per mm, so the first cell, about half a
  // millimetre long, is the size a quarter millimetre in: 9 % above end_h (asserted 10 %). The
  // last ones are h times Phi(L) / N, the rounding of the count (0.4 % here, asserted 5 %).
  EXPECT_NEAR(x[1] - x[0], end_h, 0.1 * end_h);
  EXPECT_NEAR(x[n] - x[n - 1], h, 0.05 * h);
  // Without a grading, the uniform stations of before: round(L / h) equal cells.
  const std::vector<double> uniform = tube_stations(L, 3.0);
  ASSERT_EQ(uniform.size(), 34u);
  for (std::size_t i = 1; i < uniform.size(); ++i)
    EXPECT_NEAR(uniform[i] - uniform[i - 1], L / 33.0, 1e-12 * L);
}

// The generated tubes, solid and shell, take the graded stations: every node on one, the counts
// and the size estimates the graded cells', and the solid's wall volume still the polygonal
// annulus's exactly (grading moves no node off the cylinders or the end planes).
TEST(TubeMesh, GradedSolidAndShellTubesKeepTheirGeometry) {
  auto spec = tube_spec(Symmetry::half, 1);
  spec.end_element_size = 0.3;
  spec.end_length = 4.0;
  const std::vector<double> x = tube_stations(12.0, 1.5, 0.3, 4.0);
  const int nx = static_cast<int>(x.size()) - 1, around = 21;
  EXPECT_GT(nx, 8) << "finer than the uniform 8 cells";
  const Mesh solid = generate_mesh(spec);
  EXPECT_EQ(solid.n_tets(), 6 * nx * around * 2);
  EXPECT_EQ(estimate_n_tets(spec), 6.0 * nx * around * 2);
  for (const Vec3d& node : solid.nodes)
    EXPECT_TRUE(std::any_of(x.begin(), x.end(), [&](double s) { return s == node.x(); }))
        << node.x();
  const double R = 10.0, ri = R - 0.25, ro = R + 0.25;
  const int sectors = 2 * around;
  const double polygon =
      12.0 * 0.5 * sectors * 0.5 * std::sin(2.0 * std::numbers::pi / sectors) * (ro * ro - ri * ri);
  EXPECT_NEAR(mesh_volume(solid), polygon, 1e-12 * polygon);
  for (int n : tag_nodes(solid, "left"))
    EXPECT_EQ(solid.nodes[static_cast<std::size_t>(n)].x(), 0.0);
  const MeshReport report = check_mesh(solid, {"inner", "outer", "left", "right", "sym_z"});
  for (const auto& e : report.errors) ADD_FAILURE() << "check_mesh error: " << e;
  const Mesh shell = generate_shell_surface(spec);
  EXPECT_EQ(shell.triangles.size(), static_cast<std::size_t>(2 * nx * around));
  EXPECT_EQ(estimate_n_shell_triangles(spec), 2.0 * nx * around);
  for (const Vec3d& node : shell.nodes)
    EXPECT_TRUE(std::any_of(x.begin(), x.end(), [&](double s) { return s == node.x(); }));
}

}  // namespace
}  // namespace plisse
