// Valid case files parse into the expected values: every section, defaults, flow style.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "case/case.hpp"
#include "case_test_util.hpp"
#include "physics/body_force.hpp"
#include "physics/boundary_condition.hpp"
#include "physics/cavity_settings.hpp"
#include "physics/die_contact_settings.hpp"
#include "physics/pressure_load.hpp"

namespace plisse {
namespace {

const std::string kDataDir = std::string(PLISSE_SOURCE_DIR) + "/tests/data/cases/";

TEST(CaseParse, CompleteCaseHasEveryValue) {
  const Case c = parse_case_file(kDataDir + "complete.yaml");
  EXPECT_EQ(c.path, kDataDir + "complete.yaml");
  EXPECT_EQ(std::filesystem::path(c.directory), std::filesystem::path(kDataDir).parent_path());
  EXPECT_EQ(c.title, "every section of a case file");

  ASSERT_TRUE(c.mesh.generate.has_value());
  EXPECT_FALSE(c.mesh.file.has_value());
  EXPECT_EQ(c.mesh.generate->kind, "cube");
  EXPECT_EQ(c.mesh.generate->edge, 2.0);
  EXPECT_EQ(c.mesh.generate->divisions, 2);
  EXPECT_EQ(c.mesh.place.line, 4);
  EXPECT_EQ(c.mesh.option_places.at("divisions").line, 7);

  EXPECT_EQ(c.material.model, "mooney-rivlin");
  EXPECT_EQ(c.material.params.at("c1"), 0.2);
  EXPECT_EQ(c.material.params.at("c2"), 0.05);
  EXPECT_EQ(c.material.param_places.at("c2").line, 11);
  EXPECT_EQ(c.material.param_places.at("c2").key, "material.c2");
  EXPECT_FALSE(c.material.exact_incompressibility);
  EXPECT_EQ(c.material.bulk_modulus, 100.0);
  EXPECT_EQ(c.material.density, 1.0e-9);

  ASSERT_EQ(c.terms_in("boundary").size(), 3u);
  EXPECT_EQ(test::term(c, "boundary", 0).kind->word, "symmetry");
  const auto& symmetry = test::term_settings<SurfaceConditionSettings>(c, "boundary", 0);
  EXPECT_EQ(symmetry.surface.name, "sym_x");
  EXPECT_EQ(symmetry.surface.place.line, 16);
  EXPECT_EQ(symmetry.surface.place.column, 31);
  EXPECT_EQ(symmetry.surface.place.key, "boundary[0].surface");
  EXPECT_EQ(test::term(c, "boundary", 1).kind->word, "fixed");
  EXPECT_EQ(test::term(c, "boundary", 1).name, "base");
  EXPECT_EQ(test::term(c, "boundary", 2).kind->word, "displacement");
  const auto& d = test::term_settings<DisplacementConditionSettings>(c, "boundary", 2);
  EXPECT_FALSE(d.value[0].has_value());
  ASSERT_TRUE(d.value[1].has_value());
  EXPECT_EQ(*d.value[1], 0.5);
  EXPECT_FALSE(d.value[2].has_value());
  EXPECT_EQ(d.ramp.start, 0.0);
  EXPECT_EQ(d.ramp.end, 0.5);
  EXPECT_EQ(d.place.line, 18);

  ASSERT_EQ(c.terms_in("loads").size(), 2u);
  EXPECT_EQ(test::term(c, "loads", 0).kind->word, "pressure");
  const auto& push = test::term_settings<PressureLoadSettings>(c, "loads", 0);
  EXPECT_EQ(push.name, "push");
  EXPECT_EQ(push.surface.name, "right");
  EXPECT_EQ(push.value, -1.0e-3);
  EXPECT_EQ(push.ramp.start, 0.1);
  EXPECT_EQ(push.ramp.end, 0.9);
  EXPECT_EQ(test::term(c, "loads", 1).kind->word, "gravity");
  const auto& weight = test::term_settings<GravityLoadSettings>(c, "loads", 1);
  EXPECT_EQ(weight.acceleration, Vec3d(0, -9810, 0));
  EXPECT_EQ(weight.ramp.start, 0.0);
  EXPECT_EQ(weight.ramp.end, 2.0);  // default end: solver.end_time

  ASSERT_EQ(c.terms_in("cavities").size(), 2u);
  const auto& gas = test::term_settings<Cavity>(c, "cavities", 0);
  const auto& held = test::term_settings<Cavity>(c, "cavities", 1);
  EXPECT_EQ(gas.control, CavityControl::gas);
  EXPECT_EQ(gas.initial_pressure, 0.01);
  EXPECT_EQ(gas.mass_ratio, 2.0);
  EXPECT_EQ(gas.ambient_pressure, 0.1);
  EXPECT_EQ(held.control, CavityControl::volume);
  EXPECT_EQ(held.volume_ratio, 1.5);
  EXPECT_EQ(held.surface.name, "front");

  ASSERT_EQ(c.terms_in("dies").size(), 3u);
  const auto& punch = test::term_settings<DieSettings>(c, "dies", 0);
  EXPECT_EQ(punch.shape, DieShape::sphere);
  EXPECT_EQ(punch.point, Vec3d(1, 1, 3));
  EXPECT_EQ(punch.radius, 0.5);
  EXPECT_EQ(punch.contact, ContactKind::frictionless);
  EXPECT_EQ(punch.displacement, Vec3d(0, 0, -0.5));
  EXPECT_EQ(punch.ramp.start, 0.5);
  EXPECT_EQ(punch.ramp.end, 2.0);
  EXPECT_EQ(punch.penalty, 10.0);
  EXPECT_EQ(punch.tolerance, 1.0e-4);
  const auto& floor = test::term_settings<DieSettings>(c, "dies", 1);
  EXPECT_EQ(floor.shape, DieShape::plane);
  EXPECT_EQ(floor.normal, Vec3d(0, 0, 1));  // [0, 0, 2] normalised
  EXPECT_EQ(floor.contact, ContactKind::sticking);
  ASSERT_TRUE(floor.region.has_value());
  EXPECT_EQ(floor.region->name, "bottom");
  EXPECT_EQ(floor.displacement, Vec3d::Zero());
  const auto& roller = test::term_settings<DieSettings>(c, "dies", 2);
  EXPECT_EQ(roller.shape, DieShape::cylinder);
  EXPECT_NEAR((roller.axis - Vec3d(0.6, 0.8, 0)).norm(), 0.0, 1e-15);  // [3, 4, 0] / 5
  ASSERT_TRUE(roller.surface.has_value());
  EXPECT_EQ(roller.surface->name, "top");

  ASSERT_EQ(c.probes.size(), 1u);
  EXPECT_EQ(c.probes[0].name, "corner");
  EXPECT_EQ(c.probes[0].point, Vec3d(2, 2, 2));

  const SolverSettings& s = c.solver;
  EXPECT_EQ(s.scheme, Scheme::incremental);
  EXPECT_EQ(s.end_time, 2.0);
  EXPECT_EQ(s.steps, 40);
  EXPECT_EQ(s.max_steps, 500);
  EXPECT_EQ(s.min_step, 1.0e-6);
  EXPECT_EQ(s.max_step, 0.25);
  EXPECT_EQ(s.growth, 2.0);
  EXPECT_EQ(s.cutback, 0.25);
  EXPECT_EQ(s.easy_iterations, 5);
  EXPECT_EQ(s.viscosity, 1.0e-3);
  EXPECT_EQ(s.newton.rtol, 1.0e-9);
  EXPECT_EQ(s.newton.atol, 1.0e-12);
  EXPECT_EQ(s.newton.max_iterations, 30);
  EXPECT_EQ(s.newton.line_search, LineSearch::basic);
  EXPECT_TRUE(s.stability.check);
  EXPECT_TRUE(s.stability.branch_switch);
  EXPECT_EQ(s.stability.modes, 6);
  EXPECT_EQ(s.stability.imperfection, 0.01);
  EXPECT_EQ(s.stability.imperfection_kind, "mode");
  EXPECT_EQ(s.stability.seed, 7);
  EXPECT_EQ(std::filesystem::path(s.stability.imperfection_from).filename(), "buckle");
  EXPECT_EQ(s.stability.imperfection_mode, 2);
  EXPECT_EQ(s.stability.branch_amplitude, 0.2);
  EXPECT_EQ(s.stability.branch_start, "perturbation");
  EXPECT_EQ(s.petsc_options, "-ksp_type preonly -pc_type lu");

  EXPECT_EQ(c.output.every, 2);
  EXPECT_TRUE(c.output.deformed);
  EXPECT_EQ(c.output.stretch_axis, 'z');
  EXPECT_EQ(c.output.wrinkles.axis, 'z');
  EXPECT_EQ(c.output.wrinkles.rings_deg, (std::vector<double>{0, 45, 89.5}));
  EXPECT_EQ(c.output.wrinkles.center, Vec3d(1, 1, 0));
  EXPECT_EQ(c.output.wrinkles.min_count, 4);
  EXPECT_EQ(c.output.wrinkles.surface, "top");
  EXPECT_EQ(c.output.wrinkles.threshold, 0.2);
}

TEST(CaseParse, MinimalCaseTakesTheDocumentedDefaults) {
  const Case c = parse_case_string(test::kMinimalCase, "case.yaml");
  EXPECT_EQ(c.title, "");
  EXPECT_EQ(c.directory, "");
  const MeshGenerationSpec defaults;
  EXPECT_EQ(c.mesh.generate->element_size, defaults.element_size);  // not a cube option: untouched
  EXPECT_TRUE(c.material.exact_incompressibility);
  EXPECT_EQ(c.material.bulk_modulus, 0.0);
  EXPECT_EQ(c.material.density, 0.0);
  EXPECT_TRUE(c.terms.empty() && c.probes.empty());
  const SolverSettings s = c.solver;
  EXPECT_EQ(s.scheme, Scheme::total_lagrangian);
  EXPECT_EQ(s.end_time, 1.0);
  EXPECT_EQ(s.steps, 10);
  EXPECT_EQ(s.max_steps, 10000);
  EXPECT_EQ(s.min_step, 1e-8);
  EXPECT_EQ(s.max_step, 1.0);
  EXPECT_EQ(s.growth, 1.5);
  EXPECT_EQ(s.cutback, 0.5);
  EXPECT_EQ(s.easy_iterations, 4);
  EXPECT_EQ(s.viscosity, 0.0);
  EXPECT_EQ(s.newton.rtol, 1e-8);
  EXPECT_EQ(s.newton.atol, 1e-10);
  EXPECT_EQ(s.newton.max_iterations, 25);
  EXPECT_EQ(s.newton.line_search, LineSearch::bt);
  EXPECT_FALSE(s.stability.check);
  EXPECT_FALSE(s.stability.branch_switch);
  EXPECT_EQ(s.stability.modes, 4);
  EXPECT_EQ(s.stability.imperfection, 0.0);
  EXPECT_EQ(s.stability.imperfection_kind, "random");
  EXPECT_EQ(s.stability.seed, 1);
  EXPECT_EQ(s.petsc_options, "");
  EXPECT_EQ(c.output.every, 1);
  EXPECT_FALSE(c.output.deformed);
  EXPECT_FALSE(c.output.stretch_axis.has_value());
  EXPECT_EQ(c.output.wrinkles.axis, 'y');
  EXPECT_FALSE(c.output.wrinkles.enabled());
  EXPECT_EQ(c.output.wrinkles.threshold, 0.1);
}

TEST(CaseParse, RampsDefaultToTheWholeRun) {
  const Case c =
      parse_case_string(test::kMinimalCase +
                            "solver: {end_time: 3.5}\n"
                            "loads: [{type: pressure, name: p, surface: top, value: 1}]\n"
                            "dies:\n"
                            "  - {name: d, shape: plane, point: [0, 0, 2], normal: [0, 0, -1],\n"
                            "     move: {displacement: [0, 0, -1]}}\n"
                            "boundary: [{type: displacement, surface: top, value: [0, 0, 1]}]\n",
                        "case.yaml");
  const auto& load = test::term_settings<PressureLoadSettings>(c, "loads", 0);
  const auto& die = test::term_settings<DieSettings>(c, "dies", 0);
  EXPECT_EQ(load.ramp.start, 0.0);
  EXPECT_EQ(load.ramp.end, 3.5);
  EXPECT_EQ(die.ramp.start, 0.0);
  EXPECT_EQ(die.ramp.end, 3.5);
  EXPECT_EQ(test::term_settings<DisplacementConditionSettings>(c, "boundary", 0).ramp.end, 3.5);
  EXPECT_EQ(die.contact, ContactKind::frictionless);
  EXPECT_EQ(die.penalty, 0.0);
  EXPECT_EQ(die.tolerance, 1e-3);
}

TEST(CaseParse, FlowAndBlockStylesGiveTheSameCase) {
  const Case flow = parse_case_string(
      "mesh: {generate: spherical-shell, inner_radius: 24.0, thickness: 1.0, layers: 3,\n"
      "       element_size: 2.0, symmetry: octant}\n"
      "material: {model: neo-hookean, c1: 0.0033, incompressibility: exact}\n"
      "boundary: [{type: symmetry, surface: sym_x}, {type: symmetry, surface: sym_z}]\n",
      "flow.yaml");
  const Case block = parse_case_string(
      "mesh:\n"
      "  generate: spherical-shell\n"
      "  inner_radius: 24.0\n"
      "  thickness: 1.0\n"
      "  layers: 3\n"
      "  element_size: 2.0\n"
      "  symmetry: octant\n"
      "material:\n"
      "  model: neo-hookean\n"
      "  c1: 0.0033\n"
      "  incompressibility: exact\n"
      "boundary:\n"
      "  - type: symmetry\n"
      "    surface: sym_x\n"
      "  - type: symmetry\n"
      "    surface: sym_z\n",
      "block.yaml");
  for (const Case* c : {&flow, &block}) {
    const MeshGenerationSpec& g = *c->mesh.generate;
    EXPECT_EQ(g.kind, "spherical-shell");
    EXPECT_EQ(g.inner_radius, 24.0);
    EXPECT_EQ(g.thickness, 1.0);
    EXPECT_EQ(g.layers, 3);
    EXPECT_EQ(g.element_size, 2.0);
    EXPECT_EQ(g.symmetry, Symmetry::octant);
    EXPECT_EQ(c->material.model, "neo-hookean");
    EXPECT_EQ(c->material.params, (std::map<std::string, double>{{"c1", 0.0033}}));
    ASSERT_EQ(c->terms_in("boundary").size(), 2u);
    EXPECT_EQ(test::term_settings<SurfaceConditionSettings>(*c, "boundary", 1).surface.name,
              "sym_z");
  }
  const auto surface = [](const Case& c) {
    return test::term_settings<SurfaceConditionSettings>(c, "boundary", 1).surface.place;
  };
  EXPECT_EQ(surface(flow).line, 4);
  EXPECT_EQ(surface(block).line, 16);
  EXPECT_EQ(surface(block).column, 14);
}

TEST(CaseParse, MaterialDefaultsFromTheRegistryAreFilledIn) {
  const Case c =
      parse_case_string("mesh: {generate: cube}\nmaterial: {model: yeoh, c1: 0.1}\n", "case.yaml");
  EXPECT_EQ(c.material.params.at("c1"), 0.1);
  EXPECT_EQ(c.material.params.at("c2"), 0.0);  // registry default
  EXPECT_EQ(c.material.params.at("c3"), 0.0);
  EXPECT_EQ(c.material.param_places.count("c2"), 0u);  // not written in the file
}

TEST(CaseParse, MeshFileResolvesAgainstTheCaseDirectory) {
  const Case c =
      parse_case_string("mesh: {file: meshes/b.msh}\nmaterial: {model: neo-hookean, c1: 1}\n",
                        "cases/run1/case.yaml");
  EXPECT_EQ(c.directory, "cases/run1");
  EXPECT_EQ(std::filesystem::path(*c.mesh.file), std::filesystem::path("cases/run1/meshes/b.msh"));
  EXPECT_EQ(c.mesh.file_place.line, 1);
  EXPECT_EQ(c.mesh.file_place.column, 14);
  EXPECT_EQ(c.mesh.file_place.key, "mesh.file");
  const Case abs = parse_case_string(
      "mesh: {file: /data/b.msh}\nmaterial: {model: neo-hookean, c1: 1}\n", "cases/case.yaml");
  EXPECT_EQ(*abs.mesh.file, "/data/b.msh");
}

TEST(CaseParse, YamlSpellingsOfBooleansAndNumbers) {
  const Case c = parse_case_string(test::kMinimalCase +
                                       "solver: {stability: {check: yes, branch_switch: True},\n"
                                       "         end_time: +2e0, newton: {atol: 0}}\n"
                                       "output: {deformed: off}\n",
                                   "case.yaml");
  EXPECT_TRUE(c.solver.stability.check);
  EXPECT_TRUE(c.solver.stability.branch_switch);
  EXPECT_EQ(c.solver.end_time, 2.0);
  EXPECT_EQ(c.solver.newton.atol, 0.0);
  EXPECT_FALSE(c.output.deformed);
}

TEST(CaseParse, EveryExampleAndValidationCaseParses) {
  for (const char* folder : {"/examples", "/validation"}) {
    int n = 0;
    for (const auto& entry :
         std::filesystem::directory_iterator(std::string(PLISSE_SOURCE_DIR) + folder)) {
      if (entry.path().extension() != ".yaml") continue;
      EXPECT_NO_THROW(parse_case_file(entry.path().string())) << entry.path();
      ++n;
    }
    EXPECT_GT(n, 0) << folder;
  }
}

}  // namespace
}  // namespace plisse

