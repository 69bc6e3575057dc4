// The model builder's judgement of the element family against the mesh order: a generated mesh
// follows `element` unless `mesh.order` says otherwise, and a mismatch is an input error placed at
// the key that caused it. Nodes within rounding of a symmetry plane are put on it.
#include "app/model_builder.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "app/wrinkling.hpp"
#include "case/case.hpp"
#include "material/fibre_reinforced.hpp"
#include "mesh/generate.hpp"
#include "mesh/gmsh_io.hpp"
#include "physics/model_term.hpp"

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

// A pressure on a tube whose rim a cap ties, without the cap in its `caps`: the cap gets no end
// thrust, said at the load's `caps` key (cavities.md, C14); naming the cap, or a cap that ties
// no rim of the surface, says nothing. Unknown cap names are refused when the model is built.
TEST(ModelBuilder, APressureThatLeavesACappedRimOpenIsWarnedAbout) {
  const auto text = [](const std::string& caps) {
    return "element: shell\n"
           "mesh: {generate: tube, radius: 10.0, length: 20.0, thickness: 0.2, element_size: 4.0}\n"
           "material: {model: neo-hookean, c1: 0.5}\n"
           "loads:\n  - {type: pressure, name: gas, surface: inner, value: 0.001" +
           caps +
           "}\n"
           "caps:\n"
           "  - {name: clamp, surface: left, displacement: [0, 0, 0], rotation: [0, 0, 0]}\n"
           "  - {name: tip, surface: right, displacement: [~, 0, 0], rotation: [0, 0, 0]}\n";
  };
  const Case open = parse_case_string(text(""), "c.yaml");
  const Mesh mesh = load_case_mesh(open);
  EXPECT_TRUE(setup_warnings(open).empty()) << "without the mesh nothing is judged";
  const auto warnings = setup_warnings(open, &mesh);
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_EQ(warnings[0].place().key, "loads[0].caps");
  EXPECT_EQ(warnings[0].place().line, 5);
  EXPECT_NE(warnings[0].rule().find("cap 'clamp' ties a rim of surface 'inner' but is not in the "
                                    "load's `caps`"),
            std::string::npos)
      << warnings[0].rule();
  EXPECT_NE(warnings[1].rule().find("cap 'tip'"), std::string::npos) << warnings[1].rule();
  const Case one = parse_case_string(text(", caps: [tip]"), "c.yaml");
  const auto left = setup_warnings(one, &mesh);
  ASSERT_EQ(left.size(), 1u);
  EXPECT_NE(left[0].rule().find("cap 'clamp'"), std::string::npos) << left[0].rule();
  EXPECT_TRUE(
      setup_warnings(parse_case_string(text(", caps: [clamp, tip]"), "c.yaml"), &mesh).empty());
  EXPECT_NO_THROW((void)build_model_parts(one, mesh));
  // The air-beam validation case loads its caps by follower tractions on their end faces.
  const Case beam = parse_case_string(
      "element: taylor-hood\n"
      "mesh: {generate: tube, radius: 10.0, length: 20.0, thickness: 0.2, layers: 1,"
      " element_size: 4.0, symmetry: half}\n"
      "material: {model: neo-hookean, c1: 0.5}\n"
      "boundary: [{type: symmetry, surface: sym_z}]\n"
      "loads:\n"
      "  - {type: pressure, name: gas, surface: inner, value: 0.004}\n"
      "  - {type: follower-traction, name: thrust, surface: right, normal: 0.098}\n"
      "caps:\n"
      "  - {name: clamp, surface: left, displacement: [0, 0, 0], rotation: [0, 0, 0]}\n"
      "  - {name: tip, surface: right, displacement: [~, 0, 0], rotation: [0, 0, 0]}\n",
      "c.yaml");
  const Mesh tube = load_case_mesh(beam);
  const auto beam_warnings = setup_warnings(beam, &tube);
  ASSERT_EQ(beam_warnings.size(), 1u) << "the tip is loaded by its traction, the clamp is not";
  EXPECT_NE(beam_warnings[0].rule().find("cap 'clamp'"), std::string::npos);
  // A name that is no cap, and a cap named twice: refused at the key, naming the caps there are.
  for (const char* bad : {", caps: [lid]", ", caps: [tip, tip]"}) {
    const Case wrong = parse_case_string(text(bad), "c.yaml");
    try {
      (void)build_model_parts(wrong, mesh);
      ADD_FAILURE() << bad << " was accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(e.place().key, "loads[0].caps") << bad;
      EXPECT_NE(e.rule().find(std::string(bad).find("lid") != std::string::npos
                                  ? "no cap is named 'lid' (caps: 'clamp', 'tip')"
                                  : "cap 'tip' is named twice"),
                std::string::npos)
          << e.rule();
    }
  }
}

