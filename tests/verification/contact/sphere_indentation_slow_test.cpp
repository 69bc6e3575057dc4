// The paper's case 1 as shipped in examples/sphere-indentation.yaml, on the coarser preview mesh
// (element size 2 mm, 40 to 70 s a run): it runs to the end, the two plates carry equal and
// opposite forces at every step to the equilibrium error the Newton tolerance leaves (the pressure
// has no resultant along y in the quarter model), no
// node penetrates a plate by more than the default tolerance, and the top pole ends on the punch.
// The same with a Coulomb punch (friction 0.3, docs/theory/contact.md section 5): the same checks,
// and the punch needs more force than the frictionless one at the same indentation, since
// friction holds the flattened cap from spreading.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "output/history_writer.hpp"
#include "output/json_file.hpp"
#include "support/run_plisse.hpp"

namespace plisse {
namespace {

/// The example on the preview mesh with `options`, checked as the file's header says; its
/// history.
HistoryTable run_and_check(const std::string& name, const std::string& options) {
  const auto dir = test::scratch_directory("contact-sphere-indentation-" + name);
  const int status = test::run_plisse("run " + test::example("sphere-indentation.yaml") + " -o " +
                                          dir.string() + " --set mesh.element_size=2 " + options,
                                      dir.string() + ".log");
  EXPECT_EQ(status, 0) << "see " << dir.string() << ".log";
  if (status != 0) return {};
  const HistoryTable h = read_history(dir / "history.csv");
  const auto col = [&](const std::string& name) {
    const auto it = std::find(h.columns.begin(), h.columns.end(), name);
    EXPECT_NE(it, h.columns.end()) << "no column " << name;
    return static_cast<size_t>(it - h.columns.begin());
  };
  const size_t punch = col("force_y:punch"), floor = col("force_y:floor"),
               punch_pen = col("penetration:punch"), floor_pen = col("penetration:floor"),
               top = col("uy:top"), time = col("time"), residual = col("residual_norm");
  // The plates' forces balance up to the step's equilibrium error: their sum is minus the sum of
  // the free y-residuals, at most sqrt(n) ||R|| for n nodes (Cauchy-Schwarz), ||R|| the step's
  // final residual_norm [N]; plus round-off of the forces.
  const double sqrt_nodes =
      std::sqrt(read_json_file(dir / "summary.json").at("nodes").get<double>());
  const double tolerance = 1e-3;  // the dies' default `tolerance` [mm]
  EXPECT_GE(h.rows.size(), 50u);
  if (h.rows.empty()) return h;
  for (const auto& row : h.rows) {
    const double scale = std::max(std::abs(row[punch]), 1e-6);
    EXPECT_NEAR(row[punch] + row[floor], 0.0, 1e-8 * scale + sqrt_nodes * row[residual])
        << "t = " << row[time];
    EXPECT_LE(row[punch_pen], tolerance) << "t = " << row[time];
    EXPECT_LE(row[floor_pen], tolerance) << "t = " << row[time];
  }
  EXPECT_DOUBLE_EQ(h.rows.back()[time], 1.0);
  // The top pole (y = 25) is pressed by the punch, whose plane ends at y = 27 - 10 = 17.
  EXPECT_NEAR(h.rows.back()[top], -8.0, tolerance);
  EXPECT_GT(h.rows.back()[punch], 0.0);
  return h;
}

TEST(SphereIndentationExample,
     RunsToTheEndWithBalancedPlatesAndNoPenetrationWithAndWithoutFriction) {
  const HistoryTable frictionless = run_and_check("frictionless", "");
  const HistoryTable coulomb =
      run_and_check("coulomb", "--set dies[0].contact=coulomb --set dies[0].friction=0.3");
  ASSERT_FALSE(frictionless.rows.empty());
  ASSERT_FALSE(coulomb.rows.empty());
  const auto last = [](const HistoryTable& h, const std::string& name) {
    const auto it = std::find(h.columns.begin(), h.columns.end(), name);
    EXPECT_NE(it, h.columns.end()) << "no column " << name;
    return h.rows.back()[static_cast<size_t>(it - h.columns.begin())];
  };
  const double f0 = last(frictionless, "force_y:punch"), f = last(coulomb, "force_y:punch");
  RecordProperty("punch_force_ratio", std::to_string(f / f0));
  EXPECT_GT(f, f0 * (1.0 + 1e-3));
  EXPECT_GT(last(coulomb, "stick_nodes:punch") + last(coulomb, "slip_nodes:punch"), 0.0);
}

}  // namespace
}  // namespace plisse
