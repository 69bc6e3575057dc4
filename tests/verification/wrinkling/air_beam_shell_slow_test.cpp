// The air beam with the wall as a thin shell (validation/air-beam-bending-shell.yaml; study in
// docs/studies/air-beam.md, "The shell, and a product's thickness"): the pressurised tube of
// air_beam_slow_test.cpp (R = 10 mm, L = 50 mm, neo-Hookean c1 = 0.5 MPa, half model), its end
// x = 0 a clamped edge, its end x = L a cap pushed down, at the solid study's wall (R/t = 50,
// p = 4e-3 MPa, elements of 1 mm) and at a product's (R/t = 500, p = 4e-4 MPa: the same hoop
// stress p R / t, elements of 0.5 mm), the two at once. The pressure in 10 steps, the tip's
// 15 mm in 40, every second step written; a snap (the steps fall below solver.min_step) ends the
// run.
// The clamp moment is `moment_z:clamp`, the moment of the clamped edge's reactions about the
// origin, which lies on the clamped section.
// Measured, as the rows of docs/validation.md (validation_claim.hpp):
//  - after the pressure the wall carries the closed tube's membrane forces, N_x = p r / 2 and
//    N_theta = p r at mid-length (equilibrium of an end and of half a ring), within 0.25 %: the
//    flat triangles are chords of the circle (1 - cos(pi / 2n) = 0.13 % at 31 divisions of the
//    half circle, 0.03 % at 63);
//  - at R/t = 50 the compressed fibre goes slack (N_x = 0, membrane beam theory's wrinkling
//    criterion, Comer & Levy 1963) when the local moment reaches up to 8 % less than pi p r^3 / 2
//    times the local prestress over p r / 2: next to the clamp, where the wall also bends
//    (-6.7 % on 1 mm elements, -4.0 % on 0.7 mm; the solid's wall meets it within 1 %);
//  - the collapse, the largest clamp moment before the snap that ends the path, lies below
//    membrane theory's capacity: within 10 % below pi p r^3 at R/t = 50, and at R/t = 500 within
//    20 % below pi p R^3, the capacity of the clamped end, whose radius stays R while the tube
//    grows to r; and it falls by more than 0.1 pi p r^3 from R/t = 50 to 500 (the law the study
//    reports: the thin wall's stiffness no longer carries it past the narrowed end).
// Regression guards against the study's runs: the degrees of freedom the study prints and each
// collapse within 1 % (CI's meshes), and the thin wall's first slack fibre within 2 % (it lies in
// the clamp's flare, where the wall's radius rises from R to r, and moves with the mesh:
// 0.481 pi p r^3 on 0.5 mm elements, 0.588 on 0.35).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <future>
#include <iostream>
#include <numbers>
#include <string>
#include <vector>

#include "mesh/tube_mesh.hpp"
#include "output/history_writer.hpp"
#include "output/json_file.hpp"
#include "output/pvd_writer.hpp"
#include "output/run_directory.hpp"
#include "output/vtu_reader.hpp"
#include "support/run_case.hpp"
#include "support/run_plisse.hpp"
#include "support/shell_tube.hpp"
#include "support/validation_claim.hpp"

