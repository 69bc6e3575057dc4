// Wrinkles without a bifurcation, measured along a line (examples/sheet-wrinkles-line.yaml): the
// stretched shell sheet of Cerda & Mahadevan (2003, Phys. Rev. Lett. 90, 074302), W/t = 1000,
// quarter model on 0.5 mm triangles, pulled to 12 % from a random imperfection of 0.01 t. The
// path never bifurcates, so the stability check finds every step stable, and the wrinkles grow to
// several thicknesses all the same. Checked:
//  - every step is stable, and the log and summary.json say that the body has wrinkled while it
//    was (docs/theory/wrinkles.md, W27);
//  - it wrinkles where the perfect sheet bifurcates: the first step past the threshold 0.1 t lies
//    within 0.5 % strain (two steps) of the step at which the stability check finds the perfect
//    sheet's bifurcation, a second run of the same case without the imperfection; an imperfection
//    of 0.01 t grows to 0.1 t within a few steps past a supercritical bifurcation;
//  - the line's measure against the sheet's own nodes on the middle line (nodal_crests, which
//    neither interpolates nor smooths): at every wrinkled written step (38; 5 crests, then 7 from
//    about 10 %) the same count of crests, the line's crest height between the nodes' largest
//    crest-over-troughs height and their peak to peak, within 2 %, and its wavelength within 1 %
//    of twice the mean spacing of the nodes' zeros between crests in the deformed sheet.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "app/wrinkling.hpp"
#include "case/case.hpp"
#include "output/history_writer.hpp"
#include "output/pvd_writer.hpp"
#include "output/run_directory.hpp"
#include "output/vtu_reader.hpp"
#include "support/run_plisse.hpp"

