// End to end: the built `plisse mesh KIND` writes a readable mesh and prints a summary; bad options
// exit with status 2 naming the option and the rule (docs/architecture.md, "Interface contract").
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <set>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "mesh/generate.hpp"
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
      "--symmetry octant --order 1 "
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

/// Element types of the blocks of an ASCII Gmsh 4.1 file's $Elements section.
std::set<int> element_types_v4_ascii(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line) && line != "$Elements") {
  }
  std::size_t n_blocks = 0, n_elements = 0, min_tag = 0, max_tag = 0;
  in >> n_blocks >> n_elements >> min_tag >> max_tag;
  std::set<int> types;
  for (std::size_t b = 0; b < n_blocks && in; ++b) {
    int dim = 0, entity = 0, type = 0;
    std::size_t count = 0;
    in >> dim >> entity >> type >> count;
    types.insert(type);
    std::getline(in, line);
    for (std::size_t e = 0; e < count; ++e) std::getline(in, line);
  }
  return types;
}

TEST(MeshCommand, WritesSecondOrderShellThatReadsBackIdentically) {
  const auto dir = test::scratch_dir("command_order2");
  MeshGenerationSpec spec;
  spec.kind = "spherical-shell";
  spec.inner_radius = 10.0;
  spec.thickness = 1.0;
  spec.layers = 2;
  spec.element_size = 2.5;
  spec.symmetry = Symmetry::octant;
  spec.order = 2;
  const Mesh expected = generate_mesh(spec);
  ASSERT_EQ(expected.order(), 2);
  const std::string options =
      "mesh spherical-shell --inner-radius 10 --thickness 1 --layers 2 --element-size 2.5 "
      "--symmetry octant --order 2 ";
  for (const bool binary : {true, false}) {
    const std::string path = (dir / (binary ? "binary.msh" : "ascii.msh")).string();
    const Result r = run_plisse(options + (binary ? "--binary " : "") + "-o " + path);
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find(std::to_string(expected.n_nodes()) + " nodes, " +
                            std::to_string(expected.n_tets()) + " tetrahedra (second order)"),
              std::string::npos)
        << r.output;
    const Mesh mesh = read_gmsh(path);
    ASSERT_EQ(mesh.order(), 2);
    EXPECT_EQ(mesh.tets, expected.tets);
    EXPECT_EQ(mesh.tet_edge_nodes, expected.tet_edge_nodes);
    EXPECT_EQ(mesh.triangles, expected.triangles);
    EXPECT_EQ(mesh.triangle_edge_nodes, expected.triangle_edge_nodes);
    EXPECT_EQ(mesh.surface_tags, expected.surface_tags);
    ASSERT_EQ(mesh.n_nodes(), expected.n_nodes());
    if (binary) {
      EXPECT_EQ(mesh.nodes, expected.nodes);  // bit for bit
    } else {
      // ASCII keeps Gmsh's 16 significant digits: coordinates below 11 mm within 1e-14 mm.
      double worst = 0.0;
      for (std::size_t i = 0; i < mesh.nodes.size(); ++i)
        worst = std::max(worst, (mesh.nodes[i] - expected.nodes[i]).cwiseAbs().maxCoeff());
      EXPECT_LT(worst, 1e-14);
      // Written as 10-node tetrahedra (Gmsh type 11) and 6-node triangles (type 9) only.
      EXPECT_EQ(element_types_v4_ascii(path), (std::set<int>{9, 11}));
    }
    EXPECT_TRUE(check_mesh(mesh, {"inner", "outer", "sym_x", "sym_y", "sym_z"}).ok());
  }
  // The option's range is declared: 3 is refused naming it.
  const Result r = run_plisse("mesh cube --order 3 -o " + (dir / "x.msh").string());
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("'--order': must be in [1, 2] (got 3)"), std::string::npos) << r.output;
}