namespace plisse {
namespace {

constexpr double kRadius = 10.0, kLength = 50.0;

/// One wall of the study.
struct Wall {
  double thickness = 0.0;  ///< [mm]
  double pressure = 0.0;   ///< [MPa]
  double size = 0.0;       ///< element size [mm]
};

struct Step {
  double time = 0.0, force = 0.0, moment = 0.0;  ///< -F_y at the tip, |M_clamp| (half model)
  std::vector<double> row;                       ///< N_x of the compressed row per slice, x <= L/2
  double axial_mid = 0.0, hoop_mid = 0.0, r_mid = 0.0;
};

struct ShellBeam {
  bool ran = false;
  double axial_ratio = 0.0, hoop_ratio = 0.0;  ///< mid-length N_x / (p r/2), N_theta / (p r)
  double slack_moment = 0.0;    ///< M / (pi p r^3) where the compressed fibre first goes slack
  double slack_expected = 0.0;  ///< membrane theory's value with the local prestress
  double collapse = 0.0;        ///< largest clamp moment / (pi p r^3)
  double r = 0.0;               ///< mid radius at mid-length after the pressure
  double slack_x = 0.0;         ///< where the fibre went slack [mm]
  long dofs = 0;                ///< summary.json's dofs (the study's cost line prints them)
};

std::string number(double x) { return test::six_digits(x); }

ShellBeam bend(const Wall& w) {
  ShellBeam result;
  const double p = w.pressure;
  const auto dir =
      test::scratch_directory("air-beam-shell-t" + number(w.thickness) + "-h" + number(w.size));
  const std::string options =
      " --set mesh.thickness=" + number(w.thickness) +
      " --set mesh.element_size=" + number(w.size) + " --set loads[0].value=" + number(p) +
      " --set solver.steps=50 --set solver.max_step=0.02 --set solver.min_step=1e-3";
  const int status =
      test::run_plisse("run " + std::string(PLISSE_SOURCE_DIR) +
                           "/validation/air-beam-bending-shell.yaml -o " + dir.string() + options,
                       dir.string() + ".log");
  // A snap ends the quasi-static path: the run stops (exit 1) with every converged step written.
  EXPECT_TRUE(status == 0 || status == 1) << "see " << dir.string() << ".log";
  if (!std::filesystem::exists(dir / "history.csv")) return result;
  const HistoryTable history = read_history(dir / "history.csv");
  result.dofs = read_json_file(dir / "summary.json").value("dofs", 0L);
  const std::size_t c_time = test::history_column(history, "time"),
                    c_force = test::history_column(history, "force_y:tip"),
                    c_moment = test::history_column(history, "moment_z:clamp");

  const Mesh mesh = test::half_tube_shell(kRadius, kLength, w.thickness, w.size);
  const int around = tube_divisions_around(kRadius, w.size, true);
  // The cells' length along the axis (the generator's round(L / h) stations, mesh/tube_mesh.hpp):
  // a slice is one ring of cells.
  const double dx = kLength / static_cast<double>(std::lround(kLength / w.size));
  const auto slices = static_cast<std::size_t>(std::floor(kLength / 2 / dx + 1e-9));
  const std::vector<Vec3d> centroid = test::triangle_centroids(mesh);
  // The ring of nodes nearest mid-length.
  double x_mid = 0.0;
  for (const Vec3d& X : mesh.nodes)
    if (std::abs(X.x() - kLength / 2) < std::abs(x_mid - kLength / 2)) x_mid = X.x();

  std::vector<Step> steps;
  for (const PvdEntry& entry : read_pvd(dir / "solution.pvd")) {
    if (entry.file == RunDirectory::step_file_name(0)) continue;
    const auto row = test::history_row_at(history, c_time, entry.time);
    EXPECT_NE(row, history.rows.end());
    if (row == history.rows.end()) return result;
    const auto vtu = dir / entry.file;
    const VtuField u = read_vtu_point_field(vtu, "displacement");
    const VtuField n_field = read_vtu_cell_field(vtu, "membrane_force");
    EXPECT_EQ(n_field.values.size(), 6 * mesh.triangles.size());
    if (n_field.values.size() != 6 * mesh.triangles.size()) return result;
    Step s;
    s.time = entry.time;
    s.force = -(*row)[c_force];
    s.moment = std::abs((*row)[c_moment]);
    double r_sum = 0.0;
    int r_count = 0;
    for (std::size_t n = 0; n < mesh.nodes.size(); ++n) {
      const Vec3d& X = mesh.nodes[n];
      const Vec3d x = X + Vec3d(u.values[3 * n], u.values[3 * n + 1], u.values[3 * n + 2]);
      if (std::abs(X.x() - x_mid) < 1e-9) r_sum += std::hypot(x.y(), x.z()), ++r_count;
    }
    s.r_mid = r_sum / r_count;
    std::vector<double> row_sum(slices, 0.0);
    std::vector<int> row_count(slices, 0);
    int mid = 0;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
      const double* v = &n_field.values[6 * t];  // xx, yy, zz, xy, yz, xz
      const Vec3d& c = centroid[t];
      const double phi = std::atan2(c.z(), c.y());
      if (std::abs(c.x() - x_mid) <= dx / 2) {
        const double sn = std::sin(phi), cs = std::cos(phi);  // e_phi = (0, -sin, cos)
        s.hoop_mid += sn * sn * v[1] + cs * cs * v[2] - 2.0 * sn * cs * v[4];
        s.axial_mid += v[0];
        ++mid;
      }
      const auto j = static_cast<std::size_t>(c.x() / dx);
      if (phi > std::numbers::pi * (1.0 - 1.0 / around) && j < slices) {
        row_sum[j] += v[0];
        ++row_count[j];
      }
    }
    s.axial_mid /= mid;
    s.hoop_mid /= mid;
    for (std::size_t j = 0; j < slices; ++j) s.row.push_back(row_sum[j] / row_count[j]);
    steps.push_back(s);
  }
  const auto pressurised =
      std::find_if(steps.begin(), steps.end(), [](const Step& s) { return s.time >= 0.2 - 1e-9; });
  EXPECT_NE(pressurised, steps.end());
  if (pressurised == steps.end()) return result;
  EXPECT_NEAR(pressurised->time, 0.2, 1e-9) << "the end of the pressure was not written";
  const Step& p0 = *pressurised;
  const double r = p0.r_mid;
  result.r = r;
  result.axial_ratio = p0.axial_mid / (p * r / 2);
  result.hoop_ratio = p0.hoop_mid / (p * r);
  const double unit_moment = std::numbers::pi * p * r * r * r / 2;  // half model
  const std::vector<Step> bending(pressurised + 1, steps.end());
  EXPECT_GE(bending.size(), 10u);
  if (bending.size() < 10u) return result;