// Loads far above the material's stiffness: E = 6 c1 = 1.2 MPa here, so a pressure of 1.2e5 (a
// value in Pa in a case in MPa) is 1e5 E; warned at the value's key, as are a traction and a gas's
// initial pressure past 10 E. Ten times E is the limit: 11 E is warned, 9 E not.
TEST(ModelBuilder, LoadsFarAboveTheMaterialsModulusAskAboutUnits) {
  const std::string text = kCube +
                           "boundary: [{type: fixed, surface: bottom}]\n"
                           "loads:\n"
                           "  - {type: pressure, name: p, surface: top, value: 1.2e5}\n"
                           "  - {type: pressure, name: q, surface: left, value: 10.8}\n"
                           "  - {type: traction, name: t, surface: right, traction: [0, 0, 13.2]}\n"
                           "  - {type: follower-traction, name: f, surface: front, normal: 0.5}\n";
  const auto warnings = setup_warnings(parse_case_string(text, "c.yaml"));
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_EQ(warnings[0].place().key, "loads[0].value");
  EXPECT_EQ(warnings[0].place().line, 5);
  EXPECT_NE(warnings[0].rule().find("pressure load 'p': its value 120000 is 100000 times the "
                                    "material's small-strain Young's modulus 1.2"),
            std::string::npos)
      << warnings[0].rule();
  EXPECT_NE(warnings[0].rule().find("a pressure in Pa where the material is in MPa"),
            std::string::npos);
  EXPECT_EQ(warnings[1].place().key, "loads[2].traction");
  EXPECT_NE(warnings[1].rule().find("11 times"), std::string::npos) << warnings[1].rule();
  // A stiffer region raises the limit: with E = 12 MPa nothing here but the first is too large.
  const auto stiff = setup_warnings(parse_case_string(
      text + "regions: [{box: [[0, 0, 0], [1, 1, 1]], material: {model: neo-hookean, "
             "c1: 2.0}}]\n",
      "c.yaml"));
  ASSERT_EQ(stiff.size(), 1u);
  EXPECT_EQ(stiff[0].place().key, "loads[0].value");
  // A gas's initial gauge pressure.
  const auto gas = setup_warnings(parse_case_string(
      "mesh: {generate: spherical-shell, inner_radius: 10, thickness: 1, layers: 1,"
      " element_size: 4, symmetry: octant}\n"
      "material: {model: neo-hookean, c1: 0.1}\n"
      "cavities: [{name: air, surface: inner, control: gas, initial_pressure: 100.0}]\n",
      "c.yaml"));
  ASSERT_EQ(gas.size(), 1u);
  EXPECT_EQ(gas[0].place().key, "cavities[0].initial_pressure");
}

// Lengths far below the body's: the cube's bounding box has the diagonal 2 sqrt(3) = 3.4641, so
// 1e-3 of it is 0.0034641. A pull of 0.002 (metres typed into a case meshed in millimetres), a cap
// moved 0.001, a die of radius 0.001 and a rigid region moved 1e-4 are warned at their keys; a
// pull of 0.004, a held component (0), a die's motion of 0.5 and a plane die (no radius) are not.
TEST(ModelBuilder, LengthsFarBelowTheMeshsSizeAskAboutUnits) {
  const std::string text =
      kCube +
      "boundary:\n"
      "  - {type: fixed, surface: bottom}\n"
      "  - {type: displacement, name: pull, surface: top, value: [0, ~, 0.002]}\n"
      "  - {type: displacement, name: push, surface: left, value: [0.004, 0, ~]}\n"
      "caps:\n"
      "  - {name: lid, surface: right, displacement: [0.001, 0, ~]}\n"
      "  - {name: held, surface: front, displacement: [0, 0, 0]}\n"
      "dies:\n"
      "  - {name: ball, shape: sphere, point: [1, 1, 4], radius: 0.001,\n"
      "     move: {displacement: [0, 0, -0.5]}}\n"
      "  - {name: plate, shape: plane, point: [0, 0, 3], normal: [0, 0, -1]}\n"
      "regions:\n"
      "  - {name: block, box: [[0, 0, 0], [1, 1, 1]], rigid: true, displacement: [0, 0, 1e-4]}\n";
  const Case c = parse_case_string(text, "c.yaml");
  EXPECT_TRUE(setup_warnings(c).empty()) << "without the mesh nothing is judged";
  const Mesh mesh = load_case_mesh(c);
  const auto warnings = setup_warnings(c, &mesh);
  ASSERT_EQ(warnings.size(), 4u);
  EXPECT_EQ(warnings[0].place().key, "boundary[1].value");
  EXPECT_EQ(warnings[0].place().line, 5);
  EXPECT_NE(warnings[0].rule().find("displacement condition 'pull': its largest component 0.002 "
                                    "is 0.00057735 of the mesh's size (the diagonal of its "
                                    "bounding box, 3.4641)"),
            std::string::npos)
      << warnings[0].rule();
  EXPECT_NE(warnings[0].rule().find("a length in metres in a case meshed in millimetres is 1000 "
                                    "times too small"),
            std::string::npos);
  EXPECT_EQ(warnings[1].place().key, "caps[0].displacement");
  EXPECT_NE(warnings[1].rule().find("cap 'lid': its largest displacement component 0.001"),
            std::string::npos)
      << warnings[1].rule();
  EXPECT_EQ(warnings[2].place().key, "dies[0].radius");
  EXPECT_NE(warnings[2].rule().find("die 'ball': its radius 0.001 is 0.00028867"),
            std::string::npos)
      << warnings[2].rule();
  EXPECT_EQ(warnings[3].place().key, "regions[0].displacement");
  EXPECT_NE(warnings[3].rule().find("the motion of rigid region block 0.0001"), std::string::npos)
      << warnings[3].rule();
  // The limit is 1e-3 of the size: a pull of 0.004 (0.00115 of it) and a die of radius 1 are not
  // warned about, a cap moved 0.002 (0.00058 of it) still is, a region held in place (0) is not.
  std::string larger = text;
  for (const auto& [from, to] :
       {std::pair{"0.002]", "0.004]"}, std::pair{"radius: 0.001", "radius: 1"},
        std::pair{"0.001, 0, ~", "0.002, 0, ~"}, std::pair{"1e-4]", "0]"}})
    larger.replace(larger.find(from), std::string(from).size(), to);
  const auto fewer = setup_warnings(parse_case_string(larger, "c.yaml"), &mesh);
  ASSERT_EQ(fewer.size(), 1u);
  EXPECT_EQ(fewer[0].place().key, "caps[0].displacement");
}

