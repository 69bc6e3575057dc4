// Two bonded layers of very different stiffness in pure bending, against the closed form
// (docs/theory/regions.md, BL5-BL7): a soft substrate under a stiff film, both incompressible
// neo-Hookean, in plane strain, one end held along x and the other turned by θ about the
// neutral axis. The exact solution of small strains is quadratic in the displacement and linear
// in the pressure of each layer, with a jump at the interface (BL6): the Taylor-Hood element
// with a pressure of each region's own holds it exactly, whatever the mesh, so one element
// through the film must give the closed-form moment to the size of the nonlinear terms
// (~ the strain, 5e-4 here). A pressure shared by both layers cannot jump: with one element
// through the film it misses 7 % of the bending stiffness at a contrast of 100 and 36 % at 1000,
// and does better only slowly with more elements.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <iostream>
#include <set>
#include <utility>
#include <vector>

#include "material/registry.hpp"
#include "mesh/box_mesh.hpp"
#include "mesh/topology.hpp"
#include "solver/mixed_model.hpp"
#include "solver/newton_solver.hpp"
#include "solver/stability.hpp"

namespace plisse {
namespace {

struct Bilayer {
  double length = 1.0;      ///< [mm] along x
  double width = 0.1;       ///< [mm] along y (plane strain: u_y = 0)
  double substrate = 0.4;   ///< [mm] soft layer, 0 <= z <= substrate
  double film = 0.1;        ///< [mm] stiff layer above it
  double mu_soft = 0.01;    ///< [MPa] small-strain shear moduli
  double contrast = 100.0;  ///< mu_stiff / mu_soft
  int film_elements = 1;    ///< cells through the film (the substrate has 4 times as many)
  int x_cells = 10;
  ElementFamily element = ElementFamily::taylor_hood;
  bool own_pressures = true;  ///< a pressure of each layer's own (region_pressure)
  double rotation = 1e-3;     ///< θ [rad] of the end x = length
};

struct BendingResult {
  double moment = 0.0;  ///< [N mm] about the neutral axis, from the reactions of the end
  double exact = 0.0;   ///< [N mm] b κ D (BL7)
  bool converged = false;
  int n_twins = 0;
  int negative_pivots = -1;
  int expected_negative_pivots = 0;
  std::vector<double> residuals;  ///< Newton's ||R|| history
  double pressure_jump = 0.0;     ///< [MPa] film minus substrate at the interface, mid-length
  double exact_jump = 0.0;        ///< [MPa] (BL6)
};

/// The neutral axis z_n = ∫ μ z dz / ∫ μ dz and D = ∫ 4 μ (z - z_n)^2 dz (BL7).
void section(const Bilayer& s, double& z_n, double& D) {
  const double mu_f = s.contrast * s.mu_soft, h = s.substrate, t = s.film;
  z_n = (s.mu_soft * h * h / 2 + mu_f * t * (h + t / 2)) / (s.mu_soft * h + mu_f * t);
  const auto layer = [&](double mu, double a, double b) {
    return 4.0 * mu * (std::pow(b - z_n, 3) - std::pow(a - z_n, 3)) / 3.0;
  };
  D = layer(s.mu_soft, 0.0, h) + layer(mu_f, h, h + t);
}

BendingResult bend(const Bilayer& s) {
  BendingResult result;
  const int z_cells = 5 * s.film_elements;  // substrate 0.4 = 4 film thicknesses
  const Mesh mesh = make_box_mesh(Vec3d(s.length, s.width, s.substrate + s.film),
                                  {s.x_cells, 1, z_cells}, mesh_order_of(s.element));
  ElementMaterials materials;
  materials.materials = {make_material("neo-hookean", {{"c1", s.mu_soft / 2}}),
                         make_material("neo-hookean", {{"c1", s.contrast * s.mu_soft / 2}})};
  materials.inverse_bulk_moduli = {0.0, 0.0};
  for (const auto& tet : mesh.tets) {
    double z = 0.0;
    for (int v : tet) z += mesh.nodes[static_cast<std::size_t>(v)].z() / 4.0;
    materials.of_element.push_back(z > s.substrate ? 1 : 0);
  }
  if (s.own_pressures) materials.pressure_region = materials.of_element;

  double z_n = 0.0, D = 0.0;
  section(s, z_n, D);
  // u_x = 0 at x = 0, u_x = θ (z - z_n) at x = L; u_y = 0 everywhere; u_z held at one node of
  // x = 0 (the exact solution is defined up to a translation along z).
  std::vector<ConstrainedComponent> constraints;
  std::set<int> right;
  bool pinned = false;
  for (int v = 0; v < mesh.n_nodes(); ++v) {
    const Vec3d& X = mesh.nodes[static_cast<std::size_t>(v)];
    constraints.push_back({v, 1, 0.0, Ramp{}});
    if (X.x() == 0.0) {
      constraints.push_back({v, 0, 0.0, Ramp{}});
      if (!pinned) constraints.push_back({v, 2, 0.0, Ramp{}});
      pinned = true;
    } else if (X.x() == s.length) {
      constraints.push_back({v, 0, s.rotation * (X.z() - z_n), Ramp{0.0, 1.0}});
      right.insert(v);
    }
  }
  MixedModel model(mesh, std::move(materials), constraints, {}, s.element);
  result.n_twins = model.pressure_twins().n_twins();
  NewtonSettings settings;
  settings.rtol = 1e-12;
  settings.atol = 1e-14;
  settings.reuse_factor = false;  // Newton proper: a tangent per iteration (quadratic test)
  NewtonSolver newton(model, settings);
  model.set_time(1.0);
  const NewtonResult solved = newton.solve();
  result.converged = solved.converged;
  result.residuals = solved.residual_history;
  if (!solved.converged) return result;
  model.save_converged();
  Vec f = model.create_vector();
  model.assemble_residual(f);
  VecDestroy(&f);
  const std::vector<double> reactions = model.nodal_reactions();
  for (int v : right)
    result.moment += reactions[3 * static_cast<std::size_t>(v)] *
                     (mesh.nodes[static_cast<std::size_t>(v)].z() - z_n);
  const double curvature = s.rotation / s.length;
  result.exact = s.width * curvature * D;

  // The pressures at the interface node nearest (L/2, 0, substrate): the substrate's in the
  // node's own value, the film's in its twin (BL6: p = -2 μ κ (z - z_n) in each layer).
  const PressureTwins& twins = model.pressure_twins();
  for (int k = 0; k < twins.n_twins(); ++k) {
    const int v = twins.corner[static_cast<std::size_t>(k)];
    const Vec3d& X = mesh.nodes[static_cast<std::size_t>(v)];
    if (std::abs(X.x() - s.length / 2) < 1e-9 && X.y() == 0.0) {
      result.pressure_jump =
          model.state()[DofMap::dof(mesh.n_nodes() + k, 3)] - model.state()[DofMap::dof(v, 3)];
    }
  }
  result.exact_jump = -2.0 * (s.contrast - 1.0) * s.mu_soft * curvature * (s.substrate - z_n);

  InertiaCheck check(model);
  result.negative_pivots = check.compute().negative;
  result.expected_negative_pivots = expected_negative_pivots(model);
  return result;
}

double stiffness_ratio(const Bilayer& s) {
  const BendingResult r = bend(s);
  EXPECT_TRUE(r.converged);
  return r.moment / r.exact;
}

// One Taylor-Hood element through the film, a pressure of each layer's own: the closed form's
// moment within 1e-3 (measured 1.0004 and 1.0002: the nonlinear terms of a strain of 5e-4), at
// contrasts of 100 and 1000; and the pressure jumps at the interface by (BL6) within 1 %
// (measured 0.4 %).
TEST(BondedLayers, OneTaylorHoodElementThroughTheFilmBendsAsTheClosedForm) {
  for (double contrast : {100.0, 1000.0}) {
    Bilayer s;
    s.contrast = contrast;
    const BendingResult r = bend(s);
    ASSERT_TRUE(r.converged);
    std::cout << "contrast " << contrast << ": M / M_exact = " << r.moment / r.exact << ", twins "
              << r.n_twins << ", jump " << r.pressure_jump << " (exact " << r.exact_jump << ")\n";
    EXPECT_NEAR(r.moment / r.exact, 1.0, 1e-3) << "contrast " << contrast;
    EXPECT_EQ(r.n_twins, 2 * (s.x_cells + 1)) << "a twin per corner node of the interface";
    EXPECT_NEAR(r.pressure_jump, r.exact_jump, 0.01 * std::abs(r.exact_jump));
  }
}

// The same strip with one pressure field for both layers: markedly too soft with one element
// through the film, and better with more, slowly: 0.929, 0.961, 0.980 of the closed form's
// moment at a contrast of 100 and 0.639, 0.799, 0.897 at 1000 with 1, 2 and 4 elements through
// the film. This is what the pressure of each region's own fixes; docs/case-file.md
// ("region_pressure") prints these ratios, held here to their last digit.
TEST(BondedLayers, ASharedPressureMakesAThinStiffFilmTooSoft) {
  for (const auto& [contrast, printed] : {std::pair{100.0, std::array{0.929, 0.961, 0.980}},
                                          std::pair{1000.0, std::array{0.639, 0.799, 0.897}}}) {
    Bilayer s;
    s.own_pressures = false;
    s.contrast = contrast;
    std::array<double, 3> ratio{};
    const std::array<int, 3> elements{1, 2, 4};
    for (std::size_t k = 0; k < 3; ++k) {
      s.film_elements = elements[k];
      ratio[k] = stiffness_ratio(s);
      std::cout << "contrast " << contrast << ", shared pressure, " << elements[k]
                << " element(s) through the film: M / M_exact = " << ratio[k] << '\n';
      // The numbers docs/case-file.md prints, to their last digit.
      EXPECT_NEAR(ratio[k], printed[k], 0.0005) << contrast << ", " << elements[k];
    }
    EXPECT_GT(ratio[1], ratio[0]);
    EXPECT_GT(ratio[2], ratio[1]);
  }
}

// Pressure stability with the twins: the converged state's tangent has exactly as many negative
// pivots as free pressure unknowns, twins included (stability.md, S4) — a pressure mode the
// displacements do not control would show as a zero or extra pivot — and Newton converges
// quadratically: each of the last iterations squares the relative residual, to within a factor.
TEST(BondedLayers, TheTwinPressuresAreStableAndNewtonStaysQuadratic) {
  for (ElementFamily element : {ElementFamily::taylor_hood, ElementFamily::mini}) {
    Bilayer s;
    s.element = element;
    s.rotation = 0.05;  // a finite rotation: several Newton iterations
    const BendingResult r = bend(s);
    ASSERT_TRUE(r.converged) << to_string(element);
    EXPECT_GT(r.n_twins, 0);
    EXPECT_EQ(r.negative_pivots, r.expected_negative_pivots) << to_string(element);
    const std::vector<double>& h = r.residuals;
    ASSERT_GE(h.size(), 4u);
    for (double x : h) std::cout << x << ' ';
    std::cout << '\n';
    // The last iteration that started above round-off: e_{k+1} <= C e_k^2 with e the residual
    // relative to the first.
    bool checked = false;
    for (std::size_t k = 1; k + 1 < h.size(); ++k) {
      const double e0 = h[k] / h[0], e1 = h[k + 1] / h[0];
      if (e0 > 1e-7 && e0 < 1e-2) {
        EXPECT_LT(e1, 10.0 * e0 * e0) << to_string(element) << " iteration " << k;
        checked = true;
      }
    }
    EXPECT_TRUE(checked) << "no iteration in the quadratic range";
  }
}

}  // namespace
}  // namespace plisse
