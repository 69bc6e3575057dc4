// Contact of shells (`contacts:` with `element: shell`, docs/theory/surface-contact.md N14),
// through `plisse run`: the faces of the shells, half their thicknesses off the mid-surfaces,
// meet.
//
// A propped cantilever. A strip 20 mm long, 10 mm wide and 1 mm thick (neo-Hookean μ = 1 MPa,
// incompressible: plane strain across its width through symmetry edges, D = μ t³/3 per unit
// width), clamped at x = 0 and hanging under its weight q = ρ g t, would sag q L⁴/(8 D) =
// 0.0200 mm at its free end. A second shell lies under its end, 2 mm thick and held, its upper
// face g₀ = 0.01 mm below the strip's lower face: its mid-surface is g₀ + 0.5 + 1 mm below the
// strip's. The strip's end comes down onto it and rests there, a cantilever propped at its end
// by the force per unit width
//     R = 3 q L / 8 − 3 D g₀ / L³
// (the free end's deflection under q less that under R, q L⁴/(8 D) − R L³/(3 D), is g₀:
// Timoshenko & Gere 1972, Mechanics of Materials, table of cantilever deflections). The contact
// reports R W as the push of the lower shell on the strip, the clamp the weight q L W less it,
// and the end sits g₀ down, less the penalty's penetration (~1e-7 mm). The same strip with its
// end held g₀ down by a `displacement` condition instead of the second shell is the mesh's own
// answer, without contact: the contact gives it within what the penetration moves.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "mesh/gmsh_io.hpp"
#include "mesh/mesh.hpp"
#include "output/history_writer.hpp"
#include "support/printed_errors.hpp"
#include "support/run_case.hpp"

namespace plisse {
namespace {

using test::history_column;
using test::run_case_text;

constexpr double kLength = 20.0, kWidth = 10.0;  // the strip [mm]
constexpr double kGap = 0.01;                    // between the faces at the start [mm]
constexpr double kStripThickness = 1.0, kBaseThickness = 2.0;
constexpr double kDensity = 3.4e-11;  // [tonne/mm³]
constexpr double kBaseFrom = 17.0, kBaseTo = 24.0;

/// The strip (cells of `h` mm, normals +z) and the lower shell (x from 17 to 24 mm, cells of
/// 0.8 h: non-matching, normals −z) as one shell mesh. Surface tags `strip` and `base` name the
/// faces opposite the normals, the two that look at each other; `both` holds every triangle.
/// Edge tags: `root` (x = 0), `tip` (x = L), `front` and `back` (y = 0 and W) of the strip.
Mesh propped_strip_mesh(double h) {
  Mesh mesh;
  const auto grid = [&](double x0, double x1, double z, double cell, bool down,
                        const std::string& tag) {
    const int nx = static_cast<int>(std::lround((x1 - x0) / cell));
    const int ny = static_cast<int>(std::lround(kWidth / cell));
    const int first = mesh.n_nodes();
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i)
        mesh.nodes.push_back(Vec3d(x0 + (x1 - x0) * i / nx, kWidth * j / ny, z));
    const auto node = [&](int i, int j) { return first + j * (nx + 1) + i; };
    const auto add = [&](int a, int b, int c) {
      const int t = static_cast<int>(mesh.triangles.size());
      mesh.surface_tags[tag].push_back(t);
      mesh.surface_tags["both"].push_back(t);
      mesh.triangles.push_back(down ? std::array<int, 3>{a, c, b} : std::array<int, 3>{a, b, c});
    };
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        add(node(i, j), node(i + 1, j), node(i + 1, j + 1));
        add(node(i, j), node(i + 1, j + 1), node(i, j + 1));
      }
    return std::array<int, 2>{nx, ny};
  };
  const auto [nx, ny] = grid(0.0, kLength, 0.0, h, false, "strip");
  grid(kBaseFrom, kBaseTo, -(kGap + 0.5 * (kStripThickness + kBaseThickness)), 0.8 * h, true,
       "base");
  const auto edge = [&](const std::string& tag, int a, int b) {
    mesh.edge_tags[tag].push_back(static_cast<int>(mesh.edges.size()));
    mesh.edges.push_back({a, b});
  };
  for (int j = 0; j < ny; ++j) {
    edge("root", j * (nx + 1), (j + 1) * (nx + 1));
    edge("tip", j * (nx + 1) + nx, (j + 1) * (nx + 1) + nx);
  }
  for (int i = 0; i < nx; ++i) {
    edge("front", i, i + 1);
    edge("back", ny * (nx + 1) + i, ny * (nx + 1) + i + 1);
  }
  return mesh;
}

