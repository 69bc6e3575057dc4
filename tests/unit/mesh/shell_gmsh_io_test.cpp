// Shell mid-surfaces in Gmsh files: write_gmsh writes triangles and line elements with their
// physical groups of dimension 2 and 1, read_gmsh_surface reads them back identically, makes the
// orientation of a surface consistent (a flipped triangle is turned, a closed surface comes out
// outward) and refuses what a shell cannot be, naming the file and the rule.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <fstream>
#include <iterator>
#include <numbers>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "mesh/generate.hpp"
#include "mesh/gmsh_io.hpp"
#include "mesh/shell_surface.hpp"
#include "mesh_test_util.hpp"

namespace plisse {
namespace {

void write_text(const std::string& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
}

MeshGenerationSpec sphere_spec(Symmetry symmetry) {
  MeshGenerationSpec spec;
  spec.kind = "spherical-shell";
  spec.inner_radius = 9.5;
  spec.thickness = 1.0;
  spec.element_size = 2.0;
  spec.symmetry = symmetry;
  return spec;
}

/// The error read_gmsh_surface throws for `path` (empty when it reads the file).
std::string surface_refusal(const std::string& path) {
  try {
    read_gmsh_surface(path);
  } catch (const InputError& e) {
    EXPECT_EQ(e.place().file, path);
    return e.rule();
  }
  return "";
}

/// Area vector of triangle t times 2.
Vec3d normal_of(const Mesh& mesh, std::size_t t) {
  const auto& n = mesh.triangles[t];
  const Vec3d& x0 = mesh.nodes[static_cast<std::size_t>(n[0])];
  return (mesh.nodes[static_cast<std::size_t>(n[1])] - x0)
      .cross(mesh.nodes[static_cast<std::size_t>(n[2])] - x0);
}

Vec3d centroid(const Mesh& mesh, std::size_t t) {
  Vec3d c = Vec3d::Zero();
  for (int n : mesh.triangles[t]) c += mesh.nodes[static_cast<std::size_t>(n)] / 3.0;
  return c;
}

TEST(ShellGmshFiles, GeneratedSurfacesRoundTrip) {
  const auto dir = test::scratch_dir("shell_round_trip");
  MeshGenerationSpec sheet;
  sheet.kind = "sheet";
  sheet.length = 3.0;
  sheet.width = 2.0;
  sheet.element_size = 1.0;
  for (const auto& spec : {sphere_spec(Symmetry::octant), sphere_spec(Symmetry::full), sheet})
    for (const double version : {4.1, 2.2})
      for (const bool binary : {true, false}) {
        const Mesh expected = generate_shell_surface(spec);
        const std::string path = (dir / (spec.kind + to_string(spec.symmetry) +
                                         std::to_string(version) + (binary ? "b" : "a") + ".msh"))
                                     .string();
        write_gmsh(expected, path, version, binary);
        GmshReadInfo info;
        const Mesh mesh = read_gmsh_surface(path, info);
        SCOPED_TRACE(path);
        EXPECT_TRUE(mesh.tets.empty());
        EXPECT_FALSE(mesh.is_shell());  // the caller makes it a shell, with its thickness
        EXPECT_EQ(info.n_flipped_triangles, 0);
        // Gmsh's v2 writer repeats an element once per physical group it is in: every triangle
        // is in `inner` and `outer` (`bottom` and `top`), and a sheet's edge in `left` and
        // `sym_x` or `front` and `sym_y`.
        std::size_t repeated = 0;
        if (version == 2.2) {
          repeated = expected.triangles.size();
          if (expected.edge_tags.count("sym_x") && expected.edge_tags.count("left"))
            repeated +=
                expected.edge_tags.at("left").size() + expected.edge_tags.at("front").size();
        }
        EXPECT_EQ(info.n_duplicate_elements, static_cast<int>(repeated));
        EXPECT_EQ(mesh.triangles, expected.triangles);
        EXPECT_EQ(mesh.surface_tags, expected.surface_tags);
        EXPECT_EQ(mesh.edges, expected.edges);
        EXPECT_EQ(mesh.edge_tags, expected.edge_tags);
        ASSERT_EQ(mesh.n_nodes(), expected.n_nodes());
        double worst = 0.0;
        for (std::size_t i = 0; i < mesh.nodes.size(); ++i)
          worst = std::max(worst, (mesh.nodes[i] - expected.nodes[i]).cwiseAbs().maxCoeff());
        if (binary) {
          EXPECT_EQ(worst, 0.0);  // bit for bit
        } else {
          EXPECT_LT(worst, 1e-14);  // 16 significant digits of coordinates below 11 mm
        }
      }
}

TEST(ShellGmshFiles, AFlippedTriangleIsTurnedAndCurvesBecomeEdgeTags) {
  // Two triangles of the unit square, the second numbered clockwise seen from +z; the curve
  // x = 0 is the physical curve "left", an unnamed one is y = 0, and the line 2-3 is in no
  // physical curve (ignored).
  const std::string path = (test::scratch_dir("shell_flipped") / "square.msh").string();
  write_text(path,
             "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
             "$PhysicalNames\n2\n1 1 \"left\"\n2 3 \"plate\"\n$EndPhysicalNames\n"
             "$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n$EndNodes\n"
             "$Elements\n5\n"
             "1 1 2 1 1 4 1\n"
             "2 1 2 2 2 1 2\n"
             "3 1 2 0 3 2 3\n"
             "4 2 2 3 1 1 2 3\n"
             "5 2 2 3 1 1 4 3\n"
             "$EndElements\n");
  GmshReadInfo info;
  const Mesh mesh = read_gmsh_surface(path, info);
  EXPECT_EQ(info.n_flipped_triangles, 1);
  ASSERT_EQ(mesh.triangles.size(), 2u);
  EXPECT_EQ(mesh.triangles[0], (std::array<int, 3>{0, 1, 2}));  // the first keeps its orientation
  EXPECT_EQ(mesh.triangles[1], (std::array<int, 3>{0, 2, 3}));  // turned
  for (std::size_t t = 0; t < 2; ++t) EXPECT_GT(normal_of(mesh, t).z(), 0.0);
  EXPECT_EQ(mesh.surface_tags.at("plate"), (std::vector<int>{0, 1}));
  EXPECT_EQ(mesh.edges, (std::vector<std::array<int, 2>>{{3, 0}, {0, 1}}));
  EXPECT_EQ(mesh.edge_tags.at("left"), (std::vector<int>{0}));
  EXPECT_EQ(mesh.edge_tags.at("1:2"), (std::vector<int>{1}));
  EXPECT_EQ(mesh.edge_tags.size(), 2u);
  // It is a consistent surface now: make_shell_surface takes it.
  Mesh shell = mesh;
  make_shell_surface(shell, 0.1);
  EXPECT_EQ(shell.triangle_neighbours[0][1], 3);  // across side 1 (nodes 2, 0) of (0, 1, 2)
}

TEST(ShellGmshFiles, AClosedSphereComesOutOutwardWhateverItsNumbering) {
  const auto dir = test::scratch_dir("shell_outward");
  const Mesh sphere = generate_shell_surface(sphere_spec(Symmetry::full));
  const std::size_t n = sphere.triangles.size();
  // All turned inward, and every third one only: both read back outward. Two spheres in one
  // file, the second far away and inward, are two pieces, each turned outward.
  Mesh inward = sphere, mixed = sphere, pair = sphere;
  for (std::size_t t = 0; t < n; ++t) {
    std::swap(inward.triangles[t][1], inward.triangles[t][2]);
    if (t % 3 == 1) std::swap(mixed.triangles[t][1], mixed.triangles[t][2]);
  }
  const Vec3d shift(100.0, -50.0, 30.0);
  for (const auto& x : sphere.nodes) pair.nodes.push_back(x + shift);
  for (auto tri : inward.triangles) {
    for (int& v : tri) v += sphere.n_nodes();
    pair.triangles.push_back(tri);
  }
  pair.surface_tags.clear();
  pair.edge_tags.clear();
  struct Case {
    const char* name;
    const Mesh* mesh;
    int flipped;
  };
  for (const Case& c : {Case{"inward", &inward, static_cast<int>(n)},
                        Case{"mixed", &mixed, static_cast<int>((n + 1) / 3)},
                        Case{"pair", &pair, static_cast<int>(n)}}) {
    const std::string path = (dir / (std::string(c.name) + ".msh")).string();
    write_gmsh(*c.mesh, path, 4.1, true);
    GmshReadInfo info;
    const Mesh mesh = read_gmsh_surface(path, info);
    EXPECT_EQ(info.n_flipped_triangles, c.flipped) << c.name;
    double volume = 0.0;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
      const Vec3d centre = t < n ? Vec3d::Zero() : shift;
      EXPECT_GT(normal_of(mesh, t).dot(centroid(mesh, t) - centre), 0.0) << c.name << " " << t;
      volume += normal_of(mesh, t).dot(centroid(mesh, t) - centre) / 6.0;
    }
    const double pieces = c.mesh == &pair ? 2.0 : 1.0;
    EXPECT_NEAR(volume, pieces * 4.0 / 3.0 * std::numbers::pi * 1000.0, 0.05 * pieces * 4200.0)
        << c.name;
    if (c.mesh != &pair) {
      EXPECT_EQ(mesh.triangles, sphere.triangles) << c.name;
    }
  }
}

TEST(ShellGmshFiles, RefusesAMoebiusStrip) {
  // Twelve quadrilaterals about a circle of radius 3, each cut in two, the strip's width turning
  // by half a turn: the last cell joins the first with its two sides swapped.
  Mesh strip;
  const int n = 12;
  for (int k = 0; k < n; ++k) {
    const double theta = 2.0 * std::numbers::pi * k / n;
    for (const double s : {-0.5, 0.5}) {
      const double r = 3.0 + s * std::cos(0.5 * theta);
      strip.nodes.emplace_back(r * std::cos(theta), r * std::sin(theta), s * std::sin(0.5 * theta));
    }
  }
  auto node = [](int k, int j) { return 2 * k + j; };
  for (int k = 0; k < n; ++k) {
    const int a = node(k, 0), d = node(k, 1);
    const int b = k + 1 < n ? node(k + 1, 0) : node(0, 1);
    const int c = k + 1 < n ? node(k + 1, 1) : node(0, 0);
    strip.triangles.push_back({a, b, c});
    strip.triangles.push_back({a, c, d});
  }
  const std::string path = (test::scratch_dir("shell_moebius") / "strip.msh").string();
  write_gmsh(strip, path);
  EXPECT_NE(surface_refusal(path).find("the surface is not orientable"), std::string::npos)
      << surface_refusal(path);
}

TEST(ShellGmshFiles, RefusesWhatAShellCannotBe) {
  const auto dir = test::scratch_dir("shell_refused");
  // A tetrahedral mesh.
  MeshGenerationSpec cube;
  cube.kind = "cube";
  cube.divisions = 1;
  const std::string solid = (dir / "cube.msh").string();
  write_gmsh(generate_mesh(cube), solid);
  EXPECT_NE(surface_refusal(solid).find("a shell mesh is a surface: this file has 6 tetrahedra"),
            std::string::npos)
      << surface_refusal(solid);

  const std::string head = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n";
  const std::string nodes =
      "$Nodes\n6\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n5 0.5 0 0\n6 0.5 0.5 0\n$EndNodes\n";
  auto refusal_of = [&](const std::string& name, const std::string& elements) {
    const std::string path = (dir / name).string();
    write_text(path, head + nodes + "$Elements\n" + elements + "$EndElements\n");
    return surface_refusal(path);
  };
  // A 6-node triangle.
  EXPECT_NE(refusal_of("p2.msh", "1\n1 9 2 1 1 1 2 4 5 6 4\n").find("higher-order triangles"),
            std::string::npos);
  // A quadrilateral.
  std::string rule = refusal_of("quad.msh", "1\n1 3 2 1 1 1 2 3 4\n");
  EXPECT_NE(rule.find("quadrilaterals"), std::string::npos) << rule;
  EXPECT_NE(rule.find("triangulate"), std::string::npos) << rule;
  // No triangles: a line alone.
  rule = refusal_of("lines.msh", "1\n1 1 2 1 1 1 2\n");
  EXPECT_NE(rule.find("the file contains no triangles"), std::string::npos) << rule;
  // Three triangles on the edge 1-2.
  rule = refusal_of("fin.msh", "3\n1 2 2 1 1 1 2 3\n2 2 2 1 1 2 1 4\n3 2 2 1 1 1 2 6\n");
  EXPECT_NE(
      rule.find("an edge of more than two triangles, between the nodes with Gmsh tags 1 and 2"),
      std::string::npos)
      << rule;
  // A line of a physical curve off the triangles (the diagonal 1-3 of triangles 1 2 4, 2 3 4).
  rule = refusal_of("off.msh", "3\n1 2 2 1 1 1 2 4\n2 2 2 1 1 2 3 4\n3 1 2 7 1 1 3\n");
  EXPECT_NE(rule.find("line element 3 of the physical curve '1:7', between the nodes with Gmsh "
                      "tags 1 and 3, is not a side of a triangle"),
            std::string::npos)
      << rule;
  // A triangle that repeats a node.
  rule = refusal_of("repeat.msh", "1\n1 2 2 1 1 1 2 2\n");
  EXPECT_NE(rule.find("a triangle repeats a node"), std::string::npos) << rule;
  // The security checks of read_gmsh hold: a script is not run.
  const std::string script = (dir / "script.msh").string();
  write_text(script, "Point(1) = {0, 0, 0};\n");
  EXPECT_NE(surface_refusal(script).find("not a Gmsh mesh file"), std::string::npos);
}

TEST(ShellGmshFiles, ATruncatedFileIsRefusedByTheReaderProcess) {
  const auto dir = test::scratch_dir("shell_truncated");
  const std::string path = (dir / "cut.msh").string();
  write_gmsh(generate_shell_surface(sphere_spec(Symmetry::octant)), path);
  std::ifstream in(path);
  const std::string text((std::istreambuf_iterator<char>(in)), {});
  write_text(path, text.substr(0, text.size() / 2));
  const std::string rule = surface_refusal(path);
  EXPECT_FALSE(rule.empty());
}

}  // namespace
}  // namespace plisse
