// Contact between surfaces of the body (docs/theory/surface-contact.md): on two stacked blocks
// with non-matching meshes, the tangent against central differences of the residual (N2, N3),
// the pairing rules (N4), the resultant of a uniform penetration (N7), the Uzawa update (N5),
// the declared couplings (N6) and the checkpoint; on two stacked shell sheets of different
// thicknesses, the faces half a thickness off the mid-surfaces (N14).
#include "physics/surface_contact.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <sstream>

#include "core/error.hpp"
#include "mesh/gmsh_io.hpp"
#include "mesh/shell_surface.hpp"
#include "physics/surface.hpp"
#include "support/term_testing.hpp"

namespace plisse {
namespace {

using test::DenseSink;
using test::random_state;
using test::term_residual;

Mesh two_blocks() {
  return read_gmsh(std::string(PLISSE_SOURCE_DIR) +
                   "/tests/verification/contact/meshes/two-blocks.msh");
}

SurfaceContactSettings settings(double penalty = 3.0, double tolerance = 1e-12) {
  SurfaceContactSettings s;
  s.name = "joint";
  s.penalty = penalty;
  s.tolerance = tolerance;
  s.search_distance = 0.5;
  return s;
}

TEST(SurfaceContact, TangentIsTheDerivativeOfTheResidual) {
  const Mesh mesh = two_blocks();
  const int n = kValuesPerNode * mesh.n_nodes();
  SurfaceContact term(mesh, settings(), outward_triangles(mesh, "upper_bottom"),
                      outward_triangles(mesh, "lower_top"), false);
  // Move every node of the upper block's bottom 0.02 mm down, plus noise of 0.005 mm on all.
  std::vector<double> x = random_state(n, 7, 0.005);
  for (int v : term.nodes()) x[node_dof(v, 2)] -= 0.02;
  const double t = 0.0;
  std::vector<double> scratch(n, 0.0);
  term.assemble(t, x, scratch, nullptr);
  ASSERT_TRUE(term.update_multipliers(x));  // lambda > 0: the curvature term of N3 counts
  EXPECT_GT(term.n_contact_nodes(x), 10);
  DenseSink sink(n);
  std::vector<double> r(n, 0.0);
  term.assemble(t, x, r, &sink);
  const double h = 1e-7, scale = sink.K.cwiseAbs().maxCoeff();
  // Pressures: the term does not depend on them.
  const double max_error = test::max_tangent_error(term, t, x, sink.K, h, true);
  std::ostringstream relative;
  relative << std::scientific << max_error / scale;
  RecordProperty("fd_relative_error", relative.str());
  EXPECT_LT(max_error, 1e-7 * scale);
  EXPECT_LT((sink.K - sink.K.transpose()).cwiseAbs().maxCoeff(), 1e-13 * scale);
}

/// The upper block moved rigidly by `shift` (all its nodes: those with z > 2, and the interface
/// nodes of its bottom, `term.nodes()`).
std::vector<double> upper_moved(const Mesh& mesh, const SurfaceContact& term, const Vec3d& shift) {
  std::vector<double> x(kValuesPerNode * mesh.n_nodes(), 0.0);
  std::set<int> upper(term.nodes().begin(), term.nodes().end());
  for (int v = 0; v < mesh.n_nodes(); ++v)
    if (mesh.nodes[v].z() > 2.0 + 1e-9) upper.insert(v);
  for (int v : upper)
    for (int k = 0; k < 3; ++k) x[node_dof(v, k)] = shift[k];
  return x;
}

/// The sum over the nodes of the term's residual at x: the net force of the pairs, zero when
/// each pushes its facet back as much as its node (N2).
Vec3d residual_sum(SurfaceContact& term, const Mesh& mesh, const std::vector<double>& x) {
  std::vector<double> r(x.size(), 0.0);
  term.assemble(0.0, x, r, nullptr);
  Vec3d sum = Vec3d::Zero();
  for (int v = 0; v < mesh.n_nodes(); ++v)
    for (int k = 0; k < 3; ++k) sum[k] += r[node_dof(v, k)];
  return sum;
}

SurfaceContact blocks_term(const Mesh& mesh, SurfaceContactSettings s = settings()) {
  return SurfaceContact(mesh, s, outward_triangles(mesh, "upper_bottom"),
                        outward_triangles(mesh, "lower_top"), false);
}

TEST(SurfaceContact, UniformPenetrationGivesPenaltyTimesAreaTimesDepth) {
  const Mesh mesh = two_blocks();
  SurfaceContact term = blocks_term(mesh);
  // At the reference state every node of the upper block's bottom lies on a facet of the lower
  // block's top (g = 0), which faces it.
  for (int f : term.pairs()) EXPECT_GE(f, 0);
  // The upper block 0.01 mm into the lower one: each node carries eps * 0.01 on its area, 16 mm^2
  // in all, pushed up (N2, N7).
  const auto x = upper_moved(mesh, term, Vec3d(0, 0, -0.01));
  EXPECT_TRUE(term.force(x).isApprox(Vec3d(0, 0, 3.0 * 0.01 * 16.0), 1e-12));
  EXPECT_NEAR(term.penetration(x), 0.01, 1e-14);
  EXPECT_EQ(term.n_contact_nodes(x), static_cast<int>(term.nodes().size()));
  // The facets' nodes get the opposite force: the residual sums to zero.
  EXPECT_LT(residual_sum(term, mesh, x).norm(), 1e-14);
  // Uzawa (N5): lambda = eps * 0.01 doubles the force at the same state; a rejected step
  // forgets it.
  ASSERT_TRUE(term.update_multipliers(x));
  EXPECT_TRUE(term.force(x).isApprox(Vec3d(0, 0, 2.0 * 3.0 * 0.01 * 16.0), 1e-12));
  term.reject_step();
  EXPECT_TRUE(term.force(x).isApprox(Vec3d(0, 0, 3.0 * 0.01 * 16.0), 1e-12));
  // Within the tolerance nothing changes.
  SurfaceContactSettings loose = settings();
  loose.tolerance = 0.02;
  SurfaceContact within = blocks_term(mesh, loose);
  EXPECT_FALSE(within.update_multipliers(x));
}

TEST(SurfaceContact, PairsNeedAFacingFacetWithinReach) {
  const Mesh mesh = two_blocks();
  const SurfaceContact term = blocks_term(mesh);
  // Lifted by more than the search distance 0.5 mm, no node finds a facet.
  for (int f : term.find_pairs(upper_moved(mesh, term, Vec3d(0, 0, 0.6)))) EXPECT_EQ(f, -1);
  for (int f : term.find_pairs(upper_moved(mesh, term, Vec3d(0, 0, 0.4)))) EXPECT_GE(f, 0);
  // Reversed, the lower block's top faces away from the upper block's top: the top's nodes,
  // 2 mm above, never pair even with a long reach; the upper block's bottom faces the lower's top.
  SurfaceContactSettings far = settings();
  far.search_distance = 5.0;
  const SurfaceContact away(mesh, far, outward_triangles(mesh, "lower_top"),
                            outward_triangles(mesh, "top"), false);
  for (int f : away.pairs()) EXPECT_EQ(f, -1);
  // Self-contact of the lower block's top: a flat surface never touches itself.
  const SurfaceContact flat(mesh, far, outward_triangles(mesh, "lower_top"),
                            outward_triangles(mesh, "lower_top"), true);
  for (int f : flat.pairs()) EXPECT_EQ(f, -1);
}

TEST(SurfaceContact, CouplingsGrowWithThePairsWithinReachAndTheCheckpointKeepsThem) {
  const Mesh mesh = two_blocks();
  SurfaceContactSettings s = settings();
  s.search_distance = 0.1;
  SurfaceContact term = blocks_term(mesh, s);
  EXPECT_TRUE(term.couplings_changed());  // the model reads the first pattern once
  EXPECT_FALSE(term.couplings_changed());
  std::vector<std::pair<int, int>> before;
  term.add_couplings(before);
  // Slid by 1 mm along x, the nodes reach facets they could not reach before (N6).
  const auto x = upper_moved(mesh, term, Vec3d(1.0, 0, -0.01));
  std::vector<double> r(x.size(), 0.0);
  term.assemble(0.0, x, r, nullptr);
  ASSERT_TRUE(term.update_multipliers(x));  // new pairs, penetration 0.01: solve again
  term.accept_step(x);
  EXPECT_TRUE(term.couplings_changed());
  EXPECT_FALSE(term.couplings_changed());
  std::vector<std::pair<int, int>> after;
  term.add_couplings(after);
  EXPECT_GT(after.size(), before.size());
  // Every pair declared before is still declared.
  std::sort(before.begin(), before.end());
  std::sort(after.begin(), after.end());
  EXPECT_TRUE(std::includes(after.begin(), after.end(), before.begin(), before.end()));
  // A checkpoint restores multipliers, pairs and the pattern.
  SurfaceContact restored = blocks_term(mesh, s);
  restored.load_state(term.save_state());
  EXPECT_TRUE(restored.couplings_changed());
  std::vector<std::pair<int, int>> again;
  restored.add_couplings(again);
  std::sort(again.begin(), again.end());
  EXPECT_EQ(again, after);
  EXPECT_EQ(restored.pairs(), term.pairs());
  EXPECT_TRUE(restored.force(x).isApprox(term.force(x), 1e-15));
  std::vector<double> broken = term.save_state();
  broken.pop_back();
  EXPECT_THROW(restored.load_state(broken), Error);
}

// --- Shells (N14) -------------------------------------------------------------------------------

constexpr double kUpperThickness = 0.5, kLowerThickness = 1.0;  // [mm]

/// Two flat shell sheets of 4 × 4 mm, non-matching: the upper (4 × 4 cells, thickness 0.5 mm)
/// with its mid-surface at z = `z`, the lower (5 × 5 cells, 1 mm) at z = 0. The upper's
/// triangles have the normal +z and the lower's −z, so that the tags `upper` and `lower`, which
/// name the face opposite the normals (Mesh::shell_face_side), are the two faces that look at
/// each other; `upper_top` names the upper sheet's other face.
Mesh stacked_sheets(double z) {
  Mesh mesh;
  const auto grid = [&](int n, double height, bool down) {
    const int first = mesh.n_nodes();
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) mesh.nodes.push_back(Vec3d(4.0 * i / n, 4.0 * j / n, height));
    std::vector<int> tags;
    const auto node = [&](int i, int j) { return first + j * (n + 1) + i; };
    const auto add = [&](int a, int b, int c) {
      tags.push_back(static_cast<int>(mesh.triangles.size()));
      mesh.triangles.push_back(down ? std::array<int, 3>{a, c, b} : std::array<int, 3>{a, b, c});
    };
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        add(node(i, j), node(i + 1, j), node(i + 1, j + 1));
        add(node(i, j), node(i + 1, j + 1), node(i, j + 1));
      }
    return tags;
  };
  mesh.surface_tags["upper"] = grid(4, z, false);
  mesh.surface_tags["upper_top"] = mesh.surface_tags["upper"];
  mesh.shell_face_side["upper_top"] = +1;
  mesh.surface_tags["lower"] = grid(5, 0.0, true);
  make_shell_surface(mesh, kUpperThickness);
  for (int t : mesh.surface_tags["lower"]) mesh.triangle_thickness[t] = kLowerThickness;
  return mesh;
}