// The same for what moves the body without being a load: a displacement condition, a cap and a
// rigid region whose ramps act only after end_time (never applied) or end after it; a held
// component (value 0) has no ramp to speak of.
TEST(ModelBuilder, RampsOfMotionsBeyondTheEndTimeAreWarnedAboutToo) {
  const std::string text =
      kCube +
      "boundary:\n"
      "  - {type: fixed, surface: bottom}\n"
      "  - {type: displacement, name: pull, surface: top, value: [~, ~, 1], ramp: [3, 4]}\n"
      "  - {type: displacement, surface: left, value: [0, ~, ~], ramp: [3, 4]}\n"
      "caps:\n"
      "  - {name: lid, surface: right, displacement: [0.5, ~, ~], ramp: [0, 4]}\n"
      "regions:\n"
      "  - {name: block, box: [[0, 0, 0], [1, 1, 1]], rigid: true, displacement: [0, 0, 1],\n"
      "     ramp: [2.5, 3]}\n"
      "solver: {end_time: 2.0}\n";
  const auto warnings = setup_warnings(parse_case_string(text, "c.yaml"));
  ASSERT_EQ(warnings.size(), 3u);
  EXPECT_EQ(warnings[0].place().key, "boundary[1].ramp");
  EXPECT_NE(warnings[0].rule().find("displacement 'pull' starts at 3 s, not before "
                                    "solver.end_time (2 s): it is never applied"),
            std::string::npos)
      << warnings[0].rule();
  EXPECT_EQ(warnings[1].place().key, "caps[0].ramp");
  EXPECT_NE(warnings[1].rule().find("cap 'lid' ends at 4 s, after solver.end_time (2 s): the run "
                                    "ends at 50 % of it"),
            std::string::npos)
      << warnings[1].rule();
  EXPECT_EQ(warnings[2].place().key, "regions[0].ramp");
  EXPECT_NE(warnings[2].rule().find("the motion of region block starts at 2.5 s"),
            std::string::npos)
      << warnings[2].rule();
}

// A body resting under its weight on a `symmetry` plane: the plane is a mirror, whose image would
// weigh the other way; refused with the roller that supports it instead.
TEST(ModelBuilder, GravityNormalToAMirrorPlaneIsRefusedNamingTheRoller) {
  const std::string base =
      "mesh: {generate: cube, edge: 2.0, divisions: 1}\n"
      "element: mini\n"
      "material: {model: neo-hookean, c1: 0.2, density: 1.0e-9}\n"
      "loads: [{type: gravity, name: g, acceleration: [0, 0, -9810]}]\n";
  const Case mirrored =
      parse_case_string(base + "boundary: [{type: symmetry, surface: bottom}]\n", "c.yaml");
  const Mesh mesh = load_case_mesh(mirrored);
  try {
    (void)build_model_parts(mirrored, mesh);
    ADD_FAILURE() << "gravity normal to a mirror plane was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("gravity 'g' has a component along z, normal to the "
                                         "mirror plane z = 0"),
              std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("`type: displacement, value: [~, ~, 0]`"),
              std::string::npos)
        << e.what();
  }
  const Case roller = parse_case_string(
      base +
          "boundary: [{type: displacement, surface: bottom, value: [~, ~, 0]},\n"
          "           {type: symmetry, surface: left}, {type: symmetry, surface: front}]\n",
      "c.yaml");
  EXPECT_NO_THROW((void)build_model_parts(roller, load_case_mesh(roller)));
}

// Gravity on a shell (loads.md, L6s), where `element: shell` refused it before: the generated sheet
// of 20 × 10 mm, 0.5 mm thick, clamped at one end, passes the case's checks against its mesh, and
// the load's resultant is the sheet's weight ρ g A t = 1e-9 × 9810 × 200 × 0.5 = 9.81e-4 N along
// −z (in the residual, where a load enters with its sign turned), nothing across.
/// The sum over the nodes of `term`'s residual at the undeformed state, at the end of its ramp: a
/// load's resultant with its sign turned (a load enters the residual negatively).
Vec3d resultant_at_rest(ModelTerm& term, const Mesh& mesh) {
  std::vector<double> x(static_cast<std::size_t>(kValuesPerNode * mesh.n_nodes()), 0.0);
  std::vector<double> residual(x.size(), 0.0);
  term.assemble(1.0, x, residual, nullptr);
  Vec3d total = Vec3d::Zero();
  for (int v = 0; v < mesh.n_nodes(); ++v)
    for (int i = 0; i < 3; ++i) total[i] += residual[static_cast<std::size_t>(node_dof(v, i))];
  return total;
}