namespace plisse {
namespace {

constexpr double kThickness = 0.02, kHalfLength = 25.0, kGrip = 3.0;  // mm
constexpr double kFinalStrain = kGrip / kHalfLength;                  // 12 % at t = 1

double column(const HistoryTable& h, const std::vector<double>& row, const std::string& name) {
  for (std::size_t k = 0; k < h.columns.size(); ++k)
    if (h.columns[k] == name) return row[k];
  ADD_FAILURE() << "no column " << name;
  return 0.0;
}

/// The crests of the middle line's nodes x = L/2, found without the line's gauge or smoothing:
/// their profile w(y) = the deformed z (the imperfection's offset included, as the line measures
/// the body's shape), mirrored about y = 0 as the line's `mirror: from` does; its alternating
/// extrema of at least 10 % of the largest |w - mean| (W24's rule, on the nodes); the largest
/// height of a crest over the mean of the troughs beside it (W25), and the peak to peak.
struct NodalCrests {
  int crests = 0;
  double height = 0.0, peak_to_peak = 0.0;
  double wavelength = 0.0;  ///< twice the mean spacing of the zeros between crests, deformed y
};

NodalCrests nodal_crests(const std::vector<Vec3d>& reference,
                         const std::vector<Vec3d>& displacement) {
  std::vector<std::array<double, 3>> line;  // reference y, deformed y, deformed z
  for (std::size_t i = 0; i < reference.size(); ++i)
    if (std::abs(reference[i].x() - kHalfLength) < 1e-6 * kHalfLength)
      line.push_back({reference[i].y(), reference[i].y() + displacement[i].y(),
                      reference[i].z() + displacement[i].z()});
  std::sort(line.begin(), line.end());
  std::vector<double> y, w;
  for (auto it = line.rbegin(); it != line.rend(); ++it)
    if ((*it)[0] > 1e-9) y.push_back(-(*it)[1]), w.push_back((*it)[2]);
  for (const auto& point : line) y.push_back(point[1]), w.push_back(point[2]);
  double mean = 0.0;
  for (double wi : w) mean += wi / static_cast<double>(w.size());
  double largest = 0.0, low = w.front(), high = w.front();
  for (double& wi : w) {
    wi -= mean;
    largest = std::max(largest, std::abs(wi));
    low = std::min(low, wi);
    high = std::max(high, wi);
  }
  std::vector<double> crest;
  std::vector<std::size_t> at;
  for (std::size_t k = 1; k + 1 < w.size(); ++k) {
    const bool extremum = (w[k] > 0 && w[k] >= w[k - 1] && w[k] >= w[k + 1]) ||
                          (w[k] < 0 && w[k] <= w[k - 1] && w[k] <= w[k + 1]);
    if (!extremum || std::abs(w[k]) < 0.1 * largest) continue;
    if (!crest.empty() && (crest.back() > 0) == (w[k] > 0)) {
      if (std::abs(w[k]) > std::abs(crest.back())) crest.back() = w[k], at.back() = k;
      continue;
    }
    crest.push_back(w[k]);
    at.push_back(k);
  }
  NodalCrests n;
  std::vector<double> zeros;
  for (std::size_t c = 0; c + 1 < at.size(); ++c)
    for (std::size_t k = at[c]; k < at[c + 1]; ++k)
      if ((w[k] > 0) != (w[k + 1] > 0)) {
        zeros.push_back(y[k] + w[k] * (y[k + 1] - y[k]) / (w[k] - w[k + 1]));
        break;
      }
  if (zeros.size() >= 2)
    n.wavelength = 2.0 * (zeros.back() - zeros.front()) / static_cast<double>(zeros.size() - 1);
  n.crests = static_cast<int>(crest.size());
  n.peak_to_peak = high - low;
  for (std::size_t k = 0; k < crest.size() && crest.size() >= 2; ++k) {
    const double beside = k == 0                  ? crest[1]
                          : k + 1 == crest.size() ? crest[k - 1]
                                                  : 0.5 * (crest[k - 1] + crest[k + 1]);
    n.height = std::max(n.height, std::abs(crest[k] - beside));
  }
  return n;
}

TEST(SheetLine, AnImperfectSheetWrinklesWhileEveryStepIsStableAndTheLineSeesIt) {
  const auto dir = test::scratch_directory("sheet-line");
  const auto perfect = test::scratch_directory("sheet-line-perfect");
  const std::string example = test::example("sheet-wrinkles-line.yaml");
  ASSERT_EQ(test::run_plisse("run " + example + " -o " + dir.string() + " --set output.every=1",
                             dir.string() + ".log"),
            0)
      << "see " << dir.string() << ".log";
  // The perfect sheet to 6 %: where its stability check finds the bifurcation.
  ASSERT_EQ(test::run_plisse("run " + example + " -o " + perfect.string() +
                                 " --set solver.stability.imperfection=0 --set solver.end_time=0.5"
                                 " --set boundary[0].ramp=[0,1]",
                             perfect.string() + ".log"),
            0)
      << "see " << perfect.string() << ".log";

  // 1. Every step stable; the first wrinkled step said so.
  const HistoryTable history = read_history(dir / "history.csv");
  ASSERT_GE(history.rows.size(), 50u);
  for (const auto& row : history.rows) EXPECT_EQ(column(history, row, "stable"), 1.0);
  std::ifstream summary_file(dir / "summary.json");
  const nlohmann::json summary = nlohmann::json::parse(summary_file);
  const nlohmann::json& first = summary["first_wrinkled"];
  ASSERT_TRUE(first.is_object()) << summary["wrinkles"].dump();
  EXPECT_EQ(first["by"], "line across");
  EXPECT_EQ(first["stable"], true);
  std::ifstream log(dir / "log.txt");
  const std::string text((std::istreambuf_iterator<char>(log)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("step " + std::to_string(first["step"].get<int>()) + " (t = "),
            std::string::npos);
  EXPECT_NE(text.find("the body has wrinkled: line across has"), std::string::npos);
  EXPECT_NE(text.find("while the stability check has found every step stable"), std::string::npos);

  // 2. Where the perfect sheet bifurcates.
  double onset = 0.0;
  std::ifstream perfect_log(perfect / "log.txt");
  for (std::string line; std::getline(perfect_log, line);) {
    const auto at = line.find("new instability"), t = line.find(": t = ");
    if (at != std::string::npos && t != std::string::npos && onset == 0.0)
      onset = kFinalStrain * std::stod(line.substr(t + 6));
  }
  const double wrinkled_at = kFinalStrain * first["time"].get<double>();
  std::cout << "the perfect sheet bifurcates at the step of strain " << onset
            << "; the imperfect one has wrinkled at " << wrinkled_at << "\n";
  ASSERT_GT(onset, 0.0) << "the perfect sheet's stability check found no bifurcation";
  EXPECT_NEAR(wrinkled_at, onset, 0.005);

  // 3. The line against the nodes, at every written step: the run's mesh is the generated sheet
  // with the case's imperfection (the same seed).
  const Mesh mesh = app::load_perturbed_mesh(parse_case_file(example));
  int compared = 0;
  for (const PvdEntry& entry : read_pvd(dir / "solution.pvd")) {
    if (entry.file == RunDirectory::step_file_name(0)) continue;
    const VtuField u = read_vtu_point_field(dir / entry.file, "displacement");
    ASSERT_EQ(u.values.size(), 3u * mesh.n_nodes());
    std::vector<Vec3d> displacement(mesh.n_nodes());
    for (int i = 0; i < mesh.n_nodes(); ++i)
      displacement[i] = Vec3d(u.values[3 * i], u.values[3 * i + 1], u.values[3 * i + 2]);
    const NodalCrests nodes = nodal_crests(mesh.nodes, displacement);
    const std::vector<double>* row = nullptr;
    for (const auto& r : history.rows)
      if (std::abs(r[1] - entry.time) <= 1e-12 * std::max(1.0, entry.time)) row = &r;
    ASSERT_NE(row, nullptr) << entry.file;
    const double crests = column(history, *row, "wrinkle_crests:across");
    const double amplitude = column(history, *row, "wrinkle_amplitude:across");
    const double wavelength = column(history, *row, "wrinkle_wavelength:across");
    if (crests == 0.0) continue;  // below the threshold
    ++compared;
    EXPECT_EQ(crests, nodes.crests) << entry.file;
    EXPECT_GE(amplitude, 0.98 * nodes.height) << entry.file;
    EXPECT_LE(amplitude, 1.02 * nodes.peak_to_peak) << entry.file;
    EXPECT_NEAR(wavelength, nodes.wavelength, 0.01 * nodes.wavelength) << entry.file;
  }
  std::cout << compared << " wrinkled steps compared with the nodes\n";
  EXPECT_GE(compared, 30);
  const std::vector<double>& last = history.rows.back();
  std::cout << "at 12 %: " << column(history, last, "wrinkle_crests:across") << " crests, "
            << column(history, last, "wrinkle_amplitude:across") / kThickness << " t high, "
            << "wavelength " << column(history, last, "wrinkle_wavelength:across") << " mm\n";
}

}  // namespace
}  // namespace plisse
