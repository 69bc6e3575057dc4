// The model builder's judgement of the element family against the mesh order: a generated mesh
// follows `element` unless `mesh.order` says otherwise, and a mismatch is an input error placed at
// the key that caused it.
#include "app/model_builder.hpp"

#include <gtest/gtest.h>

#include <string>

#include "io/case.hpp"

namespace plisse::app {
namespace {

const std::string kCube =
    "mesh: {generate: cube, edge: 2.0, divisions: 1}\nmaterial: {model: neo-hookean, c1: 0.2}\n";

TEST(ModelBuilder, GeneratedMeshTakesTheElementsOrder) {
  for (const auto& [element, order] : {std::pair{"mini", 1}, std::pair{"taylor-hood", 2}}) {
    const Case c = parse_case_string(std::string("element: ") + element + "\n" + kCube, "c.yaml");
    const Mesh mesh = load_case_mesh(c);
    EXPECT_EQ(mesh.order(), order) << element;
    EXPECT_TRUE(unsupported_features(c, mesh).empty()) << element;
    EXPECT_EQ(build_model_parts(c, mesh).element, c.element);
  }
  // Without the key: the Taylor-Hood element on a second-order mesh (docs/case-file.md).
  const Case plain = parse_case_string(kCube, "c.yaml");
  EXPECT_EQ(plain.element, ElementFamily::taylor_hood);
  EXPECT_EQ(load_case_mesh(plain).order(), 2);
}

TEST(ModelBuilder, ExplicitMeshOrderAgainstTheElementIsRefusedAtThatKey) {
  const std::string text =
      "element: taylor-hood\n"
      "mesh: {generate: cube, edge: 2.0, divisions: 1, order: 1}\n"
      "material: {model: neo-hookean, c1: 0.2}\n";
  const Case c = parse_case_string(text, "c.yaml");
  const Mesh mesh = load_case_mesh(c);
  EXPECT_EQ(mesh.order(), 1);
  const auto errors = unsupported_features(c, mesh);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].place().line, 2);
  EXPECT_EQ(errors[0].place().key, "mesh.order");
  EXPECT_NE(errors[0].rule().find("Taylor-Hood element needs second-order"), std::string::npos);
  EXPECT_NE(errors[0].rule().find("remove `mesh.order`"), std::string::npos);

  const Case mini = parse_case_string(
      "element: mini\n"
      "mesh: {generate: cube, edge: 2.0, divisions: 1, order: 2}\n"
      "material: {model: neo-hookean, c1: 0.2}\n",
      "c.yaml");
  const auto mini_errors = unsupported_features(mini, load_case_mesh(mini));
  ASSERT_EQ(mini_errors.size(), 1u);
  EXPECT_NE(mini_errors[0].rule().find("MINI element needs linear ones"), std::string::npos);
}

// A ramp past solver.end_time leaves the load unfinished when the run ends (a silently partial
// result unless meant), one that starts at or after it never acts: warnings at the ramp's key.
TEST(ModelBuilder, RampsBeyondTheEndTimeAreWarnedAboutAtTheirKeys) {
  const std::string text =
      kCube +
      "boundary: [{type: fixed, surface: bottom}]\n"
      "loads:\n"
      "  - {type: pressure, name: p, surface: top, value: 0.01, ramp: [0, 4]}\n"
      "  - {type: pressure, name: q, surface: left, value: 0.01}\n"
      "dies:\n"
      "  - {name: plate, shape: plane, point: [0, 0, 3], normal: [0, 0, -1],\n"
      "     move: {displacement: [0, 0, -1], ramp: [2, 3]}}\n"
      "solver: {end_time: 2.0}\n";
  const auto warnings = setup_warnings(parse_case_string(text, "c.yaml"));
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_EQ(warnings[0].place().key, "loads[0].ramp");
  EXPECT_EQ(warnings[0].place().line, 5);
  EXPECT_NE(warnings[0].rule().find("load 'p' ends at 4 s, after solver.end_time (2 s): the run "
                                    "ends at 50 % of it"),
            std::string::npos)
      << warnings[0].rule();
  EXPECT_EQ(warnings[1].place().key, "dies[0].ramp");
  EXPECT_NE(warnings[1].rule().find("die 'plate' starts at 2 s, not before solver.end_time (2 s): "
                                    "it is never applied"),
            std::string::npos)
      << warnings[1].rule();
  // The same case run to 4 s: nothing to say (the default ramps follow end_time).
  const Case whole = parse_case_string(
      text.substr(0, text.find("solver:")) + "solver: {end_time: 4.0}\n", "c.yaml");
  EXPECT_TRUE(setup_warnings(whole).empty());
}

}  // namespace
}  // namespace plisse::app
