// A driver airbag at full size (examples/airbag-full-size.yaml; study in
// docs/studies/airbag-full-size.md): two flat round panels of radius r = 350 mm, 0.35 mm thick,
// joined at their rims, inflated from flat by prescribing the gas's volume (54.4 L, 4 % above the
// inextensible limit) to a working pressure, then held while the damping's forces relax. A
// quarter of one panel, the shell triangle, on the example's mesh (12 mm, 4 mm within 40 mm of
// the seam) and a finer one (8.5 mm, 2.8 mm), at once. Asserted:
//  - the shape against Paulsen's Mylar balloon (Paulsen 1994, Amer. Math. Monthly 101(10)), the
//    inextensible limit of a bag of two discs: the seam's mean radius and the crown's height over
//    the seam lie above Paulsen's a = r / I0 and h = (pi / 4) a / I0, I0 = Gamma(1/4)^2 /
//    (4 sqrt(2 pi)), by no more than the fabric's stretch and the extra volume explain (3 % and
//    6 %);
//  - the working pressure at that volume between 20 and 50 kPa (a driver airbag's);
//  - the two meshes: the seam's radius and the crown within 1 %, the pressure within 5 %, the
//    seam's folds' count over the full circle within 25 %, and their total depth (the sum of
//    their rises over the full circle: the length the folds store radially) within 25 %, the
//    spread of the finer mesh's total over three seeds (20 %; the study), and the seam's reach
//    (its largest less its least distance from the axis: how far in the deepest fold pulls it)
//    within 15 %, the spread of the example mesh's reach over three seeds (14.5 %; the study).
// How that total is shared among the folds (the deepest, and the large folds' count and mean
// depth: those rising at least a fifth of the deepest, as scripts/airbag-full-size counts them)
// is printed, not asserted: it follows the path through the folding's snaps, which the seed of
// the imperfection and round-off decide (docs/studies/airbag-full-size.md, "The seam's folds").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <future>
#include <iostream>
#include <numbers>
#include <string>
#include <vector>

#include "output/history_writer.hpp"
#include "output/json_file.hpp"
#include "output/pvd_writer.hpp"
#include "output/vtu_reader.hpp"
#include "support/run_case.hpp"
#include "support/run_plisse.hpp"
#include "support/validation_claim.hpp"

