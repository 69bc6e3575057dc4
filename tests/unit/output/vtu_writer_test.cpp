#include "output/vtu_writer.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "output_test_support.hpp"

namespace plisse {
namespace {

using test::contents;
using test::entries;
using test::from_hex;
using test::read_with_python;
using test::ScratchDir;

/// Values that are not exact in decimal, so a lossy path (ASCII with few digits, Float32) fails.
double value(int i, int j) { return (i + 1) / 3.0 - 0.1 * j + 1e-7 * i * j; }

std::vector<double> field_values(int n_entities, int n_components, int seed) {
  std::vector<double> values;
  for (int i = 0; i < n_entities; ++i)
    for (int c = 0; c < n_components; ++c) values.push_back(value(i + seed, c));
  return values;
}

/// Exact comparison of meshio's array (rows of float.hex strings, or a flat list for scalars)
/// with point- or cell-major values.
void expect_same_values(const nlohmann::json& read, const VtuField& field) {
  ASSERT_TRUE(read.is_array()) << field.name;
  std::vector<double> flat;
  for (const auto& row : read) {
    if (row.is_array()) {
      EXPECT_EQ(static_cast<int>(row.size()), field.n_components) << field.name;
      for (const auto& x : row) flat.push_back(from_hex(x));
    } else {
      flat.push_back(from_hex(row));
    }
  }
  EXPECT_EQ(flat, field.values) << field.name;  // bit-exact: raw Float64
}

TEST(VtuWriter, TwoTetsWithFieldsReadBackExactlyByMeshio) {
  const ScratchDir dir;
  const std::vector<Vec3d> points = {{0.1, 0.0, 0.0},
                                     {1.0 / 3.0, 0.0, 0.0},
                                     {0.0, 1.0, 0.0},
                                     {0.0, 0.0, 1.0},
                                     {1.0, 1.0, 1.0 + 1e-12}};
  const std::vector<std::array<int, 4>> tets = {{0, 1, 2, 3}, {1, 2, 4, 3}};
  const std::vector<VtuField> point_fields = {{"displacement", 3, field_values(5, 3, 0)},
                                              {"pressure", 1, field_values(5, 1, 7)}};
  const std::vector<VtuField> cell_fields = {{"cauchy_stress", 6, field_values(2, 6, 3)},
                                             {"von_mises", 1, field_values(2, 1, 11)},
                                             {"F", 9, field_values(2, 9, 5)}};
  const auto path = dir / "step_0001.vtu";
  write_vtu(path, points, tets, point_fields, cell_fields);
  EXPECT_EQ(entries(dir.path()), std::set<std::string>{"step_0001.vtu"});

  // The format the brief fixes: XML 1.0, little endian, UInt64 headers, one raw appended block.
  const std::string text = contents(path);
  EXPECT_NE(text.find("version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\""),
            std::string::npos);
  EXPECT_NE(text.find("<AppendedData encoding=\"raw\">"), std::string::npos);
  EXPECT_EQ(text.find("<AppendedData"), text.rfind("<AppendedData"));
  EXPECT_EQ(text.find("format=\"ascii\""), std::string::npos);
  EXPECT_EQ(text.find("format=\"binary\""), std::string::npos);
  EXPECT_NE(text.find("<DataArray type=\"Int64\" Name=\"connectivity\""), std::string::npos);
  EXPECT_NE(text.find("<DataArray type=\"UInt8\" Name=\"types\""), std::string::npos);

  const nlohmann::json read = read_with_python("vtu", path);
  ASSERT_FALSE(read.is_null());
  EXPECT_EQ(read["points_dtype"], "float64");
  ASSERT_EQ(read["points"].size(), points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    for (int d = 0; d < 3; ++d) EXPECT_EQ(from_hex(read["points"][i][d]), points[i](d));
  ASSERT_EQ(read["cells"].size(), 1u);
  EXPECT_EQ(read["cells"][0]["type"], "tetra");  // VTK type 10
  EXPECT_EQ((read["cells"][0]["data"].get<std::vector<std::array<int, 4>>>()), tets);
  for (const VtuField& f : point_fields) expect_same_values(read["point_data"][f.name], f);
  for (const VtuField& f : cell_fields) {
    ASSERT_EQ(read["cell_data"][f.name].size(), 1u) << f.name;
    expect_same_values(read["cell_data"][f.name][0], f);
  }
}

TEST(VtuWriter, ZlibCompressedFileReadsBackExactlyByMeshio) {
  // VTK's compressed appended format, read by an independent reader: 50 000 points make the
  // displacement 1.2 MB, two zlib blocks of 1 MiB (the second partial).
  const ScratchDir dir;
  const int n = 50000;
  std::vector<Vec3d> points;
  for (int i = 0; i < n; ++i) points.emplace_back(value(i, 0), value(i, 1), value(i, 2));
  const std::vector<std::array<int, 4>> tets = {{0, 1, 2, 3}, {4, n - 3, n - 2, n - 1}};
  const std::vector<VtuField> point_fields = {{"displacement", 3, field_values(n, 3, 0)},
                                              {"pressure", 1, field_values(n, 1, 7)}};
  const std::vector<VtuField> cell_fields = {{"cauchy_stress", 6, field_values(2, 6, 3)}};
  const auto path = dir / "step_0001.vtu";
  write_vtu(path, points, tets, point_fields, cell_fields, VtuCompression::zlib);
  const std::string text = contents(path);
  EXPECT_NE(text.find("header_type=\"UInt64\" compressor=\"vtkZLibDataCompressor\""),
            std::string::npos);
  const nlohmann::json read = read_with_python("vtu", path);
  ASSERT_FALSE(read.is_null());
  ASSERT_EQ(read["points"].size(), points.size());
  for (std::size_t i = 0; i < points.size(); i += 997)
    for (int d = 0; d < 3; ++d) EXPECT_EQ(from_hex(read["points"][i][d]), points[i](d));
  EXPECT_EQ((read["cells"][0]["data"].get<std::vector<std::array<int, 4>>>()), tets);
  for (const VtuField& f : point_fields) expect_same_values(read["point_data"][f.name], f);
  expect_same_values(read["cell_data"]["cauchy_stress"][0], cell_fields[0]);
}

TEST(VtuWriter, QuadraticTetUsesVtkEdgeOrder) {
  const ScratchDir dir;
  // One 10-node tetrahedron with shuffled node numbers; edge nodes at edge midpoints, listed in
  // Gmsh's order 01, 12, 20, 30, 32, 31.
  Mesh mesh;
  mesh.nodes.resize(10);
  const std::array<int, 4> corners = {9, 2, 5, 0};
  const std::array<Vec3d, 4> corner_xyz = {Vec3d{0.0, 0.0, 0.0}, Vec3d{2.0, 0.1, 0.0},
                                           Vec3d{0.3, 1.7, 0.0}, Vec3d{0.2, 0.4, 1.1}};
  for (int k = 0; k < 4; ++k) mesh.nodes[corners[k]] = corner_xyz[k];
  const std::array<std::array<int, 2>, 6> gmsh_edges = {
      {{0, 1}, {1, 2}, {2, 0}, {3, 0}, {3, 2}, {3, 1}}};
  const std::array<int, 6> edge_nodes = {4, 7, 1, 8, 3, 6};
  for (int e = 0; e < 6; ++e)
    mesh.nodes[edge_nodes[e]] = 0.5 * (corner_xyz[gmsh_edges[e][0]] + corner_xyz[gmsh_edges[e][1]]);
  mesh.tets = {corners};
  mesh.tet_edge_nodes = {edge_nodes};
  ASSERT_EQ(mesh.order(), 2);

  const auto path = dir / "quadratic.vtu";
  write_vtu(path, mesh, mesh.nodes, {{"pressure", 1, field_values(10, 1, 0)}}, {});
  const nlohmann::json read = read_with_python("vtu", path);
  ASSERT_FALSE(read.is_null());
  ASSERT_EQ(read["cells"].size(), 1u);
  EXPECT_EQ(read["cells"][0]["type"], "tetra10");  // VTK type 24
  const auto cell = read["cells"][0]["data"][0].get<std::vector<int>>();
  // Gmsh's last two edges (32, 31) swap to VTK's (13, 23).
  EXPECT_EQ(cell, (std::vector<int>{9, 2, 5, 0, 4, 7, 1, 8, 6, 3}));
  // Geometric check of VTK's order: node 4 + j is the midpoint of VTK edge j.
  const std::array<std::array<int, 2>, 6> vtk_edges = {
      {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}}};
  const auto xyz = [&](int node) {
    return Vec3d(from_hex(read["points"][node][0]), from_hex(read["points"][node][1]),
                 from_hex(read["points"][node][2]));
  };
  for (int j = 0; j < 6; ++j) {
    const Vec3d midpoint = 0.5 * (xyz(cell[vtk_edges[j][0]]) + xyz(cell[vtk_edges[j][1]]));
    EXPECT_EQ(xyz(cell[4 + j]), midpoint) << "VTK edge " << j;
  }
}

TEST(VtuWriter, LinearMeshAndTriangleSurfaceGiveTheirCellTypes) {
  const ScratchDir dir;
  Mesh mesh;
  mesh.nodes = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  mesh.tets = {{0, 1, 2, 3}};
  mesh.triangles = {{0, 2, 1}, {0, 1, 3}};
  std::vector<Vec3d> deformed = mesh.nodes;
  deformed[3] = {0.0, 0.0, 1.25};
  const VtuField J{"J", 1, {1.25}};
  const VtuField deviation{"normal_deviation", 1, {0.0, -0.5, 0.25, 1e-3}};
  const VtuField state{"wrinkle_state", 1, {0.0, 2.0}};
  write_vtu(dir / "volume.vtu", mesh, deformed, {}, {J});
  write_vtu(dir / "surface.vtu", mesh.nodes, mesh.triangles, {deviation}, {state});

  const nlohmann::json volume = read_with_python("vtu", dir / "volume.vtu");
  ASSERT_FALSE(volume.is_null());
  EXPECT_EQ(volume["cells"][0]["type"], "tetra");
  EXPECT_EQ(from_hex(volume["points"][3][2]), 1.25);  // the caller's (deformed) coordinates
  expect_same_values(volume["cell_data"]["J"][0], J);

  const nlohmann::json surface = read_with_python("vtu", dir / "surface.vtu");
  ASSERT_FALSE(surface.is_null());
  EXPECT_EQ(surface["cells"][0]["type"], "triangle");  // VTK type 5
  EXPECT_EQ((surface["cells"][0]["data"].get<std::vector<std::array<int, 3>>>()), mesh.triangles);
  expect_same_values(surface["point_data"]["normal_deviation"], deviation);
  expect_same_values(surface["cell_data"]["wrinkle_state"][0], state);
}

TEST(VtuWriter, FieldBuildersUseVtkComponentOrder) {
  const ScratchDir dir;
  const std::vector<Vec3d> points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  Mat3d sigma;  // symmetric, every entry distinct
  sigma << 11, 12, 13, 12, 22, 23, 13, 23, 33;
  Mat3d F;
  F << 1.1, 0.2, 0.3, 0.4, 1.5, 0.6, 0.7, 0.8, 1.9;
  const std::vector<Mat3d> stresses = {sigma}, gradients = {F};
  const std::vector<double> J = {F.determinant()};
  write_vtu(dir / "a.vtu", points, std::vector<std::array<int, 4>>{{0, 1, 2, 3}},
            {make_vector_field("displacement", points)},
            {make_symmetric_tensor_field("cauchy_stress", stresses),
             make_tensor_field("F", gradients), make_scalar_field("J", J)});
  const nlohmann::json read = read_with_python("vtu", dir / "a.vtu");
  ASSERT_FALSE(read.is_null());
  const auto row = [](const nlohmann::json& values) {
    std::vector<double> out;
    for (const auto& x : values) out.push_back(from_hex(x));
    return out;
  };
  EXPECT_EQ(row(read["cell_data"]["cauchy_stress"][0][0]),
            (std::vector<double>{11, 22, 33, 12, 23, 13}));  // xx, yy, zz, xy, yz, xz
  EXPECT_EQ(row(read["cell_data"]["F"][0][0]),
            (std::vector<double>{1.1, 0.2, 0.3, 0.4, 1.5, 0.6, 0.7, 0.8, 1.9}));  // row-major
  EXPECT_EQ(row(read["cell_data"]["J"][0][0]), J);
  EXPECT_EQ(row(read["point_data"]["displacement"][3]), (std::vector<double>{0, 0, 1}));
}

TEST(VtuWriter, FieldNamesWithXmlCharactersAreEscaped) {
  const ScratchDir dir;
  const std::vector<Vec3d> points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const std::string name = "force<y> & \"punch\"";
  const VtuField field{name, 1, {1.0, 2.0, 3.0}};
  write_vtu(dir / "a.vtu", points, std::vector<std::array<int, 3>>{{0, 1, 2}}, {field}, {});
  const nlohmann::json read = read_with_python("vtu", dir / "a.vtu");
  ASSERT_FALSE(read.is_null());
  ASSERT_TRUE(read["point_data"].contains(name));
  expect_same_values(read["point_data"][name], field);
}

TEST(VtuWriter, InconsistentInputThrowsAndWritesNothing) {
  const ScratchDir dir;
  const std::vector<Vec3d> points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const std::vector<std::array<int, 4>> tets = {{0, 1, 2, 3}};
  const auto path = dir / "bad.vtu";
  const auto message_of = [&](const std::vector<VtuField>& point_fields,
                              const std::vector<VtuField>& cell_fields,
                              const std::vector<std::array<int, 4>>& cells) -> std::string {
    try {
      write_vtu(path, points, cells, point_fields, cell_fields);
    } catch (const Error& e) {
      return e.what();
    }
    return "no exception";
  };
  EXPECT_NE(message_of({{"displacement", 3, std::vector<double>(11)}}, {}, tets)
                .find("'displacement' has 11 values; expected 4 points x 3 components = 12"),
            std::string::npos);
  EXPECT_NE(
      message_of({}, {{"stress", 2, std::vector<double>(2)}}, tets).find("must be 1, 3, 6 or 9"),
      std::string::npos);
  EXPECT_NE(message_of({}, {}, {{0, 1, 2, 4}}).find("refers to node 4, outside [0, 4)"),
            std::string::npos);
  EXPECT_NE(
      message_of({{"p", 1, std::vector<double>(4)}, {"p", 1, std::vector<double>(4)}}, {}, tets)
          .find("two point fields are named 'p'"),
      std::string::npos);
  Mesh mesh;
  mesh.nodes = points;
  mesh.tets = tets;
  EXPECT_THROW(write_vtu(path, mesh, std::vector<Vec3d>(3), {}, {}), Error);
  EXPECT_THROW(write_vtu(path, points, VtkCellType::kTetra, std::vector<int>{0, 1, 2}, {}, {}),
               Error);
  EXPECT_TRUE(entries(dir.path()).empty());
}

}  // namespace
}  // namespace plisse
