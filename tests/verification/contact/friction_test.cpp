// Coulomb friction on rigid dies through `plisse run` (docs/theory/contact.md, section 5):
// - a block dragged by a plane under it (examples/block-on-sliding-plane.yaml): the middle of its
//   bottom moves with the plane while the force ratio is below mu, and once the block slides every
//   node of the bottom slides and |force_x| / force_z = mu (Coulomb's law);
// - a block held on a plane by friction under a shear load mu / 10 of its contact pressure: every
//   node sticks at every step, the bottom does not move beyond the tolerance, and the plane's force
//   balances the load;
// - a pressurised sphere pressed by a plate: friction 0 is the frictionless plate, and the plate's
//   force grows with the coefficient (friction holds the contact zone from spreading).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "output/history_writer.hpp"
#include "support/run_case.hpp"

namespace plisse {
namespace {

const std::string kCaseDir = std::string(PLISSE_SOURCE_DIR) + "/tests/verification/contact/";
constexpr double kFriction = 0.3;    ///< `friction` of the dies in the cases
constexpr double kTolerance = 1e-4;  ///< `tolerance` of the blocks' plane [mm]

/// Runs `case_file` with `options` into a scratch directory named `name`; its history.
HistoryTable run(const std::string& name, const std::string& case_file,
                 const std::string& options = "") {
  const auto dir = test::scratch_directory("friction-" + name);
  const int status = test::run_plisse("run " + case_file + " -o " + dir.string() + " " + options,
                                      dir.string() + ".log");
  EXPECT_EQ(status, 0) << "see " << dir.string() << ".log";
  if (status != 0) return {};
  return read_history(dir / "history.csv");
}

TEST(CoulombFriction, BlockDraggedByAPlaneMovesWithItThenSlidesWithTheRatioMu) {
  const HistoryTable h = run("drag", test::example("block-on-sliding-plane.yaml"));
  ASSERT_EQ(h.rows.size(), 20u);
  const auto col = [&](const std::string& c) { return test::history_column(h, c); };
  const size_t time = col("time"), fx = col("force_x:plane"), fz = col("force_z:plane"),
               stick = col("stick_nodes:plane"), slip = col("slip_nodes:plane"),
               nodes = col("contact_nodes:plane"), middle = col("ux:middle"),
               penetration = col("penetration:plane");
  double previous_middle = 0.0;
  for (const auto& row : h.rows) {
    const double t = row[time];
    const double ratio =
        -row[fx] / -row[fz];  // the body pulls the plane back (-x), presses it (-z)
    EXPECT_LE(row[penetration], kTolerance) << "t = " << t;
    EXPECT_EQ(row[stick] + row[slip], row[nodes]) << "t = " << t;
    EXPECT_LE(std::abs(ratio), kFriction * (1.0 + 1e-9)) << "t = " << t;
    if (t < 0.31) continue;
    // The plane's displacement, 0.6 mm over [0.3, 1].
    const double plane = 0.6 * (t - 0.3) / 0.7;
    if (ratio < 0.2) {
      // Well below the cone, the middle of the bottom sticks to the plane.
      EXPECT_NEAR(row[middle], plane, kTolerance) << "t = " << t;
      EXPECT_GT(row[stick], 0.0) << "t = " << t;
    }
    if (t > 0.79) {
      // Sliding: every node on its cone, all dragged along x, so the resultant's ratio is mu to
      // within the misalignment of the nodes' tractions, which the lateral spreading of the
      // pressed block turned outwards and each sliding step turns back along x (measured:
      // 9e-6 relative at t = 0.8, 1.4e-7 at t = 1).
      EXPECT_EQ(row[stick], 0.0) << "t = " << t;
      EXPECT_NEAR(ratio, kFriction, 1e-4 * kFriction) << "t = " << t;
      // The plane slides under the block, which stands: its middle moves by less than 1/40 of
      // the plane's 0.043 mm per step (measured: 1e-5 mm).
      EXPECT_LT(std::abs(row[middle] - previous_middle), 1e-3) << "t = " << t;
    }
    previous_middle = row[middle];
  }
  EXPECT_NEAR(-h.rows.back()[fx] / -h.rows.back()[fz], kFriction, 1e-6 * kFriction);
}

TEST(CoulombFriction, BlockUnderAShearBelowTheConeDoesNotSlide) {
  const HistoryTable h = run("held", kCaseDir + "block-held-by-friction.yaml");
  ASSERT_FALSE(h.rows.empty());
  const auto col = [&](const std::string& c) { return test::history_column(h, c); };
  const size_t time = col("time"), fx = col("force_x:plane"), fz = col("force_z:plane"),
               stick = col("stick_nodes:plane"), slip = col("slip_nodes:plane"),
               bottom = col("ux:bottom"), top = col("ux:top");
  EXPECT_DOUBLE_EQ(h.rows.back()[time], 1.0);
  for (const auto& row : h.rows) {
    const double t = row[time];
    // All 55 nodes of the bottom stick, and the bottom corner stays where it was.
    EXPECT_EQ(row[stick], 55.0) << "t = " << t;
    EXPECT_EQ(row[slip], 0.0) << "t = " << t;
    EXPECT_LE(std::abs(row[bottom]), kTolerance) << "t = " << t;
    // Equilibrium: the plane carries the shear 0.003 * 40 N and the pressure 0.1 * 40 N, both
    // ramped; the follower pressures on the sheared, slightly tilted faces shift the ratio by
    // 2e-4 relative (measured), hence 1e-3.
    EXPECT_NEAR(row[fx] / row[fz], -0.003 / 0.1, 1e-3 * 0.03) << "t = " << t;
    EXPECT_NEAR(row[fz], -4.0 * t, 1e-3 * 4.0 * t) << "t = " << t;
  }
  // The top shears by about tau h / mu = 0.006 mm, some 60 times the bottom's allowed slip.
  EXPECT_GT(h.rows.back()[top], 0.005);
}

TEST(CoulombFriction, PlateForceOnAPressurisedSphereGrowsWithTheCoefficient) {
  const std::string sphere = kCaseDir + "sphere-between-plates.yaml";
  const HistoryTable frictionless = run("sphere-frictionless", sphere);
  const std::vector<double> coefficients = {0.0, 0.3, 10.0};
  std::vector<HistoryTable> coulomb;
  for (double mu : coefficients)
    coulomb.push_back(
        run("sphere-mu" + std::to_string(mu), sphere,
            "--set dies[0].contact=coulomb --set dies[0].friction=" + std::to_string(mu)));
  ASSERT_FALSE(frictionless.rows.empty());
  const size_t force = test::history_column(frictionless, "force_y:punch");
  for (const HistoryTable& h : coulomb) ASSERT_EQ(h.rows.size(), frictionless.rows.size());
  for (size_t r = 0; r < frictionless.rows.size(); ++r) {
    const double f0 = frictionless.rows[r][force];
    // Friction 0 takes the frictionless path: the same residual and tangent (to round-off).
    EXPECT_NEAR(coulomb[0].rows[r][force], f0, 1e-10 * std::max(f0, 1e-6)) << "row " << r;
    // More friction, more force at the same indentation, once the contact zone spreads; before,
    // the same force to what the Newton tolerance leaves (rtol 1e-10, each run on its own path).
    for (size_t k = 1; k < coefficients.size(); ++k) {
      EXPECT_GE(coulomb[k].rows[r][force], coulomb[k - 1].rows[r][force] * (1.0 - 1e-9))
          << "row " << r << ", friction " << coefficients[k];
    }
  }
  // At the end the differences are well above the solver's tolerance: 1 % for 0.3, 3 % for 10.
  const double f0 = frictionless.rows.back()[force];
  EXPECT_GT(coulomb[1].rows.back()[force], 1.005 * f0);
  EXPECT_GT(coulomb[2].rows.back()[force], 1.02 * f0);
  // With friction 10 nothing slides on the plate.
  EXPECT_EQ(coulomb[2].rows.back()[test::history_column(coulomb[2], "slip_nodes:punch")], 0.0);
}

}  // namespace
}  // namespace plisse