TEST(ModelBuilder, GravityOnAShellIsItsWeight) {
  const std::string text =
      "element: shell\n"
      "mesh: {generate: sheet, length: 20.0, width: 10.0, thickness: 0.5, element_size: 2.0}\n"
      "material: {model: neo-hookean, c1: 0.2, density: 1.0e-9}\n"
      "boundary:\n  - {type: clamped, surface: left}\n"
      "loads:\n  - {type: gravity, name: g, acceleration: [0, 0, -9810]}\n";
  const Case c = parse_case_string(text, "c.yaml");
  const Mesh mesh = load_perturbed_mesh(c);
  ASSERT_TRUE(mesh.is_shell());
  EXPECT_TRUE(unsupported_features(c, mesh).empty());
  const ModelParts parts = build_model_parts(c, mesh);
  ASSERT_EQ(parts.terms.size(), 1u);
  const Vec3d total = resultant_at_rest(*parts.terms[0], mesh);
  const double weight = 1e-9 * 9810.0 * 200.0 * 0.5;
  EXPECT_NEAR(total.z(), weight, 1e-13 * weight);  // round-off of a sum over 66 nodes
  EXPECT_EQ(total.x(), 0.0);
  EXPECT_EQ(total.y(), 0.0);
}

/// A 20 x 10 mm sheet (2 mm cells) written to `dir`/sheet.msh with two physical surfaces: `seam`,
/// the triangles with centroid y < 2, and `rest`. Returns the file's path.
std::string write_seam_sheet(const std::filesystem::path& dir) {
  MeshGenerationSpec spec;
  spec.kind = "sheet";
  spec.length = 20.0;
  spec.width = 10.0;
  spec.thickness = 0.5;
  spec.element_size = 2.0;
  Mesh sheet = generate_shell_surface(spec);
  sheet.surface_tags.clear();
  for (std::size_t t = 0; t < sheet.triangles.size(); ++t) {
    double y = 0.0;
    for (int v : sheet.triangles[t]) y += sheet.nodes[static_cast<std::size_t>(v)].y() / 3.0;
    sheet.surface_tags[y < 2.0 ? "seam" : "rest"].push_back(static_cast<int>(t));
  }
  std::filesystem::create_directories(dir);
  const std::string file = (dir / "sheet.msh").string();
  write_gmsh(sheet, file);
  return file;
}

// A shell read from a mesh file with two physical surfaces, `seam` (the triangles with centroid
// y < 2) and `rest`: the region on `seam` has its own thickness and density, so each triangle
// weighs ρ_e g A_e t_e and the gravity load sums to g (ρ_seam A_seam t_seam + ρ A_rest t), and
// every triangle of the seam, no other, has the region's thickness and material.
TEST(ModelBuilder, AShellRegionOnASurfaceTagHasItsOwnThicknessDensityAndMaterial) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("plisse-shell-region-" + std::to_string(::getpid()));
  const std::string file = write_seam_sheet(dir);
  const std::string text =
      "element: shell\n"
      "mesh: {file: " +
      file +
      ", thickness: 0.5}\n"
      "material: {model: neo-hookean, c1: 0.2, density: 1.0e-9}\n"
      "regions: [{surface: seam, thickness: 1.5, material: {model: mooney-rivlin, c1: 0.4, "
      "c2: 0.1, density: 3.0e-9}}]\n"
      "boundary:\n  - {type: clamped, surface: left}\n"
      "loads:\n  - {type: gravity, name: g, acceleration: [0, 0, -9810]}\n";
  const Case c = parse_case_string(text, "c.yaml");
  const Mesh mesh = load_perturbed_mesh(c);
  ASSERT_TRUE(mesh.is_shell());
  const std::vector<int> seam = region_elements(c.regions[0], mesh);
  EXPECT_EQ(seam.size(), mesh.surface_tags.at("seam").size());
  std::vector<bool> in_seam(mesh.triangles.size(), false);
  for (int t : seam) in_seam[static_cast<std::size_t>(t)] = true;
  double seam_area = 0.0, rest_area = 0.0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    const Vec3d X0 = mesh.nodes[static_cast<std::size_t>(tri[0])];
    const double area = 0.5 * (mesh.nodes[static_cast<std::size_t>(tri[1])] - X0)
                                  .cross(mesh.nodes[static_cast<std::size_t>(tri[2])] - X0)
                                  .norm();
    (in_seam[t] ? seam_area : rest_area) += area;
    EXPECT_EQ(mesh.triangle_thickness[t], in_seam[t] ? 1.5 : 0.5) << "triangle " << t;
  }
  EXPECT_NEAR(seam_area, 20.0 * 2.0, 1e-12);
  const ModelParts parts = build_model_parts(c, mesh);
  const ElementMaterials& m = parts.materials;
  ASSERT_EQ(m.of_element.size(), mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    EXPECT_EQ(m.of(static_cast<int>(t)), in_seam[t] ? 1 : 0) << "triangle " << t;
  ASSERT_EQ(parts.terms.size(), 1u);
  const Vec3d total = resultant_at_rest(*parts.terms[0], mesh);
  const double weight = 9810.0 * (3.0e-9 * seam_area * 1.5 + 1.0e-9 * rest_area * 0.5);
  EXPECT_NEAR(total.z(), weight, 1e-13 * weight);
  std::filesystem::remove_all(dir);
}