SurfaceContact sheets_term(const Mesh& mesh, SurfaceContactSettings s = settings()) {
  return SurfaceContact(mesh, s, outward_triangles(mesh, "upper"), outward_triangles(mesh, "lower"),
                        false);
}

/// The upper sheet moved down by `depth` [mm].
std::vector<double> upper_lowered(const Mesh& mesh, double depth) {
  std::vector<double> x(kValuesPerNode * mesh.n_nodes(), 0.0);
  for (int v : mesh.surface_tags.at("upper"))
    for (int corner : mesh.triangles[v]) x[node_dof(corner, 2)] = -depth;
  return x;
}

TEST(SurfaceContact, ShellFacesMeetHalfTheirThicknessesOffTheMidSurfaces) {
  // The mid-surfaces 0.76 mm apart: the faces 0.76 - 0.25 - 0.5 = 0.01 mm apart (N14).
  const Mesh mesh = stacked_sheets(0.76);
  SurfaceContact term = sheets_term(mesh);
  ASSERT_EQ(term.nodes().size(), 25u);
  for (int f : term.pairs()) EXPECT_GE(f, 0);
  const auto apart = upper_lowered(mesh, 0.0);
  EXPECT_EQ(term.n_contact_nodes(apart), 0);
  EXPECT_EQ(term.penetration(apart), 0.0);
  // Lowered by 0.02 mm the faces overlap by 0.01 mm: eps * 0.01 on the 16 mm² of the upper sheet,
  // pushing it up (N2, N7); the residual sums to zero.
  const auto x = upper_lowered(mesh, 0.02);
  EXPECT_NEAR(term.penetration(x), 0.01, 1e-14);
  EXPECT_EQ(term.n_contact_nodes(x), 25);
  EXPECT_TRUE(term.force(x).isApprox(Vec3d(0, 0, 3.0 * 0.01 * 16.0), 1e-12));
  EXPECT_LT(residual_sum(term, mesh, x).norm(), 1e-14);
  // Either way round: the lower sheet's nodes against the upper's faces see the same overlap.
  const SurfaceContact reversed(mesh, settings(), outward_triangles(mesh, "lower"),
                                outward_triangles(mesh, "upper"), false);
  EXPECT_NEAR(reversed.penetration(x), 0.01, 1e-14);
  EXPECT_TRUE(reversed.force(x).isApprox(Vec3d(0, 0, -3.0 * 0.01 * 16.0), 1e-12));
}

