// Requirement: plisse writes no file through a symbolic link (docs/architecture.md, "Interface
// contract"). A link planted at any name plisse writes (the lock, the files of a run directory,
// the figures of plisse plot, the files of plisse fit -o) and pointing at a file outside is
// refused with exit status 2 naming it; the outside file is untouched and the link stays.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "support/inflated_octant.hpp"
#include "support/run_plisse.hpp"

namespace plisse {
namespace {

namespace fs = std::filesystem;

const std::string kLimits = test::limits(60);

/// A small shell of wrinkle rings: its runs write every file a run directory can hold.
const std::string kCase =
    test::inflated_octant_case(test::kSmallOctantMesh,
                               "solver: {steps: 2}\n"
                               "output: {wrinkles: {axis: y, rings_deg: [45]}}\n");

std::string text_of(const fs::path& file) {
  std::ifstream in(file);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// A finished run (with wrinkles.json) in `dir`, from the case written to `dir`.yaml, and a file
/// outside it that the links will point to.
struct Fixture {
  fs::path dir, case_file, outside;
};

Fixture finished_run(const std::string& name) {
  Fixture f;
  f.dir = test::scratch_directory(name);
  f.case_file = f.dir.string() + ".yaml";
  f.outside = f.dir.string() + "-outside.txt";
  std::ofstream(f.case_file) << kCase;
  std::ofstream(f.outside) << "outside\n";
  const test::PlisseResult run =
      test::run_plisse_captured("run " + f.case_file.string() + " -o " + f.dir.string(), kLimits);
  EXPECT_EQ(run.status, 0) << run.output;
  const test::PlisseResult wrinkles =
      test::run_plisse_captured("wrinkles " + f.dir.string(), kLimits);
  EXPECT_EQ(wrinkles.status, 0) << wrinkles.output;
  return f;
}

/// Replaces dir/name by a symbolic link to `outside`.
void plant_link(const fs::path& dir, const std::string& name, const fs::path& outside) {
  fs::remove(dir / name);
  fs::create_symlink(outside, dir / name);
}

void expect_link_refused(const test::PlisseResult& r, const std::string& name, const Fixture& f) {
  EXPECT_EQ(r.status, 2) << name << ": " << r.output;
  EXPECT_NE(r.output.find(name), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("is a symbolic link; plisse writes no file through a link"),
            std::string::npos)
      << name << ": " << r.output;
  EXPECT_EQ(text_of(f.outside), "outside\n") << name;
}

TEST(SymbolicLinks, ARunDirectoryWithALinkAtANamePlisseWritesIsRefused) {
  const Fixture f = finished_run("links-run");
  ASSERT_TRUE(fs::exists(f.dir / "wrinkles.json"));
  const std::vector<std::string> names = {".plisse.lock",         "log.txt",      "history.csv",
                                          "wrinkle_spectrum.csv", "summary.json", "checkpoint.bin",
                                          "step_0001.vtu",        "solution.pvd", "wrinkles.json"};
  for (const std::string& name : names) {
    const fs::path saved = f.dir.string() + "-saved";
    fs::remove(saved);
    if (fs::exists(f.dir / name)) fs::rename(f.dir / name, saved);
    plant_link(f.dir, name, f.outside);
    // plisse wrinkles rewrites wrinkles.json under the directory's lock.
    expect_link_refused(test::run_plisse_captured("wrinkles " + f.dir.string(), kLimits), name, f);
    EXPECT_TRUE(fs::is_symlink(f.dir / name)) << name;
    fs::remove(f.dir / name);
    if (fs::exists(saved)) fs::rename(saved, f.dir / name);
  }
  // A resumed run appends to log.txt and history.csv and takes the lock first.
  for (const std::string name : {".plisse.lock", "log.txt", "history.csv"}) {
    const fs::path saved = f.dir.string() + "-saved";
    fs::remove(saved);
    if (fs::exists(f.dir / name)) fs::rename(f.dir / name, saved);
    plant_link(f.dir, name, f.outside);
    expect_link_refused(test::run_plisse_captured(
                            "run " + f.case_file.string() + " --resume " + f.dir.string(), kLimits),
                        name, f);
    fs::remove(f.dir / name);
    if (fs::exists(saved)) fs::rename(saved, f.dir / name);
  }
}

TEST(SymbolicLinks, PlotRefusesALinkedFigureOrFolder) {
  const Fixture f = finished_run("links-plot");
  fs::create_directories(f.dir / "plots");
  plant_link(f.dir / "plots", "newton.png", f.outside);
  expect_link_refused(test::run_plisse_captured("plot " + f.dir.string(), kLimits), "newton.png",
                      f);
  fs::remove_all(f.dir / "plots");
  const fs::path elsewhere = f.dir.string() + "-elsewhere";
  fs::remove_all(elsewhere);  // a scratch directory of an earlier run of this test
  fs::create_directories(elsewhere);
  fs::create_symlink(elsewhere, f.dir / "plots");
  const test::PlisseResult r = test::run_plisse_captured("plot " + f.dir.string(), kLimits);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("plots: is a symbolic link"), std::string::npos) << r.output;
  EXPECT_TRUE(fs::is_empty(elsewhere));
}

TEST(SymbolicLinks, FitRefusesALinkedOutput) {
  const std::string data = std::string(PLISSE_SOURCE_DIR) + "/examples/materials/treloar-1944.csv";
  const fs::path dir = test::scratch_directory("links-fit");
  fs::create_directories(dir);
  const fs::path outside = dir.string() + "-outside.txt";
  std::ofstream(outside) << "outside\n";
  const Fixture f{dir, {}, outside};
  for (const std::string name : {"fit.png", "fit.json", "material.yaml"}) {
    plant_link(dir, name, outside);
    expect_link_refused(test::run_plisse_captured(
                            "fit " + data + " --model neo-hookean -o " + dir.string(), kLimits),
                        name, f);
    fs::remove(dir / name);
  }
}

}  // namespace
}  // namespace plisse
