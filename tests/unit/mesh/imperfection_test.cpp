// Geometric imperfections (mesh/imperfection.hpp, docs/theory/imperfections.md): reproducible
// seeded fields, exact amplitude, rigid through-thickness columns on a layered shell (the wall
// keeps its thickness), symmetry planes kept, the mesh check after applying, mode scaling.
#include "mesh/imperfection.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <set>

#include "core/error.hpp"
#include "mesh/generate.hpp"
#include "mesh/quality.hpp"
#include "mesh/topology.hpp"

namespace plisse {
namespace {

constexpr int kLayers = 2;
constexpr double kThickness = 1.0;  // [mm]

/// Quarter spherical shell, inner radius 10 mm, wall 1 mm, 2 layers: node k of layer j is
/// j n + k (mesh/layered_shell.hpp), so the column of node i is {i mod n + j n}.
MeshGenerationSpec quarter_shell_spec() {
  MeshGenerationSpec spec;
  spec.kind = "spherical-shell";
  spec.inner_radius = 10.0;
  spec.thickness = kThickness;
  spec.layers = kLayers;
  spec.element_size = 2.0;
  spec.symmetry = Symmetry::quarter;
  return spec;
}

const Mesh& quarter_shell() {
  static const Mesh mesh = generate_mesh(quarter_shell_spec());
  return mesh;
}

std::vector<std::array<int, 3>> tagged(const Mesh& mesh, const std::string& tag) {
  std::vector<std::array<int, 3>> out;
  for (int t : mesh.surface_tags.at(tag))
    out.push_back(mesh.triangles[static_cast<std::size_t>(t)]);
  return out;
}

std::vector<Vec3d> random_field(double amplitude, std::uint64_t seed) {
  const Mesh& mesh = quarter_shell();
  return compute_random_imperfection(mesh, tagged(mesh, "outer"), amplitude, seed,
                                     {"sym_x", "sym_z"});
}

double max_norm(const std::vector<Vec3d>& d) {
  double m = 0.0;
  for (const Vec3d& v : d) m = std::max(m, v.norm());
  return m;
}

TEST(SeededUnitValue, MapsTheEngineRangeOntoMinusOneOne) {
  EXPECT_EQ(seeded_unit_value(0), -1.0);
  EXPECT_EQ(seeded_unit_value(~std::uint64_t{0}), 1.0 - 0x1.0p-52);
  EXPECT_EQ(seeded_unit_value(std::uint64_t{1} << 63), 0.0);
  // The 10000th output of a default-seeded mt19937_64 is fixed by the C++ standard
  // ([rand.predef]); its image is a plain binary fraction, the same on every platform.
  std::mt19937_64 engine;
  engine.discard(9999);
  const std::uint64_t u = engine();
  ASSERT_EQ(u, 9981545732273789042ULL);
  EXPECT_EQ(seeded_unit_value(u), static_cast<double>(u >> 11) / 4503599627370496.0 - 1.0);
}

TEST(RandomImperfection, SameSeedGivesTheSameFieldExactly) {
  const auto a = random_field(0.05, 42);
  const auto b = random_field(0.05, 42);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t j = 0; j < a.size(); ++j) {
    EXPECT_EQ(a[j].x(), b[j].x());
    EXPECT_EQ(a[j].y(), b[j].y());
    EXPECT_EQ(a[j].z(), b[j].z());
  }
}

TEST(RandomImperfection, OtherSeedGivesAnotherField) {
  const auto a = random_field(0.05, 42);
  const auto b = random_field(0.05, 43);
  double difference = 0.0;
  for (std::size_t j = 0; j < a.size(); ++j)
    difference = std::max(difference, (a[j] - b[j]).norm());
  EXPECT_GT(difference, 0.01);  // two independent fields of amplitude 0.05 mm
}

TEST(RandomImperfection, LargestDisplacementIsTheAmplitude) {
  for (double a : {1e-4, 0.05, 0.2}) EXPECT_NEAR(max_norm(random_field(a, 7)), a, 1e-15 * a);
}

TEST(RandomImperfection, ColumnsMoveRigidlySoTheWallKeepsItsThickness) {
  const Mesh& mesh = quarter_shell();
  const auto d = random_field(0.1, 3);
  const std::size_t n = mesh.nodes.size() / (kLayers + 1);
  ASSERT_EQ(n * (kLayers + 1), mesh.nodes.size());
  for (std::size_t j = 0; j < mesh.nodes.size(); ++j) {
    const std::size_t outer = kLayers * n + j % n;
    // Same vector as the column's outer node: bit for bit (a copy, then one scaling).
    EXPECT_EQ(d[j].x(), d[outer].x()) << "node " << j;
    EXPECT_EQ(d[j].y(), d[outer].y()) << "node " << j;
    EXPECT_EQ(d[j].z(), d[outer].z()) << "node " << j;
  }
  Mesh perturbed = mesh;
  apply_imperfection(perturbed, d);
  for (std::size_t k = 0; k < n; ++k) {
    const double wall = (perturbed.nodes[kLayers * n + k] - perturbed.nodes[k]).norm();
    EXPECT_NEAR(wall, kThickness, 1e-12) << "column " << k;
  }
}

TEST(RandomImperfection, AirbagColumnsMoveRigidlyToo) {
  // The airbag's wall is offset along the normals of an oblate spheroid (unequal curvatures):
  // the nearest outer node of every node is still the one of its own column.
  MeshGenerationSpec spec;
  spec.kind = "airbag";
  spec.radius = 20.0;
  spec.height = 8.0;
  spec.thickness = 0.8;
  spec.layers = 2;
  spec.element_size = 2.5;
  spec.symmetry = Symmetry::octant;
  const Mesh mesh = generate_mesh(spec);
  const auto d = compute_random_imperfection(mesh, tagged(mesh, "outer"), 0.05, 2,
                                             {"sym_x", "sym_y", "sym_z"});
  const std::size_t n = mesh.nodes.size() / 3;
  ASSERT_EQ(3 * n, mesh.nodes.size());
  int mismatches = 0;
  for (std::size_t j = 0; j < mesh.nodes.size(); ++j)
    if (d[j] != d[2 * n + j % n]) ++mismatches;
  EXPECT_EQ(mismatches, 0);
  EXPECT_NEAR(max_norm(d), 0.05, 1e-17);
}

TEST(RandomImperfection, SecondOrderShellTakesTheCornerFieldLinearAlongEdges) {
  // (I1b): on a 10-node mesh the corners take the field of the linear mesh (same seed: the same
  // draws on the same outer corners) and each edge node the mean of its edge's corners, after
  // the symmetry projection; the perturbed mesh passes the check.
  MeshGenerationSpec spec = quarter_shell_spec();
  spec.order = 2;
  Mesh mesh = generate_mesh(spec);
  const auto d =
      compute_random_imperfection(mesh, tagged(mesh, "outer"), 0.1, 3, {"sym_x", "sym_z"});
  const std::vector<Vec3d> linear = random_field(0.1, 3);
  const double scale = max_norm(d);
  EXPECT_NEAR(scale, 0.1, 1e-17);
  // The linear field's largest value is at a corner, so the two scalings agree.
  for (std::size_t j = 0; j < linear.size(); ++j) EXPECT_LT((d[j] - linear[j]).norm(), 1e-15);
  for (std::size_t t = 0; t < mesh.tets.size(); ++t)
    for (int k = 0; k < 6; ++k) {
      const int m = mesh.tet_edge_nodes[t][k];
      const Vec3d mean =
          0.5 * (d[mesh.tets[t][kTetEdges[k][0]]] + d[mesh.tets[t][kTetEdges[k][1]]]);
      EXPECT_LT((d[m] - mean).norm(), 1e-16);  // the scaling follows the mean: round-off only
    }
  for (const std::string tag : {"sym_x", "sym_z"}) {
    const int axis = tag == "sym_x" ? 0 : 2;
    for (int t : mesh.surface_tags.at(tag))
      for (int m : mesh.triangle_edge_nodes[t]) EXPECT_EQ(d[m][axis], 0.0) << tag;
  }
  EXPECT_NO_THROW(apply_imperfection(mesh, d));
}

TEST(RandomImperfection, DisplacementIsAlongTheOutwardNormal) {
  // On a sphere the area-weighted normal is close to radial: the outer nodes move mostly radially.
  const Mesh& mesh = quarter_shell();
  const auto d = random_field(0.1, 5);
  int outward = 0, inward = 0;
  for (std::size_t j = 0; j < mesh.nodes.size(); ++j) {
    if (d[j].norm() < 1e-3) continue;
    const double cosine = d[j].normalized().dot(mesh.nodes[j].normalized());
    EXPECT_GT(std::abs(cosine), 0.98) << "node " << j;
    (cosine > 0 ? outward : inward) += 1;
  }
  EXPECT_GT(outward, 10);  // values in [-1, 1): both directions occur
  EXPECT_GT(inward, 10);
}

TEST(RandomImperfection, SymmetryPlanesAreKept) {
  Mesh mesh = quarter_shell();
  apply_imperfection(mesh, random_field(0.1, 11));
  for (int t : mesh.surface_tags.at("sym_x"))
    for (int v : mesh.triangles[static_cast<std::size_t>(t)])
      EXPECT_EQ(mesh.nodes[static_cast<std::size_t>(v)].x(), 0.0);
  for (int t : mesh.surface_tags.at("sym_z"))
    for (int v : mesh.triangles[static_cast<std::size_t>(t)])
      EXPECT_EQ(mesh.nodes[static_cast<std::size_t>(v)].z(), 0.0);
}

TEST(RandomImperfection, PerturbedMeshPassesTheQualityCheck) {
  Mesh mesh = quarter_shell();
  apply_imperfection(mesh, random_field(0.05 * kThickness, 1));
  const MeshReport report = check_mesh(mesh, {"inner", "outer", "sym_x", "sym_z"});
  EXPECT_TRUE(report.ok()) << (report.errors.empty() ? "" : report.errors.front());
  EXPECT_GT(report.min_volume, 0.0);
}

TEST(RandomImperfection, TooLargeAmplitudeIsRefusedAndTheMeshKept) {
  Mesh mesh = quarter_shell();
  // Shearing columns along themselves keeps element volumes; moving nodes inward past the
  // centre (radius 10 mm) inverts elements.
  const auto d = random_field(50.0 * kThickness, 1);
  try {
    apply_imperfection(mesh, d);
    FAIL() << "an amplitude of 50 wall thicknesses was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("too large"), std::string::npos) << e.what();
  }
  const Mesh& original = quarter_shell();
  for (std::size_t j = 0; j < mesh.nodes.size(); ++j)
    EXPECT_EQ((mesh.nodes[j] - original.nodes[j]).norm(), 0.0);
}

TEST(RandomImperfection, RejectsBadInput) {
  const Mesh& mesh = quarter_shell();
  const auto outer = tagged(mesh, "outer");
  EXPECT_THROW(compute_random_imperfection(mesh, outer, 0.0, 1), Error);
  EXPECT_THROW(compute_random_imperfection(mesh, outer, std::nan(""), 1), Error);
  EXPECT_THROW(compute_random_imperfection(mesh, {}, 0.1, 1), Error);
  EXPECT_THROW(compute_random_imperfection(mesh, outer, 0.1, 1, {"no_such_tag"}), Error);
  EXPECT_THROW(compute_random_imperfection(mesh, outer, 0.1, 1, {"outer"}), Error);  // not planar
  const std::vector<std::array<int, 3>> out_of_range = {{0, 1, mesh.n_nodes()}};
  EXPECT_THROW(compute_random_imperfection(mesh, out_of_range, 0.1, 1), Error);
  const std::vector<std::array<int, 3>> not_a_face = {{0, 0, 1}};
  EXPECT_THROW(compute_random_imperfection(mesh, not_a_face, 0.1, 1), Error);
}

TEST(RandomImperfection, WorksOnAFlatSheetAndItsEdges) {
  // A flat box: the grid has a thin axis; every node of a vertical column moves with its top node.
  MeshGenerationSpec spec;
  spec.kind = "sheet";
  spec.length = 6.0;
  spec.width = 4.0;
  spec.thickness = 0.5;
  spec.layers = 2;
  spec.element_size = 1.0;
  const Mesh mesh = generate_mesh(spec);
  const auto d = compute_random_imperfection(mesh, tagged(mesh, "top"), 0.01, 9);
  EXPECT_NEAR(max_norm(d), 0.01, 1e-17);
  for (std::size_t j = 0; j < mesh.nodes.size(); ++j) {
    // top normal is +z; nodes of the side faces keep an in-plane x, y
    EXPECT_EQ(d[j].x(), 0.0);
    EXPECT_EQ(d[j].y(), 0.0);
  }
}

/// The mid-surface of the quarter shell above (radius 10.5 mm, element: shell), whose symmetry
/// edges sym_x and sym_z lie in the planes x = 0 and z = 0.
const Mesh& quarter_mid_surface() {
  static const Mesh mesh = generate_shell_surface(quarter_shell_spec());
  return mesh;
}

/// The nodes of the edge tag `tag` held in the plane normal to axis `axis` (what the model
/// builder gives for a symmetry edge: its nodes and the axis shell_edge_plane_axis decides).
HeldPlane edge_plane(const Mesh& mesh, const std::string& tag, int axis) {
  const std::set<int> nodes = edge_nodes(mesh, mesh.edge_tags.at(tag));
  return {std::vector<int>(nodes.begin(), nodes.end()), Vec3d::Unit(axis)};
}

std::vector<Vec3d> shell_field(double amplitude, std::uint64_t seed) {
  const Mesh& mesh = quarter_mid_surface();
  return compute_random_imperfection(mesh, tagged(mesh, "outer"), amplitude, seed, {},
                                     {edge_plane(mesh, "sym_x", 0), edge_plane(mesh, "sym_z", 2)});
}

// (I1s): on a shell the field is ξ_k n_k at every node of the surface, n_k the area-weighted
// normal of its triangles (computed here again from the triangles), scaled so its largest norm is
// the amplitude; on a symmetry edge the component normal to the plane is removed.
TEST(ShellRandomImperfection, IsAlongTheNodeNormalsWithTheAmplitudeAndKeepsTheSymmetryPlanes) {
  const Mesh& mesh = quarter_mid_surface();
  ASSERT_TRUE(mesh.is_shell());
  ASSERT_TRUE(mesh.tets.empty());
  std::vector<Vec3d> normal(mesh.nodes.size(), Vec3d::Zero());
  for (const auto& t : mesh.triangles) {
    const Vec3d n =
        (mesh.nodes[t[1]] - mesh.nodes[t[0]]).cross(mesh.nodes[t[2]] - mesh.nodes[t[0]]);
    for (int v : t) normal[v] += n;
  }
  const std::set<int> on_x = edge_nodes(mesh, mesh.edge_tags.at("sym_x"));
  const std::set<int> on_z = edge_nodes(mesh, mesh.edge_tags.at("sym_z"));
  ASSERT_FALSE(on_x.empty());
  ASSERT_FALSE(on_z.empty());
  for (double a : {1e-4, 0.05}) {
    const auto d = shell_field(a, 7);
    EXPECT_NEAR(max_norm(d), a, 1e-15 * a);
    double tangent = 0.0, tangent_edge = 0.0;
    int moved = 0;
    for (std::size_t j = 0; j < d.size(); ++j) {
      Vec3d n = normal[j].normalized();
      const bool x_plane = on_x.count(static_cast<int>(j)) != 0;
      const bool z_plane = on_z.count(static_cast<int>(j)) != 0;
      if (x_plane) {
        EXPECT_EQ(d[j].x(), 0.0) << "node " << j;
      }
      if (z_plane) {
        EXPECT_EQ(d[j].z(), 0.0) << "node " << j;
      }
      // On an edge the direction is the normal without its component across the plane.
      if (x_plane) n.x() = 0.0;
      if (z_plane) n.z() = 0.0;
      n.normalize();
      const double off = (d[j] - n.dot(d[j]) * n).norm();
      double& largest = x_plane || z_plane ? tangent_edge : tangent;
      largest = std::max(largest, off);
      if (d[j].norm() > 1e-3 * a) ++moved;
    }
    std::printf("amplitude %g mm: largest tangent component %.2e mm (edges %.2e mm)\n", a, tangent,
                tangent_edge);
    EXPECT_LT(tangent, 1e-14 * a);  // round-off of a normalised vector times a
    EXPECT_LT(tangent_edge, 1e-14 * a);
    EXPECT_GT(moved, static_cast<int>(d.size()) / 2);  // ξ is uniform in [-1, 1)
  }
}

TEST(ShellRandomImperfection, SameSeedGivesTheSameFieldExactlyAndAnotherSeedAnother) {
  const auto a = shell_field(0.05, 42), b = shell_field(0.05, 42), c = shell_field(0.05, 43);
  ASSERT_EQ(a.size(), b.size());
  double difference = 0.0;
  for (std::size_t j = 0; j < a.size(); ++j) {
    EXPECT_EQ(a[j].x(), b[j].x());
    EXPECT_EQ(a[j].y(), b[j].y());
    EXPECT_EQ(a[j].z(), b[j].z());
    difference = std::max(difference, (a[j] - c[j]).norm());
  }
  EXPECT_GT(difference, 0.01);
}

TEST(ShellRandomImperfection, TheInnerFaceGivesTheSameFieldAndTheMeshStaysAShell) {
  // Both faces' tags list every triangle in the same orientation: the same field.
  const Mesh& mesh = quarter_mid_surface();
  const auto outer = shell_field(0.05, 3);
  const auto inner =
      compute_random_imperfection(mesh, tagged(mesh, "inner"), 0.05, 3, {},
                                  {edge_plane(mesh, "sym_x", 0), edge_plane(mesh, "sym_z", 2)});
  for (std::size_t j = 0; j < outer.size(); ++j) EXPECT_EQ(outer[j], inner[j]);
  Mesh perturbed = mesh;
  apply_imperfection(perturbed, outer);
  EXPECT_TRUE(check_mesh(perturbed).ok());
  for (int v : edge_nodes(mesh, mesh.edge_tags.at("sym_x"))) EXPECT_EQ(perturbed.nodes[v].x(), 0.0);
  for (int v : edge_nodes(mesh, mesh.edge_tags.at("sym_z"))) EXPECT_EQ(perturbed.nodes[v].z(), 0.0);
}

TEST(ShellRandomImperfection, NodesOffTheTaggedTrianglesStayAndSurfaceTagsAreNoPlanes) {
  const Mesh& mesh = quarter_mid_surface();
  // Half of the triangles: the nodes of none of them keep d = 0.
  std::vector<std::array<int, 3>> half(mesh.triangles.begin(),
                                       mesh.triangles.begin() + mesh.triangles.size() / 2);
  std::set<int> nodes;
  for (const auto& t : half) nodes.insert(t.begin(), t.end());
  const auto d = compute_random_imperfection(mesh, half, 0.05, 3);
  int held = 0;
  for (std::size_t j = 0; j < d.size(); ++j)
    if (!nodes.count(static_cast<int>(j))) {
      EXPECT_EQ(d[j], Vec3d::Zero()) << "node " << j;
      ++held;
    }
  EXPECT_GT(held, 0);
  EXPECT_NEAR(max_norm(d), 0.05, 1e-15 * 0.05);
  EXPECT_THROW(compute_random_imperfection(mesh, tagged(mesh, "outer"), 0.05, 3, {"outer"}), Error);
  EXPECT_THROW(compute_random_imperfection(mesh, tagged(mesh, "outer"), 0.05, 3, {},
                                           {HeldPlane{{mesh.n_nodes()}, Vec3d::UnitX()}}),
               Error);
  EXPECT_THROW(compute_random_imperfection(mesh, tagged(mesh, "outer"), 0.05, 3, {},
                                           {HeldPlane{{0}, Vec3d::Zero()}}),
               Error);
}

TEST(ModeImperfection, ScalesTheLargestNodalVectorToTheAmplitude) {
  const Mesh& mesh = quarter_shell();
  std::vector<Vec3d> shape(mesh.nodes.size());
  for (std::size_t j = 0; j < shape.size(); ++j)
    shape[j] = Vec3d(std::sin(0.3 * mesh.nodes[j].x()), 2.0 * std::cos(mesh.nodes[j].y()), 0.5);
  const double largest = max_norm(shape);
  const auto d = compute_mode_imperfection(mesh, shape, 0.02);
  EXPECT_NEAR(max_norm(d), 0.02, 1e-17);
  for (std::size_t j = 0; j < shape.size(); ++j)
    EXPECT_NEAR((d[j] - 0.02 / largest * shape[j]).norm(), 0.0, 1e-17);
  Mesh perturbed = mesh;
  apply_imperfection(perturbed, d);
  for (std::size_t j = 0; j < shape.size(); ++j)
    EXPECT_NEAR((perturbed.nodes[j] - mesh.nodes[j] - d[j]).norm(), 0.0, 1e-14);
}

TEST(ModeImperfection, RejectsZeroNonFiniteAndMismatchedModes) {
  const Mesh& mesh = quarter_shell();
  std::vector<Vec3d> zero(mesh.nodes.size(), Vec3d::Zero());
  EXPECT_THROW(compute_mode_imperfection(mesh, zero, 0.1), Error);
  std::vector<Vec3d> short_mode(3, Vec3d::Ones());
  EXPECT_THROW(compute_mode_imperfection(mesh, short_mode, 0.1), Error);
  std::vector<Vec3d> nan_mode(mesh.nodes.size(), Vec3d::Ones());
  nan_mode[5].y() = std::nan("");
  EXPECT_THROW(compute_mode_imperfection(mesh, nan_mode, 0.1), Error);
  std::vector<Vec3d> ones(mesh.nodes.size(), Vec3d::Ones());
  EXPECT_THROW(compute_mode_imperfection(mesh, ones, -1.0), Error);
}

}  // namespace
}  // namespace plisse
