// Fibre directions in a generated shell's own frame (`material.fibre_frame: shell`), through
// `plisse run`, against membrane closed forms (fibre-reinforced model: Holzapfel, Gasser & Ogden
// 2000, eq. 2.3, a neo-Hookean matrix and fibres that carry load in extension only):
// - an open tube inflated by internal pressure carries its load around the circumference with no
//   axial stress, its wall in uniaxial tension along the hoops. With fibres laid around the
//   hoops, P(λ) = p R_i λ^(1/2) / t, P the nominal uniaxial stress along the fibres (from
//   σ_θ t_cur = p r_i, σ_θ = λ P, t_cur = t λ^(-1/2), r_i = λ R_i);
// - an inflated sphere is in equibiaxial tension everywhere. With one family along the meridians
//   and one around the hoops, P(λ) = p R_i λ² / (2 t), P the nominal equibiaxial stress with
//   fibres along both stretched directions (σ t_cur = p r_i / 2, t_cur = t λ^-2), the same at
//   every latitude. (The same fibres fixed along x and y in space leave one family normal to
//   the wall near the pole: there the sphere, above its matrix's limit pressure, balloons to
//   2.6 times its radius, and 7.2 times at 45° about the axis near the equator.)
// The closed forms are a membrane's: the tolerance, 3 % of the strain, covers the walls'
// t / R = 1/40.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>
#include <utility>

#include "core/types.hpp"
#include "material/homogeneous_test.hpp"
#include "material/registry.hpp"
#include "output/history_writer.hpp"
#include "support/run_case.hpp"

