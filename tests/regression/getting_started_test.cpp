// docs/getting-started.md stays true: its two files are examples/getting-started/ verbatim, Gmsh
// meshes the geometry, and plisse runs the case to the numbers the page quotes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "output/history_writer.hpp"
#include "support/run_plisse.hpp"

namespace plisse {
namespace {

namespace fs = std::filesystem;

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

const fs::path kSource = PLISSE_SOURCE_DIR;

TEST(GettingStarted, ThePageShowsTheExampleFilesVerbatim) {
  const std::string page = read_text(kSource / "docs" / "getting-started.md");
  ASSERT_FALSE(page.empty());
  for (const char* file : {"disc.geo", "bulge.yaml"}) {
    const std::string text = read_text(kSource / "examples" / "getting-started" / file);
    ASSERT_FALSE(text.empty()) << file;
    EXPECT_NE(page.find("\n" + text + "```\n"), std::string::npos) << file;
  }
}

// The bulge of a clamped quarter disc (radius a = 20 mm) under p = 0.004 MPa: the clamp holds the
// quarter down with the air's push on the quarter disc, p π a² / 4 (the rim does not move, so the
// bulged face projects onto the disc); the whole bulge holds 4 times the quarter's volume (two
// mirror planes; the base plane z = 0 only closes it); the apex rises 9.27 mm and the wall thins
// to 0.369 mm, as the page says (to its three digits).
TEST(GettingStarted, TheCaseMeshesRunsAndGivesThePagesNumbers) {
  const fs::path dir = test::scratch_directory("getting-started");
  fs::create_directories(dir);
  const fs::path example = kSource / "examples" / "getting-started";
  fs::copy_file(example / "disc.geo", dir / "disc.geo");
  fs::copy_file(example / "bulge.yaml", dir / "bulge.yaml");
  const std::string gmsh = "cd '" + dir.string() +
                           "' && timeout 120 gmsh -3 -order 2 disc.geo -o disc.msh > gmsh.log 2>&1";
  ASSERT_EQ(std::system(gmsh.c_str()), 0) << "see " << (dir / "gmsh.log").string();
  const auto r = test::run_plisse_captured("run '" + (dir / "bulge.yaml").string() + "' -o '" +
                                           (dir / "run").string() + "'");
  ASSERT_EQ(r.status, 0) << r.output;
  const HistoryTable h = read_history(dir / "run" / "history.csv");
  const auto last = [&](const std::string& name) {
    for (std::size_t i = 0; i < h.columns.size(); ++i)
      if (h.columns[i] == name) return h.rows.back()[i];
    ADD_FAILURE() << "no column " << name;
    return 0.0;
  };
  EXPECT_NEAR(last("force_z:clamp"), -0.004 * std::numbers::pi * 400.0 / 4.0, 1e-3);
  // The whole disc's clamp holds the air's whole push on the disc of radius 20, p π a², however
  // the membrane bulges: the rim reaches both mirror planes, so its images sum (4 times the
  // quarter's z force; the in-plane components cancel). The push is p times the area inside the
  // loaded face's rim, the quadratic mesh's arcs: π a² to O((h/a)^4) (measured 1.2e-8).
  const double push = 0.004 * std::numbers::pi * 400.0;
  EXPECT_NEAR(last("full_force_z:clamp"), 4.0 * last("force_z:clamp"), 1e-12);
  EXPECT_NEAR(last("full_force_z:clamp"), -push, 1e-6 * push);
  EXPECT_EQ(last("full_force_x:clamp"), 0.0);
  EXPECT_EQ(last("full_force_y:clamp"), 0.0);
  EXPECT_NEAR(last("full_volume:air"), 4.0 * last("volume:air"), 1e-9 * last("volume:air"));
  EXPECT_NEAR(last("full_volume:air"), 6337.0, 1.0);
  EXPECT_NEAR(last("uz:apex"), 9.27, 0.005);
  EXPECT_NEAR(last("min_thickness"), 0.369, 0.0005);
  const auto p = test::run_plisse_captured("plot '" + (dir / "run").string() + "'");
  ASSERT_EQ(p.status, 0) << p.output;
  for (const char* figure : {"forces.png", "pressure_volume.png", "newton.png"})
    EXPECT_TRUE(fs::exists(dir / "run" / "plots" / figure)) << figure;
  // The fields along the top face from the apex to the clamped rim, of the last step: at the
  // apex the probe's displacement (the same quadratic interpolation, to the CSV's 10 digits), at
  // the rim none.
  const auto line = test::run_plisse_captured("plot '" + (dir / "run").string() +
                                              "' --line 0,0,0.5:20,0,0.5 --points 41");
  ASSERT_EQ(line.status, 0) << line.output;
  std::ifstream csv(dir / "run" / "plots" / "line.csv");
  std::string header, row, apex_row, rim_row;
  std::getline(csv, header);
  int rows = 0;
  while (std::getline(csv, row)) {
    if (rows++ == 0) apex_row = row;
    rim_row = row;
  }
  EXPECT_EQ(rows, 41);
  const auto field = [&](const std::string& text, const std::string& name) {
    std::vector<std::string> names, values;
    std::stringstream h(header), v(text);
    for (std::string cell; std::getline(h, cell, ',');) names.push_back(cell);
    for (std::string cell; std::getline(v, cell, ',');) values.push_back(cell);
    const auto at = std::find(names.begin(), names.end(), name);
    EXPECT_NE(at, names.end()) << name;
    return at == names.end() ? 0.0 : std::stod(values[std::size_t(at - names.begin())]);
  };
  EXPECT_NEAR(field(apex_row, "displacement_z"), last("uz:apex"), 1e-8 * last("uz:apex"));
  EXPECT_EQ(field(rim_row, "s"), 20.0);
  EXPECT_EQ(field(rim_row, "displacement_z"), 0.0);
}

}  // namespace
}  // namespace plisse