TEST(MeshCommand, WritesAShellMidSurfaceThatReadsBack) {
  MeshGenerationSpec spec;
  spec.kind = "spherical-shell";
  spec.inner_radius = 10.0;
  spec.thickness = 1.0;
  spec.element_size = 2.5;
  spec.symmetry = Symmetry::octant;
  const Mesh expected = generate_shell_surface(spec);
  const std::string path = (test::scratch_dir("command_shell") / "mid.msh").string();
  const Result r = run_plisse(
      "mesh spherical-shell --inner-radius 10 --thickness 1 --element-size 2.5 --symmetry octant "
      "--element shell -o " +
      path);
  ASSERT_EQ(r.status, 0) << r.output;
  const auto n = [](std::size_t k) { return std::to_string(k); };
  const std::size_t n_tri = expected.triangles.size();
  const std::string line =
      "wrote " + path + " (Gmsh 4.1 ASCII): " + n(expected.nodes.size()) + " nodes, " + n(n_tri) +
      " triangles (shell mid-surface); tags: inner (" + n(n_tri) + " triangles), outer (" +
      n(n_tri) + " triangles); edge tags: sym_x (" + n(expected.edge_tags.at("sym_x").size()) +
      " edges), sym_y (" + n(expected.edge_tags.at("sym_y").size()) + " edges), sym_z (" +
      n(expected.edge_tags.at("sym_z").size()) + " edges)\n";
  EXPECT_EQ(r.output, line);
  const Mesh mesh = read_gmsh_surface(path);
  EXPECT_EQ(mesh.triangles, expected.triangles);
  EXPECT_EQ(mesh.surface_tags, expected.surface_tags);
  EXPECT_EQ(mesh.edges, expected.edges);
  EXPECT_EQ(mesh.edge_tags, expected.edge_tags);
  ASSERT_EQ(mesh.n_nodes(), expected.n_nodes());
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i)
    EXPECT_LT((mesh.nodes[i] - expected.nodes[i]).cwiseAbs().maxCoeff(), 1e-14);
  // 3-node triangles (Gmsh type 2) and 2-node lines (type 1) only.
  EXPECT_EQ(element_types_v4_ascii(path), (std::set<int>{1, 2}));
}

TEST(MeshCommand, ElementChoosesTheOrderOrTheShell) {
  const auto dir = test::scratch_dir("command_element");
  const std::string path = (dir / "e.msh").string();
  Result r = run_plisse("mesh cube --divisions 2 --element mini -o " + path);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(read_gmsh(path).order(), 1);
  r = run_plisse("mesh cube --divisions 2 --element taylor-hood -o " + path);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(read_gmsh(path).order(), 2);
  // A shell ignores layers (0 is out of the solid's range).
  r = run_plisse("mesh sheet --length 4 --width 2 --layers 0 --element shell -o " + path);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(read_gmsh_surface(path).triangles.size(), 16u);
  const std::vector<std::pair<std::string, std::string>> refused = {
      {"mesh cube --element taylor-hood --order 1",
       "'--order': --element taylor-hood needs order 2 (got 1)"},
      {"mesh tube --element shell --order 2",
       "'--order': a shell mesh is a mid-surface of linear (3-node) triangles: order must be 1 "
       "(got 2)"},
      {"mesh cube --element shell", "'--element': the cube is a solid and has no mid-surface"},
      {"mesh sheet --element beam",
       "'--element': must be one of mini, taylor-hood, shell (got 'beam')"}};
  for (const auto& [command, message] : refused) {
    r = run_plisse(command + " -o " + path);
    EXPECT_EQ(r.status, 2) << command << "\n" << r.output;
    EXPECT_NE(r.output.find(message), std::string::npos) << command << "\n" << r.output;
  }
}

TEST(MeshCommand, HelpListsOptionsWithUnitsAndDefaults) {
  const Result r = run_plisse("mesh airbag --help");
  EXPECT_EQ(r.status, 0) << r.output;
  for (const char* text :
       {"--radius FLOAT=50", "--height FLOAT=20", "--thickness", "[mm]", "--layers INT=3",
        "--symmetry TEXT=full", "--order INT=2", "--element TEXT", "--format INT=4", "--binary"})
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

TEST(MeshCommand, AKilledWriteLeavesTheEarlierFileWholeAndTheNextWriteCleansUp) {
  const std::filesystem::path dir = test::scratch_dir("command_killed");
  const std::filesystem::path path = dir / "shell.msh";
  ASSERT_EQ(run_plisse("mesh cube --divisions 2 -o " + path.string()).status, 0);
  const auto bytes = [](const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), {});
  };
  const std::string earlier = bytes(path);
  const auto temporaries = [&] {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(dir))
      if (entry.path().filename().string().rfind(".shell.msh.tmp.", 0) == 0)
        names.push_back(entry.path().filename().string());
    return names;
  };
  // A large mesh, killed as soon as its temporary file appears: inside Gmsh's write.
  const std::string exe = std::string(PLISSE_BINARY_DIR) + "/bin/plisse";
  const pid_t pid = fork();
  if (pid == 0) {
    if (!freopen("/dev/null", "w", stdout)) _exit(126);
    execl(exe.c_str(), exe.c_str(), "mesh", "spherical-shell", "--inner-radius", "10",
          "--thickness", "1", "--layers", "3", "--element-size", "0.3", "--symmetry", "octant",
          "-o", path.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (temporaries().empty() && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  kill(pid, SIGKILL);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the write ended before it could be killed";
  EXPECT_EQ(bytes(path), earlier);  // the earlier file, byte for byte
  ASSERT_EQ(temporaries().size(), 1u);
  // The next write of that name removes what the killed one left.
  ASSERT_EQ(run_plisse("mesh cube --divisions 3 -o " + path.string()).status, 0);
  EXPECT_TRUE(temporaries().empty());
  EXPECT_EQ(read_gmsh(path.string()).n_tets(), 6 * 27);
}

}  // namespace
}  // namespace plisse