// An airbag's panel: a quarter disc whose rim a `displacement` condition holds on the plane
// y = 0 (the seam on the bag's mid-plane, `value: [~, 0, ~]`). A random imperfection of 0.1 t moves
// the flat panel along its normal y, but not the rim: its nodes keep y = 0 (else the cavity under
// the panel would not be closed by that plane), while the other nodes move by up to 0.1 t.
TEST(ModelBuilder, ARandomImperfectionKeepsAShellEdgeOnThePlaneADisplacementConditionHolds) {
  const std::string text =
      "element: shell\n"
      "mesh: {generate: disc, radius: 30.0, thickness: 0.2, element_size: 3.0, symmetry: quarter}\n"
      "material: {model: neo-hookean, c1: 1.0}\n"
      "boundary:\n"
      "  - {type: symmetry, surface: sym_x}\n"
      "  - {type: symmetry, surface: sym_z}\n"
      "  - {type: displacement, surface: rim, value: [~, 0, ~]}\n"
      "cavities:\n  - {name: gas, surface: inner, control: volume, volume_change: 100.0}\n"
      "solver: {stability: {imperfection: 0.1, seed: 3}}\n";
  const Case c = parse_case_string(text, "c.yaml");
  const Mesh mesh = load_perturbed_mesh(c);
  std::set<int> rim;
  for (int e : mesh.edge_tags.at("rim"))
    for (int n : mesh.edges[static_cast<std::size_t>(e)]) rim.insert(n);
  ASSERT_FALSE(rim.empty());
  double largest = 0.0;
  for (int n = 0; n < mesh.n_nodes(); ++n) {
    const double y = mesh.nodes[static_cast<std::size_t>(n)].y();
    if (rim.count(n) != 0) {
      EXPECT_EQ(y, 0.0) << "rim node " << n;
    }
    largest = std::max(largest, std::abs(y));
  }
  EXPECT_NEAR(largest, 0.1 * 0.2, 1e-12) << "the imperfection's amplitude, off the rim";
  EXPECT_EQ(build_model_parts(c, mesh).terms.empty(), false);
}

// A die on the same sheet meets the shell's face half the thickness of its candidate triangles
// from the mid-surface (z = 0.25): on the seam (1.5 mm) at z = -0.5, on the rest (0.5 mm) at 0.
// A die on one region is built, the nodes where the regions meet included (their own thickness
// is the mean of both); over both regions (no `surface`) it is refused: its offset face is one
// surface, and the thickness varies under it.
TEST(ModelBuilder, ADieOnOneShellRegionIsBuiltAndOneOverTwoThicknessesRefused) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("plisse-shell-region-die-" + std::to_string(::getpid()));
  const std::string file = write_seam_sheet(dir);
  const auto case_with_die = [&](const std::string& die) {
    return "element: shell\n"
           "mesh: {file: " +
           file +
           ", thickness: 0.5}\n"
           "material: {model: neo-hookean, c1: 0.2}\n"
           "regions: [{surface: seam, thickness: 1.5, material: {model: neo-hookean, c1: 0.2}}]\n"
           "boundary:\n  - {type: clamped, surface: left}\n"
           "loads:\n  - {type: pressure, name: p, surface: rest, value: 0.001}\n"
           "dies:\n  - " +
           die + "\n";
  };
  for (const auto& [die, ok] : std::vector<std::pair<std::string, bool>>{
           {"{name: a, shape: plane, point: [0, 0, -0.5], normal: [0, 0, 1], surface: seam}", true},
           {"{name: b, shape: plane, point: [0, 0, 0], normal: [0, 0, 1], surface: rest}", true},
           {"{name: c, shape: plane, point: [0, 0, 0], normal: [0, 0, 1]}", false}}) {
    const Case c = parse_case_string(case_with_die(die), "c.yaml");
    const Mesh mesh = load_perturbed_mesh(c);
    if (ok) {
      EXPECT_EQ(build_model_parts(c, mesh).terms.size(), 2u) << die;
    } else {
      try {
        build_model_parts(c, mesh);
        ADD_FAILURE() << "accepted: " << die;
      } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("thickness varies"), std::string::npos) << e.what();
      }
    }
  }
  std::filesystem::remove_all(dir);
}