namespace plisse {
namespace {

using test::history_column;
using test::run_case_text;

constexpr double kThickness = 0.5;  // the tube's wall [mm]
constexpr double kTubeRadius = 20.0, kTubeInnerRadius = kTubeRadius - 0.5 * kThickness;
constexpr double kTubePressure = 0.004;                          // [MPa]
constexpr double kSphereInnerRadius = 10.0, kSphereWall = 0.25;  // [mm]
constexpr double kSphereRadius = kSphereInnerRadius + 0.5 * kSphereWall;
constexpr double kSpherePressure = 0.03;  // [MPa]

/// The fibre-reinforced material of both cases (c1 0.1 MPa, k1 1 MPa, k2 0.5) with fibres along
/// the test axes: x only, or x and y.
AnyMaterial fibres_along(bool two_families) {
  MaterialValues v = {{"c1", 0.1}, {"k1", 1.0}, {"k2", 0.5}, {"a1_x", 1.0}};
  if (two_families) v["a2_y"] = 1.0;
  return make_material("fibre-reinforced", v);
}

/// The stretch λ in [1, 3] where P(mode, λ) = load(λ), by bisection.
template <class Load>
double solve_stretch(const AnyMaterial& material, TestMode mode, Load load) {
  double lo = 1.0, hi = 3.0;
  for (int k = 0; k < 200; ++k) {
    const double l = 0.5 * (lo + hi);
    (nominal_stress(material, mode, l) > load(l) ? hi : lo) = l;
  }
  return 0.5 * (lo + hi);
}

const std::string kFibres = "material: {model: fibre-reinforced, c1: 0.1, k1: 1.0, k2: 0.5, ";

TEST(ShellFibres, HoopFibresHoldAnInflatedTubeAsTheMembraneClosedFormSays) {
  const double expected = solve_stretch(fibres_along(false), TestMode::uniaxial, [](double l) {
    return kTubePressure * kTubeInnerRadius * std::sqrt(l) / kThickness;
  });
  const auto dir = test::scratch_directory("shell-fibres-tube");
  const HistoryTable h =
      run_case_text(dir,
                    "element: taylor-hood\n"
                    "mesh: {generate: tube, radius: 20, length: 30, thickness: 0.5, layers: 1,"
                    " element_size: 2, symmetry: half}\n" +
                        kFibres +
                        "a1_y: 1, fibre_frame: shell}\n"
                        "boundary:\n"
                        "  - {type: fixed, surface: left}\n"
                        "  - {type: symmetry, surface: sym_z}\n"
                        "loads: [{type: pressure, name: p, surface: inner, value: 0.004}]\n"
                        "probes: [{name: mid, point: [20, 14.142135623730951, 14.142135623730951],"
                        " fields: [position]}]\n"
                        "solver:\n  steps: 4\n  newton: {rtol: 1.0e-10, atol: 1.0e-12}\n");
  ASSERT_FALSE(h.rows.empty());
  const double stretch = std::hypot(h.rows.back()[history_column(h, "y:mid")],
                                    h.rows.back()[history_column(h, "z:mid")]) /
                         kTubeRadius;
  std::cout << "tube hoop stretch " << stretch << ", membrane " << expected << '\n';
  EXPECT_NEAR(stretch - 1.0, expected - 1.0, 0.03 * (expected - 1.0));
}

/// The mid-wall radial stretch near the pole (10° from the +y axis) and near the equator (80°),
/// both at 45° about the axis, of the inflated sphere octant with fibres in `frame`.
std::pair<double, double> sphere_stretches(const std::string& frame) {
  const auto dir = test::scratch_directory("shell-fibres-sphere-" + frame);
  const double R = kSphereRadius;
  const auto point = [&](double from_axis_deg) {
    const double a = from_axis_deg * M_PI / 180.0, s = std::sin(a) / std::sqrt(2.0);
    char text[128];
    std::snprintf(text, sizeof text, "[%.15g, %.15g, %.15g]", R * s, R * std::cos(a), R * s);
    return std::string(text);
  };
  const HistoryTable h = run_case_text(
      dir,
      "element: taylor-hood\n"
      "mesh: {generate: spherical-shell, inner_radius: 10, thickness: 0.25, layers: 1,"
      " element_size: 1, symmetry: octant}\n" +
          kFibres + "a1_x: 1, a2_y: 1, fibre_frame: " + frame +
          "}\n"
          "boundary:\n"
          "  - {type: symmetry, surface: sym_x}\n"
          "  - {type: symmetry, surface: sym_y}\n"
          "  - {type: symmetry, surface: sym_z}\n"
          "loads: [{type: pressure, name: p, surface: inner, value: 0.03}]\n"
          "probes:\n"
          "  - {name: pole, point: " +
          point(10) +
          ", fields: [position]}\n"
          "  - {name: equator, point: " +
          point(80) +
          ", fields: [position]}\n"
          "solver:\n  steps: 4\n  newton: {rtol: 1.0e-10, atol: 1.0e-12}\n");
  if (h.rows.empty()) return {NAN, NAN};
  const auto radius = [&](const std::string& probe) {
    const auto& row = h.rows.back();
    return Vec3d(row[history_column(h, "x:" + probe)], row[history_column(h, "y:" + probe)],
                 row[history_column(h, "z:" + probe)])
        .norm();
  };
  return {radius("pole") / R, radius("equator") / R};
}

TEST(ShellFibres, MeridianAndHoopFibresInflateASphereAlikeEverywhere) {
  const double expected = solve_stretch(fibres_along(true), TestMode::equibiaxial, [](double l) {
    return kSpherePressure * kSphereInnerRadius * l * l / (2.0 * kSphereWall);
  });
  const auto [pole, equator] = sphere_stretches("shell");
  std::cout << "sphere, fibres on meridians and hoops: stretch " << pole << " near the pole, "
            << equator << " near the equator; membrane " << expected << '\n';
  EXPECT_NEAR(pole - 1.0, expected - 1.0, 0.03 * (expected - 1.0));
  EXPECT_NEAR(equator - 1.0, expected - 1.0, 0.03 * (expected - 1.0));
}

}  // namespace
}  // namespace plisse
