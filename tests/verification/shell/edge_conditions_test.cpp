// The edge conditions of the shell triangle (docs/theory/shell.md, KL8 and KL8a) against the
// closed forms of a strip in cylindrical bending.
//
// A strip of length L (x), width W (y) and thickness t, flat in z = 0, under a small uniform
// pressure q on its bottom face (pushing along +z), held along its long edges y = 0 and y = W by
// symmetry conditions (v = 0 and zero slope across: plane strain in y). Its ends x = 0 and x = L
// are clamped or hinged. The incompressible neo-Hookean sheet (W = c1 (I1 - 3), μ = 2 c1) bends
// in plane strain with the rigidity
//   D = E t³ / (12 (1 - ν²)) = μ t³ / 3        (E = 3 μ, ν = 1/2; shell.md, KL13),
// and the beam theory of a strip gives the deflection at mid-span
//   clamped ends: w = q L⁴ / (384 D),    hinged ends: w = 5 q L⁴ / (384 D)
// (Timoshenko & Woinowsky-Krieger 1959, §1-§3). The load is small (w/t about 10⁻²) so that the
// membrane force of the immovable ends changes the deflection by a part O((w/t)²) below 10⁻⁴.
//
// The half strip x <= L/2 with a symmetry edge at x = L/2 must give the clamped strip's
// deflection too: there the symmetry side mirrors the node across the plane (KL8a), so the strip
// meets the plane at a right angle; a free side there (KL8) would let the strip kink.
//
// The strips are meshed three ways: every cell cut along the same diagonal, cells cut along
// alternating diagonals, and the alternating cells with their inner nodes moved. A curvature that
// is linear in the nodal positions converges on a mesh when it passes two patch tests on it
// (shell.md, KL6a): it is exact for every quadratic, and a constant moment does no work on a node
// inside the mesh, which holds when the two elements of a side use the same gradient on it. The
// element's side gradient, the mean of the two elements' quadratic fits on a 12-node patch (KL3b),
// passes both on all three meshes, and the strips converge at second order on each.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "element/shell_geometry.hpp"
#include "material/registry.hpp"
#include "mesh/shell_surface.hpp"
#include "physics/dirichlet.hpp"
#include "shell_fixtures.hpp"
#include "solver/mixed_model.hpp"
#include "solver/shell_element.hpp"

