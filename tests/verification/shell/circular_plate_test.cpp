// The shell's bending on an unstructured mesh with a curved clamped edge, against the closed form
// of a clamped circular plate under a uniform pressure (docs/theory/shell.md, section 9).
//
// A disc of radius a and thickness t, flat in z = 0, clamped along its rim, under a small
// uniform pressure q on its bottom face (pushing along +z). For the incompressible neo-Hookean
// sheet (μ = 2 c1) the plate rigidity is D = μ t³ / 3 (E = 3 μ, ν = 1/2; shell.md, KL13), and
// Kirchhoff plate theory gives the deflection at the centre
//   w0 = q a⁴ / (64 D)
// (Timoshenko & Woinowsky-Krieger 1959, §62). The load is small (w0/t = 10⁻²) so that the
// membrane force of the clamped rim changes w0 by a part O((w0/t)²), about 10⁻⁴ (§96).
//
// The mesh is built of rings: ring k has 6k nodes, each ring turned by a pseudo-random angle
// against the one inside it and the inner nodes moved radially, and the rings are joined by
// advancing along both: the nodes have 4 to 8 neighbours and no two cells are alike, unlike the
// strips of edge_conditions_test.cpp. The rim is the polygon of the outer ring; its sides are
// clamped by the half turn of KL8a.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "mesh/shell_surface.hpp"
#include "physics/dirichlet.hpp"
#include "shell_fixtures.hpp"

namespace plisse {
namespace {

constexpr double kC1 = 0.5;         // [MPa]: μ = 1 MPa
constexpr double kRadius = 50.0;    // a [mm]
constexpr double kThickness = 1.0;  // t [mm]
constexpr double kRigidity = 2.0 * kC1 * kThickness * kThickness * kThickness / 3.0;  // D [N mm]

/// A number in [-1, 1] that depends only on (i, j): the mesh is the same on every platform.
double pseudo_random(int i, int j) { return shell_test::pseudo_random(i, j, 0); }

/// The disc of `rings` rings described above, normals +z; edge tag `rim`, surface tag `bottom`
/// (the -1 face: a pressure on it pushes along +z).
Mesh disc(int rings) {
  Mesh mesh;
  mesh.nodes.push_back(Vec3d::Zero());
  std::vector<std::vector<int>> ring{{0}};
  std::vector<std::vector<double>> angle{{0.0}};
  for (int k = 1; k <= rings; ++k) {
    const int count = 6 * k;
    const double step = 2.0 * std::numbers::pi / count;
    const double turn = 0.5 * step * pseudo_random(k, 0);
    ring.emplace_back();
    angle.emplace_back();
    for (int j = 0; j < count; ++j) {
      const double phi = turn + step * j;
      double r = kRadius * k / rings;
      if (k < rings) r += 0.15 * kRadius / rings * pseudo_random(k, j + 1);
      ring.back().push_back(static_cast<int>(mesh.nodes.size()));
      angle.back().push_back(phi);
      mesh.nodes.emplace_back(r * std::cos(phi), r * std::sin(phi), 0.0);
    }
  }
  for (int j = 0; j < 6; ++j) mesh.triangles.push_back({0, ring[1][j], ring[1][(j + 1) % 6]});
  for (int k = 2; k <= rings; ++k) {
    // Advance along ring k - 1 (index a) and ring k (index b) by increasing angle, each new
    // triangle counter-clockwise about +z.
    const std::vector<int>& in = ring[k - 1];
    const std::vector<int>& out = ring[k];
    const int m = static_cast<int>(in.size()), n = static_cast<int>(out.size());
    const auto phi_in = [&](int a) {
      return angle[k - 1][a % m] + 2.0 * std::numbers::pi * (a / m);
    };
    const auto phi_out = [&](int b) { return angle[k][b % n] + 2.0 * std::numbers::pi * (b / n); };
    int a = 0, b = 0;
    while (phi_out(b) < phi_in(0)) ++b;  // start at the first outer node past inner node 0
    const int b_end = b + n;
    while (a < m || b < b_end) {
      const bool advance_out = a == m || (b < b_end && phi_out(b + 1) < phi_in(a + 1));
      if (advance_out) {
        mesh.triangles.push_back({in[a % m], out[b % n], out[(b + 1) % n]});
        ++b;
      } else {
        mesh.triangles.push_back({in[a % m], out[b % n], in[(a + 1) % m]});
        ++a;
      }
    }
  }
  for (int k = 0; k < static_cast<int>(mesh.triangles.size()); ++k)
    mesh.surface_tags["bottom"].push_back(k);
  const std::vector<int>& rim = ring.back();
  for (std::size_t j = 0; j < rim.size(); ++j) {
    mesh.edge_tags["rim"].push_back(static_cast<int>(mesh.edges.size()));
    mesh.edges.push_back({rim[j], rim[(j + 1) % rim.size()]});
  }
  make_shell_surface(mesh, kThickness);
  return mesh;
}

/// The deflection [mm] at the centre of the clamped disc of `rings` rings under the pressure q.
double centre_deflection(int rings, double q) {
  Mesh mesh = disc(rings);
  ConstraintSet set;
  fix_surface(mesh, SurfaceRef{"rim", {}}, set);
  clamp_sides(mesh, mesh.edge_tags.at("rim"));
  return shell_test::solve_under_pressure(mesh, set.components(), kC1, q)[DofMap::dof(0, 2)];
}

TEST(ShellCircularPlate, ClampedPlateOnAnUnstructuredMeshConvergesToKirchhoffsDeflection) {
  const double q = 64.0 * kRigidity * 1e-2 * kThickness / std::pow(kRadius, 4);
  const double exact = q * std::pow(kRadius, 4) / (64.0 * kRigidity);
  std::vector<double> errors;
  for (const int rings : {4, 8, 16, 32, 64}) {
    const double w = centre_deflection(rings, q);
    errors.push_back(std::abs(w / exact - 1.0));
    std::printf("rings %2d (%5d triangles): w0 = %.6e mm, exact %.6e mm, relative error %.2e",
                rings, 6 * rings * rings, w, exact, errors.back());
    if (errors.size() > 1)
      std::printf(", order %.2f", std::log2(errors[errors.size() - 2] / errors.back()));
    std::printf("\n");
  }
  // Measured 2.2e-1, 5.5e-2, 1.3e-2, 3.3e-3, 7.7e-4: second order (2.02 to 2.08) from the
  // coarsest mesh on, as on the strips; the polygonal rim's area and the element's curvature
  // are both O(h²).
  EXPECT_LT(errors.back(), 1e-3);
  for (std::size_t n = 0; n + 1 < errors.size(); ++n)
    EXPECT_GT(errors[n] / errors[n + 1], 3.5) << "halving " << n;
}

}  // namespace
}  // namespace plisse