namespace plisse {
namespace {

/// The first ```yaml block after `heading` in docs/case-file.md.
std::string documented_example(const std::string& heading) {
  std::ifstream in(std::string(PLISSE_SOURCE_DIR) + "/docs/case-file.md");
  std::stringstream text;
  text << in.rdbuf();
  const std::string doc = text.str();
  const std::size_t at = doc.find(heading);
  const std::size_t begin = doc.find("```yaml\n", at);
  const std::size_t end = doc.find("```\n", begin + 8);
  if (at == std::string::npos || begin == std::string::npos || end == std::string::npos) return {};
  return doc.substr(begin + 8, end - begin - 8);
}

TEST(CaseParse, DocumentedCompleteExampleIsValidAgainstItsMesh) {
  const std::string example = documented_example("## Complete example");
  ASSERT_FALSE(example.empty());
  const Case c = parse_case_string(example, "docs/case-file.md");
  EXPECT_EQ(c.mesh.generate->kind, "spherical-shell");
  EXPECT_EQ(c.mesh.generate->symmetry, Symmetry::quarter);
  EXPECT_EQ(test::term_settings<DieSettings>(c, "dies", 0).ramp.start, 0.2);
  EXPECT_EQ(test::term_settings<PressureLoadSettings>(c, "loads", 0).ramp.end, 0.2);
  const Mesh mesh = load_case_mesh(c);
  EXPECT_NO_THROW(check_case_against_mesh(c, mesh));
}

}  // namespace
}  // namespace plisse
