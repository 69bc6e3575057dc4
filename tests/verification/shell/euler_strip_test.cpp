// Euler buckling of a shell strip (docs/theory/shell.md, section 9), found by the sign change of
// the lowest eigenvalue of the tangent (solver/eigenmodes.hpp) along the compressed, unbuckled
// path, as tests/verification/buckling does for the solid strip.
//
// The strip [0, L] x [0, W], thickness t, flat in z = 0, of the incompressible neo-Hookean sheet
// (μ = 2 c1). Its long edges y = 0 and y = W are symmetry edges (v = 0 and zero slope across:
// plane strain in y); its ends are hinged (u = v = w = 0 at x = 0; at x = L, v = w = 0 and
// u = -δ, the sides free to turn, KL8). In plane strain the membrane stiffness is E' t with
// E' = E / (1 - ν²) = 4 μ and the bending stiffness D = E' t³ / 12 = μ t³ / 3 (KL13), so the
// pinned-pinned Euler load N = π² D / L² is reached at the strain
//   ε_cr = N / (E' t) = π² t² / (12 L²)
// whatever the modulus (Timoshenko & Gere 1961, §2.2), and the mode is w = sin(π x / L). At
// L/t = 100 the critical strain is 8.2·10⁻⁵: the finite-strain terms change it by a part of that
// order, far below the tolerance. With both ends clamped (the end x = L a grip that moves by -δ
// and keeps its slope, KL8a) the buckle is w = 1 - cos(2π x / L) at four times that strain,
// ε_cr = 4 π² t² / (12 L²) (Timoshenko & Gere 1961, §2.3: the effective length L/2).
//
// On distorted cells this test found the membrane strain of EBST1, the mean of the three side
// metrics, out of equilibrium under a homogeneous stress (shell.md, KL4): the critical strain
// came out 1.2 % high at every mesh. The mean gradient of KL4a passes, and so does this test.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include "material/registry.hpp"
#include "physics/dirichlet.hpp"
#include "shell_fixtures.hpp"
#include "solver/eigenmodes.hpp"
#include "solver/mixed_model.hpp"
#include "solver/newton_solver.hpp"
#include "support/extrapolation.hpp"
#include "verification/buckling/fixtures/clamped_strip.hpp"

