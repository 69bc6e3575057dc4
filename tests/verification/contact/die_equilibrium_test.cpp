// Global equilibrium with rigid dies (docs/theory/contact.md, D15): a pressurised thin sphere
// pressed between two plates (the die forces balance each other) and a pressurised dome on a
// clamped equator pressed by a plate (die force, clamp reaction and pressure resultant balance),
// both run through `plisse run`. At every converged step no node may penetrate a die by more than
// its tolerance (D10).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "io/case.hpp"
#include "io/history_writer.hpp"
#include "physics/surface.hpp"
#include "support/run_plisse.hpp"

namespace plisse {
namespace {

const std::string kCaseDir = std::string(PLISSE_SOURCE_DIR) + "/tests/verification/contact/";
constexpr double kDieTolerance = 1e-3;  ///< `tolerance` of the dies in both case files [mm]

/// Runs a case of this folder and returns its history.
HistoryTable run_case(const std::string& name) {
  const auto dir = test::scratch_directory("contact-" + name);
  const int status = test::run_plisse("run " + kCaseDir + name + ".yaml -o " + dir.string(),
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

TEST(DieEquilibrium, SpherePressedBetweenTwoPlatesLoadsBothEqually) {
  const HistoryTable h = run_case("sphere-between-plates");
  ASSERT_GE(h.rows.size(), 5u);
  const Columns col{h};
  const size_t punch = col("force_y:punch"), floor = col("force_y:floor"),
               punch_pen = col("penetration:punch"), floor_pen = col("penetration:floor"),
               nodes = col("contact_nodes:punch");
  double worst = 0.0;
  for (const auto& row : h.rows) {
    // The body pushes the punch up (+y) and the floor down; the pressure has no y resultant.
    EXPECT_GE(row[punch], 0.0);
    const double scale = std::max(std::abs(row[punch]), 1e-6);
    worst = std::max(worst, std::abs(row[punch] + row[floor]) / scale);
    EXPECT_NEAR(row[punch] + row[floor], 0.0, 1e-9 * scale) << "t = " << row[1];
    EXPECT_LE(row[punch_pen], kDieTolerance) << "t = " << row[1];
    EXPECT_LE(row[floor_pen], kDieTolerance) << "t = " << row[1];
  }
  RecordProperty("worst_relative_imbalance", scientific(worst));
  EXPECT_GE(h.rows.back()[nodes], 4.0);  // the punch really presses at the end
  EXPECT_GT(h.rows.back()[punch], 1e-3);
}

TEST(DieEquilibrium, DomeOnClampedEquatorBalancesDieForceAgainstPressureResultant) {
  const std::string name = "dome-on-fixed-equator";
  const HistoryTable h = run_case(name);
  ASSERT_GE(h.rows.size(), 5u);
  // Pressure resultant per unit pressure: -sum over `inner` of (c_T)_y / 2 (loads.md, L2), with
  // c_T the outward area vector; invariant under the deformation because the boundary of `inner`
  // projects onto a fixed polygon of the plane y = 0.
  const Case c = parse_case_file(kCaseDir + name + ".yaml");
  const Mesh mesh = load_case_mesh(c);
  double area = 0.0;
  for (const auto& t : outward_triangles(mesh, "inner")) {
    const Vec3d& x0 = mesh.nodes[t[0]];
    area -= 0.5 * (mesh.nodes[t[1]] - x0).cross(mesh.nodes[t[2]] - x0).y();
  }
  EXPECT_NEAR(area, M_PI * 81.0 / 4.0, 0.01 * M_PI * 81.0 / 4.0);  // inscribed quarter disc
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
  RecordProperty("worst_relative_imbalance", scientific(worst));
  EXPECT_GE(h.rows.back()[nodes], 4.0);
  EXPECT_GT(h.rows.back()[punch], 0.5 * h.rows.back()[pressure] * area);
}

}  // namespace
}  // namespace plisse