namespace plisse {
namespace {

using namespace shell_test::strip_constants;  // c1, L, W, t and D of the strip

using shell_test::Cells;

/// The strip [0, length] x [0, W] with the constants above (shell_fixtures.hpp); distorted cells
/// keep the nodes at mid-span at x = L/2.
Mesh strip(double length, int nx, int ny, Cells cells) {
  return shell_test::strip_mesh(length, kWidth, kThickness, nx, ny, cells, kLength / 2.0);
}

/// Triangle e of a shell mesh as the element sees it (KL1b): its 12 nodes, a missing one
/// repeating the corner it stands for, its reference geometry, and whether every slot is a node.
struct Patch {
  std::array<int, ShellElement::kNodes> nodes;
  shell::ShellGeometry geometry;
  bool inner = false;
};

Patch patch_of(const Mesh& mesh, std::size_t e) {
  Patch patch;
  patch.nodes = ShellElement::nodes(mesh, static_cast<int>(e));
  patch.geometry = ShellElement::geometry(mesh, static_cast<int>(e), patch.nodes).patch;
  patch.inner = std::all_of(patch.geometry.slots.begin(), patch.geometry.slots.end(),
                            [](shell::Slot s) { return s == shell::Slot::node; });
  return patch;
}

/// The two conditions that a curvature linear in the nodal positions must meet for the bending
/// of a flat mesh to converge (shell.md, KL6a), measured on the inner elements of a strip:
/// - `exactness`: the largest error of an element's curvature (KL6) of the quadratic
///   w = (x² + 0.6 x y - 0.4 y²)/2 [1/mm] lifted along z, against its Hessian, relative to it;
/// - `continuity`: the constant-moment patch test, Σ_e A_e ∂b^e/∂w_n = 0 for every node n whose
///   elements all have their three neighbours (the discrete divergence theorem: a constant moment
///   does no work on a node inside the mesh), the largest |Σ| relative to one element's A_e
///   |∂b/∂w_n|.
struct PatchTestErrors {
  double exactness = 0.0;
  double continuity = 0.0;
};

PatchTestErrors patch_test_errors(const Mesh& mesh) {
  const int n_nodes = mesh.n_nodes();
  std::vector<Vec3d> sum(static_cast<std::size_t>(n_nodes), Vec3d::Zero());
  std::vector<bool> outer(static_cast<std::size_t>(n_nodes), false);
  double scale = 0.0;
  PatchTestErrors errors;
  const Mat3d H = (Mat3d() << 1.0, 0.3, 0.0, 0.3, -0.4, 0.0, 0.0, 0.0, 0.0).finished();
  for (std::size_t e = 0; e < mesh.triangles.size(); ++e) {
    const Patch patch = patch_of(mesh, e);
    const auto& nodes = patch.nodes;
    const shell::ShellGeometry& g = patch.geometry;
    const bool inner = patch.inner;
    const Vec3d e1 = g.frame.col(0), e2 = g.frame.col(1);
    for (int a = 0; a < ShellElement::kNodes; ++a) {
      // ∂b/∂w_a in the element's frame (e1, e2), turned into the mesh's (x, y).
      const Mat3d K = g.curvature[0](a) * e1 * e1.transpose() +
                      g.curvature[1](a) * e2 * e2.transpose() +
                      g.curvature[2](a) * (e1 * e2.transpose() + e2 * e1.transpose());
      const Vec3d k(K(0, 0), K(1, 1), K(0, 1));
      sum[nodes[a]] += g.area * k;
      if (!inner) outer[nodes[a]] = true;
      scale = std::max(scale, g.area * k.norm());
    }
    if (!inner) continue;
    Vec3d b = Vec3d::Zero();
    for (int a = 0; a < ShellElement::kNodes; ++a) {
      const Vec3d& p = mesh.nodes[nodes[a]];
      b += Vec3d(g.curvature[0](a), g.curvature[1](a), g.curvature[2](a)) * 0.5 * p.dot(H * p);
    }
    const Vec3d exact(e1.dot(H * e1), e2.dot(H * e2), e1.dot(H * e2));
    errors.exactness = std::max(errors.exactness, (b - exact).norm() / H.norm());
  }
  for (int n = 0; n < n_nodes; ++n)
    if (!outer[n]) errors.continuity = std::max(errors.continuity, sum[n].norm() / scale);
  return errors;
}

/// clamped_and_symmetric: the half strip, clamped at x = 0 and symmetric at x = L/2 (u_x = 0 and
/// the mirrored side of KL8a); clamped_and_plane_held: the same with u_x = 0 only, the side at
/// x = L/2 left free to turn (KL8): what the half strip gives without the mirror.
enum class Ends { clamped, hinged, clamped_and_symmetric, clamped_and_plane_held };

/// The deflection [mm] at mid-span (the mean over the nodes at x = L/2) of the strip of nx cells
/// along L (nx / 5 across, at least 2: cells of 2:1) with the given ends under the pressure q
/// [MPa]; for clamped_and_symmetric the half strip of nx / 2 cells, clamped at x = 0, symmetric at
/// x = L/2.
double mid_span_deflection(Ends ends, int nx, double q, Cells cells = Cells::same_diagonal) {
  const bool half = ends == Ends::clamped_and_symmetric || ends == Ends::clamped_and_plane_held;
  Mesh mesh = strip(half ? kLength / 2.0 : kLength, half ? nx / 2 : nx, std::max(2, nx / 5), cells);
  ConstraintSet set;
  const SurfaceRef left{"left", {}}, right{"right", {}};
  shell_test::symmetric_long_edges(mesh, kWidth, set);
  fix_surface(mesh, left, set);
  if (ends != Ends::hinged) clamp_sides(mesh, mesh.edge_tags.at("left"));
  if (half) {
    hold_in_plane(mesh, right, set);
    if (ends == Ends::clamped_and_symmetric)
      mirror_sides(mesh, mesh.edge_tags.at("right"), 0, kLength / 2.0);
  } else {
    fix_surface(mesh, right, set);
    if (ends == Ends::clamped) clamp_sides(mesh, mesh.edge_tags.at("right"));
  }
  const std::vector<double> state =
      shell_test::solve_under_pressure(mesh, set.components(), kC1, q);
  double sum = 0.0;
  int count = 0;
  for (int v = 0; v < mesh.n_nodes(); ++v)
    if (std::abs(mesh.nodes[v].x() - kLength / 2.0) < 1e-9) {
      sum += state[DofMap::dof(v, 2)];
      ++count;
    }
  EXPECT_GT(count, 0);
  return sum / count;
}

/// The relative errors of the mid-span deflection against `exact` [mm] on nx = 10, 20, 40, 80,
/// printed with the observed orders.
std::vector<double> errors_under_refinement(Ends ends, const char* what, double q, double exact,
                                            Cells cells = Cells::same_diagonal) {
  std::vector<double> errors;
  for (const int nx : {10, 20, 40, 80}) {
    const double w = mid_span_deflection(ends, nx, q, cells);
    errors.push_back(std::abs(w - exact) / exact);
    std::printf("%s, nx = %2d: w = %.6e mm, exact %.6e mm, w/exact %.4f, relative error %.2e", what,
                nx, w, exact, w / exact, errors.back());
    if (errors.size() > 1)
      std::printf(", order %.2f", std::log2(errors[errors.size() - 2] / errors.back()));
    std::printf("\n");
  }
  return errors;
}

// w/t about 2e-3: the membrane force of the immovable ends changes w by a part below 1e-5.
constexpr double kClampedLoad = 0.256e-8;  // q [MPa]: w = 2e-3 mm clamped, 1e-2 mm hinged

TEST(ShellEdgeConditions, ClampedStripConvergesToTheBeamDeflection) {
  const double exact = kClampedLoad * std::pow(kLength, 4) / (384.0 * kRigidity);
  const std::vector<double> e =
      errors_under_refinement(Ends::clamped, "clamped", kClampedLoad, exact);
  // Second order (measured 2.0 at every halving): the clamped side's curvature is as accurate as
  // an inner side's.
  EXPECT_LT(e.back(), 2e-3);  // measured 1.2e-3
  EXPECT_GT(e[1] / e[2], 3.5);
  EXPECT_GT(e[2] / e[3], 3.5);
}

TEST(ShellEdgeConditions, HingedStripConvergesToTheBeamDeflection) {
  const double q = kClampedLoad / 5.0;
  const double exact = 5.0 * q * std::pow(kLength, 4) / (384.0 * kRigidity);
  const std::vector<double> e = errors_under_refinement(Ends::hinged, "hinged", q, exact);
  EXPECT_LT(e.back(), 1e-3);
  EXPECT_GT(e[0] / e[1], 3.0);
  EXPECT_GT(e[1] / e[2], 3.0);
}

TEST(ShellEdgeConditions, HalfStripWithASymmetryEdgeConvergesToTheClampedStrip) {
  const double exact = kClampedLoad * std::pow(kLength, 4) / (384.0 * kRigidity);
  const std::vector<double> e =
      errors_under_refinement(Ends::clamped_and_symmetric, "half, symmetric", kClampedLoad, exact);
  EXPECT_LT(e.back(), 2e-3);  // measured 1.27e-3
  // The mirrored side's gradient is the mean of the element's fit and its image's (KL8a, KL3b):
  // the half strip bends as the whole strip, whose mesh differs only in the diagonal of its right
  // half's cells. Measured 2.5e-4 at nx = 10, below 1e-5 from nx = 40.
  for (const int nx : {10, 20, 40, 80}) {
    const double half = mid_span_deflection(Ends::clamped_and_symmetric, nx, kClampedLoad);
    const double whole = mid_span_deflection(Ends::clamped, nx, kClampedLoad);
    std::printf("nx = %2d: half strip / whole strip - 1 = %.1e\n", nx, half / whole - 1.0);
    EXPECT_LT(std::abs(half / whole - 1.0), 3e-4) << "nx = " << nx;
  }
  EXPECT_GT(e[1] / e[2], 3.5);
  EXPECT_GT(e[2] / e[3], 3.5);
  // Without the mirror the side at the plane turns freely, and only u_x is held there: the half
  // strip is then a cantilever of length L/2, w = q (L/2)⁴ / (8 D), three times the clamped
  // strip's.
  const double free_side = mid_span_deflection(Ends::clamped_and_plane_held, 80, kClampedLoad);
  std::printf("half strip with the plane's side free to turn: w = %.6e mm (%.4f of the clamped)\n",
              free_side, free_side / exact);
  EXPECT_NEAR(free_side / exact, 3.0, 0.05);
}

/// The strip with its long edges symmetric, clamped at x = 0 and clamped at x = L with that end
/// moved by `move` [mm] (a grip; prescribe_surface with every component), no load; its state.
std::vector<double> strip_with_a_moved_clamp(const Mesh& mesh, const Vec3d& move) {
  Mesh clamped = mesh;
  ConstraintSet set;
  const SurfaceRef left{"left", {}}, right{"right", {}};
  shell_test::symmetric_long_edges(clamped, kWidth, set);
  fix_surface(clamped, left, set);
  clamp_sides(clamped, clamped.edge_tags.at("left"));
  prescribe_surface(clamped, right, {move.x(), move.y(), move.z()}, Ramp{}, set);
  clamp_sides(clamped, clamped.edge_tags.at("right"));
  return shell_test::solve_under_pressure(clamped, set.components(), kC1, 0.0, 1e-12);
}

TEST(ShellEdgeConditions, AClampMovedAcrossTheStripBendsItAsABeamWithASettledSupport) {
  // The end x = L moved by Δ along z, its slope held (KL8a: the image node follows the side's
  // midpoint): with no load the beam's d⁴w/dx⁴ = 0, and w = dw/dx = 0 at x = 0, w = Δ and
  // dw/dx = 0 at x = L give w(x) = Δ (3 ξ² - 2 ξ³), ξ = x/L, so w(L/5) = 13 Δ/125 (a node of
  // every mesh). A hinged end would give the straight line, Δ/5; an image node left at its
  // reference place, a kink at the
  // moved end. Δ = 2e-3 t: linear (the membrane force of the held ends is O((Δ/t)²)).
  const double settle = 2e-3 * kThickness;
  std::vector<double> errors;
  for (const int nx : {10, 20, 40, 80}) {
    const Mesh mesh = strip(kLength, nx, std::max(2, nx / 5), Cells::same_diagonal);
    const std::vector<double> state = strip_with_a_moved_clamp(mesh, Vec3d(0, 0, settle));
    double sum = 0.0;
    int count = 0;
    for (int v = 0; v < mesh.n_nodes(); ++v)
      if (std::abs(mesh.nodes[v].x() - kLength / 5.0) < 1e-9) {
        sum += state[DofMap::dof(v, 2)];
        ++count;
      }
    ASSERT_GT(count, 0);
    const double exact = 13.0 / 125.0 * settle;
    errors.push_back(std::abs(sum / count - exact) / exact);
    std::printf(
        "clamp moved by %.0e mm across, nx = %2d: w(L/5)/Δ = %.6f, exact %.6f, relative "
        "error %.2e\n",
        settle, nx, sum / count / settle, exact / settle, errors.back());
  }
  EXPECT_LT(errors.back(), 1e-3);
  EXPECT_GT(errors[1] / errors[2], 3.5);
  EXPECT_GT(errors[2] / errors[3], 3.5);
}

TEST(ShellEdgeConditions, ClampsPulledApartStretchTheStripHomogeneously) {
  // The end x = L moved by Δ = 0.2 L along x, both ends clamped, the long edges symmetric: the
  // exact state is the homogeneous stretch u = (Δ x / L, 0, 0) (plane strain in y), which the
  // element reproduces (KL3, KL4a) when the image nodes beyond the moved end move with it (KL8a).
  // Newton to 1e-12 of the first residual; a moved end whose images stayed put would bend and
  // shear the end cells by O(Δ/h).
  for (const Cells cells : {Cells::same_diagonal, Cells::distorted}) {
    const Mesh mesh = strip(kLength, 20, 4, cells);
    const double pull = 0.2 * kLength;
    const std::vector<double> state = strip_with_a_moved_clamp(mesh, Vec3d(pull, 0, 0));
    double error = 0.0;
    for (int v = 0; v < mesh.n_nodes(); ++v) {
      const Vec3d u(state[DofMap::dof(v, 0)], state[DofMap::dof(v, 1)], state[DofMap::dof(v, 2)]);
      error = std::max(error, (u - Vec3d(pull * mesh.nodes[v].x() / kLength, 0, 0)).norm());
    }
    std::printf("clamps pulled apart by %.0f mm, cells %d: largest |u - u_exact| / Δ = %.1e\n",
                pull, static_cast<int>(cells), error / pull);
    EXPECT_LT(error, 1e-9 * pull) << "cells " << static_cast<int>(cells);
  }
}

TEST(ShellEdgeConditions, TheCurvaturePassesBothPatchTestsOnEveryMesh) {
  for (const Cells cells : {Cells::same_diagonal, Cells::alternating, Cells::distorted}) {
    const PatchTestErrors e = patch_test_errors(strip(kLength, 40, 8, cells));
    std::printf("cells %d: exactness %.2e, continuity %.2e\n", static_cast<int>(cells), e.exactness,
                e.continuity);
    // Round-off of the 6 x 6 fits (KL3a, KL3b).
    EXPECT_LT(e.exactness, 1e-10);
    EXPECT_LT(e.continuity, 1e-13);
  }
}

/// The largest internal force [N] at a node whose elements all have their 12 slots filled, on
/// the strip in the homogeneous in-plane deformation u = (F0 - I) X, relative to μ t h |F0 - I|
/// (the force of one element's strain): the equilibrium patch test of the membrane (KL4a).
double equilibrium_error(Cells cells) {
  const Mesh mesh = strip(kLength, 40, 8, cells);
  MixedModel model(mesh, make_material("neo-hookean", {{"c1", kC1}}), 0.0, {}, {},
                   ElementFamily::shell);
  Eigen::Matrix2d G;  // F0 - I in the plane
  G << 2e-3, 1e-3, -5e-4, -1e-3;
  for (int v = 0; v < mesh.n_nodes(); ++v) {
    const Eigen::Vector2d u = G * mesh.nodes[v].head<2>();
    model.state()[DofMap::dof(v, 0)] = u.x();
    model.state()[DofMap::dof(v, 1)] = u.y();
  }
  Vec f = model.create_vector();
  EXPECT_TRUE(model.assemble_residual(f).ok);
  const PetscScalar* r = nullptr;
  VecGetArrayRead(f, &r);
  std::vector<bool> outer(static_cast<std::size_t>(mesh.n_nodes()), false);
  for (std::size_t e = 0; e < mesh.triangles.size(); ++e) {
    const Patch patch = patch_of(mesh, e);
    if (patch.inner) continue;
    for (const int n : patch.nodes) outer[static_cast<std::size_t>(n)] = true;
  }
  double largest = 0.0;
  for (int v = 0; v < mesh.n_nodes(); ++v) {
    if (outer[static_cast<std::size_t>(v)]) continue;
    for (int k = 0; k < 3; ++k)
      largest = std::max(largest, std::abs(r[model.dofs().equation(DofMap::dof(v, k))]));
  }
  VecRestoreArrayRead(f, &r);
  VecDestroy(&f);
  return largest / (2.0 * kC1 * kThickness * (kLength / 40) * G.norm());
}

TEST(ShellEdgeConditions, AHomogeneousStressIsInEquilibriumOnEveryMesh) {
  // The mean gradient (KL4a) is a sum over the sides of values both elements of a side share:
  // a constant stress does no virtual work on an inner node. Round-off: measured 7.8e-13 to
  // 1.6e-12 relative on the three meshes.
  for (const Cells cells : {Cells::same_diagonal, Cells::alternating, Cells::distorted}) {
    const double e = equilibrium_error(cells);
    std::printf("cells %d: largest inner nodal force of a homogeneous stress %.1e relative\n",
                static_cast<int>(cells), e);
    EXPECT_LT(e, 1e-10);
  }
}

/// The strips of the tests above on alternating and on distorted cells (KL6a): the curvature
/// passes both patch tests there too, so the bending converges as on one diagonal.
void expect_convergence_on(Cells cells, const char* what) {
  const double q = kClampedLoad / 5.0;
  const std::string hinged = std::string(what) + ", hinged";
  const std::string clamped = std::string(what) + ", clamped";
  const std::vector<double> h = errors_under_refinement(
      Ends::hinged, hinged.c_str(), q, 5.0 * q * std::pow(kLength, 4) / (384.0 * kRigidity), cells);
  const std::vector<double> c =
      errors_under_refinement(Ends::clamped, clamped.c_str(), kClampedLoad,
                              kClampedLoad * std::pow(kLength, 4) / (384.0 * kRigidity), cells);
  // The bounds of the one-diagonal strips above: measured finest 1.1e-4 and 8.1e-5 hinged,
  // 1.25e-3 and 1.11e-3 clamped; every halving 4.0 to 4.9-fold.
  EXPECT_LT(h.back(), 1e-3);
  EXPECT_LT(c.back(), 2e-3);
  for (std::size_t n = 1; n + 1 < h.size(); ++n) {
    EXPECT_GT(h[n] / h[n + 1], 3.5) << what << ", hinged, halving " << n;
    EXPECT_GT(c[n] / c[n + 1], 3.5) << what << ", clamped, halving " << n;
  }
}

TEST(ShellEdgeConditions, StripOnAlternatingCellsConverges) {
  expect_convergence_on(Cells::alternating, "alternating");
}

TEST(ShellEdgeConditions, StripOnDistortedCellsConverges) {
  expect_convergence_on(Cells::distorted, "distorted");
}

}  // namespace
}  // namespace plisse
