// Inf-sup stability of the MINI element: the numerical inf-sup test (docs/verification/inf_sup.md).
//
// At the undeformed state (u = 0, p = 0) the condensed tangent of a block is split into
// K = [A Bᵀ; B -C], and β_h² is the smallest eigenvalue of (B A⁻¹ Bᵀ + C) q = β² M q (IS1) on
// cubes with 2, 4 and 8 cells per edge. MINI must keep β_h bounded away from zero; the same
// computation for P1/P1 (no bubble: the element blocks K_xx without condensation) must not — that
// shows the test can fail, i.e. that it detects what it claims to detect. The Taylor-Hood (P2/P1)
// element must be stable too: on the cubes, and on thin sheets meshed with one and two layers of
// tetrahedra, where every vertex lies on the boundary (docs/theory/taylor_hood.md, section 4).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <set>
#include <string>

#include "mesh/generate.hpp"
#include "support/second_order_mesh.hpp"
#include "verification/fixtures/saddle_point.hpp"

namespace plisse::test {
namespace {

enum class Support {
  bottom_fixed,  ///< bottom face fixed, the rest free
  indented,      ///< bottom fixed and a rigid sticking punch on the top half x <= 1/2
};

struct InfSupLevel {
  int divisions = 0;
  int n_pressure = 0;
  double beta_mini = 0.0, beta_p1p1 = 0.0;  ///< sqrt of the smallest eigenvalue (0 if negative)
  int small_p1p1 = 0;  ///< P1/P1 eigenvalues below 1e-3 of MINI's smallest: spurious modes
  double beta_p1p1_nonzero = 0.0;  ///< sqrt of the smallest P1/P1 eigenvalue above those
  double eta_p1p1 = 0.0;           ///< checkerboard indicator (IS3) of the lowest P1/P1 mode
  bool A_positive_definite = false;
};

std::vector<ConstrainedComponent> constraints_for(const Mesh& mesh, Support support) {
  std::set<int> fixed;
  for (int t : mesh.surface_tags.at("bottom"))
    for (int v : face_nodes(mesh, t)) fixed.insert(v);
  if (support == Support::indented)
    for (int t : mesh.surface_tags.at("top"))
      for (int v : face_nodes(mesh, t))
        if (mesh.nodes[v].x() <= 0.5 + 1e-12) fixed.insert(v);
  std::vector<ConstrainedComponent> constraints;
  for (int v : fixed)
    for (int k = 0; k < 3; ++k) constraints.push_back({v, k, 0.0, Ramp{0.0, 1.0}});
  return constraints;
}

std::vector<double> lowest_mode(const SchurSpectrum& s, const SaddlePointBlocks& b, int n_nodes) {
  std::vector<double> values(n_nodes, 0.0);
  for (int i = 0; i < static_cast<int>(b.pressure_node.size()); ++i)
    values[b.pressure_node[i]] = s.eigenvectors(i, 0);
  return values;
}

InfSupLevel compute_level(int divisions, Support support) {
  MeshGenerationSpec spec;
  spec.kind = "cube";
  spec.edge = 1.0;
  spec.divisions = divisions;
  const Mesh mesh = generate_mesh(spec);
  const AnyMaterial material = make_material("neo-hookean", {{"c1", 0.5}});  // mu = 1 MPa
  MixedModel model(mesh, material, 0.0, constraints_for(mesh, support));  // exact incompressibility
  InfSupLevel level;
  level.divisions = divisions;
  const SaddlePointBlocks mini_blocks = split_blocks(assemble_mini_tangent(model), model);
  const SaddlePointBlocks p1p1_blocks =
      split_blocks(assemble_p1p1_tangent(model, material, 0.0), model);
  const SchurSpectrum mini = schur_spectrum(mini_blocks);
  const SchurSpectrum p1p1 = schur_spectrum(p1p1_blocks);
  level.A_positive_definite = mini.A_positive_definite && p1p1.A_positive_definite;
  if (!level.A_positive_definite) return level;
  level.n_pressure = static_cast<int>(mini.eigenvalues.size());
  level.beta_mini = std::sqrt(std::max(mini.eigenvalues(0), 0.0));
  level.beta_p1p1 = std::sqrt(std::max(p1p1.eigenvalues(0), 0.0));
  for (int i = 0; i < p1p1.eigenvalues.size(); ++i)
    level.small_p1p1 += p1p1.eigenvalues(i) < 1e-3 * mini.eigenvalues(0);
  if (level.small_p1p1 < p1p1.eigenvalues.size())
    level.beta_p1p1_nonzero = std::sqrt(p1p1.eigenvalues(level.small_p1p1));
  level.eta_p1p1 = checkerboard_indicator(mesh, lowest_mode(p1p1, p1p1_blocks, mesh.n_nodes()));
  return level;
}

void expect_stable_mini_and_unstable_p1p1(const std::string& title, Support support) {
  std::vector<InfSupLevel> levels;
  for (int n : {2, 4, 8}) {
    levels.push_back(compute_level(n, support));
    ASSERT_TRUE(levels.back().A_positive_definite)
        << title << ": A not positive definite, n = " << n;
  }
  std::cout << title << "\n";
  char line[200];
  std::snprintf(line, sizeof line, "%4s %6s %11s %11s %11s %11s %10s\n", "n", "n_p", "beta MINI",
                "beta P1/P1", "P1/P1 zero", "next P1/P1", "eta P1/P1");
  std::cout << line;
  for (const InfSupLevel& l : levels) {
    std::snprintf(line, sizeof line, "%4d %6d %11.4e %11.4e %11d %11.4e %10.4f\n", l.divisions,
                  l.n_pressure, l.beta_mini, l.beta_p1p1, l.small_p1p1, l.beta_p1p1_nonzero,
                  l.eta_p1p1);
    std::cout << line;
  }
  const InfSupLevel& coarse = levels.front();
  const InfSupLevel& fine = levels.back();
  // MINI: bounded away from zero under refinement (IS2).
  EXPECT_GE(fine.beta_mini, 0.5 * coarse.beta_mini) << title;
  EXPECT_GT(fine.beta_mini, 0.05) << title;
  // P1/P1: spurious pressure modes at every level, eigenvalues zero to round-off (λ < 1e-3 λ_MINI
  // counts; the ones found are ~1e-16), so β_h = 0 and the P1/P1 tangent is singular.
  for (const InfSupLevel& l : levels) {
    EXPECT_GE(l.small_p1p1, 1) << title << ", n = " << l.divisions;
    EXPECT_LT(l.beta_p1p1, 1e-4 * l.beta_mini) << title << ", n = " << l.divisions;
    // A spurious mode is a node-to-node oscillation: η = O(1) (IS3), the reference for the
    // indentation test's smoothness check.
    EXPECT_GT(l.eta_p1p1, 0.5) << title << ", n = " << l.divisions;
  }
  // Beyond the zero modes P1/P1 is still far weaker than MINI on the finest mesh (and the next
  // eigenvalue falls with h on the block with fixed bottom, docs/verification/inf_sup.md).
  EXPECT_LT(fine.beta_p1p1_nonzero, 0.5 * fine.beta_mini) << title;
}

/// β_h of `family` on `mesh` (second order for Taylor-Hood) with the bottom fixed, exact
/// incompressibility, at the undeformed state; and β_h of MINI on the corner mesh for comparison.
double taylor_hood_beta(const Mesh& mesh) {
  const AnyMaterial material = make_material("neo-hookean", {{"c1", 0.5}});  // mu = 1 MPa
  MixedModel model(mesh, material, 0.0, constraints_for(mesh, Support::bottom_fixed), {},
                   ElementFamily::taylor_hood);
  const SchurSpectrum s = schur_spectrum(split_blocks(assemble_mini_tangent(model), model));
  EXPECT_TRUE(s.A_positive_definite);
  return s.A_positive_definite ? std::sqrt(std::max(s.eigenvalues(0), 0.0)) : 0.0;
}

TEST(InfSup, TaylorHoodIsStableOnCubesAndOnSheetsOfOneAndTwoLayers) {
  std::cout << "inf-sup, Taylor-Hood (P2/P1), bottom fixed\n";
  std::vector<double> cube;
  for (int n : {2, 4, 8}) {
    MeshGenerationSpec spec;
    spec.kind = "cube";
    spec.edge = 1.0;
    spec.divisions = n;
    spec.order = 2;
    cube.push_back(taylor_hood_beta(generate_mesh(spec)));
    std::cout << "  cube, n = " << n << ": beta = " << cube.back() << "\n";
  }
  // Bounded away from zero under refinement (IS2), as MINI's.
  EXPECT_GE(cube.back(), 0.5 * cube.front());
  EXPECT_GT(cube.back(), 0.05);
  // A sheet 8 x 8 x 1 (in units of its thickness) with 1 and 2 layers: the continuous inf-sup
  // constant of a thin domain is itself small (it falls with the aspect ratio), so the check is
  // against MINI on the same corner mesh: no spurious pressure mode (β > 0 clearly) and not much
  // weaker than MINI.
  for (int layers : {1, 2}) {
    MeshGenerationSpec spec;
    spec.kind = "sheet";
    spec.length = spec.width = 8.0;
    spec.thickness = 1.0;
    spec.layers = layers;
    spec.element_size = 1.0;
    spec.order = 2;
    const double beta = taylor_hood_beta(generate_mesh(spec));
    spec.order = 1;
    const Mesh linear = generate_mesh(spec);
    const AnyMaterial material = make_material("neo-hookean", {{"c1", 0.5}});
    MixedModel mini(linear, material, 0.0, constraints_for(linear, Support::bottom_fixed));
    const SchurSpectrum s = schur_spectrum(split_blocks(assemble_mini_tangent(mini), mini));
    const double beta_mini = std::sqrt(std::max(s.eigenvalues(0), 0.0));
    std::cout << "  sheet, " << layers << " layer(s): beta = " << beta
              << ", MINI on the same corners: " << beta_mini << "\n";
    EXPECT_GT(beta, 1e-3) << layers << " layer(s)";
    EXPECT_GT(beta, 0.25 * beta_mini) << layers << " layer(s)";
  }
}

TEST(InfSup, MiniIsStableAndP1P1IsNotOnBlockWithFixedBottom) {
  expect_stable_mini_and_unstable_p1p1("inf-sup, block with fixed bottom", Support::bottom_fixed);
}

TEST(InfSup, MiniIsStableAndP1P1IsNotOnIndentedBlock) {
  expect_stable_mini_and_unstable_p1p1("inf-sup, indented block (punch on x <= 1/2 of the top)",
                                       Support::indented);
}

}  // namespace
}  // namespace plisse::test
