// `--set key.path=value` overrides: applied to the YAML tree before validation, so the result is
// checked like the file itself; errors in overrides are placed at "--set" with the key path.
#include <gtest/gtest.h>

#include "case_test_util.hpp"
#include "physics/die_contact_settings.hpp"
#include "physics/pressure_load.hpp"

namespace plisse {
namespace {

using test::case_error;

const std::string kCase =
    "mesh: {generate: cube, edge: 1.0, divisions: 1}\n"                    // 1
    "material: {model: neo-hookean, c1: 0.1}\n"                            // 2
    "loads:\n"                                                             // 3
    "  - {type: pressure, name: p, surface: top, value: 1.0e-3}\n"         // 4
    "dies:\n"                                                              // 5
    "  - {name: d, shape: plane, point: [0, 0, 2], normal: [0, 0, -1],\n"  // 6
    "     move: {displacement: [0, 0, -1], ramp: [0, 1]}}\n";              // 7

Case parse(const std::vector<std::string>& overrides) {
  return parse_case_string(kCase, "case.yaml", overrides);
}

TEST(CaseOverrides, ScalarNestedAndListValues) {
  const Case c = parse({"mesh.divisions=3", "material.c1=0.25", "solver.newton.rtol=1e-6",
                        "loads[0].value=2e-3", "dies[0].move.displacement=[0, -5, 0]",
                        "output.wrinkles.rings_deg=[10, 20.5]", "title=a run from --set"});
  EXPECT_EQ(c.mesh.generate->divisions, 3);
  EXPECT_EQ(c.material.params.at("c1"), 0.25);
  EXPECT_EQ(c.solver.newton.rtol, 1e-6);  // solver section created by the override
  EXPECT_EQ(test::term_settings<PressureLoadSettings>(c, "loads", 0).value, 2e-3);
  EXPECT_EQ(test::term_settings<DieSettings>(c, "dies", 0).displacement, Vec3d(0, -5, 0));
  EXPECT_EQ(c.output.wrinkles.rings_deg, (std::vector<double>{10, 20.5}));
  EXPECT_EQ(c.title, "a run from --set");
  // Overridden values are placed at --set; untouched ones keep their line.
  EXPECT_EQ(c.material.param_places.at("c1").file, "--set");
  EXPECT_EQ(c.material.param_places.at("c1").line, 0);
  EXPECT_EQ(test::term_settings<PressureLoadSettings>(c, "loads", 0).surface.place.line, 4);
}

TEST(CaseOverrides, ListItemAndMapValuesAndOrder) {
  const Case c = parse({"dies[0].move.displacement[1]=-2", "solver.steps=5", "solver.steps=7",
                        "material={model: mooney-rivlin, c1: 0.1, c2: 0.02}"});
  EXPECT_EQ(test::term_settings<DieSettings>(c, "dies", 0).displacement, Vec3d(0, -2, -1));
  EXPECT_EQ(c.solver.steps, 7);  // later overrides win
  EXPECT_EQ(c.material.model, "mooney-rivlin");
  EXPECT_EQ(c.material.params.at("c2"), 0.02);
  EXPECT_EQ(c.material.place.file, "--set");
}

TEST(CaseOverrides, UnknownKeysAreUnknownKeys) {
  EXPECT_INPUT_ERROR(case_error(kCase, {"solver.stepz=3"}), "--set", 0, 0, "solver.stepz",
                     "unknown key 'stepz' in 'solver' (did you mean 'steps'?)");
  EXPECT_INPUT_ERROR(case_error(kCase, {"materal.c1=1"}), "--set", 0, 0, "materal",
                     "unknown key 'materal' (did you mean 'material'?)");
  EXPECT_INPUT_ERROR(case_error(kCase, {"loads[0].valeu=1"}), "--set", 0, 0, "loads[0].valeu",
                     "did you mean 'value'?");
}

TEST(CaseOverrides, ValuesAreValidatedAfterTheOverride) {
  EXPECT_INPUT_ERROR(case_error(kCase, {"solver.steps=0"}), "--set", 0, 0, "solver.steps",
                     "must be >= 1 (got 0)");
  EXPECT_INPUT_ERROR(case_error(kCase, {"material.c1=-1"}), "--set", 0, 0, "material.c1",
                     "must be > 0 (got -1)");
  EXPECT_INPUT_ERROR(case_error(kCase, {"mesh.divisions=2.5"}), "--set", 0, 0, "mesh.divisions",
                     "expected an integer, got '2.5'");
  EXPECT_INPUT_ERROR(case_error(kCase, {"dies[0].move.displacement=[0, 1]"}), "--set", 0, 0,
                     "dies[0].move.displacement", "expected a list of 3 numbers");
  EXPECT_INPUT_ERROR(case_error(kCase, {"material={model: mooney-rivlin, c1: -1, c2: 2}"}), "--set",
                     0, 0, "material.c1", "must be >= 0 (got -1)");
  // An error elsewhere in the file still names its line.
  EXPECT_INPUT_ERROR(case_error(kCase + "probes: [{name: q, point: [0, 0]}]\n", {"solver.steps=3"}),
                     "case.yaml", 8, 27, "probes[0].point", "expected a list of 3 numbers");
}

TEST(CaseOverrides, MalformedOverrides) {
  EXPECT_INPUT_ERROR(case_error(kCase, {"mesh.layers"}), "--set", 0, 0, "",
                     "malformed override 'mesh.layers': expected key.path=value");
  EXPECT_INPUT_ERROR(case_error(kCase, {"=3"}), "--set", 0, 0, "",
                     "the key path before '=' is empty");
  EXPECT_INPUT_ERROR(case_error(kCase, {"loads[x].value=1"}), "--set", 0, 0, "loads[x].value",
                     "the list index '[x]' must be a non-negative integer");
  EXPECT_INPUT_ERROR(case_error(kCase, {"loads[-1].value=1"}), "--set", 0, 0, "loads[-1].value",
                     "must be a non-negative integer");
  EXPECT_INPUT_ERROR(case_error(kCase, {"loads[0.value=1"}), "--set", 0, 0, "loads[0.value",
                     "must be a non-negative integer");
  EXPECT_INPUT_ERROR(case_error(kCase, {"solver..steps=1"}), "--set", 0, 0, "solver..steps",
                     "malformed override");
  EXPECT_INPUT_ERROR(case_error(kCase, {"loads[3].value=1"}), "--set", 0, 0, "loads[3].value",
                     "index 3 is out of range, 'loads' has 1 items");
  EXPECT_INPUT_ERROR(case_error(kCase, {"probes[0].name=a"}), "--set", 0, 0, "probes[0].name",
                     "'probes' is missing, not a list");
  EXPECT_INPUT_ERROR(case_error(kCase, {"loads.value=1"}), "--set", 0, 0, "loads.value",
                     "'loads' is a list, not a map (select an item, e.g. loads[0].value)");
  EXPECT_INPUT_ERROR(case_error(kCase, {"material.c1.x=1"}), "--set", 0, 0, "material.c1.x",
                     "'material.c1' is a single value, not a map");
  EXPECT_INPUT_ERROR(case_error(kCase, {"title=[a, b"}), "--set", 0, 0, "title",
                     "cannot read the value of override 'title=[a, b' as YAML");
}

}  // namespace
}  // namespace plisse
