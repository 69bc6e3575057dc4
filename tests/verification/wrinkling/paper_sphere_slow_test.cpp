// The paper's indented sphere (Daanouni, Tillier & Bay 2009, section 4.2.1) at its stated values,
// in the dimensionless form of validation/paper-sphere-squeeze.yaml (map, references and mesh
// convergence in docs/studies/paper-sphere.md): mid-surface radius R = 25 mm, wall t = 1 mm,
// neo-Hookean c1 = 0.0033 MPa, p = 1e-4 MPa = 0.31 of the thin sphere's limit pressure
// 2.479 c1 t / R, octant of one Taylor-Hood layer, a frictionless plate flattening the pole by
// d = 0.2 R (the paper's 10 mm plate travel onto a sphere of this size on a frictionless floor);
// 50 steps. Asserted:
//  - the paper's answer at these values is not plisse's: the stability check finds no
//    bifurcation at any step (every pivot count is the pressure unknowns' count), no ring's
//    amplitude reaches the wrinkle threshold 0.1 t, and no element is in compression by the
//    tension-field test at the end (a pressurised membrane pressed by a frictionless plate stays
//    in biaxial tension: the study's map);
//  - membrane equilibrium of the flattened patch: a flat piece of wall between the gas and the
//    plate carries no normal load of its own, so the plate's traction per current area equals the
//    gas pressure. The bending moments of the wall act within a few bending lengths
//    (R^2 t^2 / 9)^(1/4) = 2.9 mm of the contact edge, which lies 12 mm from the pole at the end,
//    so at the middle of the patch (within 4 mm of the pole) the traction must be p within 1 %
//    (a row of docs/validation.md, validation_claim.hpp: the wall's bending, the discrete
//    traction at the edge nodes and the patch's 4 mm of curvature share that). The traction is the
//    contact_pressure_punch field (force per reference area) divided by the outer surface's
//    current-to-reference area ratio there.
// The same case with the shell triangle on the mid-surface (the plate pressing its face t/2 above
// it) must give the same verdict and the same equilibrium (its own row).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <string>

#include "mesh/generate.hpp"
#include "output/history_writer.hpp"
#include "output/pvd_writer.hpp"
#include "output/vtu_reader.hpp"
#include "support/run_case.hpp"
#include "support/run_plisse.hpp"
#include "support/validation_claim.hpp"