namespace plisse {
namespace {

constexpr double kRadius = 350.0, kThickness = 0.35;

/// Paulsen's I0 = int_0^1 du / sqrt(1 - u^4) = Gamma(1/4)^2 / (4 sqrt(2 pi)).
double paulsen_i0() {
  return std::tgamma(0.25) * std::tgamma(0.25) / (4.0 * std::sqrt(2.0 * std::numbers::pi));
}

struct BagMesh {
  double size = 0.0, rim_size = 0.0;  ///< [mm]
};

struct Bag {
  bool ran = false;
  double pressure = 0.0;     ///< at the end [MPa]
  double crown = 0.0;        ///< the crown's height over the seam's plane at the end [mm]
  double seam = 0.0;         ///< the seam's mean distance from the axis at the end [mm]
  int folds = 0;             ///< over the full circle
  double depth = 0.0;        ///< the largest rise of a fold over its neighbouring minima [mm]
  int large_folds = 0;       ///< over the full circle: those rising at least kLargeFold * depth
  double large_depth = 0.0;  ///< the large folds' mean rise [mm]
  double total_depth = 0.0;  ///< the folds' rises summed over the full circle [mm]
  double reach = 0.0;        ///< the seam's largest less its least distance from the axis [mm]
  double dissipated = 0.0, strain_energy = 0.0;  ///< [mJ]
  long dofs = 0;
};

/// A large fold rises at least this share of the deepest one (scripts/airbag_full_size.py's
/// LARGE_FOLD).
constexpr double kLargeFold = 0.2;

/// The rises of the seam's folds: maxima of r (by angle) rising at least `prominence` above the
/// lowest point between them and the next higher point (or the end) on both sides.
std::vector<double> fold_rises(const std::vector<double>& r, double prominence) {
  std::vector<double> rises;
  const std::size_t n = r.size();
  for (std::size_t i = 1; i + 1 < n; ++i) {
    if (!(r[i] > r[i - 1] && r[i] >= r[i + 1])) continue;
    double low_left = r[i], low_right = r[i];
    for (std::size_t k = i; k > 0 && r[k - 1] <= r[i]; --k) low_left = std::min(low_left, r[k - 1]);
    for (std::size_t k = i; k + 1 < n && r[k + 1] <= r[i]; ++k)
      low_right = std::min(low_right, r[k + 1]);
    const double rise = r[i] - std::max(low_left, low_right);
    if (rise >= prominence) rises.push_back(rise);
  }
  return rises;
}

/// The bag at the end of the finished run in `dir`.
Bag measure(const std::filesystem::path& dir, const BagMesh& m) {
  Bag result;
  result.dofs = read_json_file(dir / "summary.json").value("free_dofs", 0L);
  const HistoryTable h = read_history(dir / "history.csv");
  const auto& last = h.rows.back();
  EXPECT_NEAR(last[test::history_column(h, "time")], 1.1, 1e-9) << "the run did not finish";
  result.pressure = last[test::history_column(h, "pressure:gas")];
  result.crown = last[test::history_column(h, "uy:crown")];
  result.dissipated = last[test::history_column(h, "dissipated_energy")];
  result.strain_energy = last[test::history_column(h, "strain_energy")];

  // The seam from the last step file: its points (the reference positions) and displacements,
  // the rim's nodes by angle. (The mesh generated again would do only while its node order is
  // the run's.)
  const std::filesystem::path step = dir / read_pvd(dir / "solution.pvd").back().file;
  const VtuField X0 = read_vtu_points(step);
  const VtuField u = read_vtu_point_field(step, "displacement");
  EXPECT_EQ(u.values.size(), X0.values.size());
  if (u.values.size() != X0.values.size()) return result;
  std::vector<std::pair<double, double>> rim;  // (angle, distance from the axis)
  for (std::size_t n = 0; 3 * n < X0.values.size(); ++n) {
    const Vec3d X(X0.values[3 * n], X0.values[3 * n + 1], X0.values[3 * n + 2]);
    if (std::abs(std::hypot(X.x(), X.z()) - kRadius) > 1e-6 * kRadius) continue;
    const Vec3d x = X + Vec3d(u.values[3 * n], u.values[3 * n + 1], u.values[3 * n + 2]);
    rim.emplace_back(std::atan2(X.z(), X.x()), std::hypot(x.x(), x.z()));
  }
  std::sort(rim.begin(), rim.end());
  std::vector<double> r;
  for (const auto& [angle, distance] : rim) {
    r.push_back(distance);
    result.seam += distance / static_cast<double>(rim.size());
  }
  const std::vector<double> rises = fold_rises(r, kThickness);
  result.folds = 4 * static_cast<int>(rises.size());
  for (const double rise : rises) result.total_depth += 4.0 * rise;
  result.depth = rises.empty() ? 0.0 : *std::max_element(rises.begin(), rises.end());
  int large = 0;
  for (const double rise : rises) {
    if (rise < kLargeFold * result.depth) continue;
    ++large;
    result.large_depth += rise;
  }
  result.large_folds = 4 * large;
  if (large > 0) result.large_depth /= large;
  if (!r.empty())
    result.reach = *std::max_element(r.begin(), r.end()) - *std::min_element(r.begin(), r.end());
  std::cout << "h = " << m.size << " (" << m.rim_size << " at the seam): " << result.dofs
            << " unknowns, pressure " << 1e3 * result.pressure << " kPa, crown " << result.crown
            << " mm, seam " << result.seam << " mm, " << result.folds << " folds, deepest "
            << result.depth << " mm, " << result.large_folds << " large of mean depth "
            << result.large_depth << " mm, total depth " << result.total_depth << " mm, reach "
            << result.reach << " mm, dissipated " << result.dissipated << " of strain energy "
            << result.strain_energy << " mJ\n";
  result.ran = true;
  return result;
}

Bag inflate(const BagMesh& m) {
  const auto dir = test::scratch_directory("airbag-full-size-h" + test::six_digits(m.size));
  const int status = test::run_plisse(
      "run " + std::string(PLISSE_SOURCE_DIR) + "/examples/airbag-full-size.yaml -o " +
          dir.string() + " --set mesh.element_size=" + test::six_digits(m.size) +
          " --set mesh.rim_element_size=" + test::six_digits(m.rim_size),
      dir.string() + ".log");
  EXPECT_EQ(status, 0) << "see " << dir.string() << ".log";
  if (status != 0) return Bag{};
  return measure(dir, m);
}

constexpr const char* kSubject =
    "driver airbag at full size inflated from flat, shell, two discs r = 350 mm, t = 0.35 mm, "
    "E t = 300 N/mm, 54.4 L";

std::string mesh_text(const BagMesh& m) {
  return "h = " + test::six_digits(m.rim_size) + " mm within 40 mm of the seam, " +
         test::six_digits(m.size) + " mm elsewhere, shell triangles";
}

void expect_rows(const BagMesh& m, const Bag& b, const std::string& id) {
  const double a = kRadius / paulsen_i0();
  const double h = std::numbers::pi / 4.0 * a / paulsen_i0();
  test::expect_claim({.row = "airbag-full-size/" + id + "/seam-radius",
                      .subject = kSubject,
                      .quantity = "the seam's mean distance from the axis [mm]",
                      .mesh = mesh_text(m),
                      .measured = b.seam,
                      .reference = a,
                      .source = "Paulsen 1994, the Mylar balloon's rim (inextensible)",
                      .low = 0.0,
                      .high = 0.03,
                      .why = "above by the fabric's stretch (p a / (2 E t) = 1.3 % at the seam) "
                             "and the 4 % more volume"});
  test::expect_claim({.row = "airbag-full-size/" + id + "/crown",
                      .subject = kSubject,
                      .quantity = "the crown's height over the seam [mm]",
                      .mesh = mesh_text(m),
                      .measured = b.crown,
                      .reference = h,
                      .source = "Paulsen 1994, the Mylar balloon's half height (inextensible)",
                      .low = 0.0,
                      .high = 0.06,
                      .why = "above by the stretch, which grows towards the crown, and the 4 % "
                             "more volume"});
  EXPECT_GT(b.pressure, 0.020) << "a driver airbag's working pressure, on " << mesh_text(m);
  EXPECT_LT(b.pressure, 0.050) << "a driver airbag's working pressure, on " << mesh_text(m);
  EXPECT_GT(b.folds, 0) << "the seam takes up a quarter of its length in folds";
}

// The full tier only: two runs at once (PROCESSORS 2).
TEST(AirbagFullSizeSlow, InflatesFromFlatToPaulsensShapeAndFoldsItsSeam) {
  const BagMesh coarse{.size = 12.0, .rim_size = 4.0};
  const BagMesh fine{.size = 8.5, .rim_size = 2.8};
  auto fine_run = std::async(std::launch::async, inflate, fine);
  const Bag a = inflate(coarse);
  const Bag b = fine_run.get();
  ASSERT_TRUE(a.ran && b.ran);
  expect_rows(coarse, a, "h4");
  expect_rows(fine, b, "h2.8");
  EXPECT_NEAR(b.seam / a.seam, 1.0, 0.01) << "the seam's radius on the two meshes";
  EXPECT_NEAR(b.crown / a.crown, 1.0, 0.01) << "the crown on the two meshes";
  EXPECT_NEAR(b.pressure / a.pressure, 1.0, 0.05) << "the pressure on the two meshes";
  EXPECT_NEAR(static_cast<double>(b.folds) / a.folds, 1.0, 0.25) << "the folds' count";
  EXPECT_NEAR(b.total_depth / a.total_depth, 1.0, 0.25) << "the folds' total depth";
  EXPECT_NEAR(b.reach / a.reach, 1.0, 0.15) << "the seam's reach";
}

}  // namespace
}  // namespace plisse
