// Parallel VTU output (output/pvtu_writer.hpp) and reading it back (output/vtu_reader.hpp): a box
// mesh split into element sets, written as pieces + .pvtu, merged back bit for bit through
// global_node by plisse and, independently, by Python (xml.etree + meshio, fixtures/read_pvtu.py);
// then every input check and every error path of the reader (missing piece, "../" piece,
// conflicting shared nodes, missing global_node, truncated or corrupted .pvtu).
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <numeric>
#include <set>

#include "core/error.hpp"
#include "mesh/box_mesh.hpp"
#include "output/pvtu_writer.hpp"
#include "output/vtu_reader.hpp"
#include "output_test_support.hpp"
#include "support/shell_mesh.hpp"

namespace plisse {
namespace {

using test::contents;
using test::from_hex;
using test::ScratchDir;

/// Values that are not exact in decimal, so a lossy path (ASCII, Float32) would show.
double value(int i, int j) { return (i + 1) / 3.0 - 0.1 * j + 1e-7 * i * j; }

VtuField make_field(std::string name, int n_entities, int n_components, int seed) {
  VtuField f{std::move(name), n_components, {}};
  for (int i = 0; i < n_entities; ++i)
    for (int c = 0; c < n_components; ++c) f.values.push_back(value(i + seed, c));
  return f;
}

void write_bytes(const std::filesystem::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

/// A box mesh with full-mesh fields, split into pieces: element e goes to piece e % n_pieces
/// (interleaved, so most nodes are shared by several pieces); piece 1 lists its elements in
/// decreasing order (a piece keeps the order it is given).
struct Split {
  Mesh mesh;
  std::vector<Vec3d> points;  // deformed: nodes + displacement
  std::vector<VtuField> point_fields;
  std::vector<VtuField> cell_fields;
  std::vector<std::vector<int>> elements;  // per piece
  std::vector<std::string> sources;        // per piece, relative to the .pvtu

  explicit Split(Mesh m, int n_pieces = 3) : mesh(std::move(m)) {
    const int n = mesh.n_nodes(), n_tets = n_mesh_cells(mesh);
    point_fields = {make_field("displacement", n, 3, 0), make_field("p & <q>", n, 1, 5)};
    cell_fields = {make_field("von_mises", n_tets, 1, 3),
                   make_field("cauchy_stress", n_tets, 6, 7)};
    for (int v = 0; v < n; ++v)
      points.push_back(mesh.nodes[v] + Vec3d(point_fields[0].values[3 * v],
                                             point_fields[0].values[3 * v + 1],
                                             point_fields[0].values[3 * v + 2]));
    elements.resize(n_pieces);
    for (int e = 0; e < n_tets; ++e) elements[e % n_pieces].push_back(e);
    if (n_pieces > 1) std::reverse(elements[1].begin(), elements[1].end());
    for (int k = 0; k < n_pieces; ++k)
      sources.push_back("step_0001/piece_" + std::to_string(k) + ".vtu");
  }

  /// Writes the pieces (DIR/step_0001/) and DIR/step_0001.pvtu; returns the .pvtu's path.
  std::filesystem::path write(const std::filesystem::path& dir) const {
    std::filesystem::create_directories(dir / "step_0001");
    for (std::size_t k = 0; k < elements.size(); ++k)
      write_vtu_piece(dir / sources[k], mesh, points, elements[k], point_fields, cell_fields);
    const auto pvtu = dir / "step_0001.pvtu";
    write_pvtu(pvtu, sources, describe_fields(point_fields), describe_fields(cell_fields));
    return pvtu;
  }
};

Mesh box() { return make_box_mesh(Vec3d(3.0, 2.0, 1.0), {3, 2, 2}); }  // 36 nodes, 72 tets

/// `linear` with a node at the midpoint of every edge (Gmsh's edge order), i.e. a 10-node mesh.
Mesh quadratic(const Mesh& linear) {
  Mesh mesh = linear;
  std::map<std::pair<int, int>, int> midpoint;
  static constexpr std::array<std::array<int, 2>, 6> kGmshEdges = {
      {{0, 1}, {1, 2}, {2, 0}, {3, 0}, {3, 2}, {3, 1}}};
  for (const auto& tet : linear.tets) {
    std::array<int, 6> edge_nodes{};
    for (int j = 0; j < 6; ++j) {
      const int a = tet[kGmshEdges[j][0]], b = tet[kGmshEdges[j][1]];
      const auto [it, added] = midpoint.emplace(std::minmax(a, b), mesh.n_nodes());
      if (added) mesh.nodes.push_back(0.5 * (linear.nodes[a] + linear.nodes[b]));
      edge_nodes[j] = it->second;
    }
    mesh.tet_edge_nodes.push_back(edge_nodes);
  }
  return mesh;
}

/// Runs fixtures/read_pvtu.py on `pvtu` and returns its JSON (null and a test failure if the
/// script fails), as test::read_with_python does for read_output.py.
nlohmann::json read_pvtu_with_python(const std::filesystem::path& pvtu) {
  std::string argument = "'";  // appended piecewise: g++ 12 warns falsely on "'" + string
  argument += pvtu.string();
  argument += '\'';
  return test::run_python_fixture("read_pvtu.py", argument);
}

/// Flattens Python's rows of hex strings (or a flat list for scalars) to doubles.
std::vector<double> flat(const nlohmann::json& rows) {
  std::vector<double> out;
  for (const auto& row : rows) {
    if (row.is_array()) {
      for (const auto& x : row) out.push_back(from_hex(x));
    } else {
      out.push_back(from_hex(row));
    }
  }
  return out;
}

std::vector<double> iota_values(int n) {
  std::vector<double> v(n);
  for (int i = 0; i < n; ++i) v[i] = i;
  return v;
}

std::string read_error(const std::filesystem::path& path,
                       const std::string& field = "displacement") {
  try {
    read_vtu_point_field(path, field);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

std::string summary_error(const std::filesystem::path& path) {
  try {
    read_vtu_summary(path);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(Pvtu, BoxInThreePiecesMergesBackBitForBit) {
  const ScratchDir dir;
  const Split s(box());
  ASSERT_EQ(s.mesh.n_nodes(), 36);
  ASSERT_EQ(s.mesh.n_tets(), 72);
  const auto pvtu = s.write(dir.path());

  const VtuSummary summary = read_vtu_summary(pvtu);
  EXPECT_EQ(summary.n_points, 36u);
  EXPECT_EQ(summary.n_cells, 72u);  // 24 + 24 + 24: each element in one piece
  EXPECT_EQ(read_vtu_point_count(pvtu), 36u);
  ASSERT_EQ(summary.point_fields.size(), 3u);
  EXPECT_EQ(summary.point_fields[0].name, "displacement");
  EXPECT_EQ(summary.point_fields[0].n_components, 3);
  EXPECT_EQ(summary.point_fields[1].name, "p & <q>");  // escaped in the file, decoded here
  EXPECT_EQ(summary.point_fields[2].name, "global_node");
  ASSERT_EQ(summary.cell_fields.size(), 2u);
  EXPECT_EQ(summary.cell_fields[0].name, "von_mises");
  EXPECT_EQ(summary.cell_fields[1].name, "cauchy_stress");
  EXPECT_EQ(summary.cell_fields[1].n_components, 6);

  for (const VtuField& written : s.point_fields) {
    const VtuField read = read_vtu_point_field(pvtu, written.name);
    EXPECT_EQ(read.name, written.name);
    EXPECT_EQ(read.n_components, written.n_components);
    EXPECT_EQ(read.values, written.values) << written.name;  // bit-exact, global node order
  }
  EXPECT_EQ(read_vtu_point_field(pvtu, "global_node").values, iota_values(36));

  // Each piece on its own: the nodes of its elements, increasing global order.
  for (std::size_t k = 0; k < s.elements.size(); ++k) {
    std::set<int> used;
    for (const int e : s.elements[k]) used.insert(s.mesh.tets[e].begin(), s.mesh.tets[e].end());
    const auto piece = dir / s.sources[k];
    EXPECT_EQ(read_vtu_point_count(piece), used.size()) << k;
    EXPECT_EQ(read_vtu_summary(piece).n_cells, s.elements[k].size()) << k;
    const std::vector<double> global = read_vtu_point_field(piece, "global_node").values;
    EXPECT_EQ(global, std::vector<double>(used.begin(), used.end())) << k;
  }
  EXPECT_NE(read_error(pvtu, "von_mises").find("no point field 'von_mises'"), std::string::npos);
}

TEST(Pvtu, PythonReadsTheSameFilesIndependently) {
  const ScratchDir dir;
  const Split s(box());
  const auto pvtu = s.write(dir.path());
  const nlohmann::json read = read_pvtu_with_python(pvtu);
  ASSERT_FALSE(read.is_null());
  EXPECT_EQ(read["root"]["tag"], "VTKFile");
  EXPECT_EQ(read["root"]["type"], "PUnstructuredGrid");
  EXPECT_EQ(read["root"]["version"], "1.0");
  EXPECT_EQ(read["root"]["byte_order"], "LittleEndian");
  EXPECT_EQ(read["root"]["header_type"], "UInt64");
  EXPECT_EQ(read["grid"]["GhostLevel"], "0");
  using Rows = std::vector<std::vector<std::string>>;
  EXPECT_EQ(read["point_arrays"].get<Rows>(), (Rows{{"displacement", "Float64", "3"},
                                                    {"p & <q>", "Float64", "1"},
                                                    {"global_node", "Float64", "1"}}));
  EXPECT_EQ(read["cell_arrays"].get<Rows>(),
            (Rows{{"von_mises", "Float64", "1"}, {"cauchy_stress", "Float64", "6"}}));
  EXPECT_EQ(read["points_arrays"].get<Rows>(), (Rows{{"Points", "Float64", "3"}}));
  EXPECT_EQ(read["sources"].get<std::vector<std::string>>(), s.sources);

  const nlohmann::json& merged = read["merged"];
  EXPECT_EQ(merged["n_nodes"], 36);
  EXPECT_TRUE(merged["conflicts"].empty());  // shared nodes: same coordinates and values
  std::vector<double> points;
  for (const Vec3d& x : s.points) points.insert(points.end(), {x(0), x(1), x(2)});
  EXPECT_EQ(flat(merged["points"]), points);  // deformed coordinates, bit-exact
  for (const VtuField& f : s.point_fields) EXPECT_EQ(flat(merged["point_data"][f.name]), f.values);
  EXPECT_EQ(flat(merged["point_data"]["global_node"]), iota_values(36));

  // Cells: meshio's connectivity mapped through global_node gives the mesh's tetrahedra, in
  // the order each piece was given; cell fields are the full fields restricted to them.
  ASSERT_EQ(merged["cells"].size(), s.elements.size());
  for (std::size_t k = 0; k < s.elements.size(); ++k) {
    std::vector<std::array<int, 4>> expected;
    std::vector<double> von_mises;
    for (const int e : s.elements[k]) {
      expected.push_back(s.mesh.tets[e]);
      von_mises.push_back(s.cell_fields[0].values[e]);
    }
    EXPECT_EQ((merged["cells"][k].get<std::vector<std::array<int, 4>>>()), expected) << k;
    const nlohmann::json& piece = read["pieces"][k];
    EXPECT_EQ(piece["cells"][0]["type"], "tetra");
    EXPECT_EQ(flat(piece["cell_data"]["von_mises"][0]), von_mises) << k;
  }
}

TEST(Pvtu, QuadraticPiecesKeepTheirEdgeNodes) {
  const ScratchDir dir;
  const Split s(quadratic(make_box_mesh(Vec3d(1.0, 1.0, 1.0), {1, 1, 1})), 2);
  ASSERT_EQ(s.mesh.n_nodes(), 8 + 19);  // a cube cut into 6 tets has 19 edges
  const auto pvtu = s.write(dir.path());
  EXPECT_EQ(read_vtu_point_count(pvtu), 27u);
  EXPECT_EQ(read_vtu_point_field(pvtu, "displacement").values, s.point_fields[0].values);

  const nlohmann::json read = read_pvtu_with_python(pvtu);
  ASSERT_FALSE(read.is_null());
  // VTK's quadratic tetra: corners, then edges 01, 12, 20, 03, 13, 23 (Gmsh's last two swap).
  static constexpr std::array<int, 6> kGmshEdgeOfVtkEdge = {0, 1, 2, 3, 5, 4};
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_EQ(read["pieces"][k]["cells"][0]["type"], "tetra10");
    std::vector<std::vector<int>> expected;
    for (const int e : s.elements[k]) {
      std::vector<int> cell(s.mesh.tets[e].begin(), s.mesh.tets[e].end());
      for (const int j : kGmshEdgeOfVtkEdge) cell.push_back(s.mesh.tet_edge_nodes[e][j]);
      expected.push_back(cell);
    }
    EXPECT_EQ(read["merged"]["cells"][k].get<std::vector<std::vector<int>>>(), expected) << k;
  }
  EXPECT_EQ(flat(read["merged"]["point_data"]["displacement"]), s.point_fields[0].values);
}

TEST(Pvtu, ShellPiecesHoldTheTrianglesOfTheMidSurface) {
  // A shell mesh's elements are its triangles (no tetrahedra): each piece holds VTK_TRIANGLE
  // cells with their cell fields, and the serial file of the whole mesh the same. (16 triangles:
  // with 9, Debian's meshio 5.3 misreads the first piece's raw arrays, since its raw reader
  // renumbers the arrays' offsets one by one and finds the Points under a renumbered offset that
  // equals the connectivity's original one; plisse's reader reads both.)
  const ScratchDir dir;
  const Split s(test::octahedral_sphere(2.0, 0.1, 4, true), 2);
  ASSERT_EQ(s.mesh.n_tets(), 0);
  ASSERT_EQ(n_mesh_cells(s.mesh), 16);
  const auto pvtu = s.write(dir.path());
  const VtuSummary summary = read_vtu_summary(pvtu);
  EXPECT_EQ(summary.n_points, static_cast<std::uint64_t>(s.mesh.n_nodes()));
  EXPECT_EQ(summary.n_cells, 16u);
  EXPECT_EQ(read_vtu_point_field(pvtu, "displacement").values, s.point_fields[0].values);
  for (std::size_t k = 0; k < s.elements.size(); ++k) {
    const auto piece = dir / s.sources[k];
    EXPECT_EQ(read_vtu_cell_types(piece),
              std::vector<std::uint8_t>(s.elements[k].size(),
                                        static_cast<std::uint8_t>(VtkCellType::kTriangle)));
    std::vector<double> von_mises;
    for (const int e : s.elements[k]) von_mises.push_back(s.cell_fields[0].values[e]);
    EXPECT_EQ(read_vtu_cell_field(piece, "von_mises").values, von_mises) << k;
  }
  const nlohmann::json read = read_pvtu_with_python(pvtu);
  ASSERT_FALSE(read.is_null());
  for (std::size_t k = 0; k < s.elements.size(); ++k) {
    EXPECT_EQ(read["pieces"][k]["cells"][0]["type"], "triangle");
    std::vector<std::array<int, 3>> expected;
    for (const int e : s.elements[k]) expected.push_back(s.mesh.triangles[e]);
    EXPECT_EQ((read["merged"]["cells"][k].get<std::vector<std::array<int, 3>>>()), expected) << k;
  }

  const auto serial = dir / "whole.vtu";
  write_vtu(serial, s.mesh, s.points, s.point_fields, s.cell_fields);
  EXPECT_EQ(read_vtu_summary(serial).n_cells, 16u);
  EXPECT_EQ(read_vtu_cell_types(serial),
            std::vector<std::uint8_t>(16, static_cast<std::uint8_t>(VtkCellType::kTriangle)));
  EXPECT_EQ(read_vtu_cell_field(serial, "cauchy_stress").values, s.cell_fields[1].values);
}

TEST(Pvtu, EmptyPieceOfARankWithoutElements) {
  const ScratchDir dir;
  Split s(box(), 2);
  s.elements[0].clear();
  s.elements[1].resize(72);
  std::iota(s.elements[1].begin(), s.elements[1].end(), 0);
  const auto pvtu = s.write(dir.path());
  EXPECT_EQ(read_vtu_point_count(dir / s.sources[0]), 0u);
  const VtuSummary summary = read_vtu_summary(pvtu);
  EXPECT_EQ(summary.n_points, 36u);
  EXPECT_EQ(summary.n_cells, 72u);
  EXPECT_EQ(read_vtu_point_field(pvtu, "p & <q>").values, s.point_fields[1].values);
}

template <class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(Pvtu, WriterChecksItsInput) {
  const ScratchDir dir;
  const auto path = dir / "a.pvtu";
  const std::vector<VtuArrayInfo> fields = {{"u", 3}};
  const auto pvtu_error = [&](const std::vector<std::string>& pieces,
                              const std::vector<VtuArrayInfo>& point,
                              const std::vector<VtuArrayInfo>& cell = {}) {
    return error_of([&] { write_pvtu(path, pieces, point, cell); });
  };
  EXPECT_TRUE(has(pvtu_error({}, fields), "no pieces"));
  EXPECT_TRUE(has(pvtu_error({"a.vtu", "a.vtu"}, fields), "listed twice"));
  EXPECT_TRUE(has(pvtu_error({"d/a.vtu", "./d//a.vtu"}, fields), "listed twice"));
  EXPECT_TRUE(has(pvtu_error({"../a.vtu"}, fields), "'..'"));
  EXPECT_TRUE(has(pvtu_error({"p/../../a.vtu"}, fields), "'..'"));
  EXPECT_TRUE(has(pvtu_error({"/tmp/a.vtu"}, fields), "absolute"));
  EXPECT_TRUE(has(pvtu_error({""}, fields), "empty"));
  EXPECT_TRUE(has(pvtu_error({"a\\b.vtu"}, fields), "backslash"));
  EXPECT_TRUE(has(pvtu_error({"a\nb.vtu"}, fields), "control character"));
  EXPECT_TRUE(has(pvtu_error({"a.vtu"}, {{"u", 3}, {"u", 1}}), "two point fields are named 'u'"));
  EXPECT_TRUE(has(pvtu_error({"a.vtu"}, {}, {{"s", 1}, {"s", 6}}), "two cell fields"));
  EXPECT_TRUE(has(pvtu_error({"a.vtu"}, {{"u", 2}}), "must be 1, 3, 6 or 9"));
  EXPECT_TRUE(has(pvtu_error({"a.vtu"}, {{"", 1}}), "has no name"));
  EXPECT_TRUE(has(pvtu_error({"a.vtu"}, {{"global_node", 1}}), "reserved"));
  EXPECT_TRUE(has(pvtu_error({"a.vtu", "a.vtu"}, fields), "PVTU '" + path.string() + "'"));
  EXPECT_FALSE(std::filesystem::exists(path));  // nothing written on a refused input
  EXPECT_EQ(pvtu_error({"a.vtu", "sub/./b.vtu"}, {{"u", 3}, {"T", 9}}, {{"s", 6}}), "");

  const Split s(box(), 2);
  const auto piece = dir / "p.vtu";
  const auto piece_error = [&](const std::vector<int>& elements, const std::vector<VtuField>& point,
                               const std::vector<VtuField>& cell) {
    return error_of([&] { write_vtu_piece(piece, s.mesh, s.points, elements, point, cell); });
  };
  EXPECT_TRUE(has(piece_error({0, 72}, {}, {}), "element 72 outside [0, 72)"));
  EXPECT_TRUE(has(piece_error({-1}, {}, {}), "element -1 outside"));
  EXPECT_TRUE(has(piece_error({3, 5, 3}, {}, {}), "element 3 listed twice"));
  EXPECT_TRUE(has(piece_error({0}, {make_field("u", 35, 3, 0)}, {}), "full mesh"));
  EXPECT_TRUE(has(piece_error({0}, {}, {make_field("s", 36, 1, 0)}), "full mesh"));
  EXPECT_TRUE(has(piece_error({0}, {make_field("global_node", 36, 1, 0)}, {}), "reserved"));
  EXPECT_TRUE(has(piece_error({0}, {make_field("u", 36, 2, 0)}, {}), "must be 1, 3, 6 or 9"));
  EXPECT_TRUE(has(
      error_of([&] { write_vtu_piece(piece, s.mesh, std::span(s.points).first(35), {}, {}, {}); }),
      "35 points given for a mesh of 36 nodes"));
  EXPECT_FALSE(std::filesystem::exists(piece));
}

/// A good split in DIR, and a way to rewrite its .pvtu with one substitution.
struct Written {
  ScratchDir dir;
  Split split{box()};
  std::filesystem::path pvtu = split.write(dir.path());
  std::string text = contents(pvtu);

  std::filesystem::path variant(const std::string& from, const std::string& to) {
    std::string changed = text;
    const std::size_t at = changed.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) changed.replace(at, from.size(), to);
    const auto path = dir / "variant.pvtu";
    write_bytes(path, changed);
    return path;
  }
};

TEST(PvtuReader, MissingPieceNamesThePvtuAndThePiece) {
  Written w;
  std::filesystem::remove(w.dir / w.split.sources[2]);
  for (const std::string& message : {read_error(w.pvtu), summary_error(w.pvtu)}) {
    EXPECT_TRUE(has(message, "PVTU '" + w.pvtu.string() + "'")) << message;
    EXPECT_TRUE(has(message, "piece 'step_0001/piece_2.vtu'")) << message;
    EXPECT_TRUE(has(message, "no such file")) << message;
  }
}

TEST(PvtuReader, PiecesOutsideTheFolderAreRefused) {
  Written w;
  // A real file outside the folder: refused by name, not read.
  write_vtu_piece(w.dir.path().parent_path() / ("outside-" + w.dir.path().filename().string()),
                  w.split.mesh, w.split.points, w.split.elements[0], w.split.point_fields,
                  w.split.cell_fields);
  const std::string outside = "../outside-" + w.dir.path().filename().string();
  const auto up = w.variant("step_0001/piece_0.vtu", outside);
  EXPECT_TRUE(has(read_error(up), "piece '" + outside + "'")) << read_error(up);
  EXPECT_TRUE(has(read_error(up), "'..'")) << read_error(up);
  EXPECT_TRUE(
      has(read_error(w.variant("step_0001/piece_0.vtu", "step_0001/../step_0001/piece_0.vtu")),
          "'..'"));
  const auto absolute = w.variant("step_0001/piece_0.vtu", (w.dir / w.split.sources[0]).string());
  EXPECT_TRUE(has(read_error(absolute), "absolute")) << read_error(absolute);
  EXPECT_TRUE(
      has(read_error(w.variant("step_0001/piece_1.vtu", "step_0001/piece_0.vtu")), "listed twice"));
  EXPECT_TRUE(has(read_error(w.variant("step_0001/piece_1.vtu", "./step_0001//piece_0.vtu")),
                  "listed twice"));
  std::filesystem::remove(w.dir.path().parent_path() /
                          ("outside-" + w.dir.path().filename().string()));
}

TEST(PvtuReader, SharedNodesWithDifferentValuesAreRefused) {
  Written w;
  // Piece 1 rewritten from a displacement that differs in the last bit at one shared node.
  Split changed = w.split;
  const int node = changed.mesh.tets[changed.elements[1].front()][0];
  double& x = changed.point_fields[0].values[3 * node + 1];
  x = std::nextafter(x, 1e300);
  write_vtu_piece(w.dir / changed.sources[1], changed.mesh, changed.points, changed.elements[1],
                  changed.point_fields, changed.cell_fields);
  const std::string message = read_error(w.pvtu);
  EXPECT_TRUE(has(message, "node " + std::to_string(node))) << message;
  EXPECT_TRUE(has(message, "differ")) << message;
  // The other field is still consistent and reads back.
  EXPECT_EQ(read_vtu_point_field(w.pvtu, "p & <q>").values, w.split.point_fields[1].values);
}

TEST(PvtuReader, PiecesWithoutValidGlobalNodeAreRefused) {
  Written w;
  const auto piece = w.dir / w.split.sources[1];
  const Mesh one = [] {
    Mesh m;
    m.nodes = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    m.tets = {{0, 1, 2, 3}};
    return m;
  }();
  const std::vector<VtuField> cells = {make_field("von_mises", 1, 1, 0),
                                       make_field("cauchy_stress", 1, 6, 0)};
  const auto write_plain = [&](std::vector<double> global_node) {
    std::vector<VtuField> point = {make_field("displacement", 4, 3, 0),
                                   make_field("p & <q>", 4, 1, 0)};
    if (!global_node.empty()) point.push_back({"global_node", 1, std::move(global_node)});
    write_vtu(piece, one.nodes, one.tets, point, cells);
  };
  write_plain({});
  EXPECT_TRUE(has(read_error(w.pvtu), "no point field 'global_node'")) << read_error(w.pvtu);
  EXPECT_TRUE(has(summary_error(w.pvtu), "piece 'step_0001/piece_1.vtu'"));
  write_plain({0, 1, 2.5, 3});
  EXPECT_TRUE(has(read_error(w.pvtu), "not a node index")) << read_error(w.pvtu);
  write_plain({0, 1, -1, 3});
  EXPECT_TRUE(has(read_error(w.pvtu), "not a node index"));
  write_plain({0, 1, std::nan(""), 3});
  EXPECT_TRUE(has(read_error(w.pvtu), "not a node index"));
  // A huge index: refused from the point counts, nothing of that size allocated.
  write_plain({0, 1, 2, 1e15});
  EXPECT_TRUE(has(summary_error(w.pvtu), "some nodes are in no piece")) << summary_error(w.pvtu);
  // Nodes 1 and 2 in no piece (N = 4 from the largest index, 4 points in all).
  write_plain({0, 0, 3, 3});
  const auto single = w.dir / "single.pvtu";
  write_pvtu(single, {w.split.sources[1]}, describe_fields(w.split.point_fields),
             describe_fields(w.split.cell_fields));
  EXPECT_TRUE(has(summary_error(single), "node 1 of 4 is in no piece")) << summary_error(single);
  EXPECT_TRUE(has(read_error(single), "differ")) << read_error(single);  // local points 0 and 1
  write_plain({3, 2, 1, 0});
  EXPECT_EQ(read_vtu_point_count(single), 4u);
  EXPECT_EQ(read_vtu_point_field(single, "p & <q>").values,
            (std::vector<double>{value(3, 0), value(2, 0), value(1, 0), value(0, 0)}));
  // A piece without a field the .pvtu declares.
  write_vtu_piece(piece, w.split.mesh, w.split.points, w.split.elements[1],
                  {w.split.point_fields[0]}, w.split.cell_fields);
  EXPECT_TRUE(has(summary_error(w.pvtu), "no point field 'p & <q>', which the .pvtu declares"));
}

TEST(PvtuReader, MalformedPvtuFilesAreRefusedByName) {
  Written w;
  EXPECT_TRUE(has(read_error(w.variant("PUnstructuredGrid\"", "UnstructuredGrid\"")),
                  "not a PUnstructuredGrid file"));
  EXPECT_TRUE(has(read_error(w.variant("GhostLevel=\"0\"", "GhostLevel=\"1\"")), "GhostLevel"));
  EXPECT_TRUE(has(read_error(w.variant("type=\"Float64\" Name=\"displacement\"",
                                       "type=\"Float32\" Name=\"displacement\"")),
                  "Float32"));
  EXPECT_TRUE(has(read_error(w.variant("Name=\"displacement\" NumberOfComponents=\"3\"",
                                       "Name=\"displacement\" NumberOfComponents=\"1\"")),
                  "the .pvtu declares 1"));
  EXPECT_TRUE(has(read_error(w.variant("Source=", "Sauce=")), "no Source attribute"));
  EXPECT_TRUE(has(read_error(w.variant("</PPoints>", "")), "<Piece> outside <PUnstructuredGrid>"));
  EXPECT_TRUE(has(read_error(w.variant("</VTKFile>\n", "</VTKFile>\n<VTKFile>")),
                  "content after </VTKFile>"));
  EXPECT_TRUE(has(read_error(w.variant("<PPoints>", "<PPoints>x")), "text between tags"));
  EXPECT_TRUE(
      has(read_error(w.variant("<PPoints>", std::string(40, '<') + "a>")), "'<' inside a tag"));
  std::string nested;
  for (int i = 0; i < 100; ++i) nested += "<a>";
  EXPECT_TRUE(has(read_error(w.variant("<PPoints>", nested)), "nested too deeply"));
  EXPECT_TRUE(has(read_error(w.dir / "missing.pvtu"), "no such file"));
  std::filesystem::resize_file(w.variant("", ""), (16 << 20) + 1);
  EXPECT_TRUE(has(read_error(w.dir / "variant.pvtu"), "larger than 16 MiB"));
}

TEST(PvtuReader, EveryTruncationIsAnError) {
  Written w;
  const auto path = w.dir / "cut.pvtu";
  write_bytes(path, w.text);
  ASSERT_EQ(read_vtu_point_count(path), 36u);
  // Only the final newline can go: the file then still ends with </VTKFile>.
  for (std::size_t n = w.text.size() - 1; n-- > 0;) {
    std::filesystem::resize_file(path, n);
    EXPECT_NE(read_error(path), "") << "truncated to " << n << " of " << w.text.size();
  }
}

TEST(PvtuReader, SingleByteCorruptionIsReadOrRefusedNeverACrash) {
  // Each byte of the .pvtu replaced by '<', then by 0xff: the merge either succeeds with the full
  // field or throws plisse::Error.
  Written w;
  std::fstream file(w.pvtu, std::ios::in | std::ios::out | std::ios::binary);
  const auto put = [&](std::size_t at, char c) {  // in place: one byte written, then restored
    file.seekp(static_cast<std::streamoff>(at));
    file.put(c);
    file.flush();
  };
  int refused = 0;
  for (const char replacement : {'<', '\xff'}) {
    for (std::size_t i = 0; i < w.text.size(); ++i) {
      if (w.text[i] == replacement) continue;
      put(i, replacement);
      try {
        EXPECT_EQ(read_vtu_point_field(w.pvtu, "displacement").values,
                  w.split.point_fields[0].values)
            << "byte " << i;
      } catch (const Error&) {
        ++refused;
      }
      put(i, w.text[i]);
    }
  }
  ASSERT_TRUE(file.good());
  EXPECT_EQ(contents(w.pvtu), w.text);  // every byte restored
  EXPECT_GT(refused, static_cast<int>(w.text.size()));
}

}  // namespace
}  // namespace plisse
