// End to end: the built `plisse mesh KIND` writes a readable mesh and prints a summary; bad options
// exit with status 2 naming the option and the rule (docs/architecture.md, "Interface contract").
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <string>

#include "mesh/gmsh_io.hpp"
#include "mesh/quality.hpp"
#include "mesh_test_util.hpp"
#include "support/run_plisse.hpp"

namespace plisse {
namespace {

using Result = plisse::test::PlisseResult;

Result run_plisse(const std::string& args) { return plisse::test::run_plisse_captured(args); }

TEST(MeshCommand, WritesShellWithSummary) {
  const std::string path = (test::scratch_dir("command") / "s.msh").string();
  const Result r = run_plisse(
      "mesh spherical-shell --inner-radius 10 --thickness 1 --layers 2 --element-size 2.5 "
      "--symmetry octant "
      "--format 2 --binary -o " +
      path);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("wrote " + path + " (Gmsh 2.2 binary)"), std::string::npos) << r.output;
  const Mesh mesh = read_gmsh(path);
  EXPECT_NE(r.output.find(std::to_string(mesh.n_tets()) + " tetrahedra"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("sym_y (" + std::to_string(mesh.surface_tags.at("sym_y").size()) +
                          " triangles)"),
            std::string::npos)
      << r.output;
  EXPECT_TRUE(check_mesh(mesh, {"inner", "outer", "sym_x", "sym_y", "sym_z"}).ok());
  // 2 layers: nodes on exactly 3 radii.
  for (const auto& x : mesh.nodes) {
    const double r_layer = 10.0 + 0.5 * std::round((x.norm() - 10.0) / 0.5);
    EXPECT_NEAR(x.norm(), r_layer, 1e-12 * r_layer);
  }
}

TEST(MeshCommand, HelpListsOptionsWithUnitsAndDefaults) {
  const Result r = run_plisse("mesh airbag --help");
  EXPECT_EQ(r.status, 0) << r.output;
  for (const char* text : {"--radius FLOAT=50", "--height FLOAT=20", "--thickness", "[mm]",
                           "--layers INT=3", "--symmetry TEXT=full", "--format INT=4", "--binary"})
    EXPECT_NE(r.output.find(text), std::string::npos) << text << "\n" << r.output;
}

TEST(MeshCommand, BadOptionsExitTwoNamingOptionAndRule) {
  const std::string path = (test::scratch_dir("command_bad") / "x.msh").string();
  Result r = run_plisse("mesh cube --divisions 0 -o " + path);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("'--divisions': must be in [1, 200] (got 0)"), std::string::npos)
      << r.output;
  r = run_plisse("mesh airbag --radius 50 --height 20 --thickness 4 -o " + path);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("'--thickness': must be < 2 (height/2)^2 / radius = 4 mm"),
            std::string::npos)
      << r.output;
  r = run_plisse("mesh spherical-shell --symmetry sixth -o " + path);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("'--symmetry': must be one of full, half, quarter, octant"),
            std::string::npos)
      << r.output;
  r = run_plisse("mesh sheet --format 3 -o " + path);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("'--format'"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace plisse