TEST(ModelBuilder, NodesWithinRoundingOfASymmetryPlaneArePutOnIt) {
  // An octant shell whose file has one node of the plane x = 0, on the edge of the pressurised
  // inner surface, at x = 1e-16 (a CAD export's rounding). The follower pressure's tangent is
  // symmetric only with the open edge exactly on its planes; before, this node made it
  // unsymmetric and the factorisation LU.
  MeshGenerationSpec spec;
  spec.kind = "spherical-shell";
  spec.inner_radius = 10.0;
  spec.thickness = 1.0;
  spec.layers = 1;
  spec.element_size = 2.0;
  spec.symmetry = parse_symmetry("octant").value();
  spec.order = 1;
  Mesh mesh = generate_mesh(spec);
  int moved = -1;
  for (int v = 0; v < mesh.n_nodes() && moved < 0; ++v) {
    const Vec3d& x = mesh.nodes[v];
    if (x.x() == 0.0 && x.y() > 1.0 && x.z() > 1.0 && std::abs(x.norm() - 10.0) < 1e-9) moved = v;
  }
  ASSERT_GE(moved, 0);
  mesh.nodes[moved].x() = 1e-16;
  const auto dir =
      std::filesystem::temp_directory_path() / ("plisse-snap-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  write_gmsh(mesh, (dir / "shell.msh").string());
  const std::string text =
      "element: mini\nmesh: {file: shell.msh}\nmaterial: {model: neo-hookean, c1: 0.0033}\n"
      "boundary:\n  - {type: symmetry, surface: sym_x}\n  - {type: symmetry, surface: sym_y}\n"
      "  - {type: symmetry, surface: sym_z}\n"
      "loads: [{name: gas, type: pressure, surface: inner, value: 1.0e-4}]\n";
  const Case c = parse_case_string(text, (dir / "case.yaml").string());
  const Mesh loaded = load_perturbed_mesh(c);
  EXPECT_EQ(loaded.nodes[moved].x(), 0.0);  // on the plane, exactly
  const ModelParts parts = build_model_parts(c, loaded);
  ASSERT_EQ(parts.terms.size(), 1u);
  EXPECT_TRUE(parts.terms[0]->symmetric());
  // Off by more than rounding (1e-9 of the extent): not moved, and the tangent says so.
  mesh.nodes[moved].x() = 5e-8;  // within the plane check (1e-8 of the extent), beyond rounding
  write_gmsh(mesh, (dir / "shell.msh").string());
  const Mesh off = load_perturbed_mesh(c);
  EXPECT_EQ(off.nodes[moved].x(), 5e-8);
  EXPECT_FALSE(build_model_parts(c, off).terms[0]->symmetric());
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace plisse::app

namespace plisse::app {
namespace {

/// The unit fibre directions of every element of `parts` (a fibre-reinforced case).
std::vector<FibreReinforced::Fibres> element_fibres(const ModelParts& parts, const Mesh& mesh) {
  std::vector<FibreReinforced::Fibres> fibres;
  for (int e = 0; e < mesh.n_tets(); ++e)
    fibres.push_back(
        std::get<FibreReinforced>(parts.materials.materials[std::size_t(parts.materials.of(e))])
            .fibres());
  return fibres;
}

// `fibre_frame: shell` on the generated airbag (axis y; docs/theory/materials.md, F6), an oblate
// spheroid of radius a = 50 and half-height b = 10 mm: the hoop family runs around the axis and
// the meridian family lies in the element's meridional plane (to round-off); on the flat faces
// (r < 20 mm) the meridian runs along the radius within the spheroid's slope there,
// r b² / (a² y) < 0.09 rad; at the rim's equator (y < 1 mm), where the spheroid is steeper than
// 45° (y < r b² / a² = 2 mm), it runs more along the axis than along the radius.
TEST(ModelBuilder, AirbagFibresInTheShellFrameFollowItsMeridiansAndHoops) {
  const Case c = parse_case_string(
      "element: mini\n"
      "mesh: {generate: airbag, radius: 50, height: 20, thickness: 1, layers: 1,"
      " element_size: 2.5, symmetry: octant}\n"
      "material: {model: fibre-reinforced, c1: 0.1, k1: 1, k2: 0.5, a1_x: 1, a2_y: 1,"
      " fibre_frame: shell}\n",
      "airbag.yaml");
  const Mesh mesh = load_case_mesh(c);
  const ModelParts parts = build_model_parts(c, mesh);
  const std::vector<FibreReinforced::Fibres> fibres = element_fibres(parts, mesh);
  int flat = 0, rim = 0;
  for (int e = 0; e < mesh.n_tets(); ++e) {
    Vec3d X = Vec3d::Zero();
    for (int v : mesh.tets[std::size_t(e)]) X += mesh.nodes[std::size_t(v)] / 4.0;
    const Vec3d radial = Vec3d(X.x(), 0.0, X.z()).normalized();
    const Vec3d around = Vec3d::UnitY().cross(radial);
    const Vec3d meridian = fibres[std::size_t(e)].a[0], hoop = fibres[std::size_t(e)].a[1];
    ASSERT_EQ(fibres[std::size_t(e)].n, 2);
    EXPECT_NEAR(std::abs(hoop.dot(around)), 1.0, 1e-12) << "element " << e;
    EXPECT_LT(std::abs(meridian.dot(around)), 1e-12) << "element " << e;
    EXPECT_LT(std::abs(meridian.dot(hoop)), 1e-12);
    if (std::hypot(X.x(), X.z()) < 20.0) {  // the flat top and bottom
      ++flat;
      EXPECT_GT(std::abs(meridian.dot(radial)), std::cos(0.09)) << "element " << e;
    }
    if (std::abs(X.y()) < 1.0 && std::hypot(X.x(), X.z()) > 48.0) {  // the rim's equator
      ++rim;
      EXPECT_GT(std::abs(meridian.y()), std::abs(meridian.dot(radial))) << "element " << e;
    }
  }
  EXPECT_GT(flat, 10);
  EXPECT_GT(rim, 3);
}

}  // namespace
}  // namespace plisse::app

namespace plisse::app {
namespace {

// A shell's random imperfection through the case (load_perturbed_mesh; imperfections.md, I1s):
// the octant mid-surface of radius 10 mm, t = 0.2 mm, 0.05 t. Each node moves along the normal of
// the generated mid-surface (the area-weighted normal of its triangles), on a symmetry edge along
// that normal without its component across the edge's plane, and that coordinate stays exactly 0;
// the largest move is 0.05 t.
TEST(ModelBuilder, ShellRandomImperfectionKeepsTheSymmetryEdgesInTheirPlanes) {
  const std::string text =
      "element: shell\n"
      "mesh: {generate: spherical-shell, inner_radius: 9.9, thickness: 0.2, element_size: 1.5,"
      " symmetry: octant}\n"
      "material: {model: neo-hookean, c1: 0.5}\n"
      "boundary:\n  - {type: symmetry, surface: sym_x}\n  - {type: symmetry, surface: sym_y}\n"
      "  - {type: symmetry, surface: sym_z}\n"
      "loads: [{name: p, type: pressure, surface: inner, value: 0.005}]\n"
      "solver: {stability: {imperfection: 0.05, seed: 3}}\n"
      "output: {wrinkles: {axis: y, rings_deg: [45]}}\n";
  const Case c = parse_case_string(text, "c.yaml");
  const Mesh generated = load_case_mesh(c);
  const Mesh perturbed = load_perturbed_mesh(c);
  ASSERT_TRUE(perturbed.is_shell());
  ASSERT_EQ(perturbed.nodes.size(), generated.nodes.size());
  std::vector<Vec3d> normal(generated.nodes.size(), Vec3d::Zero());
  for (const auto& t : generated.triangles) {
    const Vec3d n = (generated.nodes[t[1]] - generated.nodes[t[0]])
                        .cross(generated.nodes[t[2]] - generated.nodes[t[0]]);
    for (int v : t) normal[v] += n;
  }
  std::vector<std::array<bool, 3>> held(generated.nodes.size(), {false, false, false});
  for (int axis = 0; axis < 3; ++axis)
    for (int e : generated.edge_tags.at(std::string("sym_") + "xyz"[axis]))
      for (int v : generated.edges[e]) held[v][axis] = true;
  const double a = 0.05 * 0.2;
  double largest = 0.0, tangent = 0.0;
  int on_edges = 0;
  for (std::size_t j = 0; j < generated.nodes.size(); ++j) {
    const Vec3d d = perturbed.nodes[j] - generated.nodes[j];
    largest = std::max(largest, d.norm());
    Vec3d n = normal[j];
    for (int axis = 0; axis < 3; ++axis)
      if (held[j][axis]) {
        EXPECT_EQ(generated.nodes[j][axis], 0.0);
        EXPECT_EQ(perturbed.nodes[j][axis], 0.0) << "node " << j << ", axis " << axis;
        n[axis] = 0.0;
        ++on_edges;
      }
    n.normalize();
    tangent = std::max(tangent, (d - n.dot(d) * n).norm());
  }
  EXPECT_GT(on_edges, 20);
  // The difference of two positions of size 10 mm: round-off of 10 mm, not of a.
  EXPECT_NEAR(largest, a, 1e-13);
  EXPECT_LT(tangent, 1e-13);
  // The model builds on it, and the wrinkle meter measures its reference state as flat and slack.
  EXPECT_NO_THROW(build_model_parts(c, perturbed));
  const WrinkleMeter meter(c, perturbed);
  const WrinkleMeter::Result r =
      meter.evaluate(perturbed, std::vector<Vec3d>(perturbed.nodes.size(), Vec3d::Zero()),
                     std::vector<Mat3d>(perturbed.triangles.size(), Mat3d::Zero()), {});
  EXPECT_EQ(r.tension.n_elements[static_cast<int>(MembraneState::slack)],
            static_cast<int>(perturbed.triangles.size()));
  EXPECT_EQ(r.rings.max_amplitude, 0.0);
}

}  // namespace
}  // namespace plisse::app

namespace plisse::app {
namespace {

// wrinkle_count counts waves only above the wrinkle threshold (0.1 t = 0.02 mm here),
// wrinkle_peak_count at any amplitude (docs/theory/wrinkles.md, section 7). The octant shell
// sphere of radius 10 mm moved along its normal by a cos(12 phi), phi the azimuth about y: a
// full-circle count of 12 and a peak-to-peak amplitude 2a on the ring at 30 degrees (radius 8.66
// mm, 9 elements of 0.5 mm per wave: within 5 %). 2a = 0.01 mm is below the threshold, 0.1 mm
// above it; the undeformed sphere has no wrinkle peak at all.
TEST(ModelBuilder, WrinkleCountIsZeroBelowTheThresholdWhereThePeakCountIsNot) {
  const Case c = parse_case_string(
      "element: shell\n"
      "mesh: {generate: spherical-shell, inner_radius: 9.9, thickness: 0.2, element_size: 0.5,"
      " symmetry: octant}\n"
      "material: {model: neo-hookean, c1: 0.5}\n"
      "output: {wrinkles: {axis: y, rings_deg: [30]}}\n",
      "c.yaml");
  const Mesh mesh = load_case_mesh(c);
  const WrinkleMeter meter(c, mesh);
  const std::vector<std::string> names = meter.history_columns();
  const auto value = [&](const std::vector<double>& row, const std::string& name) {
    const auto at = std::find(names.begin(), names.end(), name);
    EXPECT_NE(at, names.end()) << name;
    return at == names.end() ? -1.0 : row[std::size_t(at - names.begin())];
  };
  const std::vector<Mat3d> sigma(mesh.triangles.size(), Mat3d::Zero());
  for (const double a : {0.0, 0.005, 0.05}) {
    std::vector<Vec3d> u(mesh.nodes.size());
    for (std::size_t j = 0; j < mesh.nodes.size(); ++j) {
      const Vec3d& X = mesh.nodes[j];
      u[j] = a * std::cos(12.0 * std::atan2(X.z(), X.x())) * X.normalized();
    }
    const std::vector<double> row = meter.history_values(meter.evaluate(mesh, u, sigma, {}));
    const double amplitude = value(row, "wrinkle_amplitude");
    EXPECT_NEAR(amplitude, 2.0 * a, 0.05 * 2.0 * a) << "a = " << a;
    EXPECT_EQ(value(row, "wrinkle_peak_count"), a > 0.0 ? 12.0 : 0.0) << "a = " << a;
    EXPECT_EQ(value(row, "wrinkle_count"), 2.0 * a > 0.02 ? 12.0 : 0.0) << "a = " << a;
  }
}

// A measurement line (docs/theory/wrinkles.md, W20-W27) on a shell sheet 50 x 20 mm, t = 0.2 mm,
// moved out of its plane by a sin(2 pi 5 x / 50): 10 crests, wavelength 10 mm, height 2a, seen
// along y = 5 on 0.5 mm triangles (20 to a wave: the height within 1.2 %). wrinkle_crests counts
// them only above the threshold 0.1 t = 0.02 mm, wrinkle_peak_crests at any height; the flat
// sheet has none. Without rings the meter writes no ring columns.
TEST(ModelBuilder, LineColumnsCountCrestsOnlyAboveTheThreshold) {
  const Case c = parse_case_string(
      "element: shell\n"
      "mesh: {generate: sheet, length: 50, width: 20, thickness: 0.2, element_size: 0.5}\n"
      "material: {model: neo-hookean, c1: 0.5}\n"
      "output: {wrinkles: {surface: top,\n"
      "                    lines: [{name: across, from: [0, 5, 0.1], to: [50, 5, 0.1]}]}}\n",
      "c.yaml");
  const Mesh mesh = load_case_mesh(c);
  check_case_against_mesh(c, mesh);
  const WrinkleMeter meter(c, mesh);
  const std::vector<std::string> names = meter.history_columns();
  EXPECT_EQ(names,
            (std::vector<std::string>{"wrinkled_fraction", "slack_fraction",
                                      "wrinkle_crests:across", "wrinkle_peak_crests:across",
                                      "wrinkle_amplitude:across", "wrinkle_wavelength:across"}));
  const std::vector<Mat3d> sigma(mesh.triangles.size(), Mat3d::Zero());
  for (const double a : {0.0, 0.005, 0.05}) {
    std::vector<Vec3d> u(mesh.nodes.size());
    for (std::size_t j = 0; j < mesh.nodes.size(); ++j)
      u[j] = Vec3d(0.0, 0.0, a * std::sin(2.0 * std::numbers::pi * mesh.nodes[j].x() / 10.0));
    const WrinkleMeter::Result r = meter.evaluate(mesh, u, sigma, {});
    const std::vector<double> row = meter.history_values(r);
    ASSERT_EQ(row.size(), names.size());
    const bool above = 2.0 * a > 0.02;
    EXPECT_EQ(row[2], above ? 10.0 : 0.0) << "a = " << a;
    EXPECT_EQ(row[3], a > 0.0 ? 10.0 : 0.0) << "a = " << a;
    EXPECT_NEAR(row[4], 2.0 * a, 0.012 * 2.0 * a) << "a = " << a;
    if (a > 0.0) {
      EXPECT_NEAR(row[5], 10.0, 0.001 * 10.0) << "a = " << a;
    }
    EXPECT_EQ(r.wrinkled(), above) << "a = " << a;
    EXPECT_EQ(wrinkles_json(c, r)["lines"][0]["wrinkled"], above);
  }
}

}  // namespace
}  // namespace plisse::app