  // First slack fibre of the compressed row outside the clamp's first slice, interpolated.
  bool slack = false;
  for (std::size_t k = 0; k < bending.size() && !slack; ++k) {
    const Step& a = k == 0 ? p0 : bending[k - 1];
    const Step& c = bending[k];
    std::size_t j = 1;
    for (std::size_t i = 1; i < c.row.size(); ++i)
      if (c.row[i] < c.row[j]) j = i;
    if (c.row[j] > 0.0 || a.row[j] <= 0.0) continue;
    slack = true;
    const double f = a.row[j] / (a.row[j] - c.row[j]);
    const double F = a.force + f * (c.force - a.force);
    result.slack_x = (static_cast<double>(j) + 0.5) * dx;
    result.slack_moment = (a.moment + f * (c.moment - a.moment) - F * result.slack_x) / unit_moment;
    result.slack_expected = 0.5 * p0.row[j] / (p * r / 2);
  }
  EXPECT_TRUE(slack) << "the compressed fibre never went slack at R/t = " << kRadius / w.thickness;
  double largest = 0.0;
  for (const auto& s : bending) largest = std::max(largest, s.moment);
  result.collapse = largest / unit_moment;
  std::cout << "R/t = " << kRadius / w.thickness << ": r " << r << ", closed tube N_x "
            << result.axial_ratio << " N_theta " << result.hoop_ratio
            << "; first slack at x = " << result.slack_x << ": M/(pi p r^3) " << result.slack_moment
            << " (theory " << result.slack_expected << "); largest clamp moment " << result.collapse
            << " pi p r^3\n";
  result.ran = slack;
  return result;
}

std::string subject(double r_over_t) {
  return "air beam: pressurised tube in bending, shell, R/t = " + number(r_over_t) +
         ", L/R = 5, neo-Hookean, p R/t = 0.2 MPa";
}

std::string mesh_text(const Wall& w) { return test::shell_mesh_text(w.size); }

void expect_membrane_theory(const Wall& w, const ShellBeam& b, const std::string& id) {
  const double rt = kRadius / w.thickness;
  test::expect_closed_tube_axial_force("air-beam-shell/" + id + "/axial-prestress", subject(rt),
                                       "mid-length", mesh_text(w), b.axial_ratio);
  test::expect_claim({.row = "air-beam-shell/" + id + "/hoop-prestress",
                      .subject = subject(rt),
                      .quantity = "membrane force N_θ at mid-length after the pressure, over p r",
                      .mesh = mesh_text(w),
                      .measured = b.hoop_ratio,
                      .reference = 1.0,
                      .source = "closed tube's equilibrium, N_θ = p r",
                      .low = -0.0025,
                      .high = 0.0025,
                      .why = "the same"});
}

constexpr const char* kSlack = "moment where the compressed fibre goes slack, M/(π p r³)";
constexpr const char* kSlackSource =
    "Comer & Levy 1963, M_w = π p r³/2, with the clamp's local prestress";

/// A regression guard against the study's run, within `band` (relative).
void expect_study(const Wall& w, const std::string& id, const std::string& quantity,
                  double measured, double study, double band, const std::string& why) {
  test::expect_claim({.row = "air-beam-shell/" + id,
                      .subject = subject(kRadius / w.thickness),
                      .quantity = quantity,
                      .mesh = mesh_text(w),
                      .measured = measured,
                      .reference = study,
                      .source = "the study's run (docs/studies/air-beam.md)",
                      .low = -band,
                      .high = band,
                      .why = why,
                      .kind = test::ClaimKind::regression});
}

// The full tier (PLISSE_VALIDATION_FULL, test name suffix .full) runs both walls on finer
// elements, 0.7 and 0.35 mm: the study's mesh convergence.
constexpr double kRefine = test::kFullTier ? 0.7 : 1.0;

TEST(AirBeamShellSlow, CollapseFallsBelowMembraneTheoryAsTheWallThins) {
  const Wall thick{.thickness = 0.2, .pressure = 4.0e-3, .size = 1.0 * kRefine};
  const Wall thin{.thickness = 0.02, .pressure = 4.0e-4, .size = 0.5 * kRefine};
  // The full tier runs the two walls at once (PROCESSORS 2 in CMakeLists.txt); CI's tier one
  // after the other on one processor, where the thick wall takes a tenth of the thin one's time
  // and a second processor would mostly wait.
  auto thin_run =
      std::async(test::kFullTier ? std::launch::async : std::launch::deferred, bend, thin);
  const ShellBeam a = bend(thick);
  const ShellBeam b = thin_run.get();
  ASSERT_TRUE(a.ran && b.ran);
  expect_membrane_theory(thick, a, "rt50");
  expect_membrane_theory(thin, b, "rt500");
  // The thick wall's slack fibre against membrane theory. The thin wall's lies in the clamp's
  // flare, where the wall's radius rises from R to r over some millimetres, and moves with the
  // mesh (the study): guarded, not compared.
  test::expect_claim({.row = "air-beam-shell/rt50/slack",
                      .subject = subject(kRadius / thick.thickness),
                      .quantity = kSlack,
                      .mesh = mesh_text(thick),
                      .measured = a.slack_moment,
                      .reference = a.slack_expected,
                      .source = kSlackSource,
                      .low = -0.08,
                      .high = 0.0,
                      .why = "earlier: next to the clamp the wall also bends (study)"});
  expect_study(thin, "rt500/slack", kSlack, b.slack_moment, test::kFullTier ? 0.5882 : 0.4807, 0.02,
               "a guard: it lies in the clamp's flare and moves with the mesh (study)");
  // The collapse lies below membrane theory's capacity: pi p r^3 of the uniform tube at R/t = 50;
  // at R/t = 500 even pi p R^3, the clamped end's, whose radius stays R.
  const double end = std::pow(kRadius / b.r, 3);
  test::expect_claim({.row = "air-beam-shell/rt50/collapse",
                      .subject = subject(kRadius / thick.thickness),
                      .quantity = "collapse (a snap): largest clamp moment / (π p r³)",
                      .mesh = mesh_text(thick),
                      .measured = a.collapse,
                      .reference = 1.0,
                      .source = "Comer & Levy 1963, M_c = π p r³",
                      .low = -0.10,
                      .high = 0.0,
                      .why = "below: reached only as the slack sector spreads round the section, "
                             "and the snap comes first (study)"});
  test::expect_claim({.row = "air-beam-shell/rt500/collapse",
                      .subject = subject(kRadius / thin.thickness),
                      .quantity = "collapse (a snap): largest clamp moment / (π p R³), R the "
                                  "clamped end's radius",
                      .mesh = mesh_text(thin),
                      .measured = b.collapse / end,
                      .reference = 1.0,
                      .source = "Comer & Levy 1963, M_c = π p R³ at the clamped end",
                      .low = -0.20,
                      .high = 0.0,
                      .why = "below, as at R/t = 50; not converged on these meshes (study)"});
  // The law: the thin wall's collapse falls further below membrane theory.
  EXPECT_LT(b.collapse, a.collapse - 0.1);
  if (!test::kFullTier) {
    // The degrees of freedom the study's cost line prints (summary.json `dofs`).
    EXPECT_EQ(a.dofs, 6624);
    EXPECT_EQ(b.dofs, 26048);
    const char* collapse = "collapse: largest clamp moment / (π p r³)";
    expect_study(thick, "rt50/collapse-guard", collapse, a.collapse, 0.9428, 0.01,
                 "a guard, not evidence");
    expect_study(thin, "rt500/collapse-guard", collapse, b.collapse, 0.7715, 0.01,
                 "a guard, not evidence");
  }
}

}  // namespace
}  // namespace plisse
