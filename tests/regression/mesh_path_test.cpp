// Requirement: a run on a mesh file is the same run whatever path names its files. `plisse
// wrinkles DIR`, `plisse run CASE --resume DIR` and `plisse run CASE --from DIR` accept a run
// started from another working directory, its case given by a relative path, an absolute path or
// a path through `..` (the checkpoint compares the mesh file's content, not the spelling of its
// path), and still refuse the run when the mesh file's content changed.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "support/inflated_octant.hpp"
#include "support/run_plisse.hpp"

namespace plisse {
namespace {

namespace fs = std::filesystem;
using test::run_plisse_captured;
using test::scratch_directory;

/// An octant of an inflated spherical shell read from shell.msh beside the case, two steps, with
/// one wrinkle ring (so that `plisse wrinkles` has something to measure).
const std::string kCase =
    test::inflated_octant_case("mesh: {file: shell.msh, thickness: 1.0}\n",
                               "solver: {steps: 2}\n"
                               "output: {wrinkles: {axis: y, rings_deg: [45]}}\n");

/// `plisse ARGS` run in the working directory `cwd`.
test::PlisseResult run_in(const fs::path& cwd, const std::string& args) {
  return run_plisse_captured(args, "cd '" + cwd.string() + "' && ");
}

TEST(MeshPath, AnotherSpellingOfTheCaseAndMeshIsTheSameRun) {
  const fs::path dir = scratch_directory("mesh-path");
  fs::create_directories(dir / "case");
  fs::create_directories(dir / "other");
  auto r = run_in(dir,
                  "mesh spherical-shell --inner-radius 10 --thickness 1 --layers 1 "
                  "--element-size 4 --symmetry octant --order 1 -o case/shell.msh");
  ASSERT_EQ(r.status, 0) << r.output;
  std::ofstream(dir / "case" / "shell.yaml") << kCase;
  // The run names its case (and so its mesh) relative to the case's own directory.
  r = run_in(dir / "case", "run shell.yaml -o ../out");
  ASSERT_EQ(r.status, 0) << r.output;

  // plisse wrinkles reads the case by its absolute path: from another directory, by a relative
  // and by an absolute path to the run.
  for (const std::string& run : {std::string("../out"), (dir / "out").string()}) {
    r = run_in(dir / "other", "wrinkles " + run);
    EXPECT_EQ(r.status, 0) << run << ": " << r.output;
    EXPECT_EQ(r.output.find("differs"), std::string::npos) << r.output;
  }
  // --resume with the case through `..`, and by its absolute path (the run is complete: the
  // resumed run has no step left and ends at once).
  for (const std::string& case_file :
       {std::string("../case/../case/shell.yaml"), (dir / "case" / "shell.yaml").string()}) {
    r = run_in(dir / "other", "run " + case_file + " --resume ../out");
    EXPECT_EQ(r.status, 0) << case_file << ": " << r.output;
  }
  // --from a run that named its mesh otherwise.
  r = run_in(dir / "other", "run " + (dir / "case" / ".." / "case" / "shell.yaml").string() +
                                " --from ../out -o ../second");
  EXPECT_EQ(r.status, 0) << r.output;

  // The same spelling with other content is still another mesh: one more layer through the wall.
  r = run_in(dir,
             "mesh spherical-shell --inner-radius 10 --thickness 1 --layers 2 "
             "--element-size 4 --symmetry octant --order 1 -o case/shell.msh");
  ASSERT_EQ(r.status, 0) << r.output;
  r = run_in(dir / "other", "wrinkles ../out");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("changed since the checkpoint was written"), std::string::npos)
      << r.output;
  r = run_in(dir / "other", "run ../case/shell.yaml --resume ../out");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("the checkpoint belongs to another run"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace plisse