namespace plisse {
namespace {

using shell_test::Cells;

using namespace shell_test::strip_constants;  // c1, L, W and t of the strip

struct Buckling {
  double strain = 0.0;            ///< δ_cr / L, λ_1 interpolated linearly to zero
  double mode_correlation = 0.0;  ///< of the critical mode's w(x) with sin(π x / L)
};

/// Pearson correlation of w with f over the same samples.
double correlation(const std::vector<double>& w, const std::vector<double>& f) {
  const double n = static_cast<double>(w.size());
  double mw = 0, mf = 0;
  for (std::size_t i = 0; i < w.size(); ++i) mw += w[i] / n, mf += f[i] / n;
  double wf = 0, ww = 0, ff = 0;
  for (std::size_t i = 0; i < w.size(); ++i) {
    wf += (w[i] - mw) * (f[i] - mf);
    ww += (w[i] - mw) * (w[i] - mw);
    ff += (f[i] - mf) * (f[i] - mf);
  }
  return wf / std::sqrt(ww * ff);
}

/// The critical strain of the strip of thickness t (nx cells along L, nx / 5 across) cut as
/// `cells`, its ends hinged or clamped: steps at 0.5 and 1 ε_cr, then at the zero of the line
/// through the last two λ_1 with 2 % overshoot, until λ_1 < 0; the zero interpolated between the
/// last two steps. The mode is compared with sin(π x / L) (hinged) or 1 - cos(2π x / L) (clamped).
Buckling critical_strain(int nx, Cells cells, double exact, bool clamped = false,
                         double thickness = kThickness) {
  Mesh mesh = shell_test::strip_mesh(kLength, kWidth, thickness, nx, nx / 5, cells, kLength);
  const double strain_max = 3.0 * exact;
  ConstraintSet set;
  fix_surface(mesh, SurfaceRef{"left", {}}, set);
  shell_test::symmetric_long_edges(mesh, kWidth, set);
  if (clamped) {
    clamp_sides(mesh, mesh.edge_tags.at("left"));
    clamp_sides(mesh, mesh.edge_tags.at("right"));
  }
  for (int k : mesh.edge_tags.at("right"))
    for (int v : mesh.edges[static_cast<std::size_t>(k)]) {
      set.add(v, 0, -strain_max * kLength, Ramp{0.0, 1.0});
      set.add(v, 1, 0.0, Ramp{});
      set.add(v, 2, 0.0, Ramp{});
    }
  MixedModel model(mesh, make_material("neo-hookean", {{"c1", kC1}}), 0.0, set.components(), {},
                   ElementFamily::shell);
  NewtonSettings settings;
  settings.rtol = 1e-10;
  NewtonSolver newton(model, settings);
  const EigenSettings options{2, 0.0, 1e-8};
  std::vector<double> strains, lowest;
  Eigenmode critical;
  const auto step_to = [&](double strain) {
    model.set_time(strain / strain_max);
    const NewtonResult result = newton.solve();
    EXPECT_TRUE(result.converged) << "Newton at eps = " << strain << ": " << result.reason;
    if (!result.converged) return false;
    model.save_converged();
    const std::vector<Eigenmode> modes = lowest_eigenmodes(model, options);
    strains.push_back(strain);
    lowest.push_back(modes.front().eigenvalue);
    if (modes.front().eigenvalue < 0) critical = modes.front();
    return true;
  };
  const auto zero_between = [&](std::size_t i, std::size_t j) {
    return strains[i] + (strains[j] - strains[i]) * lowest[i] / (lowest[i] - lowest[j]);
  };
  Buckling b;
  if (!step_to(0.5 * exact) || !step_to(exact)) return b;
  while (lowest.back() > 0) {
    const std::size_t k = lowest.size() - 1;
    const double next = lowest[k] < lowest[k - 1]
                            ? std::max(1.02 * zero_between(k - 1, k), 1.01 * strains[k])
                            : 2.0 * strains[k];
    if (next > strain_max || k > 10) {
      ADD_FAILURE() << "the lowest eigenvalue stayed positive up to " << strains[k];
      return b;
    }
    if (!step_to(next)) return b;
  }
  b.strain = zero_between(lowest.size() - 2, lowest.size() - 1);
  // w(x) of the mode: u_z averaged over the nodes of each x (exact x of the undistorted meshes,
  // x rounded to a cell for the distorted one).
  std::map<long, std::pair<double, int>> sections;
  const double hx = kLength / nx;
  for (int v = 0; v < mesh.n_nodes(); ++v) {
    auto& [sum, n] = sections[std::lround(mesh.nodes[v].x() / hx)];
    sum += critical.state[DofMap::dof(v, 2)];
    ++n;
  }
  std::vector<double> w, f;
  for (const auto& [i, section] : sections) {
    w.push_back(section.first / section.second);
    const double x = static_cast<double>(i) * hx / kLength;
    f.push_back(clamped ? 1.0 - std::cos(2.0 * std::numbers::pi * x)
                        : std::sin(std::numbers::pi * x));
  }
  b.mode_correlation = std::abs(correlation(w, f));
  return b;
}

TEST(ShellEulerStrip, HingedStripBucklesAtTheEulerStrainOnEveryMesh) {
  const double pi = std::numbers::pi;
  const double exact = pi * pi * kThickness * kThickness / (12.0 * kLength * kLength);
  for (const Cells cells : {Cells::same_diagonal, Cells::alternating, Cells::distorted}) {
    std::vector<double> errors;
    for (const int nx : {20, 40, 80}) {
      const Buckling b = critical_strain(nx, cells, exact);
      errors.push_back(std::abs(b.strain / exact - 1.0));
      std::printf(
          "cells %d, nx = %2d: eps_cr = %.6e, Euler %.6e, relative error %.2e, mode "
          "correlation with sin(pi x / L) %.6f\n",
          static_cast<int>(cells), nx, b.strain, exact, errors.back(), b.mode_correlation);
      EXPECT_GT(b.mode_correlation, 0.999) << "cells " << static_cast<int>(cells) << ", nx " << nx;
    }
    // Measured 2.3e-3 to 2.8e-3 at nx = 20, 1.1e-4 to 1.5e-4 at nx = 80 on the three meshes.
    EXPECT_LT(errors.back(), 3e-4) << "cells " << static_cast<int>(cells);
    EXPECT_GT(errors[0] / errors[2], 8.0) << "cells " << static_cast<int>(cells);
  }
}

TEST(ShellEulerStrip, ClampedStripBucklesAtFourTimesTheEulerStrain) {
  // Both ends clamped, the end x = L a grip moved along the strip (KL8a): ε_cr = 4 π² t²/(12 L²).
  const double pi = std::numbers::pi;
  const double exact = 4.0 * pi * pi * kThickness * kThickness / (12.0 * kLength * kLength);
  std::vector<double> errors;
  for (const int nx : {20, 40, 80}) {
    const Buckling b = critical_strain(nx, Cells::alternating, exact, true);
    errors.push_back(std::abs(b.strain / exact - 1.0));
    std::printf(
        "clamped, nx = %2d: eps_cr = %.6e, clamped Euler %.6e, relative error %.2e, mode "
        "correlation with 1 - cos(2 pi x / L) %.6f\n",
        nx, b.strain, exact, errors.back(), b.mode_correlation);
    EXPECT_GT(b.mode_correlation, 0.999) << "nx " << nx;
  }
  EXPECT_LT(errors.back(), 2e-3);
  EXPECT_GT(errors[0] / errors[2], 8.0);
}

// The shell beside the solid: the clamped strip above in plane strain, and the quadratic
// Taylor-Hood solid strip of tests/verification/buckling in plane strain (u_y = 0, three layers
// through the thickness), at L/t = 20 and 40. Each is refined three times (the shell: nx = 20,
// 40, 80, cells of t, t/2, t/4 at L/t = 20; the solid: in-plane cells of t, t/2, t/4) and
// extrapolated, r_0 = r_3 - (r_2 - r_3) / (q - 1) with q = (r_1 - r_2) / (r_2 - r_3) the ratio of
// its successive changes. Beam theory gives both the same critical strain,
// ε_cr = π² t² / (3 L²) (E cancels); the solid adds what Kirchhoff-Love kinematics and plane
// stress through the wall leave out (the shear of the wall, the normal stress through it, the
// wall's own thinning and thickening), a relative part of order (t/L)², that is of order ε_cr.
// The largest of them is the wall's shear, which Engesser's correction of the Euler load,
// N_cr / (1 + N_cr / (κ_s G t)), estimates for the strip as the relative part
// -ε_cr E' / (κ_s G) = -4.8 ε_cr (E' = 4μ in plane strain, G = μ, κ_s = 5/6; Timoshenko & Gere
// 1961, "Effect of shearing force on the critical load"). Checked: each sequence converges
// (observed order above 1.5); the gap solid - shell is negative and between 0.5 and 1 times that
// estimate at both L/t, and it falls 3.2 to 4.8-fold from L/t = 20 to 40, as (t/L)² (fourfold) and
// not as t/L (twofold) would. Measured: the shell 3.0 % above beam theory at L/t = 20 and 0.73 % at
// 40 (the wall thickens as the strip shortens), the solid within 3·10⁻⁴ of it; gaps -3.7 and -3.6
// ε_cr, ratio 4.1.
TEST(ShellEulerStrip, TheClampedStripBucklesWhereTheSolidStripInPlaneStrainDoes) {
  const double pi = std::numbers::pi;
  std::vector<double> gaps;
  const double engesser = -4.8;  // the shear's relative part over ε_cr (above)
  for (const double slenderness : {20.0, 40.0}) {
    const double t = kLength / slenderness;
    const double beam = 4.0 * pi * pi * t * t / (12.0 * kLength * kLength);
    std::vector<double> shell, solid;
    for (const int nx : {20, 40, 80}) {
      const int n = nx * static_cast<int>(slenderness) / 20;
      shell.push_back(critical_strain(n, Cells::alternating, beam, true, t).strain / beam);
    }
    for (const double size : {1.0, 0.5, 0.25}) {
      test::ClampedStrip strip;
      strip.length = slenderness;
      strip.layers = 3;
      strip.in_plane_size = size;
      strip.element = ElementFamily::taylor_hood;
      strip.plane_strain = true;
      const test::BucklingResult r = test::find_critical_strain(strip);
      ASSERT_GT(r.strain_critical, 0.0) << "L/t " << slenderness << ", size " << size;
      solid.push_back(r.strain_critical / r.strain_analytic);
    }
    const test::Extrapolation shell_fit = test::extrapolate_halvings(shell[0], shell[1], shell[2]);
    const test::Extrapolation solid_fit = test::extrapolate_halvings(solid[0], solid[1], solid[2]);
    gaps.push_back(solid_fit.limit - shell_fit.limit);
    std::printf(
        "L/t = %g: eps_cr / beam theory, shell %.6f %.6f %.6f (order %.2f, limit %.6f), solid "
        "%.6f %.6f %.6f (order %.2f, limit %.6f); solid - shell %.2e\n",
        slenderness, shell[0], shell[1], shell[2], shell_fit.order, shell_fit.limit, solid[0],
        solid[1], solid[2], solid_fit.order, solid_fit.limit, gaps.back());
    EXPECT_GT(shell_fit.order, 1.5) << "L/t " << slenderness;
    EXPECT_GT(solid_fit.order, 1.5) << "L/t " << slenderness;
    EXPECT_LT(gaps.back(), 0.5 * engesser * beam) << "L/t " << slenderness;
    EXPECT_GT(gaps.back(), engesser * beam) << "L/t " << slenderness;
  }
  EXPECT_GT(gaps[0] / gaps[1], 3.2);
  EXPECT_LT(gaps[0] / gaps[1], 4.8);
}

}  // namespace
}  // namespace plisse
