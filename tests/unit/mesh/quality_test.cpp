// check_mesh on small hand-made meshes: each defect is found and named.
#include "mesh/quality.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace plisse {
namespace {

bool mentions(const std::vector<std::string>& messages, const std::string& text) {
  for (const auto& m : messages)
    if (m.find(text) != std::string::npos) return true;
  return false;
}

/// One positive unit right tetrahedron with its four faces as tagged triangles.
Mesh one_tet() {
  Mesh mesh;
  mesh.nodes = {Vec3d(0, 0, 0), Vec3d(1, 0, 0), Vec3d(0, 1, 0), Vec3d(0, 0, 1)};
  mesh.tets = {{0, 1, 2, 3}};
  mesh.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  mesh.surface_tags["bottom"] = {0};
  mesh.surface_tags["rest"] = {1, 2, 3};
  return mesh;
}

TEST(CheckMesh, CleanTetrahedron) {
  const MeshReport r = check_mesh(one_tet(), {"bottom", "rest"});
  EXPECT_TRUE(r.ok());
  EXPECT_TRUE(r.warnings.empty());
  EXPECT_NEAR(r.min_volume, 1.0 / 6.0, 1e-15);
  EXPECT_EQ(r.n_boundary_faces, 4);
}

TEST(CheckMesh, RegularTetrahedronHasAspectRatioOne) {
  Mesh mesh;
  mesh.nodes = {Vec3d(1, 1, 1), Vec3d(1, -1, -1), Vec3d(-1, 1, -1), Vec3d(-1, -1, 1)};
  mesh.tets = {{0, 1, 2, 3}};
  const double v = (mesh.nodes[1] - mesh.nodes[0])
                       .dot((mesh.nodes[2] - mesh.nodes[0]).cross(mesh.nodes[3] - mesh.nodes[0]));
  if (v < 0) std::swap(mesh.tets[0][1], mesh.tets[0][2]);
  const MeshReport r = check_mesh(mesh);
  EXPECT_TRUE(r.ok());
  EXPECT_NEAR(r.max_aspect_ratio, 1.0, 1e-12);
}

TEST(CheckMesh, FindsInvertedTetrahedronWithIndexAndVolume) {
  Mesh mesh = one_tet();
  std::swap(mesh.tets[0][1], mesh.tets[0][2]);
  const MeshReport r = check_mesh(mesh);
  EXPECT_FALSE(r.ok());
  EXPECT_TRUE(mentions(
      r.errors,
      "tetrahedron 1 (centred at [0.25, 0.25, 0.25]) is inverted (volume -0.166667 mm^3)"));
  EXPECT_NEAR(r.min_volume, -1.0 / 6.0, 1e-15);
}

TEST(CheckMesh, FindsDegenerateTetrahedron) {
  Mesh mesh = one_tet();
  mesh.nodes[3] = Vec3d(0.3, 0.3, 0.0);  // in the plane of the other three
  // Named by its place among the tetrahedra counted from 1, and by its centre.
  EXPECT_TRUE(mentions(check_mesh(mesh).errors,
                       "tetrahedron 1 (centred at [0.325, 0.325, 0]) is degenerate"));
}

TEST(CheckMesh, WarnsAboutUnusedNode) {
  Mesh mesh = one_tet();
  mesh.nodes.emplace_back(5, 5, 5);
  const MeshReport r = check_mesh(mesh);
  EXPECT_TRUE(r.ok());
  EXPECT_EQ(r.n_unused_nodes, 1);
  EXPECT_TRUE(mentions(r.warnings, "1 nodes are used by no tetrahedron (first: 4)"));
}

TEST(CheckMesh, FindsMissingAndEmptyRequiredTags) {
  Mesh mesh = one_tet();
  mesh.surface_tags["inner"] = {};
  const MeshReport r = check_mesh(mesh, {"inner", "outer", "bottom"});
  EXPECT_TRUE(mentions(r.errors, "required tag 'inner' is empty"));
  EXPECT_TRUE(mentions(r.errors, "required tag 'outer' is missing"));
  EXPECT_FALSE(mentions(r.errors, "'bottom'"));
}

TEST(CheckMesh, FindsTagIndexOutOfRange) {
  Mesh mesh = one_tet();
  mesh.surface_tags["rest"].push_back(7);
  EXPECT_TRUE(mentions(check_mesh(mesh).errors, "tag 'rest' lists triangle 7"));
}

TEST(CheckMesh, FindsTriangleThatIsNoFace) {
  Mesh mesh = one_tet();
  mesh.nodes.emplace_back(2, 2, 2);
  mesh.triangles.push_back({1, 2, 4});
  EXPECT_TRUE(mentions(check_mesh(mesh).errors,
                       "triangle 4 (nodes 1, 2, 4) is not a face of any tetrahedron"));
}

TEST(CheckMesh, WarnsAboutInteriorTriangle) {
  Mesh mesh = one_tet();
  mesh.nodes.emplace_back(1, 1, 1);
  mesh.tets.push_back({1, 2, 3, 4});  // shares face (1, 2, 3), positive
  mesh.triangles.push_back({1, 2, 3});
  const MeshReport r = check_mesh(mesh);
  EXPECT_TRUE(r.ok()) << (r.errors.empty() ? "" : r.errors.front());
  EXPECT_TRUE(mentions(r.warnings, "interior faces"));
}

TEST(CheckMesh, FindsNonManifoldEdge) {
  // Two tetrahedra touching along the edge (0, 1) only: four boundary faces meet there.
  Mesh mesh;
  mesh.nodes = {Vec3d(0, 0, 0), Vec3d(1, 0, 0),  Vec3d(0, 1, 0),
                Vec3d(0, 0, 1), Vec3d(0, -1, 0), Vec3d(0, 0, -1)};
  mesh.tets = {{0, 1, 2, 3}, {0, 1, 4, 5}};
  const MeshReport r = check_mesh(mesh);
  EXPECT_GT(r.min_volume, 0.0);
  EXPECT_TRUE(mentions(r.errors, "boundary edge (0, 1) is shared by 4 boundary faces"));
}

TEST(CheckMesh, FindsNodeIndexOutOfRange) {
  Mesh mesh = one_tet();
  mesh.tets[0][3] = 11;
  EXPECT_TRUE(mentions(check_mesh(mesh).errors, "tetrahedron 0 references node 11"));
}

TEST(CheckMesh, FindsInconsistentEdgeNodes) {
  Mesh mesh = one_tet();
  mesh.nodes.emplace_back(1, 1, 1);
  mesh.tets.push_back({1, 2, 3, 4});
  for (int i = 0; i < 12; ++i)
    mesh.nodes.emplace_back(0.1 * i, 0.5, 0.5);  // stand-in edge nodes 5..16
  mesh.tet_edge_nodes = {{5, 6, 7, 8, 9, 10},
                         {11, 12, 13, 14, 15, 16}};  // edges shared, nodes differ
  EXPECT_TRUE(mentions(check_mesh(mesh).errors, "has different edge nodes"));
}

}  // namespace
}  // namespace plisse
