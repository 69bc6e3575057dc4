// Follower pressure: the tangent is the derivative of the residual (central differences), the
// resultant of a closed surface vanishes, and the symmetry rule for open surfaces holds.
#include "physics/pressure_load.hpp"

#include <gtest/gtest.h>

#include <random>
#include <utility>
#include <vector>

#include "mesh/box_mesh.hpp"
#include "mesh/generate.hpp"
#include "physics/dirichlet.hpp"
#include "physics/surface.hpp"
#include "support/term_testing.hpp"

namespace plisse {
namespace {

using test::DenseSink;
using test::random_state;
using test::term_residual;

Mesh small_cube() {
  MeshGenerationSpec spec;
  spec.kind = "cube";
  spec.edge = 2.0;
  spec.divisions = 2;
  return generate_mesh(spec);
}

TEST(PressureLoad, TangentIsDerivativeOfResidualOnAnOpenSurface) {
  const Mesh mesh = small_cube();
  PressureLoad load(mesh, "p", "top", 0.7, Ramp{0.0, 1.0}, {}, 0);
  EXPECT_FALSE(load.symmetric());  // free edges: the load stiffness is not symmetric
  const int n = kValuesPerNode * mesh.n_nodes();
  const auto x = random_state(n, 3, 0.2);
  DenseSink sink(n);
  std::vector<double> r(n, 0.0);
  load.assemble(1.0, x, r, &sink);
  const double h = 1e-6;
  const double scale = sink.K.cwiseAbs().maxCoeff();
  const double max_error = test::max_tangent_error(load, 1.0, x, sink.K, h);
  // The residual is quadratic in x, so central differences are exact up to round-off.
  EXPECT_LT(max_error, 1e-8 * scale);
  EXPECT_GT((sink.K - sink.K.transpose()).cwiseAbs().maxCoeff(), 1e-3 * scale);
}

TEST(PressureLoad, ClosedSurfaceHasZeroResultantAndSymmetricStiffness) {
  Mesh mesh = small_cube();
  std::vector<int> all;
  for (const char* face : {"left", "right", "front", "back", "bottom", "top"})
    for (int t : mesh.surface_tags.at(face)) all.push_back(t);
  mesh.surface_tags["all"] = all;
  PressureLoad load(mesh, "p", "all", 0.3, Ramp{0.0, 1.0}, {}, 0);
  EXPECT_TRUE(load.symmetric());
  const int n = kValuesPerNode * mesh.n_nodes();
  const auto x = random_state(n, 5, 0.3);
  DenseSink sink(n);
  std::vector<double> r(n, 0.0);
  load.assemble(1.0, x, r, &sink);
  Vec3d resultant = Vec3d::Zero();
  for (int v = 0; v < mesh.n_nodes(); ++v)
    for (int i = 0; i < 3; ++i) resultant[i] += r[node_dof(v, i)];
  EXPECT_LT(resultant.norm(), 1e-13);  // uniform pressure on a closed surface: no net force
  EXPECT_LT((sink.K - sink.K.transpose()).cwiseAbs().maxCoeff(),
            1e-13 * sink.K.cwiseAbs().maxCoeff());
}

TEST(PressureLoad, ResultantOnAFlatFaceIsPressureTimesArea) {
  const Mesh mesh = small_cube();
  PressureLoad load(mesh, "p", "top", 0.25, Ramp{0.0, 2.0}, {}, 0);
  const int n = kValuesPerNode * mesh.n_nodes();
  const std::vector<double> x(n, 0.0);
  std::vector<double> r(n, 0.0);
  load.assemble(1.0, x, r, nullptr);  // half-way up the ramp: p = 0.125 MPa
  double fz = 0.0;
  for (int v = 0; v < mesh.n_nodes(); ++v) fz += r[node_dof(v, 2)];
  // Residual = internal - external; the external force on the top face (outward +z) is -p A.
  EXPECT_NEAR(fz, 0.125 * 4.0, 1e-14);
}

TEST(PressureLoad, SymmetryPlanesCloseTheBoundaryOfAnOpenSurface) {
  const Mesh mesh = small_cube();
  const auto top = outward_faces(mesh, "top");
  std::vector<ConstrainedComponent> constraints;
  for (int v : surface_nodes(top)) {
    const Vec3d& X = mesh.nodes[v];
    for (int k = 0; k < 2; ++k)
      if (X[k] == 0.0 || X[k] == 2.0) constraints.push_back({v, k, 0.0, Ramp{}});
  }
  EXPECT_TRUE(pressure_stiffness_is_symmetric(mesh, top, constraints));
  constraints.pop_back();
  EXPECT_FALSE(pressure_stiffness_is_symmetric(mesh, top, constraints));
}

// The volume under a lifted quarter sheet: its bottom face, on z = 0, is closed by the planes
// x = 0, y = 0 (mirrors: `symmetry` conditions there) and z = 0 (only a closure: the sheet's far
// edges stay in it, with no condition there). The whole body's volume is 4 times the quarter's,
// not 8.
// A mirror plane is a cut through the whole body (docs/output.md, "Symmetry"). A body between
// symmetry planes on both its faces along an axis is a slice (plane strain) with no whole body
// along that axis: neither face mirrors. The roller-base case, a block on the base y = 0 with
// symmetric z faces and a side x = 4 pulled: with the base held by a `displacement` (a roller:
// not a symmetry condition), no plane is a mirror and the side's whole force is its force, where
// plisse reported 4 times it; with `symmetry` on the base, y = 0 is declared a mirror (the block
// is half of one twice as high) and the factor is 2, never 4.
TEST(Symmetry, ASliceBetweenSymmetryPlanesMirrorsNothing) {
  const Mesh mesh = make_box_mesh(Vec3d(4.0, 3.0, 2.0), {4, 3, 2});
  EXPECT_EQ(mirror_planes({"bottom"}, mesh), 4);
  EXPECT_EQ(mirror_planes({"bottom", "top"}, mesh), 0);
  EXPECT_EQ(
      planes_reached(mesh, mesh.surface_tags.at("right"), mirror_planes({"bottom", "top"}, mesh)),
      0);
  const int with_base = mirror_planes({"front", "bottom", "top"}, mesh);
  EXPECT_EQ(with_base, 2);
  EXPECT_EQ(whole_body_force(Vec3d(1.0, 2.0, 3.0),
                             planes_reached(mesh, mesh.surface_tags.at("right"), with_base)),
            Vec3d(2.0, 0.0, 6.0));
}

// A force f at x and its mirror images (f and x reflected in each plane of `cut`) have the
// moment about the origin that whole_body_moment gives from the modelled part's x × f.
TEST(Symmetry, WholeBodyMomentIsTheSumOfTheMirrorImagesMoments) {
  const Vec3d x(0.3, -1.7, 2.2), f(1.1, 0.4, -0.9);
  for (int cut = 0; cut < 8; ++cut) {
    std::vector<std::pair<Vec3d, Vec3d>> images = {{x, f}};
    for (int k = 0; k < 3; ++k) {
      if (!(cut & (1 << k))) continue;
      const std::size_t n = images.size();
      for (std::size_t i = 0; i < n; ++i) {
        auto [xi, fi] = images[i];
        xi[k] = -xi[k];
        fi[k] = -fi[k];
        images.emplace_back(xi, fi);
      }
    }
    Vec3d sum = Vec3d::Zero(), force = Vec3d::Zero();
    for (const auto& [xi, fi] : images) sum += xi.cross(fi), force += fi;
    const Vec3d m = whole_body_moment(x.cross(f), cut), whole = whole_body_force(f, cut);
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(m[k], sum[k], 1e-14) << "cut " << cut << " axis " << k;
      EXPECT_NEAR(whole[k], force[k], 1e-14) << "cut " << cut << " axis " << k;
    }
  }
  EXPECT_EQ(whole_body_moment(Vec3d(1.0, 2.0, 3.0), 4), Vec3d(0.0, 0.0, 6.0));
  EXPECT_EQ(whole_body_moment(Vec3d(1.0, 2.0, 3.0), 1 | 4), Vec3d::Zero());
}

TEST(PressureLoad, EnclosedVolumeAndTheWholeBodysCountOnlyMirrorPlanes) {
  const Mesh mesh = make_box_mesh(Vec3d(4.0, 3.0, 0.5), {4, 3, 1});
  const int mirrors = mirror_planes({"left", "front"}, mesh);
  EXPECT_EQ(mirrors, 1 | 2);
  // The bottom face reaches both mirror planes, the far edge x = 4 neither; a force on a surface
  // that reaches a plane loses its normal component and doubles the others.
  EXPECT_EQ(planes_reached(mesh, mesh.surface_tags.at("bottom"), mirrors), 1 | 2);
  EXPECT_EQ(planes_reached(mesh, mesh.surface_tags.at("bottom"), 1), 1);
  EXPECT_EQ(planes_reached(mesh, mesh.surface_tags.at("right"), mirrors), 2);  // x = 4, y from 0
  EXPECT_EQ(whole_body_force(Vec3d(1.0, 2.0, 3.0), 1 | 2), Vec3d(0.0, 0.0, 12.0));
  EXPECT_EQ(whole_body_force(Vec3d(1.0, 2.0, 3.0), 4), Vec3d(2.0, 4.0, 0.0));
  PressureLoad load(mesh, "p", "bottom", 0.1, Ramp{0.0, 1.0}, {}, mirrors);
  EXPECT_EQ(load.history_columns(),
            (std::vector<std::string>{"pressure:p", "volume:p", "full_volume:p"}));
  // Lift the sheet by w = (4 - x)(3 - y) / 48, so that its far edges stay on z = 0 (the rule a
  // closed volume needs). The volume between the bottom face and z = 0 is then the sum over the
  // face's triangles of area times their corners' mean lift: prisms, not cones from the origin.
  std::vector<double> x(kValuesPerNode * mesh.n_nodes(), 0.0);
  const auto lift = [&](int v) {
    return (4.0 - mesh.nodes[v].x()) * (3.0 - mesh.nodes[v].y()) / 48.0;
  };
  for (int v = 0; v < mesh.n_nodes(); ++v) x[node_dof(v, 2)] = lift(v);
  double prisms = 0.0;
  for (int t : mesh.surface_tags.at("bottom")) {
    const auto& [a, b, c] = mesh.triangles[t];
    const double area =
        0.5 * (mesh.nodes[b] - mesh.nodes[a]).cross(mesh.nodes[c] - mesh.nodes[a]).norm();
    prisms += area * (lift(a) + lift(b) + lift(c)) / 3.0;
  }
  const std::vector<double> h = load.history_values(1.0, x);
  EXPECT_EQ(h[0], 0.1);
  EXPECT_GT(prisms, 0.1);
  EXPECT_NEAR(h[1], prisms, 1e-12);
  EXPECT_NEAR(h[2], 4.0 * h[1], 1e-12);
  // An open surface (the top face's far edges lie in no coordinate plane): no volume.
  PressureLoad open(mesh, "q", "top", 0.1, Ramp{0.0, 1.0}, {}, mirrors);
  EXPECT_EQ(open.history_columns(), std::vector<std::string>{"pressure:q"});
}

}  // namespace
}  // namespace plisse
