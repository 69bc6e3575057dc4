// A wall closed over the caps on its rims (docs/theory/cavities.md, C14-C17): the volume of a
// capped prism of flat triangles is the prism's exactly and does not change under a rigid motion;
// the pressure on the closed wall has no resultant and no moment; the tangents of the cavity and
// of the pressure load are the derivatives of their residuals (central differences, straight and
// curved rims); both are symmetric where the closed surface says so; and a rim no cap or plane
// closes is refused.
#include "physics/cap_closure.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <set>

#include "mesh/generate.hpp"
#include "physics/cavity.hpp"
#include "physics/cavity_volume.hpp"
#include "physics/dirichlet.hpp"
#include "physics/pressure_load.hpp"
#include "physics/surface.hpp"
#include "support/term_testing.hpp"

namespace plisse {
namespace {

using test::DenseSink;

constexpr double kRadius = 10.0, kLength = 24.0;

/// A tube of flat triangles (element: shell's mid-surface) or of Taylor-Hood tetrahedra, with its
/// end tags `left` (x = 0) and `right` (x = L); `shift` moves it along x (no rim on x = 0).
Mesh tube(Symmetry symmetry, bool shell, double shift = 0.0) {
  MeshGenerationSpec spec;
  spec.kind = "tube";
  spec.radius = kRadius;
  spec.length = kLength;
  spec.thickness = 1.0;
  spec.layers = 1;
  spec.element_size = 4.0;
  spec.symmetry = symmetry;
  spec.order = shell ? 1 : 2;
  Mesh mesh = shell ? generate_shell_surface(spec) : generate_mesh(spec);
  for (Vec3d& x : mesh.nodes) x.x() += shift;
  return mesh;
}

/// The caps on both ends: the nodes of the edge tags (shell) or face tags (solid).
std::vector<CapNodes> end_caps(const Mesh& mesh) {
  std::vector<CapNodes> caps;
  for (const char* end : {"left", "right"})
    caps.push_back({end, condition_nodes(mesh, SurfaceRef{end, InputPlace{}})});
  return caps;
}

/// The cavity's wall: a shell's mid-surface (tag `inner`, its -1 face) or a solid's inner face.
std::vector<SurfaceFace> wall(const Mesh& mesh) { return outward_faces(mesh, "inner"); }

std::vector<double> zero_state(const Mesh& mesh, int extra = 0) {
  return std::vector<double>(kValuesPerNode * mesh.n_nodes() + extra, 0.0);
}

/// The state that moves every node rigidly: rotation by `angle` about z, then `shift`.
std::vector<double> rigid_state(const Mesh& mesh, double angle, const Vec3d& shift) {
  std::vector<double> x = zero_state(mesh);
  const Eigen::Matrix3d r = Eigen::AngleAxisd(angle, Vec3d::UnitZ()).toRotationMatrix();
  for (int v = 0; v < mesh.n_nodes(); ++v) {
    const Vec3d u = r * mesh.nodes[v] + shift - mesh.nodes[v];
    for (int i = 0; i < 3; ++i) x[node_dof(v, i)] = u[i];
  }
  return x;
}

TEST(CapClosure, ClosesBothRimsOfATube) {
  for (Symmetry symmetry : {Symmetry::full, Symmetry::half}) {
    const Mesh mesh = tube(symmetry, true, 5.0);
    const auto faces = wall(mesh);
    ASSERT_TRUE(first_open_edge(mesh, faces).has_value()) << "an open tube is not closed";
    const WallClosure closure = close_over_caps(mesh, faces, end_caps(mesh));
    EXPECT_FALSE(closure.open_edge.has_value());
    ASSERT_EQ(closure.caps.size(), 2u);
    EXPECT_EQ(closure.caps[0].cap, "left");
    EXPECT_EQ(closure.caps[1].cap, "right");
    // The half tube's rims are arcs ending on z = 0: the apex is taken into that plane.
    const Vec3d keep = symmetry == Symmetry::half ? Vec3d(1, 1, 0) : Vec3d(1, 1, 1);
    for (const CapClosure& c : closure.caps) EXPECT_EQ(c.keep, keep);
    EXPECT_EQ(closure.planes, symmetry == Symmetry::half ? 4 : 0);
  }
}

TEST(CapClosure, VolumeOfACappedPrismIsExactAndRigidMotionsKeepIt) {
  for (Symmetry symmetry : {Symmetry::full, Symmetry::half}) {
    const bool half = symmetry == Symmetry::half;
    const Mesh mesh = tube(symmetry, true, 5.0);
    const auto faces = wall(mesh);
    const WallClosure closure = close_over_caps(mesh, faces, end_caps(mesh));
    // A regular prism of n_a sides around (n_a / 2 R^2 sin(2 pi / n_a) per full turn) and L long.
    const int sides = static_cast<int>(closure.caps[0].rim.size());
    const int around = half ? 2 * sides : sides;
    const double prism = (half ? 0.5 : 1.0) * 0.5 * around * kRadius * kRadius *
                         std::sin(2.0 * std::numbers::pi / around) * kLength;
    const double v0 = closed_volume(mesh, faces, closure.caps, zero_state(mesh));
    std::printf("%s prism, %d sides: volume %.15g, exact %.15g\n", half ? "half" : "full", around,
                v0, prism);
    EXPECT_NEAR(v0, prism, 1e-13 * prism);
    // Rigid motions that keep the half tube on z = 0 (its mirror plane): turns about z, shifts
    // in x and y. The cones move with the rims; the apex stays the rim's centre.
    const auto moved = rigid_state(mesh, 0.7, Vec3d(3.0, -2.0, 0.0));
    EXPECT_NEAR(closed_volume(mesh, faces, closure.caps, moved), prism, 1e-12 * prism);
    // Without the cones the formula over the open wall is not the volume: it misses the flux of
    // x through the end discs, (1/3) x_c . a per rim (a its vector area), at x = 5 and 29.
    EXPECT_GT(std::abs(cavity_volume(mesh, faces, zero_state(mesh)) - prism), 0.1 * prism);
  }
}

TEST(CapClosure, CurvedRimsOfATaylorHoodTubeCloseAsFlatDiscs) {
  // The inner face of a quadratic tube: the rims are parabolic arcs on the planes x = 5 and
  // x = 29. Their closing cones lie in those planes, so a rigid motion keeps the volume to
  // round-off, and the volume approaches pi R^2 L.
  const Mesh mesh = tube(Symmetry::half, false, 5.0);
  const auto faces = wall(mesh);
  const WallClosure closure = close_over_caps(mesh, faces, end_caps(mesh));
  ASSERT_FALSE(closure.open_edge.has_value());
  const double v0 = closed_volume(mesh, faces, closure.caps, zero_state(mesh));
  const double ri = kRadius - 0.5;  // inner radius of the wall of thickness 1
  const double cylinder = 0.5 * std::numbers::pi * ri * ri * kLength;
  std::printf("Taylor-Hood half tube: volume %.12g, cylinder %.12g (%.1e)\n", v0, cylinder,
              v0 / cylinder - 1.0);
  EXPECT_NEAR(v0, cylinder, 1e-3 * cylinder);  // the chordal error of parabolic arcs of 4 mm
  EXPECT_NEAR(closed_volume(mesh, faces, closure.caps, rigid_state(mesh, -0.4, Vec3d(1, 2, 0))), v0,
              1e-12 * v0);
}

/// Sum of the nodal residuals (force) and of their moments about the origin.
std::pair<Vec3d, Vec3d> resultant(const Mesh& mesh, std::span<const double> x,
                                  std::span<const double> r) {
  Vec3d force = Vec3d::Zero(), moment = Vec3d::Zero();
  for (int v = 0; v < mesh.n_nodes(); ++v) {
    const Vec3d f(r[node_dof(v, 0)], r[node_dof(v, 1)], r[node_dof(v, 2)]);
    force += f;
    moment += deformed_position(mesh, x, v).cross(f);
  }
  return {force, moment};
}

TEST(CapClosure, PressureOnAFullCappedTubeHasNoResultantAndItsTangentIsSymmetric) {
  for (bool shell : {true, false}) {
    const Mesh mesh = tube(Symmetry::full, shell, 5.0);
    const auto caps = end_caps(mesh);
    PressureLoad load(mesh, "p", "inner", 0.3, Ramp{0.0, 1.0}, {}, 0, caps);
    PressureLoad open(mesh, "p", "inner", 0.3, Ramp{0.0, 1.0}, {}, 0);
    EXPECT_TRUE(load.symmetric());
    EXPECT_FALSE(open.symmetric());
    const int n = kValuesPerNode * mesh.n_nodes();
    const auto x = test::random_state(n, shell ? 11 : 12, 0.3);
    DenseSink sink(n);
    std::vector<double> r(n, 0.0);
    load.assemble(1.0, x, r, &sink);
    const auto [force, moment] = resultant(mesh, x, r);
    // The thrust on one end, for scale: p pi R^2.
    const double thrust = 0.3 * std::numbers::pi * kRadius * kRadius;
    std::printf("%s: resultant %.1e N, moment %.1e N mm (thrust %.3g N)\n",
                shell ? "shell" : "Taylor-Hood", force.norm(), moment.norm(), thrust);
    EXPECT_LT(force.norm(), 1e-12 * thrust);
    EXPECT_LT(moment.norm(), 1e-12 * thrust * kLength);
    // In the reference state the closure adds to the right rim the thrust p a on the end's
    // vector area a = (A, 0, 0): a regular polygon's area on the shell's rim, the parabolic
    // arcs' (pi R_i^2 within their chordal error) on the solid's.
    std::vector<double> r_closed(n, 0.0), r_open(n, 0.0);
    load.assemble(1.0, zero_state(mesh), r_closed, nullptr);
    open.assemble(1.0, zero_state(mesh), r_open, nullptr);
    Vec3d thrust_right = Vec3d::Zero();
    for (int v : caps[1].nodes)
      for (int i = 0; i < 3; ++i)
        thrust_right[i] -= r_closed[node_dof(v, i)] - r_open[node_dof(v, i)];
    const int sides = static_cast<int>(close_over_caps(mesh, wall(mesh), caps).caps[1].rim.size());
    const double area =
        shell ? 0.5 * sides * kRadius * kRadius * std::sin(2.0 * std::numbers::pi / sides)
              : std::numbers::pi * (kRadius - 0.5) * (kRadius - 0.5);
    std::printf("%s: thrust on the right cap %.12g N, p A %.12g N\n",
                shell ? "shell" : "Taylor-Hood", thrust_right.x(), 0.3 * area);
    EXPECT_NEAR(thrust_right.x(), 0.3 * area, (shell ? 1e-13 : 1e-3) * 0.3 * area);
    EXPECT_LT(thrust_right.tail<2>().norm(), 1e-13 * 0.3 * area);
    EXPECT_LT((sink.K - sink.K.transpose()).cwiseAbs().maxCoeff(),
              1e-13 * sink.K.cwiseAbs().maxCoeff());
    // Central differences: the residual is quadratic in x, so O(h^2) vanishes up to round-off.
    const double error = test::max_tangent_error(load, 1.0, x, sink.K, 1e-6, true);
    std::printf("%s: largest FD error of the pressure load's tangent %.1e (scale %.1e)\n",
                shell ? "shell" : "Taylor-Hood", error, sink.K.cwiseAbs().maxCoeff());
    EXPECT_LT(error, 1e-8 * sink.K.cwiseAbs().maxCoeff());
  }
}

Cavity gas_cavity() {
  Cavity c;
  c.name = "tube";
  c.surface = {"inner", InputPlace{}};
  c.control = CavityControl::gas;
  c.initial_pressure = 0.02;
  c.mass_ratio = 2.0;
  c.ramp = Ramp{0.0, 1.0};
  return c;
}

/// Zero normal displacement on sym_z.
std::vector<ConstrainedComponent> mirror_z(const Mesh& mesh) {
  std::vector<ConstrainedComponent> out;
  for (int v : condition_nodes(mesh, SurfaceRef{"sym_z", InputPlace{}}))
    out.push_back({v, 2, 0.0, Ramp{}});
  return out;
}

TEST(CapClosure, BorderedCavityTangentIsTheDerivativeAndSymmetricOnAHalfTube) {
  for (bool shell : {true, false}) {
    const Mesh mesh = tube(Symmetry::half, shell, 5.0);
    const auto constraints = mirror_z(mesh);
    CavityTerm term(gas_cavity(), mesh, constraints, 4, end_caps(mesh));
    EXPECT_TRUE(term.symmetric());
    const int n = kValuesPerNode * mesh.n_nodes() + 1;
    term.set_first_global_dof(n - 1);
    auto x = test::random_state(n, shell ? 21 : 22, 0.3);
    for (const auto& c : constraints) x[node_dof(c.node, c.component)] = 0.0;
    x.back() = 0.05;
    DenseSink sink(n);
    std::vector<double> r(n, 0.0);
    term.assemble(0.5, x, r, &sink);
    const double error = test::max_tangent_error(term, 0.5, x, sink.K, 1e-6, false);
    std::printf("%s half tube: largest FD error of the bordered tangent %.1e (scale %.1e)\n",
                shell ? "shell" : "Taylor-Hood", error, sink.K.cwiseAbs().maxCoeff());
    EXPECT_LT(error, 1e-7 * sink.K.cwiseAbs().maxCoeff());
    std::vector<bool> free(n, true);
    for (const auto& c : constraints) free[node_dof(c.node, c.component)] = false;
    double asymmetry = 0.0;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        if (free[i] && free[j] && i % kValuesPerNode != 3 && j % kValuesPerNode != 3)
          asymmetry = std::max(asymmetry, std::abs(sink.K(i, j) - sink.K(j, i)));
    EXPECT_LT(asymmetry, 1e-12 * sink.K.cwiseAbs().maxCoeff());
    // The half cavity's volume, and the whole tube's through the mirror plane.
    EXPECT_EQ(term.history_columns(),
              (std::vector<std::string>{"pressure:tube", "volume:tube", "full_volume:tube"}));
  }
}

TEST(CapClosure, AHalfTubesRimInThePlaneXZeroTakesTheWholeThrust) {
  // The rim at x = 0 ends on z = 0 (the mirror) and lies in x = 0 as a whole: only z = 0 holds
  // the apex. Both caps take p times the half-disc's area along x, and the pressure on the closed
  // half tube has no x or y resultant (its z resultant is the mirror plane's load).
  for (bool shell : {true, false}) {
    const Mesh mesh = tube(Symmetry::half, shell, 0.0);
    const auto caps = end_caps(mesh);
    const WallClosure closure = close_over_caps(mesh, wall(mesh), caps);
    ASSERT_EQ(closure.caps.size(), 2u);
    EXPECT_EQ(closure.caps[0].keep, Vec3d(1, 1, 0));
    PressureLoad load(mesh, "p", "inner", 0.3, Ramp{0.0, 1.0}, {}, 4, caps);
    std::vector<double> r(kValuesPerNode * mesh.n_nodes(), 0.0);
    load.assemble(1.0, zero_state(mesh), r, nullptr);
    const Vec3d force = resultant(mesh, zero_state(mesh), r).first;
    std::array<double, 2> thrust{};
    for (int c = 0; c < 2; ++c)
      for (int v : caps[c].nodes) thrust[c] += r[node_dof(v, 0)];
    std::printf("%s half tube on x = 0: cap thrusts %.12g and %.12g N, resultant x %.1e y %.1e\n",
                shell ? "shell" : "Taylor-Hood", thrust[0], thrust[1], force.x(), force.y());
    EXPECT_NEAR(thrust[0], -thrust[1], 1e-13 * thrust[0]);
    EXPECT_LT(std::abs(force.x()) + std::abs(force.y()), 1e-12 * thrust[0]);
    // With the tangent (the sanitizer runs reach its assembly here; the central differences
    // above are too slow for them): the same residual, and a closure block that couples the
    // rim's nodes with one another, which the couplings list.
    DenseSink sink(static_cast<int>(r.size()));
    std::vector<double> again(r.size(), 0.0);
    load.assemble(1.0, zero_state(mesh), again, &sink);
    EXPECT_EQ(again, r);
    EXPECT_TRUE(sink.K.allFinite());
    std::vector<std::pair<int, int>> pairs;
    load.add_couplings(pairs);
    const std::set<std::pair<int, int>> listed(pairs.begin(), pairs.end());
    const auto& rim = closure.caps[1].nodes;
    for (int u : {rim.front(), rim.back()})
      for (int v : {rim.front(), rim.back()}) {
        // The follower stiffness is a cross product: its blocks have no diagonal, so the whole
        // 3 x 3 block is looked at.
        double block = 0.0;
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) {
            block += std::abs(sink.K(node_dof(u, i), node_dof(v, j)));
            EXPECT_TRUE(listed.count({node_dof(u, i), node_dof(v, j)}));
          }
        EXPECT_GT(block, 0.0) << "nodes " << u << " and " << v;
      }
  }
}

TEST(CapClosure, ARimNoCapOrPlaneClosesIsRefused) {
  const Mesh mesh = tube(Symmetry::half, true, 5.0);
  const auto faces = wall(mesh);
  // One cap only: the other rim is open.
  const auto one = std::vector<CapNodes>{end_caps(mesh)[1]};
  const WallClosure closure = close_over_caps(mesh, faces, one);
  ASSERT_TRUE(closure.open_edge.has_value());
  for (int v : *closure.open_edge) EXPECT_NEAR(mesh.nodes[v].x(), 5.0, 1e-12);
  try {
    CavityTerm term(gas_cavity(), mesh, mirror_z(mesh), 4, one);
    FAIL() << "an open rim was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(e.rule().find("is not closed"), std::string::npos) << e.rule();
    EXPECT_NE(e.rule().find("cap"), std::string::npos) << e.rule();
  }
  // A pressure load names a cap that ties no rim of its surface.
  CapNodes stray{"stray", {0}};
  EXPECT_THROW(PressureLoad(mesh, "p", "inner", 0.1, Ramp{}, {}, 4, {stray}), InputError);
}

}  // namespace
}  // namespace plisse
