// Requirement: `plisse check` makes every check `plisse run` makes before its first step. The
// table of run's pre-step checks (app/pre_step_checks) is listed here by name, and for each one
// a case that only it refuses is given to `plisse check` and to `plisse run`: both refuse it with
// exit status 2 and the check's message, and the run writes nothing. A check added to the table
// without a case here fails the test.
#include "app/pre_step_checks.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "support/run_plisse.hpp"

namespace plisse::app {
namespace {

namespace fs = std::filesystem;

const std::string kMeshes = std::string(PLISSE_SOURCE_DIR) + "/tests/bad-inputs/meshes/";

/// A case refused by one check alone, and a fragment of its message.
struct RefusedCase {
  std::string text;
  std::string message;
};

const std::map<std::string, RefusedCase>& refused_cases() {
  static const std::map<std::string, RefusedCase> cases = {
      {"element and scheme",
       {"mesh: {generate: cube, edge: 2.0, divisions: 1, order: 1}\n"
        "element: taylor-hood\n"
        "material: {model: neo-hookean, c1: 0.2}\n"
        "boundary: [{type: fixed, surface: bottom}]\n",
        "the Taylor-Hood element needs second-order (10-node) ones"}},
      {"curved elements",
       {"mesh: {file: " + kMeshes + "curved-tet10.msh}\n" +
            "element: taylor-hood\n"
            "material: {model: neo-hookean, c1: 0.2}\n"
            "boundary: [{type: fixed, surface: bottom}]\n",
        "second-order tetrahedron 1 (1-based"}},
      {"rigid pieces",
       {"mesh: {file: " + kMeshes + "two-pieces.msh}\n" +
            "element: mini\n"
            "material: {model: neo-hookean, c1: 0.2}\n"
            "boundary: [{type: fixed, surface: fixed}]\n",
        "is held by no boundary condition"}},
  };
  return cases;
}

TEST(PreStepChecks, RunsChecksAreListed) {
  std::vector<std::string> names;
  for (const PreStepCheck& check : pre_step_checks()) names.push_back(check.name);
  EXPECT_EQ(names,
            (std::vector<std::string>{"element and scheme", "curved elements", "rigid pieces"}));
}

TEST(PreStepChecks, CheckMakesEveryCheckRunMakes) {
  const fs::path dir = test::scratch_directory("pre-step-checks");
  fs::create_directories(dir);
  int k = 0;
  for (const PreStepCheck& check : pre_step_checks()) {
    SCOPED_TRACE(check.name);
    const auto found = refused_cases().find(check.name);
    ASSERT_NE(found, refused_cases().end()) << "no case refused by '" << check.name << "' here";
    const fs::path file = dir / ("case-" + std::to_string(k++) + ".yaml");
    std::ofstream(file) << found->second.text;
    const fs::path out = dir / (file.stem().string() + "-run");
    for (const std::string& args : {"check '" + file.string() + "'",
                                    "run '" + file.string() + "' -o '" + out.string() + "'"}) {
      const test::PlisseResult r = test::run_plisse_captured(args, test::limits(60));
      EXPECT_EQ(r.status, 2) << args << "\n" << r.output;
      EXPECT_NE(r.output.find(found->second.message), std::string::npos) << args << "\n"
                                                                         << r.output;
    }
    EXPECT_FALSE(fs::exists(out)) << "the refused run wrote " << out;
  }
}

/// A unit cube held across the symmetry planes x = 0 and y = 0 (free to slide along z) and by
/// `support`, under its own weight, written to dir/name.yaml.
fs::path write_sliding_cube(const fs::path& dir, const std::string& name,
                            const std::string& support) {
  const fs::path file = dir / (name + ".yaml");
  std::ofstream(file) << "mesh: {generate: cube, edge: 1.0, divisions: 2}\n"
                         "element: mini\n"
                         "material: {model: neo-hookean, c1: 0.2, density: 1.0e-9}\n"
                         "boundary:\n"
                         "  - {type: symmetry, surface: left}\n"
                         "  - {type: symmetry, surface: front}\n"
                         "loads: [{name: weight, type: gravity, acceleration: [0, 0, -9810]}]\n"
                      << support << "solver: {steps: 4}\n";
  return file;
}

test::PlisseResult check_held_cube(const fs::path& dir, const std::string& name,
                                   const std::string& support) {
  return test::run_plisse_captured(
      "check '" + write_sliding_cube(dir, name, support).string() + "'", test::limits(60));
}

TEST(PreStepChecks, ASlidingBodyIsHeldByADieThatPressesInByTheFirstStepOrByACap) {
  // The first step ends at t = 0.25. A plate at the face z = 0 that rises 0.4 mm over the run has
  // pressed 0.1 mm into it by then; one that stays there touches it (the weight presses the cube
  // onto it from the first iteration on), and a sticking one glues the face from the start. One
  // that starts 0.5 mm below and rises 0.5 mm reaches the face only at t = 1: it holds nothing at
  // the first step. A cap on the top face holds the slide when its z displacement is prescribed,
  // not when it is free under a force.
  const fs::path dir = test::scratch_directory("held-cube");
  fs::create_directories(dir);
  const std::string presses =
      "dies: [{name: plate, shape: plane, point: [0, 0, 0], normal: [0, 0, 1], "
      "contact: frictionless, surface: bottom, move: {displacement: [0, 0, 0.4]}}]\n";
  const std::string touches =
      "dies: [{name: plate, shape: plane, point: [0, 0, 0], normal: [0, 0, 1], "
      "contact: frictionless, surface: bottom}]\n";
  const std::string glues =
      "dies: [{name: plate, shape: plane, point: [0, 0, 0], normal: [0, 0, 1], "
      "contact: sticking, surface: bottom}]\n";
  const std::string below =
      "dies: [{name: plate, shape: plane, point: [0, 0, -0.5], normal: [0, 0, 1], "
      "contact: frictionless, surface: bottom, move: {displacement: [0, 0, 0.5]}}]\n";
  const std::string held_cap = "caps: [{name: lid, surface: top, displacement: [~, ~, 0]}]\n";
  const std::string free_cap = "caps: [{name: lid, surface: top, force: [0, 0, 1.0e-3]}]\n";
  for (const auto& [name, support, refused] :
       std::vector<std::tuple<std::string, std::string, bool>>{{"presses", presses, false},
                                                               {"touches", touches, false},
                                                               {"glues", glues, false},
                                                               {"below", below, true},
                                                               {"held-cap", held_cap, false},
                                                               {"free-cap", free_cap, true}}) {
    SCOPED_TRACE(name);
    const test::PlisseResult r = check_held_cube(dir, name, support);
    EXPECT_EQ(r.status, refused ? 2 : 0) << r.output;
    EXPECT_EQ(
        r.output.find("can still move as a rigid body by translation along z") != std::string::npos,
        refused)
        << r.output;
  }
}

TEST(PreStepChecks, AFreeMotionTheCheckCannotJudgeStopsTheFirstStepAtOnce) {
  // Surface contacts may hold one piece against another, so the check leaves a case with them to
  // the run (here a self-contact on the top face, which never closes). The run's first try of
  // step 1 fails on the singular tangent, and instead of cutting the step back until it is below
  // the minimum, the run stops there, naming the motion from the tangent itself.
  const fs::path dir = test::scratch_directory("free-with-contact");
  fs::create_directories(dir);
  const fs::path file = write_sliding_cube(dir, "case", "contacts: [{name: fold, self: top}]\n");
  const test::PlisseResult checked =
      test::run_plisse_captured("check '" + file.string() + "'", test::limits(60));
  EXPECT_EQ(checked.status, 0) << checked.output;
  const test::PlisseResult r = test::run_plisse_captured(
      "run '" + file.string() + "' -o '" + (dir / "run").string() + "'", test::limits(120));
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find("step 1: t = 0.25 failed: the body of 48 tetrahedra (centred near "
                          "[0.5, 0.5, 0.5]) can still move as a rigid body by translation along z"),
            std::string::npos)
      << r.output;
  EXPECT_EQ(r.output.find("cutting the step"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace plisse::app
