// The checks that need the mesh: loading/generating it with errors at the case's keys, surface
// tags named by the case, planar symmetry surfaces, mesh admissibility.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "case_test_util.hpp"
#include "mesh/generate.hpp"
#include "mesh/gmsh_io.hpp"

namespace plisse {
namespace {

/// Runs check_case_against_mesh and returns its InputError (fails the test if there is none).
InputError mesh_error(const Case& c, const Mesh& mesh) {
  try {
    check_case_against_mesh(c, mesh);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "expected an InputError";
  return InputError({}, "(no error)");
}

InputError load_error(const Case& c) {
  try {
    load_case_mesh(c);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "expected an InputError";
  return InputError({}, "(no error)");
}

const std::string kCube =
    "mesh: {generate: cube, edge: 1.0, divisions: 2}\n"
    "material: {model: neo-hookean, c1: 0.1}\n";

TEST(CaseMesh, CompleteCaseMatchesItsGeneratedCube) {
  const Case c =
      parse_case_file(std::string(PLISSE_SOURCE_DIR) + "/tests/data/cases/complete.yaml");
  const Mesh mesh = load_case_mesh(c);
  EXPECT_EQ(mesh.n_tets(), 6 * 2 * 2 * 2);  // the cube generator splits each of 2^3 cells into 6
  // Every tag exists; what a cube cannot have is a wall thickness for the imperfection.
  const InputError e = mesh_error(c, mesh);
  EXPECT_NE(e.place().file.find("complete.yaml"), std::string::npos);
  EXPECT_EQ(e.place().key, "solver.stability");
  EXPECT_NE(e.rule().find("the generated cube has no wall"), std::string::npos) << e.what();
}

TEST(CaseMesh, UnknownTagNamesTheLineOfSurfaceAndListsTheTags) {
  const Case c = parse_case_string(kCube +
                                       "boundary:\n"
                                       "  - {type: fixed, surface: bottom}\n"
                                       "  - type: displacement\n"
                                       "    surface: tpo\n"
                                       "    value: [0, 0, 1]\n",
                                   "case.yaml");
  const Mesh mesh = load_case_mesh(c);
  const InputError e = mesh_error(c, mesh);
  EXPECT_INPUT_ERROR(e, "case.yaml", 6, 14, "boundary[1].surface",
                     "no surface tag 'tpo' in the generated cube mesh (did you mean 'top'?)");
  // Each generated cube face has 2 x 2 cells of 2 triangles.
  EXPECT_NE(e.rule().find("available surface tags: back (8 triangles), bottom (8 triangles)"),
            std::string::npos)
      << e.rule();
}

TEST(CaseMesh, EveryKindOfSurfaceReferenceIsChecked) {
  const std::vector<std::pair<std::string, std::string>> cases{
      {"loads: [{type: pressure, name: p, surface: inner, value: 1}]\n", "loads[0].surface"},
      {"cavities: [{name: c, surface: inner}]\n", "cavities[0].surface"},
      {"dies: [{name: d, shape: sphere, point: [0, 0, 0], radius: 1, surface: inner}]\n",
       "dies[0].surface"},
      {"dies: [{name: d, shape: sphere, point: [0, 0, 0], radius: 1, contact: sticking, region: "
       "inner}]\n",
       "dies[0].region"}};
  for (const auto& [text, key] : cases) {
    const Case c = parse_case_string(kCube + text, "case.yaml");
    const Mesh mesh = load_case_mesh(c);
    const InputError e = mesh_error(c, mesh);
    EXPECT_EQ(e.place().key, key);
    EXPECT_EQ(e.place().line, 3);
    EXPECT_NE(e.rule().find("no surface tag 'inner'"), std::string::npos) << e.rule();
  }
}

TEST(CaseMesh, EmptyTagIsRefused) {
  const Case c =
      parse_case_string(kCube + "boundary: [{type: fixed, surface: nothing}]\n", "case.yaml");
  Mesh mesh = load_case_mesh(c);
  mesh.surface_tags["nothing"] = {};
  EXPECT_INPUT_ERROR(mesh_error(c, mesh), "case.yaml", 3, 35, "boundary[0].surface",
                     "surface tag 'nothing' of the generated cube mesh has no triangles");
}

TEST(CaseMesh, SymmetrySurfacesMustBePlanar) {
  const Case c = parse_case_string(kCube +
                                       "boundary:\n"
                                       "  - {type: symmetry, surface: sym_x}\n"
                                       "  - {type: symmetry, surface: corner}\n",
                                   "case.yaml");
  Mesh mesh = load_case_mesh(c);
  // An L-shaped surface (two faces of the cube): its nodes lie up to ~0.4 mm off any plane.
  std::vector<int> corner = mesh.surface_tags.at("bottom");
  for (int t : mesh.surface_tags.at("left")) corner.push_back(t);
  mesh.surface_tags["corner"] = corner;
  EXPECT_INPUT_ERROR(mesh_error(c, mesh), "case.yaml", 5, 31, "boundary[1].surface",
                     "symmetry surface 'corner' is not planar");

  // A plane a little off-axis is still a plane: shear the cube so x = 0 becomes tilted.
  Mesh tilted = load_case_mesh(c);
  for (Vec3d& x : tilted.nodes) x.x() += 0.3 * x.z();
  const Case only_sym =
      parse_case_string(kCube + "boundary: [{type: symmetry, surface: sym_x}]\n", "c.yaml");
  EXPECT_NO_THROW(check_case_against_mesh(only_sym, tilted));
}

TEST(CaseMesh, MeshCheckErrorsNameTheMeshFile) {
  Case c = parse_case_string("mesh: {file: bad.msh}\nmaterial: {model: neo-hookean, c1: 1}\n",
                             "case.yaml");
  Mesh mesh;
  mesh.nodes = {Vec3d(0, 0, 0), Vec3d(1, 0, 0), Vec3d(0, 1, 0), Vec3d(0, 0, 1)};
  mesh.tets = {{0, 2, 1, 3}};  // negative orientation
  mesh.triangles = {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}};
  const InputError e = mesh_error(c, mesh);
  EXPECT_EQ(e.place().file, "bad.msh");
  EXPECT_EQ(e.place().line, 0);
  EXPECT_NE(e.rule().find("the mesh fails its check"), std::string::npos) << e.rule();
}

TEST(CaseMesh, MissingMeshFileIsReportedAtTheFileKey) {
  const Case c =
      parse_case_string("mesh:\n  file: meshes/none.msh\nmaterial: {model: neo-hookean, c1: 1}\n",
                        "some/dir/case.yaml");
  const InputError e = load_error(c);
  EXPECT_INPUT_ERROR(e, "some/dir/case.yaml", 2, 9, "mesh.file", "does not exist");
  EXPECT_NE(e.rule().find("some/dir/meshes/none.msh"), std::string::npos) << e.rule();
}

TEST(CaseMesh, RelativeMeshFileIsReadFromTheCaseDirectory) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::path(PLISSE_BINARY_DIR) / "test-runs" / "case_mesh_relative";
  fs::remove_all(dir);
  fs::create_directories(dir / "meshes");
  MeshGenerationSpec spec;
  spec.kind = "cube";
  spec.divisions = 1;
  write_gmsh(generate_mesh(spec), (dir / "meshes" / "cube.msh").string());
  std::ofstream(dir / "case.yaml") << "mesh: {file: meshes/cube.msh}\n"
                                      "material: {model: neo-hookean, c1: 0.1}\n"
                                      "boundary: [{type: symmetry, surface: sym_z}]\n";
  // Parsed from another working directory's point of view: the path is relative to the case.
  const Case c = parse_case_file((dir / "case.yaml").string());
  const Mesh mesh = load_case_mesh(c);
  EXPECT_EQ(mesh.n_tets(), 6);
  EXPECT_NO_THROW(check_case_against_mesh(c, mesh));
  fs::remove_all(dir);
}

TEST(CaseMesh, GeneratorErrorsArePlacedAtTheOptionOrTheMeshKey) {
  // Cross-option rule of the generator (element size larger than the shell's radius).
  const Case given = parse_case_string(
      "mesh:\n  generate: spherical-shell\n  inner_radius: 2\n  element_size: 3\n"
      "material: {model: neo-hookean, c1: 1}\n",
      "case.yaml");
  EXPECT_INPUT_ERROR(load_error(given), "case.yaml", 4, 17, "mesh.element_size", "");
  // The same rule broken by a default value: placed at `mesh:`.
  const Case defaulted = parse_case_string(
      "material: {model: neo-hookean, c1: 1}\nmesh: {generate: spherical-shell, inner_radius: "
      "0.5}\n",
      "case.yaml");
  EXPECT_INPUT_ERROR(load_error(defaulted), "case.yaml", 2, 1, "mesh.element_size", "");
}

TEST(CaseMesh, OrderKeyGeneratesASecondOrderMeshThatPassesTheChecks) {
  const Case c = parse_case_string(
      "mesh: {generate: spherical-shell, inner_radius: 10, element_size: 3, layers: 2, "
      "symmetry: octant, order: 2}\n"
      "material: {model: neo-hookean, c1: 1}\n"
      "boundary: [{type: symmetry, surface: sym_x}, {type: symmetry, surface: sym_z}]\n",
      "case.yaml");
  ASSERT_TRUE(c.mesh.generate.has_value());
  EXPECT_EQ(c.mesh.generate->order, 2);
  EXPECT_EQ(c.mesh.option_places.at("order").line, 1);
  const Mesh mesh = load_case_mesh(c);
  EXPECT_EQ(mesh.order(), 2);
  EXPECT_NO_THROW(check_case_against_mesh(c, mesh));
  // Declared range [1, 2], reported at the key.
  EXPECT_INPUT_ERROR(test::case_error("mesh: {generate: cube, order: 3}\n"
                                      "material: {model: neo-hookean, c1: 1}\n"),
                     "case.yaml", 1, 31, "mesh.order", "must be in [1, 2] (got 3)");
}

}  // namespace
}  // namespace plisse