namespace plisse {
namespace {

constexpr double kRadius = 25.0, kThickness = 1.0, kPressure = 1.0e-4;
constexpr double kPatch = 4.0;  ///< [mm] from the pole axis: the middle of the flattened patch

double triangle_area(const Vec3d& a, const Vec3d& b, const Vec3d& c) {
  return 0.5 * (b - a).cross(c - a).norm();
}

/// What a run of the case gives: the flattening d / R and the plate's traction per current area
/// at the middle of the patch [MPa].
struct Squeeze {
  double flattening = 0.0;
  double traction = 0.0;
};

/// Runs the case (with `options`, e.g. the shell's) and asserts that it stays taut and stable;
/// `mesh` is the run's mesh, generated again. The traction: the contact_pressure_punch field (force
/// per reference area) over the loaded nodes of the patch (a Taylor-Hood face's edge nodes, which
/// carry its load, or a shell triangle's corners), divided by the current-to-reference area ratio
/// of the patch's triangles (the outer face's, or the shell's mid-surface).
Squeeze squeeze(const std::string& name, const std::string& options, const Mesh& mesh) {
  const auto dir = test::scratch_directory(name);
  const int status =
      test::run_plisse("run " + std::string(PLISSE_SOURCE_DIR) +
                           "/validation/paper-sphere-squeeze.yaml -o " + dir.string() + options,
                       dir.string() + ".log");
  EXPECT_EQ(status, 0) << "see " << dir.string() << ".log";
  if (status != 0) return {};
  const HistoryTable history = read_history(dir / "history.csv");
  const auto column = [&](const std::string& name) { return test::history_column(history, name); };
  const std::size_t c_stable = column("stable"), c_amplitude = column("wrinkle_amplitude"),
                    c_compressed = column("wrinkled_fraction"), c_slack = column("slack_fraction"),
                    c_pressure = column("pressure:gas"), c_top = column("uy:top");
  EXPECT_EQ(history.rows.size(), 50U);
  if (history.rows.size() < 5) return {};
  for (const auto& row : history.rows) {
    EXPECT_EQ(row[c_stable], 1.0) << "unstable at step " << row[0];
    EXPECT_LT(row[c_amplitude], 0.1 * kThickness) << "step " << row[0];
  }
  const auto& last = history.rows.back();
  EXPECT_EQ(last[c_compressed], 0.0);
  EXPECT_EQ(last[c_slack], 0.0);
  EXPECT_EQ(last[c_pressure], kPressure);

  const auto entries = read_pvd(dir / "solution.pvd");
  EXPECT_FALSE(entries.empty());
  if (entries.empty()) return {};
  const VtuField u = read_vtu_point_field(dir / entries.back().file, "displacement");
  const VtuField traction =
      read_vtu_point_field(dir / entries.back().file, "contact_pressure_punch");
  EXPECT_EQ(u.values.size(), 3 * mesh.nodes.size());
  if (u.values.size() != 3 * mesh.nodes.size()) return {};
  const auto deformed = [&](int n) {
    const auto k = static_cast<std::size_t>(n);
    return Vec3d(mesh.nodes[k] + Vec3d(u.values[3 * k], u.values[3 * k + 1], u.values[3 * k + 2]));
  };
  const auto in_patch = [&](const Vec3d& x) { return std::hypot(x.x(), x.z()) < kPatch; };
  double area = 0.0, reference_area = 0.0, traction_sum = 0.0;
  int loaded = 0;
  std::vector<char> seen(mesh.nodes.size(), 0);
  for (int t : mesh.surface_tags.at("outer")) {
    const auto& tri = mesh.triangles[static_cast<std::size_t>(t)];
    const Vec3d& a = mesh.nodes[static_cast<std::size_t>(tri[0])];
    const Vec3d& b = mesh.nodes[static_cast<std::size_t>(tri[1])];
    const Vec3d& c = mesh.nodes[static_cast<std::size_t>(tri[2])];
    if (a.y() <= 0.0 || !in_patch((a + b + c) / 3.0)) continue;
    reference_area += triangle_area(a, b, c);
    area += triangle_area(deformed(tri[0]), deformed(tri[1]), deformed(tri[2]));
    std::vector<int> carriers(tri.begin(), tri.end());  // a shell's corners
    if (!mesh.is_shell()) {
      const auto& edge_nodes = mesh.triangle_edge_nodes[static_cast<std::size_t>(t)];
      carriers.assign(edge_nodes.begin(), edge_nodes.end());
    }
    for (int n : carriers) {
      const auto k = static_cast<std::size_t>(n);
      if (seen[k] || !in_patch(mesh.nodes[k])) continue;
      seen[k] = 1;
      EXPECT_GT(traction.values[k], 0.0) << "node " << n << " is off the plate";
      traction_sum += traction.values[k];
      ++loaded;
    }
  }
  EXPECT_GE(loaded, 20);
  if (loaded == 0) return {};
  const double ratio = area / reference_area;
  Squeeze result;
  result.traction = traction_sum / loaded / ratio;
  result.flattening = (history.rows[4][c_top] - last[c_top]) / kRadius;
  std::cout << "d/R = " << result.flattening << "; patch: " << loaded << " nodes, area ratio "
            << ratio << ", plate traction " << result.traction
            << " MPa = " << result.traction / kPressure << " p\n";
  EXPECT_GT(result.flattening, 0.19);
  return result;
}

/// The case's mesh: its quadratic tetrahedra, or with `order` 1 the shell's mid-surface.
MeshGenerationSpec case_mesh(int order = 2) {
  MeshGenerationSpec spec;
  spec.kind = "spherical-shell";
  spec.inner_radius = kRadius - 0.5 * kThickness;
  spec.thickness = kThickness;
  spec.layers = 1;
  spec.element_size = 2.5;
  spec.pole_element_size = 1.0;
  spec.pole_radius = 18.75;
  spec.symmetry = Symmetry::octant;
  spec.order = order;
  return spec;
}

constexpr const char* kSubject =
    "the paper's indented sphere at its stated values: R/t = 25, ΔP = 1e-4 MPa = 0.31 p_max, d = "
    "0.2 R";

void expect_plate_traction(const Squeeze& s, const std::string& row, const std::string& mesh) {
  test::expect_claim({.row = row,
                      .subject = kSubject,
                      .quantity = "plate traction per current area at the middle of the "
                                  "flattened patch [MPa]",
                      .mesh = mesh,
                      .measured = s.traction,
                      .reference = kPressure,
                      .source = "membrane equilibrium of a flat wall between gas and plate",
                      .low = -0.01,
                      .high = 0.01,
                      .why = "bending acts within a few (R²t²/9)^¼ of the contact's edge"});
}

TEST(PaperSphereSlow, SqueezedPressurisedSphereStaysTautAndTheFlatPatchCarriesThePressure) {
  const Squeeze s = squeeze("paper-sphere", "", generate_mesh(case_mesh()));
  expect_plate_traction(s, "paper-sphere/plate-traction",
                        "h = 1 mm within 0.75 R of the pole, 1 TH layer, 22k unknowns");
}

// The same with the shell triangle on the mid-surface (--set element=shell; the plate presses the
// face t/2 above it): the same verdict and the same equilibrium, in about 10 s.
TEST(PaperSphereSlow, TheShellTriangleStaysTautAndItsFlatPatchCarriesThePressure) {
  const Squeeze s =
      squeeze("paper-sphere-shell", " --set element=shell", generate_shell_surface(case_mesh(1)));
  expect_plate_traction(s, "paper-sphere/shell-plate-traction",
                        "h = 1 mm within 0.75 R of the pole, shell triangles");
}

}  // namespace
}  // namespace plisse
