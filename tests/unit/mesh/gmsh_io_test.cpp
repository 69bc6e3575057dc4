// Gmsh files: exact round trips (v2.2/v4.1, ASCII/binary), second-order meshes, refusal of
// non-tetrahedral meshes, missing and truncated files, orientation normalisation.
#include "mesh/gmsh_io.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/error.hpp"
#include "mesh/generate.hpp"
#include "mesh/quality.hpp"
#include "mesh_test_util.hpp"

namespace plisse {
namespace {

/// InputError message of reading `path`, or "" if it was read.
std::string read_error(const std::string& path) {
  try {
    read_gmsh(path);
  } catch (const InputError& e) {
    EXPECT_EQ(e.place().file, path);
    return e.what();
  }
  return "";
}

/// A cube mesh with overlapping tags (left = sym_x), volume tags on part of the tetrahedra, an
/// untagged triangle run, and a node used by nothing.
Mesh awkward_mesh() {
  MeshGenerationSpec spec;
  spec.kind = "cube";
  spec.edge = 1.7;
  spec.divisions = 2;
  Mesh mesh = generate_mesh(spec);
  mesh.surface_tags.erase("top");  // its triangles stay, untagged
  for (int t = 0; t < mesh.n_tets(); t += 3) mesh.volume_tags["core"].push_back(t);
  for (int t = 0; t < mesh.n_tets(); t += 2) mesh.volume_tags["even"].push_back(t);
  mesh.nodes.emplace_back(9.0, 9.0, 9.0);  // unused
  // Coordinates with all 53 bits in use, to see what survives ASCII.
  for (auto& x : mesh.nodes) x *= 1.0 / 3.0;
  return mesh;
}

void expect_same_topology(const Mesh& a, const Mesh& b) {
  ASSERT_EQ(a.n_nodes(), b.n_nodes());
  EXPECT_EQ(a.tets, b.tets);
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.tet_edge_nodes, b.tet_edge_nodes);
  EXPECT_EQ(a.triangle_edge_nodes, b.triangle_edge_nodes);
  EXPECT_EQ(a.surface_tags, b.surface_tags);
  EXPECT_EQ(a.volume_tags, b.volume_tags);
}

struct Format {
  double version;
  bool binary;
};

void PrintTo(const Format& f, std::ostream* out) {
  *out << "v" << f.version << (f.binary ? " binary" : " ASCII");
}

class GmshRoundTrip : public ::testing::TestWithParam<Format> {};

TEST_P(GmshRoundTrip, NodesElementsAndTagsComeBackIdentical) {
  const Format f = GetParam();
  const auto dir = test::scratch_dir("round_trip");
  MeshGenerationSpec shell_spec;
  shell_spec.kind = "spherical-shell";
  shell_spec.inner_radius = 5.0;
  shell_spec.element_size = 2.0;
  shell_spec.symmetry = Symmetry::quarter;
  for (const Mesh& mesh : {awkward_mesh(), generate_mesh(shell_spec)}) {
    const std::string path = (dir / "mesh.msh").string();
    write_gmsh(mesh, path, f.version, f.binary);
    GmshReadInfo info;
    const Mesh back = read_gmsh(path, info);
    expect_same_topology(mesh, back);
    EXPECT_EQ(info.n_flipped_tets, 0);
    EXPECT_EQ(info.n_flipped_triangles, 0);
    for (int i = 0; i < mesh.n_nodes(); ++i) {
      const Vec3d& x = mesh.nodes[static_cast<std::size_t>(i)];
      const Vec3d& y = back.nodes[static_cast<std::size_t>(i)];
      if (f.binary)
        EXPECT_EQ(x, y) << "node " << i;  // binary: bit for bit
      else
        EXPECT_LE((x - y).cwiseAbs().maxCoeff(), 1e-15 * x.cwiseAbs().maxCoeff())
            << "node " << i;  // %.16g
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Formats, GmshRoundTrip,
                         ::testing::Values(Format{2.2, false}, Format{2.2, true},
                                           Format{4.1, false}, Format{4.1, true}),
                         [](const auto& info) {
                           return std::string(info.param.version == 2.2 ? "v22" : "v41") +
                                  (info.param.binary ? "_binary" : "_ascii");
                         });

TEST(GmshRead, SecondOrderTetrahedraWithGmshEdgeOrder) {
  const std::string path = test::data_file("cube_order2.msh");
  const Mesh mesh = read_gmsh(path);
  ASSERT_EQ(mesh.order(), 2);
  ASSERT_EQ(mesh.tet_edge_nodes.size(), mesh.tets.size());
  ASSERT_EQ(mesh.triangle_edge_nodes.size(), mesh.triangles.size());
  // Straight-sided (Mesh.SecondOrderLinear): edge node k is the midpoint of edge k of
  // (01, 12, 20, 30, 32, 31), exactly up to round-off.
  for (std::size_t t = 0; t < mesh.tets.size(); ++t)
    for (std::size_t e = 0; e < 6; ++e) {
      const Vec3d mid = 0.5 * (mesh.nodes[mesh.tets[t][kTetEdges[e][0]]] +
                               mesh.nodes[mesh.tets[t][kTetEdges[e][1]]]);
      EXPECT_LT((mesh.nodes[mesh.tet_edge_nodes[t][e]] - mid).norm(), 1e-14)
          << "tet " << t << " edge " << e;
    }
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (std::size_t e = 0; e < 3; ++e) {
      const Vec3d mid =
          0.5 * (mesh.nodes[mesh.triangles[t][e]] + mesh.nodes[mesh.triangles[t][(e + 1) % 3]]);
      EXPECT_LT((mesh.nodes[mesh.triangle_edge_nodes[t][e]] - mid).norm(), 1e-14)
          << "triangle " << t;
    }
  // Named and unnamed physical groups.
  EXPECT_TRUE(mesh.has_surface("left"));
  EXPECT_TRUE(mesh.has_surface("top"));
  EXPECT_TRUE(mesh.has_surface("2:7"));
  EXPECT_EQ(mesh.volume_tags.at("body").size(), mesh.tets.size());
  for (int n : test::tag_nodes(mesh, "left"))
    EXPECT_NEAR(mesh.nodes[static_cast<std::size_t>(n)].x(), 0.0, 1e-15);
  for (int n : test::tag_nodes(mesh, "2:7"))
    EXPECT_NEAR(mesh.nodes[static_cast<std::size_t>(n)].x(), 1.0, 1e-15);
  EXPECT_NEAR(test::mesh_volume(mesh), 1.0, 1e-12);
  const MeshReport report = check_mesh(mesh, {"left", "top", "body"});
  EXPECT_TRUE(report.ok()) << (report.errors.empty() ? "" : report.errors.front());
  EXPECT_GT(report.min_volume, 0.0);

  // And back out as a second-order file.
  const auto dir = test::scratch_dir("order2");
  for (double version : {2.2, 4.1}) {
    const std::string out = (dir / "order2.msh").string();
    write_gmsh(mesh, out, version, true);
    expect_same_topology(mesh, read_gmsh(out));
  }
}

TEST(GmshRead, RefusesHexahedraNamingFileAndType) {
  const std::string path = test::data_file("hex_cube.msh");
  const std::string message = read_error(path);
  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_NE(message.find("Hexahedron"), std::string::npos) << message;
}

TEST(GmshRead, MissingFileNamesTheFile) {
  const std::string path = (test::scratch_dir("missing") / "no_such_mesh.msh").string();
  const std::string message = read_error(path);
  EXPECT_NE(message.find("no_such_mesh.msh"), std::string::npos) << message;
  EXPECT_NE(message.find("not found"), std::string::npos) << message;
}

TEST(GmshRead, TruncatedFilesAreInputErrors) {
  const auto dir = test::scratch_dir("truncated");
  MeshGenerationSpec spec;
  spec.kind = "cube";
  spec.divisions = 3;
  const Mesh mesh = generate_mesh(spec);
  for (const auto& f :
       {Format{4.1, false}, Format{4.1, true}, Format{2.2, false}, Format{2.2, true}}) {
    const auto full = dir / "full.msh";
    write_gmsh(mesh, full.string(), f.version, f.binary);
    const auto size = std::filesystem::file_size(full);
    for (double fraction : {0.3, 0.6, 0.9}) {
      const auto cut = dir / "cut.msh";
      std::filesystem::copy_file(full, cut, std::filesystem::copy_options::overwrite_existing);
      std::filesystem::resize_file(
          cut, static_cast<std::uintmax_t>(fraction * static_cast<double>(size)));
      const std::string message = read_error(cut.string());
      EXPECT_NE(message.find("cut.msh"), std::string::npos)
          << "v" << f.version << (f.binary ? " binary" : " ascii") << " cut at " << fraction
          << ": '" << message << "'";
    }
    // Gmsh is usable again after the failures.
    expect_same_topology(mesh, read_gmsh(full.string()));
  }
}

TEST(GmshRead, NormalisesOrientationOfTetrahedraAndBoundaryTriangles) {
  MeshGenerationSpec spec;
  spec.kind = "cube";
  spec.divisions = 2;
  const Mesh mesh = generate_mesh(spec);
  Mesh flipped = mesh;
  flip_tet(flipped, 5);
  std::swap(flipped.triangles[3][0], flipped.triangles[3][1]);
  const auto path = (test::scratch_dir("orientation") / "flipped.msh").string();
  write_gmsh(flipped, path);
  GmshReadInfo info;
  const Mesh back = read_gmsh(path, info);
  EXPECT_EQ(info.n_flipped_tets, 1);
  EXPECT_EQ(info.n_flipped_triangles, 1);
  EXPECT_GT(test::min_tet_volume(back), 0.0);
  EXPECT_EQ(back.tets, mesh.tets);
  // Triangle 3 is outward again (same cyclic order as the generator's).
  const auto& a = back.triangles[3];
  const auto& b = mesh.triangles[3];
  const std::array<int, 3> b1 = {b[1], b[2], b[0]}, b2 = {b[2], b[0], b[1]};
  EXPECT_TRUE(a == b || a == b1 || a == b2);
}

TEST(GmshWrite, RequiresMshExtension) {
  MeshGenerationSpec spec;
  spec.kind = "cube";
  spec.divisions = 1;
  const auto dir = test::scratch_dir("extension");
  EXPECT_THROW(write_gmsh(generate_mesh(spec), (dir / "cube.vtk").string()), InputError);
  EXPECT_THROW(write_gmsh(generate_mesh(spec), (dir / "no_such_dir" / "cube.msh").string()),
               InputError);
}

}  // namespace
}  // namespace plisse
