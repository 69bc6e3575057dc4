// Every way a case file can be wrong gives an InputError at the right place (file, 1-based line
// and column, key path) with the rule in words.
#include <gtest/gtest.h>

#include "case_test_util.hpp"

namespace plisse {
namespace {

using test::case_error;
using test::kMinimalCase;

TEST(CaseErrors, YamlSyntaxErrorHasYamlCppsPosition) {
  // yaml-cpp reports where it gave up: the wrongly indented key (0-based 1:2 -> 1-based 2:3).
  EXPECT_INPUT_ERROR(case_error("mesh: {generate: cube}\n  material: 2\n"), "case.yaml", 2, 3, "",
                     "YAML syntax error");
  EXPECT_INPUT_ERROR(case_error("mesh: {generate: cube\n"), "case.yaml", 2, 1, "",
                     "YAML syntax error");
}

TEST(CaseErrors, MissingEmptyAndNonMapFiles) {
  try {
    parse_case_file("/nonexistent/plisse/case.yaml");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_INPUT_ERROR(e, "/nonexistent/plisse/case.yaml", 0, 0, "", "does not exist");
  }
  try {
    parse_case_file(PLISSE_SOURCE_DIR);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_INPUT_ERROR(e, PLISSE_SOURCE_DIR, 0, 0, "", "is a directory");
  }
  EXPECT_INPUT_ERROR(case_error(""), "case.yaml", 0, 0, "", "the case file is empty");
  EXPECT_INPUT_ERROR(case_error("# only a comment\n\n"), "case.yaml", 0, 0, "", "is empty");
  EXPECT_INPUT_ERROR(case_error("- mesh\n- material\n"), "case.yaml", 1, 1, "",
                     "expected a map of sections");
  EXPECT_INPUT_ERROR(case_error(kMinimalCase + "---\nmesh: {generate: sheet}\n"), "case.yaml", 4, 1,
                     "", "a case file holds one YAML document");
  EXPECT_NO_THROW(parse_case_string("---\n" + kMinimalCase, "case.yaml"));
}

TEST(CaseErrors, UnknownKeysListTheAllowedOnesAndSuggestTypos) {
  const InputError section = case_error(kMinimalCase + "laods: []\n");
  EXPECT_INPUT_ERROR(section, "case.yaml", 3, 1, "laods", "unknown key 'laods'");
  EXPECT_NE(section.rule().find("did you mean 'loads'?"), std::string::npos) << section.rule();
  EXPECT_NE(section.rule().find("allowed keys: title, element, mesh, material, regions, "
                                "region_pressure, boundary, loads"),
            std::string::npos)
      << section.rule();

  const InputError nested =
      case_error(kMinimalCase + "solver:\n  newton: {rtol: 1e-8, max_iteratons: 5}\n");
  EXPECT_INPUT_ERROR(
      nested, "case.yaml", 4, 24, "solver.newton.max_iteratons",
      "unknown key 'max_iteratons' in 'solver.newton' (did you mean 'max_iterations'?)");
  EXPECT_NE(nested.rule().find("allowed keys: rtol, atol, max_iterations, stall_iterations, "
                               "stall_ratio, line_search"),
            std::string::npos)
      << nested.rule();

  // No suggestion when nothing is close.
  const InputError far = case_error(kMinimalCase + "output: {colour: red}\n");
  EXPECT_INPUT_ERROR(far, "case.yaml", 3, 10, "output.colour", "unknown key 'colour' in 'output'");
  EXPECT_EQ(far.rule().find("did you mean"), std::string::npos) << far.rule();
}

TEST(CaseErrors, KeysOfAnotherVariantSayWhyTheyDoNotApply) {
  EXPECT_INPUT_ERROR(
      case_error(kMinimalCase + "boundary:\n  - {type: fixed, surface: top, value: [0, 0, 1]}\n"),
      "case.yaml", 4, 33, "boundary[0].value", "'value' does not apply to type 'fixed'");
  EXPECT_INPUT_ERROR(
      case_error("mesh: {generate: cube, layers: 3}\nmaterial: {model: neo-hookean, c1: 1}\n"),
      "case.yaml", 1, 24, "mesh.layers", "'layers' does not apply to generate: cube");
  EXPECT_INPUT_ERROR(
      case_error("mesh: {generate: cube}\nmaterial: {model: neo-hookean, c1: 1, c2: 1}\n"),
      "case.yaml", 2, 39, "material.c2", "'c2' does not apply to model 'neo-hookean'");
  EXPECT_INPUT_ERROR(
      case_error(
          kMinimalCase +
          "dies: [{name: d, shape: plane, point: [0, 0, 0], normal: [0, 0, 1], region: top}]\n"),
      "case.yaml", 3, 69, "dies[0].region",
      "'region' does not apply to shape 'plane' with contact 'frictionless'");
}

TEST(CaseErrors, WrongTypes) {
  const std::string head = "mesh: {generate: cube}\nmaterial:\n  model: neo-hookean\n";
  EXPECT_INPUT_ERROR(case_error(head + "  c1: abc\n"), "case.yaml", 4, 7, "material.c1",
                     "expected a number, got 'abc'");
  EXPECT_INPUT_ERROR(case_error(head + "  c1: [1, 2]\n"), "case.yaml", 4, 7, "material.c1",
                     "expected a number, got a list of 2 items");
  EXPECT_INPUT_ERROR(case_error(head + "  c1: \"0.1\"\n"), "case.yaml", 4, 7, "material.c1",
                     "quoted");
  EXPECT_INPUT_ERROR(case_error(head + "  c1:\n"), "case.yaml", 4, 3, "material.c1",
                     "expected a number, got nothing");
  EXPECT_INPUT_ERROR(case_error(kMinimalCase + "probes: [{name: p, point: [1, 2]}]\n"), "case.yaml",
                     3, 27, "probes[0].point", "expected a list of 3 numbers");
  EXPECT_INPUT_ERROR(case_error(kMinimalCase + "probes: [{name: p, point: [1, x, 2]}]\n"),
                     "case.yaml", 3, 31, "probes[0].point[1]", "expected a number, got 'x'");
  EXPECT_INPUT_ERROR(case_error(kMinimalCase + "output: {deformed: maybe}\n"), "case.yaml", 3, 20,
                     "output.deformed", "expected true or false, got 'maybe'");
  EXPECT_INPUT_ERROR(case_error(kMinimalCase + "loads: {type: pressure}\n"), "case.yaml", 3, 8,
                     "loads", "expected a list");
  EXPECT_INPUT_ERROR(case_error(kMinimalCase + "solver: 3\n"), "case.yaml", 3, 9, "solver",
                     "expected a map");
  EXPECT_INPUT_ERROR(case_error(kMinimalCase + "title: [a, b]\n"), "case.yaml", 3, 8, "title",
                     "expected a text value");
}

// A huge value (a generated file, a pasted blob) is named by its first 60 characters and its
// length, not quoted whole into the message.
TEST(CaseErrors, HugeValuesAreCutInTheMessage) {
  const std::string head = "mesh: {generate: cube}\nmaterial:\n  model: neo-hookean\n";
  const InputError number = case_error(head + "  c1: " + std::string(1000000, 'x') + "\n");
  EXPECT_NE(number.rule().find("expected a number, got '" + std::string(60, 'x') +
                               "…' (1000000 characters)"),
            std::string::npos)
      << number.rule().substr(0, 200);
  EXPECT_LT(number.rule().size(), 200u);
  // yaml-cpp refuses plain keys over 1024 characters itself ("illegal map value").
  const InputError key = case_error(head + "  c1: 1\n  " + std::string(500, 'k') + ": 2\n");
  EXPECT_NE(key.rule().find("unknown key '" + std::string(60, 'k') + "…' (500 characters)"),
            std::string::npos)
      << key.rule().substr(0, 200);
  EXPECT_LT(key.rule().size(), 1000u);
  EXPECT_EQ(quoted_excerpt("short"), "'short'");
  // A cut never splits a UTF-8 character: 59 letters, then two-byte ones (the 60th byte is the
  // first half of one, so the cut keeps 59).
  std::string accents(59, 'a');
  for (int i = 0; i < 20; ++i) accents += "é";
  EXPECT_EQ(quoted_excerpt(accents), "'" + std::string(59, 'a') + "…' (99 characters)");
}

TEST(CaseErrors, IntegersMustBeIntegers) {
  EXPECT_INPUT_ERROR(case_error("mesh: {generate: spherical-shell, layers: 3.5}\nmaterial: {model: "
                                "neo-hookean, c1: 1}\n"),
                     "case.yaml", 1, 43, "mesh.layers", "expected an integer, got '3.5'");
  EXPECT_INPUT_ERROR(case_error(kMinimalCase + "solver: {steps: 2.0}\n"), "case.yaml", 3, 17,
                     "solver.steps", "expected an integer, got '2.0'");
  EXPECT_INPUT_ERROR(case_error(kMinimalCase + "solver: {steps: 1e2}\n"), "case.yaml", 3, 17,
                     "solver.steps", "expected an integer");
}

TEST(CaseErrors, MissingRequiredValues) {
  EXPECT_INPUT_ERROR(case_error("mesh: {generate: cube}\n"), "case.yaml", 1, 1, "material",
                     "required value is missing");
  EXPECT_INPUT_ERROR(case_error("mesh: {generate: cube}\nmaterial: {c1: 1}\n"), "case.yaml", 2, 1,
                     "material.model", "required value is missing");
  EXPECT_INPUT_ERROR(
      case_error(kMinimalCase + "loads:\n  - type: pressure\n    name: p\n    value: 1\n"),
      "case.yaml", 4, 5, "loads[0].surface", "required value is missing");
  EXPECT_INPUT_ERROR(
      case_error(kMinimalCase + "dies: [{name: s, shape: sphere, point: [0, 0, 0]}]\n"),
      "case.yaml", 3, 8, "dies[0].radius", "required value is missing");
  EXPECT_INPUT_ERROR(case_error(kMinimalCase + "boundary: [{type: displacement, surface: top}]\n"),
                     "case.yaml", 3, 12, "boundary[0].value", "required value is missing");
  // A required material parameter (from the registry) missing.
  EXPECT_INPUT_ERROR(case_error("mesh: {generate: cube}\nmaterial: {model: fung, mu: 1}\n"),
                     "case.yaml", 2, 1, "material.gamma", "");
}

TEST(CaseErrors, OutOfRangeValuesUseTheDeclaredRange) {
  EXPECT_INPUT_ERROR(case_error(kMinimalCase + "solver: {steps: 0}\n"), "case.yaml", 3, 17,
                     "solver.steps", "must be >= 1 (got 0)");
  EXPECT_INPUT_ERROR(case_error(kMinimalCase + "solver: {cutback: 1}\n"), "case.yaml", 3, 19,
                     "solver.cutback", "must be in (0, 1) (got 1)");
  EXPECT_INPUT_ERROR(case_error(kMinimalCase + "output: {wrinkles: {rings_deg: [30, 95]}}\n"),
                     "case.yaml", 3, 37, "output.wrinkles.rings_deg[1]",
                     "must be in (-90, 90) (got 95)");
  EXPECT_INPUT_ERROR(
      case_error("mesh: {generate: cube}\nmaterial:\n  model: neo-hookean\n  c1: -0.5\n"),
      "case.yaml", 4, 7, "material.c1", "must be > 0 (got -0.5)");
  EXPECT_INPUT_ERROR(
      case_error("mesh: {generate: cube, divisions: 0}\nmaterial: {model: neo-hookean, c1: 1}\n"),
      "case.yaml", 1, 35, "mesh.divisions", "must be");
}

TEST(CaseErrors, CrossRulesNameTheKey) {
  EXPECT_INPUT_ERROR(
      case_error("mesh: {generate: cube}\nmaterial: {model: mooney-rivlin, c1: 0, c2: 0}\n"),
      "case.yaml", 2, 38, "material.c1", "c1 + c2 must be > 0");
  EXPECT_INPUT_ERROR(case_error(kMinimalCase + "solver: {min_step: 0.5, max_step: 0.1}\n"),
                     "case.yaml", 3, 20, "solver.min_step", "min_step must be <= max_step");
  EXPECT_INPUT_ERROR(case_error(kMinimalCase + "solver: {steps: 50, max_steps: 20}\n"), "case.yaml",
                     3, 17, "solver.steps", "steps must be <= max_steps");
  EXPECT_INPUT_ERROR(case_error(kMinimalCase + "solver: {stability: {branch_switch: true}}\n"),
                     "case.yaml", 3, 37, "solver.stability.branch_switch", "needs 'check: true'");
  EXPECT_INPUT_ERROR(
      case_error(kMinimalCase + "loads: [{type: gravity, name: g, acceleration: [0, -9810, 0]}]\n"),
      "case.yaml", 3, 16, "loads[0].type", "needs material.density > 0");
}

TEST(CaseErrors, NonFiniteNumbers) {
  EXPECT_INPUT_ERROR(
      case_error("mesh: {generate: cube}\nmaterial: {model: neo-hookean, c1: .nan}\n"), "case.yaml",
      2, 36, "material.c1", "must be a finite number");
  EXPECT_INPUT_ERROR(case_error(kMinimalCase + "solver: {end_time: .inf}\n"), "case.yaml", 3, 20,
                     "solver.end_time", "must be a finite number");
  EXPECT_INPUT_ERROR(case_error(kMinimalCase + "probes: [{name: p, point: [0, -.Inf, 0]}]\n"),
                     "case.yaml", 3, 31, "probes[0].point[1]", "must be a finite number");
}

TEST(CaseErrors, DuplicateNamesAcrossLoadsCavitiesDiesProbes) {
  const std::string text = kMinimalCase +
                           "loads:\n"
                           "  - {type: pressure, name: gas, surface: top, value: 1}\n"
                           "probes:\n"
                           "  - {name: gas, point: [0, 0, 0]}\n";
  EXPECT_INPUT_ERROR(case_error(text), "case.yaml", 6, 12, "probes[0].name",
                     "name 'gas' is already used by loads[0] (line 4)");
  EXPECT_INPUT_ERROR(
      case_error(kMinimalCase + "dies:\n"
                                "  - {name: d, shape: sphere, point: [0, 0, 0], radius: 1}\n"
                                "  - {name: d, shape: sphere, point: [0, 0, 0], radius: 1}\n"),
      "case.yaml", 5, 12, "dies[1].name", "already used by dies[0]");
  EXPECT_INPUT_ERROR(case_error(kMinimalCase + "probes: [{name: a b, point: [0, 0, 0]}]\n"),
                     "case.yaml", 3, 17, "probes[0].name", "may contain only letters");
  EXPECT_INPUT_ERROR(
      case_error("mesh: {generate: cube}\nmaterial: {model: neo-hookean, c1: 1, c1: 2}\n"),
      "case.yaml", 2, 39, "material.c1", "key given twice (first at line 2)");
}

TEST(CaseErrors, BadEnumerationsListTheAllowedValues) {
  const InputError shape =
      case_error(kMinimalCase + "dies: [{name: d, shape: spere, point: [0, 0, 0], radius: 1}]\n");
  EXPECT_INPUT_ERROR(
      shape, "case.yaml", 3, 25, "dies[0].shape",
      "must be one of: plane, sphere, cylinder (got 'spere'); did you mean 'sphere'?");
  EXPECT_INPUT_ERROR(
      case_error(kMinimalCase + "solver: {scheme: total_lagrangian}\n"), "case.yaml", 3, 18,
      "solver.scheme",
      "must be one of: total-lagrangian, incremental (got 'total_lagrangian'); did you "
      "mean 'total-lagrangian'?");
  EXPECT_INPUT_ERROR(case_error("mesh: {generate: cube}\nmaterial: {model: neo-hookean, c1: 1, "
                                "incompressibility: total}\n"),
                     "case.yaml", 2, 58, "material.incompressibility",
                     "must be one of: exact, nearly (got 'total')");
  EXPECT_INPUT_ERROR(case_error(kMinimalCase + "boundary: [{type: pinned, surface: top}]\n"),
                     "case.yaml", 3, 19, "boundary[0].type",
                     "must be one of: fixed, symmetry, displacement, clamped, hinged");
  EXPECT_INPUT_ERROR(
      case_error(kMinimalCase + "cavities: [{name: c, surface: inner, control: pressure}]\n"),
      "case.yaml", 3, 47, "cavities[0].control", "must be one of: volume, gas");
  EXPECT_INPUT_ERROR(case_error(kMinimalCase + "output: {wrinkles: {axis: w}}\n"), "case.yaml", 3,
                     27, "output.wrinkles.axis", "must be one of: x, y, z");
  EXPECT_INPUT_ERROR(case_error("mesh: {generate: spherical-shell, symmetry: third}\n"
                                "material: {model: neo-hookean, c1: 1}\n"),
                     "case.yaml", 1, 45, "mesh.symmetry",
                     "must be one of: full, half, quarter, octant");
  EXPECT_INPUT_ERROR(
      case_error("mesh: {generate: sphere}\nmaterial: {model: neo-hookean, c1: 1}\n"), "case.yaml",
      1, 18, "mesh.generate", "unknown mesh kind 'sphere'; known kinds: cube");
  EXPECT_INPUT_ERROR(
      case_error("mesh: {generate: cube}\nmaterial: {model: neo-hooke, c1: 1}\n"), "case.yaml", 2,
      19, "material.model",
      "unknown material model 'neo-hooke'; known models: neo-hookean, mooney-rivlin");
}

TEST(CaseErrors, Ramps) {
  const std::string head =
      kMinimalCase + "loads:\n  - {type: pressure, name: p, surface: top, value: 1, ";
  EXPECT_INPUT_ERROR(case_error(head + "ramp: [0.5, 0.5]}\n"), "case.yaml", 4, 61, "loads[0].ramp",
                     "ramp end must be > start (got [0.5, 0.5])");
  EXPECT_INPUT_ERROR(case_error(head + "ramp: [0.5, 0.2]}\n"), "case.yaml", 4, 61, "loads[0].ramp",
                     "ramp end must be > start");
  EXPECT_INPUT_ERROR(case_error(head + "ramp: [-1, 1]}\n"), "case.yaml", 4, 61, "loads[0].ramp",
                     "ramp start must be >= 0 (got -1)");
  EXPECT_INPUT_ERROR(case_error(head + "ramp: [1]}\n"), "case.yaml", 4, 61, "loads[0].ramp",
                     "expected a list of 2 numbers [start, end]");
  EXPECT_INPUT_ERROR(case_error(kMinimalCase + "dies: [{name: d, shape: plane, point: [0, 0, 0], "
                                               "normal: [0, 0, 1], move: {ramp: [0, 0]}}]\n"),
                     "case.yaml", 3, 82, "dies[0].move.ramp", "ramp end must be > start");
}

TEST(CaseErrors, MeshNeedsExactlyOneOfFileAndGenerate) {
  EXPECT_INPUT_ERROR(
      case_error("mesh: {file: a.msh, generate: cube}\nmaterial: {model: neo-hookean, c1: 1}\n"),
      "case.yaml", 1, 21, "mesh.generate", "either 'file' or 'generate', not both");
  EXPECT_INPUT_ERROR(case_error("mesh: {edge: 1}\nmaterial: {model: neo-hookean, c1: 1}\n"),
                     "case.yaml", 1, 1, "mesh", "needs either 'file: PATH'");
  EXPECT_INPUT_ERROR(case_error("mesh:\nmaterial: {model: neo-hookean, c1: 1}\n"), "case.yaml", 1,
                     1, "mesh", "needs either");
  EXPECT_INPUT_ERROR(
      case_error("mesh: {file: a.msh, layers: 2}\nmaterial: {model: neo-hookean, c1: 1}\n"),
      "case.yaml", 1, 21, "mesh.layers", "does not apply to a mesh read from a file");
}

TEST(CaseErrors, BulkModulusGoesWithNearIncompressibility) {
  EXPECT_INPUT_ERROR(
      case_error(
          "mesh: {generate: cube}\nmaterial: {model: neo-hookean, c1: 1, bulk_modulus: 10}\n"),
      "case.yaml", 2, 39, "material.bulk_modulus", "applies only with 'incompressibility: nearly'");
  EXPECT_INPUT_ERROR(case_error("mesh: {generate: cube}\nmaterial: {model: neo-hookean, c1: 1,\n"
                                "           incompressibility: nearly}\n"),
                     "case.yaml", 3, 31, "material.bulk_modulus",
                     "required with 'incompressibility: nearly'");
  EXPECT_INPUT_ERROR(case_error("mesh: {generate: cube}\nmaterial: {model: neo-hookean, c1: 1,\n"
                                "           incompressibility: nearly, bulk_modulus: 0}\n"),
                     "case.yaml", 3, 53, "material.bulk_modulus", "must be > 0 (got 0)");
}

TEST(CaseErrors, DieDirectionsMustBeNonZero) {
  EXPECT_INPUT_ERROR(
      case_error(kMinimalCase +
                 "dies: [{name: d, shape: plane, point: [0, 0, 0], normal: [0, 0, 0]}]\n"),
      "case.yaml", 3, 58, "dies[0].normal", "must be a non-zero direction");
  EXPECT_INPUT_ERROR(
      case_error(kMinimalCase + "dies: [{name: d, shape: cylinder, point: [0, 0, 0], radius: 1,\n"
                                "        axis: [0, 0, 0]}]\n"),
      "case.yaml", 4, 15, "dies[0].axis", "must be a non-zero direction");
}

TEST(CaseErrors, DisplacementConditionNeedsAComponent) {
  EXPECT_INPUT_ERROR(
      case_error(kMinimalCase +
                 "boundary: [{type: displacement, surface: top, value: [~, ~, ~]}]\n"),
      "case.yaml", 3, 54, "boundary[0].value", "at least one component");
  EXPECT_INPUT_ERROR(
      case_error(kMinimalCase + "boundary: [{type: displacement, surface: top, value: [0, 1]}]\n"),
      "case.yaml", 3, 54, "boundary[0].value", "expected a list of 3 displacements");
}

}  // namespace
}  // namespace plisse