/// The propped strip with cells of `h` mm; `support` is the case's `contacts:` line, or a
/// condition of its `boundary:` list.
HistoryTable propped_strip(const std::string& label, double h, const std::string& support) {
  const auto dir = test::scratch_directory("shell-contact-" + label);
  std::filesystem::create_directories(dir);
  write_gmsh(propped_strip_mesh(h), (dir / "strips.msh").string());
  const bool contact = support.starts_with("contacts:");
  return run_case_text(
      dir,
      "element: shell\n"
      "mesh: {file: strips.msh, thickness: 1.0}\n"
      "material: {model: neo-hookean, c1: 0.5, density: 3.4e-11}\n"
      "regions: [{surface: base, thickness: 2.0, material: {model: neo-hookean, c1: 0.5}}]\n"
      "boundary:\n"
      "  - {type: clamped, surface: root, name: root}\n"
      "  - {type: symmetry, surface: front}\n"
      "  - {type: symmetry, surface: back}\n"
      "  - {type: fixed, surface: base}\n" +
          (contact ? "" : "  - " + support + "\n") +
          "loads: [{type: gravity, name: g, acceleration: [0, 0, -9810]}]\n" +
          (contact ? support + "\n" : "") +
          "probes: [{name: end, point: [20, 5, 0]}]\n"
          "solver:\n  steps: 4\n"
          "  newton: {line_search: cp, rtol: 1.0e-12, atol: 1.0e-14}\n");
}

constexpr double kWeightPerArea = kDensity * 9810.0 * kStripThickness;  // q [MPa]
constexpr double kBending = 1.0 / 3.0;                                  // D = μ t³/3 [N mm]

/// R W [N]: the closed form of the file comment.
double propping_force() {
  const double L = kLength;
  return (3.0 * kWeightPerArea * L / 8.0 - 3.0 * kBending * kGap / (L * L * L)) * kWidth;
}

const std::vector<double>& last_row(const HistoryTable& t) {
  EXPECT_FALSE(t.rows.empty());
  static const std::vector<double> none(64, std::nan(""));
  if (t.rows.empty()) return none;
  EXPECT_DOUBLE_EQ(t.rows.back()[history_column(t, "time")], 1.0);
  return t.rows.back();
}

TEST(ShellContact, AStripPropsItsEndOnASecondShellHalfTheirThicknessesApart) {
  const double exact = propping_force();
  const double weight = kWeightPerArea * kLength * kWidth;
  std::vector<double> errors;
  for (double h : {1.0, 0.5, 0.25}) {
    const std::string label = "h" + std::to_string(errors.size());
    const HistoryTable t =
        propped_strip(label, h, "contacts: [{name: prop, surfaces: [strip, base]}]");
    const HistoryTable held =
        propped_strip(label + "-held", h,
                      "{type: displacement, surface: tip, name: tip, value: [null, null, -0.01]}");
    const auto& row = last_row(t);
    const double prop = row[history_column(t, "force_z:prop")];
    const double clamp = row[history_column(t, "force_z:root")];
    const double end = row[history_column(t, "uz:end")];
    const double by_condition = last_row(held)[history_column(held, "force_z:tip")];
    errors.push_back(std::abs(prop - exact) / exact);
    std::printf(
        "cells %.4g mm: prop %.8e N, end held %.8e N, clamp %.6e N, end %.8e mm; "
        "R W = %.8e N, error %.2e\n",
        h, prop, by_condition, clamp, end, exact, errors.back());
    // The clamp and the prop carry the strip's weight between them.
    EXPECT_NEAR(prop + clamp, weight, 1e-7 * weight) << h;
    // The end rests on the lower shell's face, its mid-surface g₀ down: penetration below 1e-4 g₀.
    EXPECT_LT(end, -kGap) << h;
    EXPECT_NEAR(end, -kGap, 1e-4 * kGap) << h;
    // The contact gives the held end's force, less what the penetration δ takes off it, 3 D W δ /
    // L³ (5e-5 of it here): within 3e-6 (the solver's tolerance; measured 4e-8 to 1.2e-6).
    const double moved = 3.0 * kBending * kWidth * (-end - kGap) / std::pow(kLength, 3);
    std::printf("  contact against the held end: %.1e\n", (prop - by_condition + moved) / exact);
    EXPECT_NEAR(prop, by_condition - moved, 3e-6 * exact) << h;
  }
  // The numbers docs/theory/surface-contact.md prints, to their last digit (the discretisation
  // error of the shell, against the closed form).
  test::expect_printed_second_order(errors, std::array{3.8e-3, 9.2e-4, 2.1e-4},
                                    std::array{5e-5, 5e-6, 5e-6});
}

// The same strip with one surface tag for both shells, in contact with itself (`self: both`):
// every node of either shell is kept out of the faces of both, so the lower shell's nodes under
// the end push back as well. The force across a self-contact sums to nothing, so the clamp tells
// the prop: q L W less the clamp's force is R W, as with two surfaces.
TEST(ShellContact, TheSameStripAsOneSurfaceInContactWithItself) {
  const double exact = propping_force();
  const double weight = kWeightPerArea * kLength * kWidth;
  const HistoryTable pair =
      propped_strip("pair", 0.5, "contacts: [{name: prop, surfaces: [strip, base]}]");
  const HistoryTable self = propped_strip("self", 0.5, "contacts: [{name: prop, self: both}]");
  const double by_pair = weight - last_row(pair)[history_column(pair, "force_z:root")];
  const double by_self = weight - last_row(self)[history_column(self, "force_z:root")];
  std::printf("prop from the clamp: pair %.8e N, self %.8e N, R W = %.8e N\n", by_pair, by_self,
              exact);
  EXPECT_NEAR(by_self, by_pair, 1e-5 * exact);
  EXPECT_NEAR(last_row(self)[history_column(self, "uz:end")], -kGap, 1e-4 * kGap);
}

}  // namespace
}  // namespace plisse
