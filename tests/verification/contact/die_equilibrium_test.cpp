// Global equilibrium with rigid dies (docs/theory/contact.md, D15): a pressurised thin sphere
// pressed between two plates (the die forces balance each other) and a pressurised dome on a
// clamped equator pressed by a plate (die force, clamp reaction and pressure resultant balance),
// both run through `plisse run`, with the MINI and with the Taylor-Hood element (its die contact
// acts on the edge nodes of the 6-node faces, D16). At every converged step no node may penetrate
// a die by more than its tolerance (D10).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <vector>

#include "case/case.hpp"
#include "output/history_writer.hpp"
#include "physics/follower_pressure.hpp"
#include "physics/surface.hpp"
#include "support/run_plisse.hpp"

namespace plisse {
namespace {

const std::string kCaseDir = std::string(PLISSE_SOURCE_DIR) + "/tests/verification/contact/";
constexpr double kDieTolerance = 1e-3;  ///< `tolerance` of the dies in both case files [mm]

/// Runs a case of this folder with `element` and returns its history.
HistoryTable run_case(const std::string& name, const std::string& element) {
  const auto dir = test::scratch_directory("contact-" + name + "-" + element);
  const int status = test::run_plisse(
      "run " + kCaseDir + name + ".yaml -o " + dir.string() + " --set element=" + element,
      dir.string() + ".log");
  EXPECT_EQ(status, 0) << "see " << dir.string() << ".log";
  return read_history(dir / "history.csv");
}

std::string scientific(double value) {
  std::ostringstream out;
  out << std::scientific << value;
  return out.str();
}

/// Column accessor by name.
struct Columns {
  const HistoryTable& table;
  size_t operator()(const std::string& name) const {
    const auto it = std::find(table.columns.begin(), table.columns.end(), name);
    EXPECT_NE(it, table.columns.end()) << "no column " << name;
    return static_cast<size_t>(it - table.columns.begin());
  }
};

void expect_plates_balance(const std::string& element) {
  SCOPED_TRACE(element);
  const HistoryTable h = run_case("sphere-between-plates", element);
  ASSERT_GE(h.rows.size(), 5u);
  const Columns col{h};
  const size_t punch = col("force_y:punch"), floor = col("force_y:floor"),
               punch_pen = col("penetration:punch"), floor_pen = col("penetration:floor"),
               nodes = col("contact_nodes:punch"), pole = col("uy:pole");
  double worst = 0.0;
  for (const auto& row : h.rows) {
    // The pole, a corner node with Taylor-Hood, lies on the sticking floor at t = 0 and is glued
    // there (D17): it stays within the tolerance, also before the punch arrives (t < 0.3).
    EXPECT_LE(std::abs(row[pole]), kDieTolerance) << "t = " << row[1];
    // The body pushes the punch up (+y) and the floor down; the pressure has no y resultant.
    EXPECT_GE(row[punch], 0.0);
    const double scale = std::max(std::abs(row[punch]), 1e-6);
    worst = std::max(worst, std::abs(row[punch] + row[floor]) / scale);
    EXPECT_NEAR(row[punch] + row[floor], 0.0, 1e-9 * scale) << "t = " << row[1];
    // Both plates are their own mirror images in x = 0 and z = 0: the whole sphere pushes each
    // with 4 times the quarter's force, and the whole body balances too.
    EXPECT_EQ(row[col("full_force_y:punch")], 4.0 * row[punch]) << "t = " << row[1];
    EXPECT_EQ(row[col("full_force_y:floor")], 4.0 * row[floor]) << "t = " << row[1];
    EXPECT_EQ(row[col("full_force_x:punch")], 0.0);
    EXPECT_EQ(row[col("full_force_z:floor")], 0.0);
    EXPECT_LE(row[punch_pen], kDieTolerance) << "t = " << row[1];
    EXPECT_LE(row[floor_pen], kDieTolerance) << "t = " << row[1];
  }
  ::testing::Test::RecordProperty("worst_relative_imbalance", scientific(worst));
  EXPECT_GE(h.rows.back()[nodes], 4.0);  // the punch really presses at the end
  EXPECT_GT(h.rows.back()[punch], 1e-3);
}

TEST(DieEquilibrium, SpherePressedBetweenTwoPlatesLoadsBothEqually) {
  expect_plates_balance("mini");
}
TEST(DieEquilibrium, TaylorHoodSpherePressedBetweenTwoPlatesLoadsBothEqually) {
  expect_plates_balance("taylor-hood");
}

/// The pressure resultant per unit pressure along -y of the surface `inner` in the reference
/// configuration: -Σ (c_T)_y / 2 over linear faces (loads.md, L2), -Σ_a (g_a)_y over 6-node faces
/// (L8); invariant under the deformation because the boundary of `inner` stays in the plane y = 0.
double lift_area(const Mesh& mesh) {
  double area = 0.0;
  for (const SurfaceFace& f : outward_faces(mesh, "inner")) {
    if (f.n_nodes == 3) {
      const Vec3d& x0 = mesh.nodes[f.nodes[0]];
      area -= 0.5 * (mesh.nodes[f.nodes[1]] - x0).cross(mesh.nodes[f.nodes[2]] - x0).y();
      continue;
    }
    std::array<Vec3d, 6> xs;
    for (int a = 0; a < 6; ++a) xs[a] = mesh.nodes[f.nodes[a]];
    std::vector<double> residual(18, 0.0);
    std::array<int, 18> dofs;
    for (int i = 0; i < 18; ++i) dofs[i] = i;
    for (const Vec3d& g : add_follower_pressure_residual(1.0, xs, dofs, residual)) area -= g.y();
  }
  return area;
}

void expect_dome_balance(const std::string& element, double area_tolerance) {
  SCOPED_TRACE(element);
  const std::string name = "dome-on-fixed-equator";
  const HistoryTable h = run_case(name, element);
  ASSERT_GE(h.rows.size(), 5u);
  const Case c = parse_case_file(kCaseDir + name + ".yaml", {"element=" + element});
  const Mesh mesh = load_case_mesh(c);
  const double area = lift_area(mesh);
  // The quarter disc of radius 9 mm: inscribed polygon (linear) or quadratic arcs on the circle.
  EXPECT_NEAR(area, M_PI * 81.0 / 4.0, area_tolerance * M_PI * 81.0 / 4.0);
  const Columns col{h};
  const size_t punch = col("force_y:punch"), clamp = col("force_y:equator"),
               pressure = col("pressure:gas"), pen = col("penetration:punch"),
               nodes = col("contact_nodes:punch");
  double worst = 0.0;
  for (const auto& row : h.rows) {
    const double lift = row[pressure] * area;
    const double scale = std::max({std::abs(row[punch]), std::abs(row[clamp]), lift});
    const double imbalance = row[clamp] - row[punch] + lift;
    worst = std::max(worst, std::abs(imbalance) / scale);
    EXPECT_NEAR(imbalance, 0.0, 1e-9 * scale) << "t = " << row[1];
    EXPECT_LE(row[pen], kDieTolerance) << "t = " << row[1];
  }
  ::testing::Test::RecordProperty("worst_relative_imbalance", scientific(worst));
  EXPECT_GE(h.rows.back()[nodes], 4.0);
  EXPECT_GT(h.rows.back()[punch], 0.5 * h.rows.back()[pressure] * area);
}

TEST(DieEquilibrium, DomeOnClampedEquatorBalancesDieForceAgainstPressureResultant) {
  expect_dome_balance("mini", 0.01);
}
// Quadratic arcs through the circle's points: the area error of the quarter disc falls from
// O(h^2) to O(h^4), within 1e-4 here.
TEST(DieEquilibrium, TaylorHoodDomeOnClampedEquatorBalancesDieForceAgainstPressureResultant) {
  expect_dome_balance("taylor-hood", 1e-4);
}

}  // namespace
}  // namespace plisse
