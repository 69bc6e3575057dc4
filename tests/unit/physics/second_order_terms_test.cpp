// The physics terms on second-order meshes (6-node faces, 10-node tetrahedra), built in the test
// by adding edge nodes to generated linear meshes (support/second_order_mesh.hpp): oriented faces
// and their nodes, the follower pressure on flat, curved and closed surfaces, the cavity volume of
// a sphere and its convergence, the cavity's derivatives, Dirichlet conditions on edge nodes, body
// force and viscous lumping on 10-node tetrahedra, and the die's consistent tributary areas
// (docs/theory/loads.md L7-L10, cavities.md C12-C13, contact.md D16, viscous.md Z5).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <set>

#include "mesh/generate.hpp"
#include "physics/body_force.hpp"
#include "physics/cavity.hpp"
#include "physics/cavity_volume.hpp"
#include "physics/die_contact.hpp"
#include "physics/die_surface.hpp"
#include "physics/dirichlet.hpp"
#include "physics/pressure_load.hpp"
#include "physics/quadratic_triangle.hpp"
#include "physics/surface.hpp"
#include "physics/viscous_damping.hpp"
#include "support/second_order_mesh.hpp"
#include "support/term_testing.hpp"

namespace plisse {
namespace {

using test::DenseSink;
using test::random_state;
using test::term_residual;

/// [0, 2]^3 with 2 divisions, straight second-order: the top face z = 2 has 9 corners and 16
/// edge nodes on the 5 x 5 grid of spacing 0.5.
Mesh quadratic_cube() {
  MeshGenerationSpec spec;
  spec.kind = "cube";
  spec.edge = 2.0;
  spec.divisions = 2;
  return test::with_edge_nodes(generate_mesh(spec));
}

/// A one-layer spherical shell, inner radius 10, thickness 1, with its edge nodes on the spheres.
Mesh quadratic_shell(Symmetry symmetry, double element_size, bool curved = true) {
  MeshGenerationSpec spec;
  spec.kind = "spherical-shell";
  spec.inner_radius = 10.0;
  spec.thickness = 1.0;
  spec.layers = 1;
  spec.element_size = element_size;
  spec.symmetry = symmetry;
  const Mesh linear = generate_mesh(spec);
  return curved ? test::with_edge_nodes(linear, test::on_sphere_of_ends)
                : test::with_edge_nodes(linear);
}

std::array<Vec3d, 6> face_positions(const Mesh& mesh, const SurfaceFace& f) {
  std::array<Vec3d, 6> xs;
  for (int a = 0; a < 6; ++a) xs[a] = mesh.nodes[f.nodes[a]];
  return xs;
}

TEST(SecondOrderSurface, FacesCarryTheirEdgeNodesInOrderAndPointOutward) {
  const Mesh mesh = quadratic_cube();
  const Vec3d centre(1, 1, 1);
  for (const char* tag : {"top", "bottom", "left", "right", "front", "back"}) {
    const auto faces = outward_faces(mesh, tag);
    ASSERT_FALSE(faces.empty());
    for (const SurfaceFace& f : faces) {
      ASSERT_EQ(f.n_nodes, 6);
      for (int k = 0; k < 3; ++k)  // edge node k is the midpoint of corners k, k + 1
        EXPECT_LT((mesh.nodes[f.nodes[3 + k]] -
                   0.5 * (mesh.nodes[f.nodes[k]] + mesh.nodes[f.nodes[(k + 1) % 3]]))
                      .norm(),
                  1e-15);
      const auto xs = face_positions(mesh, f);
      for (const auto& q : quadratic_triangle::rule_points()) {
        const auto frame = quadratic_triangle::face_frame(xs, q);
        EXPECT_GT(frame.x_xi.cross(frame.x_eta).dot(frame.x - centre), 0.0) << tag;
      }
    }
    EXPECT_EQ(surface_nodes(faces).size(), 25u) << tag;
  }
  // The die takes faces by their corners: the edge nodes found through the tetrahedra are the
  // same, whatever the corner order.
  const auto top = outward_faces(mesh, "top");
  std::vector<std::array<int, 3>> corners;
  for (const auto& f : top) corners.push_back({f.nodes[1], f.nodes[2], f.nodes[0]});
  const auto again = faces_with_corners(mesh, corners);
  for (size_t i = 0; i < top.size(); ++i)
    EXPECT_EQ(again[i].nodes,
              (std::array<int, 6>{top[i].nodes[1], top[i].nodes[2], top[i].nodes[0],
                                  top[i].nodes[4], top[i].nodes[5], top[i].nodes[3]}));
}

TEST(SecondOrderSurface, CurvedFacesOfASphereShellPointAwayFromTheBody) {
  const Mesh mesh = quadratic_shell(Symmetry::octant, 4.0);
  // The body lies between the radii 10 and 11: `inner` points to the centre, `outer` away.
  for (const auto& [tag, sign] : {std::pair{"inner", -1.0}, std::pair{"outer", 1.0}})
    for (const SurfaceFace& f : outward_faces(mesh, tag)) {
      const auto xs = face_positions(mesh, f);
      for (const auto& q : quadratic_triangle::rule_points()) {
        const auto frame = quadratic_triangle::face_frame(xs, q);
        EXPECT_GT(sign * frame.x_xi.cross(frame.x_eta).dot(frame.x), 0.0) << tag;
      }
    }
}

TEST(SecondOrderPressure, FlatFaceLoadsOnlyTheEdgeNodesWithATotalOfPressureTimesArea) {
  const Mesh mesh = quadratic_cube();
  const double p = 0.3;
  PressureLoad load(mesh, "p", "top", p, Ramp{0.0, 1.0}, {}, 0);
  const int n = kValuesPerNode * mesh.n_nodes();
  const std::vector<double> x(n, 0.0);
  std::vector<double> r(n, 0.0);
  load.assemble(1.0, x, r, nullptr);
  // Consistent load (loads.md, L8): p ∫ N_a dA n with ∫ N_a dA = 0 at corners and |T|/3 at edge
  // nodes; an edge node inside the face collects |T|/3 from its two triangles (|T| = 0.5).
  const auto top = outward_faces(mesh, "top");
  std::set<int> corners, edges;
  for (const auto& f : top)
    for (int a = 0; a < 6; ++a) (a < 3 ? corners : edges).insert(f.nodes[a]);
  double fz = 0.0;
  for (int v : corners)
    EXPECT_LT(Vec3d(r[node_dof(v, 0)], r[node_dof(v, 1)], r[node_dof(v, 2)]).norm(), 1e-15);
  for (int v : edges) {
    const Vec3d& X = mesh.nodes[v];
    const bool boundary = X.x() == 0.0 || X.x() == 2.0 || X.y() == 0.0 || X.y() == 2.0;
    EXPECT_NEAR(r[node_dof(v, 2)], p * (boundary ? 1.0 : 2.0) * 0.5 / 3.0, 1e-16);
    fz += r[node_dof(v, 2)];
  }
  EXPECT_NEAR(fz, p * 4.0, 1e-14);
}

TEST(SecondOrderPressure, ClosedCurvedSphereHasZeroResultantAndSymmetricStiffness) {
  const Mesh mesh = quadratic_shell(Symmetry::full, 5.0);
  PressureLoad load(mesh, "p", "inner", 0.2, Ramp{0.0, 1.0}, {}, 0);
  EXPECT_TRUE(load.symmetric());
  const int n = kValuesPerNode * mesh.n_nodes();
  const auto x = random_state(n, 7, 0.3);
  DenseSink sink(n);
  std::vector<double> r(n, 0.0);
  load.assemble(1.0, x, r, &sink);
  Vec3d resultant = Vec3d::Zero();
  double largest = 0.0;
  for (int v = 0; v < mesh.n_nodes(); ++v) {
    const Vec3d f(r[node_dof(v, 0)], r[node_dof(v, 1)], r[node_dof(v, 2)]);
    resultant += f;
    largest = std::max(largest, f.norm());
  }
  EXPECT_LT(resultant.norm(), 1e-13 * largest * mesh.n_nodes());
  EXPECT_LT((sink.K - sink.K.transpose()).cwiseAbs().maxCoeff(),
            1e-13 * sink.K.cwiseAbs().maxCoeff());
}

TEST(SecondOrderPressure, TangentIsTheDerivativeOfTheResidualOnAnOpenCurvedSurface) {
  const Mesh mesh = quadratic_shell(Symmetry::octant, 5.0);
  PressureLoad load(mesh, "p", "outer", 0.6, Ramp{0.0, 1.0}, {}, 0);
  EXPECT_FALSE(load.symmetric());  // free edges on the (unconstrained) symmetry planes
  const int n = kValuesPerNode * mesh.n_nodes();
  const auto x = random_state(n, 3, 0.2);
  DenseSink sink(n);
  std::vector<double> r(n, 0.0);
  load.assemble(1.0, x, r, &sink);
  const double h = 1e-6;
  // Pressure values carry no load: their columns are skipped.
  const double worst = test::max_tangent_error(load, 1.0, x, sink.K, h, true);
  EXPECT_LT(worst, 1e-7 * sink.K.cwiseAbs().maxCoeff());
}

TEST(SecondOrderPressure, SymmetryRuleNeedsTheBoundaryEdgeNodesConstrained) {
  const Mesh mesh = quadratic_cube();
  const auto top = outward_faces(mesh, "top");
  std::vector<ConstrainedComponent> constraints;
  int last_edge_node = -1;
  for (int v : surface_nodes(top)) {
    const Vec3d& X = mesh.nodes[v];
    for (int k = 0; k < 2; ++k)
      if (X[k] == 0.0 || X[k] == 2.0) {
        constraints.push_back({v, k, 0.0, Ramp{}});
        if (v >= 27) last_edge_node = static_cast<int>(constraints.size()) - 1;  // not a corner
      }
  }
  EXPECT_TRUE(pressure_stiffness_is_symmetric(mesh, top, constraints));
  ASSERT_GE(last_edge_node, 0);
  constraints.erase(constraints.begin() + last_edge_node);
  EXPECT_FALSE(pressure_stiffness_is_symmetric(mesh, top, constraints));
}

std::vector<double> zero_state(const Mesh& mesh) {
  return std::vector<double>(kValuesPerNode * mesh.n_nodes(), 0.0);
}

TEST(SecondOrderCavity, SphereVolumeConvergesFasterThanTheLinearOne) {
  const double R = 10.0, exact = std::numbers::pi * R * R * R / 6.0;  // octant
  std::vector<double> sizes = {2.0, 1.0, 0.5}, linear_error, quadratic_error, h;
  for (double size : sizes) {
    const Mesh mesh = quadratic_shell(Symmetry::octant, size);
    const auto faces = outward_faces(mesh, "inner");
    ASSERT_FALSE(first_open_edge(mesh, faces).has_value());
    std::vector<SurfaceFace> corners_only = faces;
    double edge = 0.0;
    for (auto& f : corners_only) {
      f.n_nodes = 3;
      for (int k = 0; k < 3; ++k)
        edge += (mesh.nodes[f.nodes[k]] - mesh.nodes[f.nodes[(k + 1) % 3]]).norm();
    }
    h.push_back(edge / (3.0 * static_cast<double>(faces.size())));
    linear_error.push_back(std::abs(cavity_volume(mesh, corners_only, zero_state(mesh)) - exact));
    quadratic_error.push_back(std::abs(cavity_volume(mesh, faces, zero_state(mesh)) - exact));
  }
  for (size_t i = 0; i + 1 < sizes.size(); ++i) {
    const double ratio = std::log(h[i] / h[i + 1]);
    const double linear_rate = std::log(linear_error[i] / linear_error[i + 1]) / ratio;
    const double quadratic_rate = std::log(quadratic_error[i] / quadratic_error[i + 1]) / ratio;
    std::printf(
        "h %.3f -> %.3f: linear error %.3e -> %.3e (rate %.2f), quadratic %.3e -> %.3e "
        "(rate %.2f)\n",
        h[i], h[i + 1], linear_error[i], linear_error[i + 1], linear_rate, quadratic_error[i],
        quadratic_error[i + 1], quadratic_rate);
    // Chordal error of the inscribed polyhedron: O(h^2); the quadratic surface: O(h^4).
    EXPECT_NEAR(linear_rate, 2.0, 0.3);
    EXPECT_GT(quadratic_rate, 3.5);
  }
  for (size_t i = 0; i < sizes.size(); ++i) EXPECT_LT(quadratic_error[i], 0.1 * linear_error[i]);
}

TEST(SecondOrderCavity, VolumeIsInvariantUnderTranslationOfAClosedSurface) {
  const Mesh mesh = quadratic_shell(Symmetry::full, 5.0);
  const auto faces = outward_faces(mesh, "inner");
  auto x = random_state(kValuesPerNode * mesh.n_nodes(), 11, 0.3);
  const double v0 = cavity_volume(mesh, faces, x);
  const Vec3d shift(2.0, -3.0, 4.5);
  for (int v = 0; v < mesh.n_nodes(); ++v)
    for (int i = 0; i < 3; ++i) x[node_dof(v, i)] += shift[i];
  EXPECT_NEAR(cavity_volume(mesh, faces, x), v0, 1e-12 * v0);
}

Cavity inner_cavity() {
  Cavity c;
  c.name = "balloon";
  c.surface = {"inner", InputPlace{}};
  c.control = CavityControl::gas;
  c.initial_pressure = 0.02;
  c.mass_ratio = 2.0;
  c.ambient_pressure = 0.1;
  c.ramp = Ramp{0.0, 1.0};
  return c;
}

TEST(SecondOrderCavity, TangentIsTheDerivativeOfTheResidualAndTheRowIsDvDx) {
  const Mesh mesh = quadratic_shell(Symmetry::full, 6.0);
  CavityTerm term(inner_cavity(), mesh, {}, 0);
  EXPECT_TRUE(term.symmetric());  // closed wall
  const int n = kValuesPerNode * mesh.n_nodes() + 1, m = n - 1;
  term.set_first_global_dof(m);
  auto x = random_state(n, 5, 0.3);
  x[m] = 0.05;
  DenseSink sink(n);
  std::vector<double> r(n, 0.0);
  term.assemble(0.5, x, r, &sink);
  // The residual and the volume are cubic in x: central differences with h = 1e-4 are exact up
  // to O(h^2) ~ 1e-9 relative and the round-off eps V / h ~ 1e-8 of the volume (V ~ 4e3 mm^3).
  const double h = 1e-4;
  std::vector<int> columns;  // a sample of displacement columns and the pressure: enough, faster
  for (int j = 0; j < m; j += 3 * kValuesPerNode + 1) columns.push_back(j);
  columns.push_back(m);
  double uu = 0.0, up = 0.0, pu = 0.0, volume_error = 0.0;
  for (int j : columns) {
    auto xp = x, xm = x;
    xp[j] += h;
    xm[j] -= h;
    const Eigen::VectorXd fd =
        (term_residual(term, 0.5, xp) - term_residual(term, 0.5, xm)) / (2 * h);
    const Eigen::VectorXd e = (fd - sink.K.col(j)).cwiseAbs();
    if (j < m) {
      uu = std::max(uu, e.head(m).maxCoeff());
      pu = std::max(pu, e[m]);
      // The row is -dV/dx (C11, C13).
      const double dvdx = (term.volume(xp) - term.volume(xm)) / (2 * h);
      volume_error = std::max(volume_error, std::abs(sink.K(m, j) + dvdx));
    } else {
      up = e.head(m).maxCoeff();
    }
  }
  const Eigen::MatrixXd k = sink.K.cwiseAbs();
  const double row_scale = k.bottomLeftCorner(1, m).maxCoeff();
  EXPECT_LT(uu, 1e-7 * k.topLeftCorner(m, m).maxCoeff());
  EXPECT_LT(up, 1e-7 * k.topRightCorner(m, 1).maxCoeff());
  EXPECT_LT(pu, 1e-7 * row_scale);
  EXPECT_LT(volume_error, 1e-7 * row_scale);
  // On a closed wall the column, the follower-pressure residual per unit pressure (loads.md, L8),
  // equals the row -dV/dx (cavities.md, C5 and C13): the cavity's p dV work is consistent and the
  // bordered tangent symmetric.
  const Eigen::VectorXd row = sink.K.bottomLeftCorner(1, m).transpose();
  const Eigen::VectorXd column = sink.K.topRightCorner(m, 1);
  EXPECT_LT((column - row).cwiseAbs().maxCoeff(), 1e-12 * row_scale);
}

TEST(SecondOrderCavity, OpenEdgesAreFoundOnCornerEdgesAndCurvedPlaneEdgesAreRefused) {
  Mesh mesh = quadratic_shell(Symmetry::octant, 4.0);
  const auto faces = outward_faces(mesh, "inner");
  EXPECT_FALSE(first_open_edge(mesh, faces).has_value());  // closed by the three planes
  // Lift one edge node of the rim off its symmetry plane: the edge no longer lies in it.
  for (const auto& f : faces)
    for (int k = 0; k < 3; ++k) {
      const int a = f.nodes[k], b = f.nodes[(k + 1) % 3], mid = f.nodes[3 + k];
      if (std::abs(mesh.nodes[a].z()) < 1e-12 && std::abs(mesh.nodes[b].z()) < 1e-12) {
        mesh.nodes[mid].z() += 0.1;
        const auto open = first_open_edge(mesh, faces);
        ASSERT_TRUE(open.has_value());
        EXPECT_EQ(*open, (std::array<int, 2>{std::min(a, b), std::max(a, b)}));
        return;
      }
    }
  FAIL() << "no rim edge on z = 0";
}

TEST(SecondOrderDirichlet, ConditionsHoldTheEdgeNodesOfTheTaggedTriangles) {
  const Mesh mesh = quadratic_cube();
  ConstraintSet set;
  fix_surface(mesh, {"bottom", InputPlace{}}, set);
  hold_in_plane(mesh, {"left", InputPlace{}}, set);
  const auto constraints = set.components();
  std::set<std::pair<int, int>> held;
  for (const auto& c : constraints) held.insert({c.node, c.component});
  int bottom = 0, left = 0;
  for (int v = 0; v < mesh.n_nodes(); ++v) {
    const Vec3d& X = mesh.nodes[v];
    if (X.z() == 0.0) {
      ++bottom;
      for (int k = 0; k < 3; ++k) EXPECT_TRUE(held.count({v, k})) << v;
    }
    if (X.x() == 0.0) {
      ++left;
      EXPECT_TRUE(held.count({v, 0})) << v;
    }
  }
  EXPECT_EQ(bottom, 25);
  EXPECT_EQ(left, 25);
  EXPECT_EQ(constraints.size(), 3u * 25u + 25u - 5u);  // the shared edge x = z = 0: 5 nodes
}

/// One 10-node tetrahedron: corners (0,0,0), (2,0,0), (0,1.5,0), (0,0,1.2) and its edge nodes at
/// the midpoints plus `bend` (Gmsh's edge order), tagged "all" on its four faces.
Mesh one_tet(const std::array<Vec3d, 6>& bend) {
  Mesh mesh;
  mesh.nodes = {Vec3d(0, 0, 0), Vec3d(2, 0, 0), Vec3d(0, 1.5, 0), Vec3d(0, 0, 1.2)};
  mesh.tets = {{0, 1, 2, 3}};
  mesh.triangles = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  mesh.surface_tags["all"] = {0, 1, 2, 3};
  Mesh quadratic = test::with_edge_nodes(mesh);
  for (int e = 0; e < 6; ++e) quadratic.nodes[4 + e] += bend[e];
  return quadratic;
}

/// one_tet with straight edges.
Mesh one_tet() {
  std::array<Vec3d, 6> straight;
  straight.fill(Vec3d::Zero());
  return one_tet(straight);
}

TEST(SecondOrderBodyForce, StraightTetGetsMinusATwentiethOnCornersAndAFifthOnEdgeNodes) {
  const Mesh mesh = one_tet();
  const double V = 2.0 * 1.5 * 1.2 / 6.0;
  const auto volume = consistent_nodal_volumes(mesh);
  for (int a = 0; a < 10; ++a) EXPECT_NEAR(volume[a], a < 4 ? -V / 20.0 : V / 5.0, 1e-15);
  const Vec3d b(0.0, -9.81e-6, 2e-6);
  BodyForce force(mesh, "g", b, Ramp{0.0, 1.0});
  const std::vector<double> x(kValuesPerNode * mesh.n_nodes(), 0.0);
  std::vector<double> r(x.size(), 0.0);
  force.assemble(1.0, x, r, nullptr);
  Vec3d resultant = Vec3d::Zero();
  for (int v = 0; v < mesh.n_nodes(); ++v)
    for (int i = 0; i < 3; ++i) resultant[i] -= r[node_dof(v, i)];
  EXPECT_LT((resultant - b * V).norm(), 1e-15 * b.norm() * V);
}

TEST(SecondOrderBodyForce, CurvedTetResultantIsForceDensityTimesItsVolume) {
  const std::array<Vec3d, 6> bend = {Vec3d(0.1, -0.1, 0.05),   Vec3d(0.05, 0.1, 0.1),
                                     Vec3d(-0.1, 0.05, -0.05), Vec3d(-0.05, 0.1, 0.0),
                                     Vec3d(0.08, 0.02, -0.1),  Vec3d(0.0, -0.05, 0.1)};
  const Mesh mesh = one_tet(bend);
  // Independent volume: the divergence theorem over the four curved faces (cavities.md, C12).
  double V = 0.0;
  for (const SurfaceFace& f : outward_faces(mesh, "all"))
    V += quadratic_cone_volume(face_positions(mesh, f));
  EXPECT_GT(std::abs(V - 0.6), 1e-3);  // the bending changes the volume
  const auto volume = consistent_nodal_volumes(mesh);
  double sum = 0.0;
  for (double v : volume) sum += v;
  EXPECT_NEAR(sum, V, 1e-14 * V);
}

TEST(SecondOrderViscousDamping, LumpingIsPositiveAndSumsToTheVolume) {
  const Mesh mesh = one_tet();
  const double V = 0.6, eta = 0.2, length = 0.5, scale = eta / (length * length);
  ViscousDamping damping(mesh, eta, length);
  // Diagonal scaling of the consistent mass of a straight 10-node tetrahedron: diag ∫ N_a² dV is
  // V/70 (corners) and 8V/105 (edge nodes), sum 18V/35, scaled to V: V/36 and 4V/27.
  for (int a = 0; a < 10; ++a)
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(damping.damping_coefficient(a, k), scale * (a < 4 ? V / 36.0 : 4.0 * V / 27.0),
                  1e-15);
  const std::array<Vec3d, 6> bend = {Vec3d(0.1, -0.1, 0.05),   Vec3d(0.05, 0.1, 0.1),
                                     Vec3d(-0.1, 0.05, -0.05), Vec3d(-0.05, 0.1, 0.0),
                                     Vec3d(0.08, 0.02, -0.1),  Vec3d(0.0, -0.05, 0.1)};
  const Mesh curved = one_tet(bend);
  ViscousDamping curved_damping(curved, eta, length);
  double sum = 0.0;
  for (int a = 0; a < 10; ++a) {
    EXPECT_GT(curved_damping.damping_coefficient(a, 0), 0.0);
    sum += curved_damping.damping_coefficient(a, 0) / scale;
  }
  double expected = 0.0;
  for (double v : consistent_nodal_volumes(curved)) expected += v;
  EXPECT_NEAR(sum, expected, 1e-14);
}

DieContactSettings die_settings() {
  DieContactSettings s;
  s.name = "die";
  s.contact = ContactKind::frictionless;
  s.penalty = 40.0;
  s.tolerance = 1e-9;
  return s;
}

TEST(SecondOrderDie, UniformPressOnAFlatFaceGivesTheConsistentPressureLoad) {
  const Mesh mesh = quadratic_cube();
  const double depth = 0.01;
  // A plane die at z = 2 - depth facing down: every node of the top face penetrates by depth.
  DieContact die(mesh,
                 DieGeometry(DieShape::plane, Vec3d(0, 0, 2.0 - depth), Vec3d(0, 0, -1),
                             Vec3d::UnitZ(), 0.0, Vec3d::Zero(), Ramp{0.0, 1.0}),
                 die_settings(), outward_triangles(mesh, "top"));
  const int n = kValuesPerNode * mesh.n_nodes();
  const std::vector<double> x(n, 0.0);
  std::vector<double> r_die(n, 0.0), r_pressure(n, 0.0);
  die.assemble(1.0, x, r_die, nullptr);
  // The contact pressure is eps * depth on every node; the same follower pressure on `top`:
  PressureLoad load(mesh, "p", "top", 40.0 * depth, Ramp{0.0, 1.0}, {}, 0);
  load.assemble(1.0, x, r_pressure, nullptr);
  const Eigen::Map<Eigen::VectorXd> a(r_die.data(), n), b(r_pressure.data(), n);
  EXPECT_LT((a - b).norm(), 1e-12 * b.norm());
  // Corners carry nothing and are no contact nodes; penetration is measured at the edge nodes.
  EXPECT_EQ(die.n_contact_nodes(1.0, x), 16);
  for (const auto& f : outward_faces(mesh, "top"))
    for (int c = 0; c < 3; ++c) EXPECT_EQ(die.area(f.nodes[c]), 0.0);
  const auto history = die.history_values(1.0, x);
  for (double v : history) EXPECT_TRUE(std::isfinite(v));
  EXPECT_NEAR(history[4], depth, 1e-14);
  EXPECT_NEAR(history[2], 40.0 * depth * 4.0, 1e-13);  // force on the die: +z, eps depth A
}

/// The sum of per-node weights, each expected positive.
double sum_of_positive(const std::map<int, double>& weights) {
  double sum = 0.0;
  for (const auto& [node, w] : weights) {
    EXPECT_GT(w, 0.0) << "node " << node;
    sum += w;
  }
  return sum;
}

TEST(SecondOrderDie, TributaryAreasSumToTheFaceArea) {
  // Flat face with edge nodes moved within its plane: the Jacobian varies, the area does not.
  Mesh mesh = quadratic_cube();
  const auto top = outward_faces(mesh, "top");
  for (const auto& f : top)
    for (int k = 3; k < 6; ++k) {
      Vec3d& X = mesh.nodes[f.nodes[k]];
      if (X.x() > 0.0 && X.x() < 2.0 && X.y() > 0.0 && X.y() < 2.0)
        X += Vec3d(0.04 * std::sin(7.0 * X.y()), -0.03 * std::cos(5.0 * X.x()), 0.0);
    }
  EXPECT_NEAR(sum_of_positive(tributary_areas(mesh, top)), 4.0, 1e-14);
  // A curved face: the sum is the area of the curved octant, 4 pi R^2 / 8 up to the O(h^4) error
  // of the quadratic surface (and the rule's error on the non-polynomial |x_ξ × x_η|).
  const Mesh shell = quadratic_shell(Symmetry::octant, 2.0);
  double shell_sum = 0.0;
  for (const auto& [node, area] : tributary_areas(shell, outward_faces(shell, "inner")))
    shell_sum += area;
  const double exact = std::numbers::pi * 100.0 / 2.0;
  std::printf("octant area: tributary sum %.8f, exact %.8f\n", shell_sum, exact);
  EXPECT_NEAR(shell_sum, exact, 1e-4 * exact);
}

TEST(SecondOrderDie, TieAreasArePositiveOnEveryNodeAndSumToTheFaceArea) {
  // One flat face: the diagonal of the 6-node mass matrix, 6 : 32, scaled to the area (D17).
  const Mesh mesh = quadratic_cube();
  const auto top = outward_faces(mesh, "top");
  const auto one = tie_areas(mesh, {top.front()});
  const Vec3d& x0 = mesh.nodes[top.front().nodes[0]];
  const double area =
      0.5 *
      (mesh.nodes[top.front().nodes[1]] - x0).cross(mesh.nodes[top.front().nodes[2]] - x0).norm();
  for (int a = 0; a < 6; ++a)
    EXPECT_NEAR(one.at(top.front().nodes[a]), area * (a < 3 ? 1.0 / 19.0 : 16.0 / 57.0), 1e-15)
        << "node " << a;
  EXPECT_NEAR(sum_of_positive(tie_areas(mesh, top)), 4.0, 1e-14);
  // The curved octant: the same total as the tributary areas (both are the face areas).
  const Mesh shell = quadratic_shell(Symmetry::octant, 2.0);
  const auto inner = outward_faces(shell, "inner");
  const double tributary_sum = sum_of_positive(tributary_areas(shell, inner));
  EXPECT_NEAR(sum_of_positive(tie_areas(shell, inner)), tributary_sum, 1e-12 * tributary_sum);
}

DieContactSettings sticking_settings() {
  DieContactSettings s = die_settings();
  s.contact = ContactKind::sticking;
  s.touch_slack = 1e-12;
  return s;
}

TEST(SecondOrderDie, StickingDieTiesTheCornersThatTouchItAtTheStart) {
  // A plane lying on the top face at t = 0 glues all its nodes, corners included (D17); moving
  // the die by `shift` drags the face with eps * area * shift, and every node takes its share.
  const Mesh mesh = quadratic_cube();
  const Vec3d shift(0.1, -0.05, 0.02);
  DieContact die(mesh,
                 DieGeometry(DieShape::plane, Vec3d(0, 0, 2.0), Vec3d(0, 0, -1), Vec3d::UnitZ(),
                             0.0, shift, Ramp{0.0, 1.0}),
                 sticking_settings(), outward_triangles(mesh, "top"));
  std::set<int> nodes;
  for (const auto& f : outward_faces(mesh, "top")) nodes.insert(f.nodes.begin(), f.nodes.end());
  EXPECT_EQ(die.n_glued(), static_cast<int>(nodes.size()));  // 25: 9 corners, 16 edge nodes
  for (int v : nodes) {
    EXPECT_TRUE(die.glued(v));
    EXPECT_GT(die.tie_area(v), 0.0);
  }
  const std::vector<double> x(kValuesPerNode * mesh.n_nodes(), 0.0);
  EXPECT_TRUE(die.force_on_die(1.0, x).isApprox(-40.0 * 4.0 * shift, 1e-14));
  EXPECT_NEAR(die.violation(1.0, x), shift.norm(), 1e-15);
  // The tangent of the ties against central differences of the residual (linear in x: exact).
  const std::vector<double> y = test::random_state(static_cast<int>(x.size()), 7, 0.05);
  test::DenseSink sink(static_cast<int>(y.size()));
  std::vector<double> r(y.size(), 0.0);
  die.assemble(1.0, y, r, &sink);
  double worst = 0.0;
  for (int v : nodes)
    for (int c = 0; c < 3; ++c) {
      const int j = node_dof(v, c);
      std::vector<double> plus = y, minus = y;
      plus[j] += 1e-4;
      minus[j] -= 1e-4;
      const Eigen::VectorXd column =
          (test::term_residual(die, 1.0, plus) - test::term_residual(die, 1.0, minus)) / 2e-4;
      worst = std::max(worst, (column - sink.K.col(j)).norm() / sink.K.col(j).norm());
    }
  EXPECT_LT(worst, 1e-10);
}

TEST(SecondOrderDie, CornerThatDipsIntoAStickingDieIsGluedWhereItIsWithoutAForceJump) {
  // A plane 0.01 below the top: every node penetrates; only the edge nodes carry the contact
  // pressure (D16). At the accepted step the corners are glued where they are, with no force,
  // and the edge nodes keep their force (D13): the die force does not change.
  const Mesh mesh = quadratic_cube();
  DieContact die(mesh,
                 DieGeometry(DieShape::plane, Vec3d(0, 0, 1.99), Vec3d(0, 0, -1), Vec3d::UnitZ(),
                             0.0, Vec3d::Zero(), Ramp{0.0, 1.0}),
                 sticking_settings(), outward_triangles(mesh, "top"));
  EXPECT_EQ(die.n_glued(), 0);
  const std::vector<double> x(kValuesPerNode * mesh.n_nodes(), 0.0);
  std::vector<double> r(x.size(), 0.0);
  die.assemble(0.5, x, r, nullptr);
  EXPECT_EQ(die.n_contact_nodes(0.5, x), 16);  // the edge nodes
  const Vec3d sliding = die.force_on_die(0.5, x);
  EXPECT_NEAR(sliding.z(), 40.0 * 0.01 * 4.0, 1e-13);
  die.accept_step(x);
  EXPECT_EQ(die.n_glued(), 25);
  EXPECT_TRUE(die.force_on_die(0.5, x).isApprox(sliding, 1e-14));
  // The edge nodes are glued on the die surface (0.01 away), the corners where they are.
  EXPECT_NEAR(die.violation(0.5, x), 0.01, 1e-15);
  for (const auto& f : outward_faces(mesh, "top"))
    for (int c = 0; c < 3; ++c) EXPECT_EQ(die.area(f.nodes[c]), 0.0);
}

}  // namespace
}  // namespace plisse