TEST(SurfaceContact, ShellTangentIsTheDerivativeOfTheResidual) {
  const Mesh mesh = stacked_sheets(0.76);
  const int n = kValuesPerNode * mesh.n_nodes();
  SurfaceContact term = sheets_term(mesh);
  std::vector<double> x = random_state(n, 11, 0.005);
  for (int v : term.nodes()) x[node_dof(v, 2)] -= 0.03;
  std::vector<double> scratch(n, 0.0);
  term.assemble(0.0, x, scratch, nullptr);
  ASSERT_TRUE(term.update_multipliers(x));
  EXPECT_GT(term.n_contact_nodes(x), 10);
  DenseSink sink(n);
  std::vector<double> r(n, 0.0);
  term.assemble(0.0, x, r, &sink);
  const double scale = sink.K.cwiseAbs().maxCoeff();
  EXPECT_LT(test::max_tangent_error(term, 0.0, x, sink.K, 1e-7, true), 1e-7 * scale);
}

TEST(SurfaceContact, AShellsTwoFacesNeverTouchEachOtherOrAFlatFaceItself) {
  // The two faces of one sheet hold the same triangles a thickness apart, and face opposite
  // ways: the top's nodes would find the bottom's facets around them 0.5 mm "inside". A node
  // skips the facets touching its own faces on a shell (N4), so nothing pairs, however far the
  // search reaches.
  const Mesh mesh = stacked_sheets(0.76);
  SurfaceContactSettings far = settings();
  far.search_distance = 5.0;
  const SurfaceContact faces(mesh, far, outward_triangles(mesh, "upper_top"),
                             outward_triangles(mesh, "upper"), false);
  for (int f : faces.pairs()) EXPECT_EQ(f, -1);
  for (const char* face : {"upper", "upper_top", "lower"}) {
    const SurfaceContact flat(mesh, far, outward_triangles(mesh, face),
                              outward_triangles(mesh, face), true);
    for (int f : flat.pairs()) EXPECT_EQ(f, -1) << face;
  }
}

TEST(SurfaceContact, RefusesBadSettings) {
  const Mesh mesh = two_blocks();
  for (auto bad : {&SurfaceContactSettings::penalty, &SurfaceContactSettings::tolerance,
                   &SurfaceContactSettings::search_distance}) {
    SurfaceContactSettings s = settings();
    s.*bad = 0.0;
    EXPECT_THROW(blocks_term(mesh, s), Error);
  }
  EXPECT_THROW(SurfaceContact(mesh, settings(), {}, outward_triangles(mesh, "lower_top"), false),
               Error);
}

}  // namespace
}  // namespace plisse
