// A cavity that starts flat (docs/theory/cavities.md, C8): the fluid under a clamped square sheet,
// the bulge test. Its wall, the sheet's lower face, lies in the plane z = 0 that closes it, so
// V0 = 0 and the volume is prescribed as a change. Checked: the volume follows the prescription at
// every step; the first step from the flat state converges without cut-backs even when it is the
// whole run; and the sheet under the pressure the volume-controlled run ends at, applied as a
// follower pressure instead, reaches the same bulge (one equilibrium, two loadings).
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "output/history_writer.hpp"
#include "support/run_plisse.hpp"

namespace plisse {
namespace {

namespace fs = std::filesystem;

/// A quarter of a 40 x 40 x 0.5 mm sheet, clamped on its outer edges, neo-Hookean c1 = 0.1 MPa,
/// quadratic tetrahedra, one layer; `load` is its `cavities:` or `loads:` section.
/// Volume control goes with the default line search (bt); under pressure control the sheet bends
/// before it stretches, and bt shortens those Newton steps to a crawl (9 cut-backs from the
/// flat state), so that run uses the critical-point search (cp), as docs/case-file.md advises.
/// cp is no choice for volume control: the cavity makes the system a saddle point, not a
/// minimum, and cp's steps there invert elements.
std::string sheet_case(const std::string& load, int steps, const std::string& line_search) {
  return "mesh: {generate: sheet, length: 20.0, width: 20.0, thickness: 0.5, layers: 1,"
         " element_size: 2.0}\n"
         "material: {model: neo-hookean, c1: 0.1}\n"
         "boundary:\n"
         "  - {type: symmetry, surface: sym_x}\n"
         "  - {type: symmetry, surface: sym_y}\n"
         "  - {type: fixed, surface: right}\n"
         "  - {type: fixed, surface: back}\n" +
         load +
         "probes: [{name: apex, point: [0, 0, 0.5]}]\n"
         "solver:\n"
         "  steps: " +
         std::to_string(steps) +
         "\n"
         "  newton: {rtol: 1.0e-11, atol: 1.0e-14, line_search: " +
         line_search + "}\n";
}

struct SheetRun {
  int status = -1;
  HistoryTable history;
  std::string log;
};

SheetRun run(const std::string& name, const std::string& yaml) {
  const fs::path dir = test::scratch_directory("flat-cavity-" + name);
  fs::create_directories(dir);
  std::ofstream(dir / "case.yaml") << yaml;
  SheetRun r;
  r.status = test::run_plisse(
      "run " + (dir / "case.yaml").string() + " -o " + (dir / "run").string(), dir / "out.txt");
  if (r.status != 0) return r;
  r.history = read_history(dir / "run" / "history.csv");
  std::ifstream log(dir / "run" / "log.txt");
  r.log.assign(std::istreambuf_iterator<char>(log), std::istreambuf_iterator<char>());
  return r;
}

double value(const HistoryTable& h, std::size_t row, const std::string& column) {
  for (std::size_t i = 0; i < h.columns.size(); ++i)
    if (h.columns[i] == column) return h.rows[row][i];
  ADD_FAILURE() << "no column " << column;
  return 0.0;
}

const std::string kVolumeControl =
    "cavities: [{name: fluid, surface: bottom, control: volume, volume_change: 800.0}]\n";

TEST(FlatCavity, VolumeChangeBulgesTheClampedSheetAndPressureControlAgrees) {
  const SheetRun by_volume = run("volume", sheet_case(kVolumeControl, 4, "bt"));
  ASSERT_EQ(by_volume.status, 0) << by_volume.log;
  const HistoryTable& h = by_volume.history;
  ASSERT_FALSE(h.rows.empty());
  double apex = 0.0, pressure = 0.0;
  for (std::size_t k = 0; k < h.rows.size(); ++k) {
    const double V = value(h, k, "volume:fluid"), t = value(h, k, "load_factor");
    EXPECT_NEAR(V, 800.0 * t, 1e-8 * 800.0) << "step " << k + 1;
    EXPECT_GT(value(h, k, "uz:apex"), apex) << "the apex rises, step " << k + 1;
    EXPECT_GT(value(h, k, "pressure:fluid"), pressure) << "the pressure rises, step " << k + 1;
    apex = value(h, k, "uz:apex");
    pressure = value(h, k, "pressure:fluid");
  }
  // The same sheet under that final pressure as a follower pressure on the same face.
  char load[160];
  std::snprintf(load, sizeof load,
                "loads: [{type: pressure, name: p, surface: bottom, value: %.17g}]\n", pressure);
  const SheetRun by_pressure = run("pressure", sheet_case(load, 4, "cp"));
  ASSERT_EQ(by_pressure.status, 0) << by_pressure.log;
  const HistoryTable& q = by_pressure.history;
  ASSERT_FALSE(q.rows.empty());
  EXPECT_NEAR(value(q, q.rows.size() - 1, "uz:apex"), apex, 1e-7 * apex);
}

TEST(FlatCavity, FirstStepFromTheFlatStateNeedsNoCutBack) {
  // The whole volume change in one step from the flat, stress-free sheet.
  const SheetRun r = run("one-step", sheet_case(kVolumeControl, 1, "bt"));
  ASSERT_EQ(r.status, 0) << r.log;
  ASSERT_EQ(r.history.rows.size(), 1u);
  EXPECT_EQ(r.log.find("cutting the step"), std::string::npos) << r.log;
  EXPECT_LE(value(r.history, 0, "newton_iterations"), 8.0);
  EXPECT_NEAR(value(r.history, 0, "volume:fluid"), 800.0, 1e-8 * 800.0);
}

}  // namespace
}  // namespace plisse
