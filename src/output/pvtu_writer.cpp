#include "output/pvtu_writer.hpp"

#include <algorithm>
#include <set>
#include <utility>

#include "core/error.hpp"
#include "output/atomic_file.hpp"

namespace plisse {
namespace {

bool is_control(char c) { return static_cast<unsigned char>(c) < 0x20 || c == '\x7f'; }

void check_declared_fields(const std::filesystem::path& path,
                           const std::vector<VtuArrayInfo>& fields, const char* kind) {
  std::set<std::string> names;
  for (const VtuArrayInfo& f : fields) {
    PLISSE_CHECK(!f.name.empty(),
                 "PVTU '" << path.string() << "': a " << kind << " field has no name");
    PLISSE_CHECK(std::none_of(f.name.begin(), f.name.end(), is_control),
                 "PVTU '" << path.string() << "': " << kind << " field name '" << f.name
                          << "' contains a control character");
    PLISSE_CHECK(names.insert(f.name).second, "PVTU '" << path.string() << "': two " << kind
                                                       << " fields are named '" << f.name << "'");
    PLISSE_CHECK(
        f.n_components == 1 || f.n_components == 3 || f.n_components == 6 || f.n_components == 9,
        "PVTU '" << path.string() << "': " << kind << " field '" << f.name << "' has "
                 << f.n_components << " components; must be 1, 3, 6 or 9");
  }
}

void declare(std::string& xml, const VtuArrayInfo& f) {
  xml += "      <PDataArray type=\"Float64\" Name=\"" + escape_xml(f.name) +
         "\" NumberOfComponents=\"" + std::to_string(f.n_components) + "\"/>\n";
}

}  // namespace

std::vector<VtuArrayInfo> describe_fields(const std::vector<VtuField>& fields) {
  std::vector<VtuArrayInfo> out;
  out.reserve(fields.size());
  for (const VtuField& f : fields) out.push_back({f.name, f.n_components});
  return out;
}

std::string pvtu_piece_source_problem(std::string_view source) {
  if (source.empty()) return "the piece name is empty";
  if (std::any_of(source.begin(), source.end(), is_control))
    return "the piece name contains a control character";
  if (source.find('\\') != std::string_view::npos)
    return "the piece name contains a backslash (use '/')";
  const std::filesystem::path p{std::string(source)};
  if (p.has_root_name() || p.has_root_directory())
    return "the piece name is an absolute path (must be relative to the .pvtu's folder)";
  for (const auto& component : p)
    if (component == "..")
      return "the piece name has a '..' component (pieces must lie in the .pvtu's folder or "
             "below)";
  return "";
}

void write_pvtu(const std::filesystem::path& path, const std::vector<std::string>& piece_files,
                const std::vector<VtuArrayInfo>& point_fields,
                const std::vector<VtuArrayInfo>& cell_fields) {
  PLISSE_CHECK(!piece_files.empty(), "PVTU '" << path.string() << "': no pieces to list");
  std::set<std::string> sources;  // lexically normal: "a.vtu" and "./a.vtu" are one piece
  for (const std::string& piece : piece_files) {
    const std::string problem = pvtu_piece_source_problem(piece);
    PLISSE_CHECK(problem.empty(),
                 "PVTU '" << path.string() << "': piece '" << piece << "': " << problem);
    PLISSE_CHECK(
        sources.insert(std::filesystem::path(piece).lexically_normal().generic_string()).second,
        "PVTU '" << path.string() << "': piece '" << piece << "' is listed twice");
  }
  check_declared_fields(path, point_fields, "point");
  check_declared_fields(path, cell_fields, "cell");
  for (const VtuArrayInfo& f : point_fields)
    PLISSE_CHECK(f.name != kGlobalNodeField,
                 "PVTU '" << path.string() << "': the point field name '" << kGlobalNodeField
                          << "' is reserved (added to every piece)");

  std::string xml;
  xml += "<?xml version=\"1.0\"?>\n";
  xml += kUnitsComment;
  xml +=
      "<VTKFile type=\"PUnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
      "header_type=\"UInt64\">\n";
  xml += "  <PUnstructuredGrid GhostLevel=\"0\">\n";
  xml += "    <PPointData>\n";
  for (const VtuArrayInfo& f : point_fields) declare(xml, f);
  declare(xml, {std::string(kGlobalNodeField), 1});
  xml += "    </PPointData>\n";
  xml += "    <PCellData>\n";
  for (const VtuArrayInfo& f : cell_fields) declare(xml, f);
  xml += "    </PCellData>\n";
  xml += "    <PPoints>\n";
  declare(xml, {"Points", 3});
  xml += "    </PPoints>\n";
  for (const std::string& piece : piece_files)
    xml += "    <Piece Source=\"" + escape_xml(piece) + "\"/>\n";
  xml += "  </PUnstructuredGrid>\n";
  xml += "</VTKFile>\n";
  write_file_atomically(path, xml);
}

void write_vtu_piece(const std::filesystem::path& path, const Mesh& mesh,
                     std::span<const Vec3d> points, std::span<const int> elements,
                     const std::vector<VtuField>& point_fields,
                     const std::vector<VtuField>& cell_fields, VtuCompression compression) {
  const auto n_nodes = static_cast<std::size_t>(mesh.n_nodes());
  // The elements: the tetrahedra, or the triangles of a shell's mid-surface (write_vtu's cells).
  const bool shell = mesh.is_shell();
  const auto n_cells = static_cast<std::size_t>(n_mesh_cells(mesh));
  const bool quadratic = !shell && mesh.order() == 2;
  const auto n_tets = static_cast<std::size_t>(mesh.n_tets());
  PLISSE_CHECK(points.size() == n_nodes, "VTU piece '" << path.string() << "': " << points.size()
                                                       << " points given for a mesh of " << n_nodes
                                                       << " nodes");
  PLISSE_CHECK(!quadratic || mesh.tet_edge_nodes.size() == n_tets,
               "VTU piece '" << path.string() << "': mesh has " << n_tets << " tetrahedra but "
                             << mesh.tet_edge_nodes.size() << " edge-node lists");
  // Full-mesh sizes first: the restriction below indexes them.
  const auto check_full = [&](const std::vector<VtuField>& fields, std::size_t n_entities,
                              const char* kind) {
    for (const VtuField& f : fields) {
      PLISSE_CHECK(f.n_components >= 1, "VTU piece '" << path.string() << "': " << kind
                                                      << " field '" << f.name << "' has "
                                                      << f.n_components << " components");
      PLISSE_CHECK(f.values.size() == n_entities * static_cast<std::size_t>(f.n_components),
                   "VTU piece '" << path.string() << "': " << kind << " field '" << f.name
                                 << "' has " << f.values.size() << " values; expected "
                                 << n_entities << " " << kind << "s x " << f.n_components
                                 << " components of the full mesh");
    }
  };
  check_full(point_fields, n_nodes, "point");
  check_full(cell_fields, n_cells, "cell");
  for (const VtuField& f : point_fields)
    PLISSE_CHECK(f.name != kGlobalNodeField,
                 "VTU piece '" << path.string() << "': the point field name '" << kGlobalNodeField
                               << "' is reserved (added to every piece)");

  // Nodes used by the piece, and their local numbers in increasing global order.
  std::vector<char> element_seen(n_cells, 0);
  std::vector<int> local_of(n_nodes, -1);
  for (const int e : elements) {
    PLISSE_CHECK(
        e >= 0 && static_cast<std::size_t>(e) < n_cells,
        "VTU piece '" << path.string() << "': element " << e << " outside [0, " << n_cells << ")");
    PLISSE_CHECK(!element_seen[e],
                 "VTU piece '" << path.string() << "': element " << e << " listed twice");
    element_seen[e] = 1;
    const auto mark = [&](int node) {
      PLISSE_CHECK(node >= 0 && static_cast<std::size_t>(node) < n_nodes,
                   "VTU piece '" << path.string() << "': element " << e << " refers to node "
                                 << node << ", outside [0, " << n_nodes << ")");
      local_of[node] = 0;
    };
    if (shell)
      for (const int node : mesh.triangles[e]) mark(node);
    else
      for (const int node : mesh.tets[e]) mark(node);
    if (quadratic)
      for (const int node : mesh.tet_edge_nodes[e]) mark(node);
  }
  std::vector<int> global_of;  // local -> global, increasing
  for (std::size_t g = 0; g < n_nodes; ++g)
    if (local_of[g] == 0) {
      local_of[g] = static_cast<int>(global_of.size());
      global_of.push_back(static_cast<int>(g));
    }

  Mesh piece;
  piece.nodes.reserve(global_of.size());
  for (const int g : global_of) piece.nodes.push_back(points[g]);
  if (shell) {
    piece.triangles.reserve(elements.size());
    for (const int e : elements) {
      std::array<int, 3> corners{};
      for (int k = 0; k < 3; ++k) corners[k] = local_of[mesh.triangles[e][k]];
      piece.triangles.push_back(corners);
    }
  } else {
    piece.tets.reserve(elements.size());
    for (const int e : elements) {
      std::array<int, 4> corners{};
      for (int k = 0; k < 4; ++k) corners[k] = local_of[mesh.tets[e][k]];
      piece.tets.push_back(corners);
      if (quadratic) {
        std::array<int, 6> edges{};
        for (int k = 0; k < 6; ++k) edges[k] = local_of[mesh.tet_edge_nodes[e][k]];
        piece.tet_edge_nodes.push_back(edges);
      }
    }
  }
  // An empty quadratic piece has no edge-node lists and is written as a (linear) empty piece.

  std::vector<VtuField> piece_point_fields;
  piece_point_fields.reserve(point_fields.size() + 1);
  for (const VtuField& f : point_fields) {
    const auto nc = static_cast<std::size_t>(f.n_components);
    VtuField local{f.name, f.n_components, {}};
    local.values.reserve(global_of.size() * nc);
    for (const int g : global_of)
      local.values.insert(local.values.end(),
                          f.values.begin() + static_cast<std::ptrdiff_t>(g * nc),
                          f.values.begin() + static_cast<std::ptrdiff_t>((g + 1) * nc));
    piece_point_fields.push_back(std::move(local));
  }
  VtuField global_node{std::string(kGlobalNodeField), 1, {}};
  global_node.values.assign(global_of.begin(), global_of.end());  // exact: |g| < 2^31
  piece_point_fields.push_back(std::move(global_node));

  std::vector<VtuField> piece_cell_fields;
  piece_cell_fields.reserve(cell_fields.size());
  for (const VtuField& f : cell_fields) {
    const auto nc = static_cast<std::size_t>(f.n_components);
    VtuField local{f.name, f.n_components, {}};
    local.values.reserve(elements.size() * nc);
    for (const int e : elements) {
      const auto first = static_cast<std::size_t>(e) * nc;
      local.values.insert(local.values.end(), f.values.begin() + static_cast<std::ptrdiff_t>(first),
                          f.values.begin() + static_cast<std::ptrdiff_t>(first + nc));
    }
    piece_cell_fields.push_back(std::move(local));
  }
  if (shell) {
    write_vtu(path, piece.nodes, std::span<const std::array<int, 3>>(piece.triangles),
              piece_point_fields, piece_cell_fields, compression);
    return;
  }
  write_vtu(path, piece, piece.nodes, piece_point_fields, piece_cell_fields, compression);
}

}  // namespace plisse
