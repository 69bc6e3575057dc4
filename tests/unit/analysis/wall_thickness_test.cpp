// The wall thickness field: exact on a flat slab under a homogeneous stretch and under a shear
// that slides its through-thickness fibres, and on a layered sphere blown up uniformly.
#include "analysis/wall_thickness.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "fixtures/shells.hpp"
#include "mesh/box_mesh.hpp"

namespace plisse {
namespace {

/// u = (F − I) X at every node.
std::vector<Vec3d> affine_displacement(const Mesh& mesh, const Mat3d& F) {
  std::vector<Vec3d> u(mesh.nodes.size());
  for (std::size_t v = 0; v < u.size(); ++v) u[v] = (F - Mat3d::Identity()) * mesh.nodes[v];
  return u;
}

TEST(WallThickness, FacesAreInnerAndOuterOrBottomAndTop) {
  const Mesh slab = make_box_mesh(Vec3d(4, 3, 0.5), {8, 6, 2});
  ASSERT_TRUE(wall_faces(slab));
  EXPECT_EQ(*wall_faces(slab), (WallFaces{"bottom", "top"}));
  const Mesh sphere = test::sphere_shell(Symmetry::octant, 10.0, 1.0, 2, 2.0);
  EXPECT_EQ(*wall_faces(sphere), (WallFaces{"inner", "outer"}));
  Mesh bare = slab;
  bare.surface_tags.erase("top");
  EXPECT_FALSE(wall_faces(bare));
  EXPECT_THROW(WallThickness(bare, {"bottom", "top"}), Error);
}

TEST(WallThickness, FlatSlabIsExactUnderStretchAndShear) {
  const double t = 0.5;
  for (int order : {1, 2}) {
    const Mesh slab = make_box_mesh(Vec3d(4, 3, t), {8, 6, 2}, order);
    const WallThickness thickness(slab, {"bottom", "top"});
    for (double value : thickness(std::vector<Vec3d>(slab.nodes.size(), Vec3d::Zero())))
      EXPECT_NEAR(value, t, 1e-14) << "order " << order;
    // An incompressible biaxial stretch thins the slab by 1 / (1.2 × 1.1).
    const Mat3d stretch = Vec3d(1.2, 1.1, 1.0 / 1.32).asDiagonal();
    for (double value : thickness(affine_displacement(slab, stretch)))
      EXPECT_NEAR(value, t / 1.32, 1e-14) << "order " << order;
    // A shear x += 0.6 z slides the top by 0.3 mm over the bottom (more than half an element of
    // 0.5 mm): the planes stay 0.5 mm apart, away from the ends, where the top overhangs.
    Mat3d shear = Mat3d::Identity();
    shear(0, 2) = 0.6;
    const std::vector<double> sheared = thickness(affine_displacement(slab, shear));
    for (std::size_t v = 0; v < sheared.size(); ++v) {
      if (slab.nodes[v].x() > 0.5 && slab.nodes[v].x() < 3.5) {
        EXPECT_NEAR(sheared[v], t, 1e-14) << "order " << order << ", node " << v;
      }
    }
  }
}

TEST(WallThickness, LayeredSphereBlownUpUniformly) {
  // x = λ X moves the faces of radius 10 and 11 to 10 λ and 11 λ. The layers' nodes lie on common
  // radii. Seen from the outer face the inner face's chords bend away, so its nearest point is a
  // node and the thickness is λ exactly. Seen from inside the wall the outer face's chords bend
  // towards the node: the distance is short by at most a factor cos(h / R) (h the edge, R the
  // radius), 1 − cos(0.15 λ / 1.3) < 1.2 %; measured 0.35 %.
  const Mesh sphere = test::sphere_shell(Symmetry::octant, 10.0, 1.0, 2, 1.5);
  const WallThickness thickness(sphere, {"inner", "outer"});
  const double lambda = 1.3;
  const std::vector<double> t = thickness(affine_displacement(sphere, lambda * Mat3d::Identity()));
  for (std::size_t v = 0; v < t.size(); ++v) {
    if (std::abs(sphere.nodes[v].norm() - 11.0) < 1e-9) {
      EXPECT_NEAR(t[v], lambda, 1e-12) << "outer node " << v;
    }
    EXPECT_LE(t[v], lambda * (1 + 1e-12)) << "node " << v;
    EXPECT_GE(t[v], lambda * std::cos(0.15)) << "node " << v;
  }
}

}  // namespace
}  // namespace plisse
