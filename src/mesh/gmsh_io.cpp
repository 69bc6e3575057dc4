#include "mesh/gmsh_io.hpp"

#include <gmsh.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <new>
#include <numeric>
#include <sstream>
#include <unordered_map>
#include <vector>

#include "core/error.hpp"
#include "core/input_file.hpp"
#include "mesh/gmsh_raw_model.hpp"
#include "mesh/gmsh_session.hpp"
#include "mesh/isolated_process.hpp"
#include "mesh/topology.hpp"

namespace plisse {
namespace {

std::string element_type_name(int type) {
  std::string name;
  int dim = 0, order = 0, n_nodes = 0, n_primary = 0;
  std::vector<double> local;
  gmsh::model::mesh::getElementProperties(type, name, dim, order, n_nodes, local, n_primary);
  return name;
}

InputError file_error(const std::string& path, const std::string& rule) {
  return InputError(InputPlace{path, 0, 0, ""}, rule);
}

/// Hash of a small array of node indices (for duplicate detection).
struct ArrayHash {
  template <std::size_t N>
  std::size_t operator()(const std::array<int, N>& a) const {
    std::size_t h = 1469598103934665603ull;
    for (int v : a) h = (h ^ static_cast<std::size_t>(v)) * 1099511628211ull;
    return h;
  }
};

/// Elements of one Gmsh type read from the whole model, in increasing element tag, with
/// repeated elements (same corner set) merged.
template <int NCorner, int NNode>
struct ElementBlock {
  std::vector<std::array<int, NNode>> nodes;          ///< corners first, Gmsh order
  std::unordered_map<std::size_t, int> index_of_tag;  ///< Gmsh element tag -> index
  int n_duplicates = 0;
};

/// The block of `type` in `model`, or nullptr.
const RawElementBlock* find_block(const RawGmshModel& model, int type) {
  for (const auto& b : model.blocks)
    if (b.type == type) return &b;
  return nullptr;
}

std::string type_name(const RawGmshModel& model, int type) {
  for (const auto& t : model.types)
    if (t.type == type) return t.name;
  return "element type " + std::to_string(type);
}

template <int NCorner, int NNode>
ElementBlock<NCorner, NNode> read_block(const RawGmshModel& model, int type,
                                        const std::unordered_map<std::size_t, int>& node_index,
                                        const std::string& path) {
  ElementBlock<NCorner, NNode> block;
  const RawElementBlock* raw = find_block(model, type);
  if (!raw) return block;
  const auto& tags = raw->element_tags;
  const auto& node_tags = raw->node_tags;
  if (node_tags.size() != tags.size() * NNode)
    throw file_error(path, "inconsistent element data for " + type_name(model, type));
  std::vector<std::size_t> order(tags.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return tags[a] < tags[b]; });
  std::unordered_map<std::array<int, NCorner>, int, ArrayHash> by_corners;
  by_corners.reserve(tags.size());
  block.index_of_tag.reserve(tags.size());
  for (std::size_t e : order) {
    std::array<int, NNode> n{};
    for (int k = 0; k < NNode; ++k) {
      const auto it = node_index.find(node_tags[e * NNode + static_cast<std::size_t>(k)]);
      if (it == node_index.end())
        throw file_error(path, type_name(model, type) + " element " + std::to_string(tags[e]) +
                                   " references a node that is not in the file");
      n[static_cast<std::size_t>(k)] = it->second;
    }
    std::array<int, NCorner> key{};
    std::copy_n(n.begin(), NCorner, key.begin());
    std::sort(key.begin(), key.end());
    const auto [it, inserted] = by_corners.emplace(key, static_cast<int>(block.nodes.size()));
    if (inserted)
      block.nodes.push_back(n);
    else
      ++block.n_duplicates;
    block.index_of_tag[tags[e]] = it->second;
  }
  return block;
}

void sort_unique(std::vector<int>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

/// Orients every triangle that is a boundary face of the tetrahedra like that face (outward).
int orient_triangles_outward(Mesh& mesh) {
  const auto faces = compute_boundary_faces(mesh);
  std::unordered_map<std::array<int, 3>, std::size_t, ArrayHash> face_of;
  face_of.reserve(faces.size());
  for (std::size_t i = 0; i < faces.size(); ++i) face_of.emplace(sorted_face(faces[i].nodes), i);
  int n_flipped = 0;
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    auto& tri = mesh.triangles[i];
    const auto it = face_of.find(sorted_face(tri));
    if (it == face_of.end()) continue;
    const auto& out = faces[it->second].nodes;
    // Same orientation iff tri is a cyclic rotation of out.
    const bool same = (tri == out) || (tri == std::array<int, 3>{out[1], out[2], out[0]}) ||
                      (tri == std::array<int, 3>{out[2], out[0], out[1]});
    if (same) continue;
    std::swap(tri[1], tri[2]);
    // Corners (0, 1, 2) -> (0, 2, 1): edges (01, 12, 20) become (02, 21, 10) = old (2, 1, 0).
    if (!mesh.triangle_edge_nodes.empty())
      std::swap(mesh.triangle_edge_nodes[i][0], mesh.triangle_edge_nodes[i][2]);
    ++n_flipped;
  }
  return n_flipped;
}

/// Which elements and groups the reader process copies: a solid's (dimensions 2 and 3) or a
/// shell surface's (also dimension 1: the line elements of its curves).
enum class ReadDims { solid, surface };

/// In the reader process: copies what read_gmsh (or read_gmsh_surface) needs out of the model
/// Gmsh just read.
RawGmshModel extract_model(ReadDims what) {
  RawGmshModel m;
  const std::vector<int> dims =
      what == ReadDims::solid ? std::vector<int>{2, 3} : std::vector<int>{1, 2, 3};
  for (int dim : dims) {
    std::vector<int> types;
    gmsh::model::mesh::getElementTypes(types, dim, -1);
    for (int type : types) m.types.push_back({type, dim, element_type_name(type)});
  }
  std::vector<double> parametric;
  gmsh::model::mesh::getNodes(m.node_tags, m.coordinates, parametric, -1, -1, false, false);
  const auto is_read = [&](int type) {
    return type == kTet4 || type == kTet10 || type == kTri3 || type == kTri6 ||
           (what == ReadDims::surface && type == kLine2);
  };
  for (const auto& t : m.types) {
    if (!is_read(t.type)) continue;
    RawElementBlock& b = m.blocks.emplace_back();
    b.type = t.type;
    gmsh::model::mesh::getElementsByType(t.type, b.element_tags, b.node_tags, -1);
  }
  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups, -1);
  for (const auto& [dim, tag] : groups) {
    if (std::find(dims.begin(), dims.end(), dim) == dims.end()) continue;
    RawPhysicalGroup& g = m.groups.emplace_back();
    g.dim = dim;
    g.tag = tag;
    gmsh::model::getPhysicalName(dim, tag, g.name);
    std::vector<int> entities;
    gmsh::model::getEntitiesForPhysicalGroup(dim, tag, entities);
    for (const auto& t : m.types) {
      if (t.dim != dim || !is_read(t.type)) continue;
      RawGroupElements& e = g.elements.emplace_back();
      e.type = t.type;
      for (int entity : entities) {
        std::vector<std::size_t> tags, node_tags;
        gmsh::model::mesh::getElementsByType(t.type, tags, node_tags, entity);
        e.element_tags.insert(e.element_tags.end(), tags.begin(), tags.end());
      }
    }
  }
  return m;
}

/// A Gmsh 2 file lists every node once in its one $Nodes section; Gmsh keeps the last of two
/// records with the same tag, silently moving every element that uses it. Throws InputError (the
/// rule only) for a tag given to two different points, as read_nodes does for the entities of a
/// v4 file. ASCII records are lines "tag x y z"; binary ones (file-type 1, native byte order) a
/// 4-byte tag and three coordinates of the format's data size. v4 files are left to read_nodes.
void refuse_v2_node_defined_twice(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  if (!std::getline(in, line) || line.rfind("$MeshFormat", 0) != 0) return;
  if (!std::getline(in, line)) return;
  std::istringstream format(line);
  std::string version;
  int file_type = -1, data_size = 0;
  if (!(format >> version >> file_type >> data_size) || version.rfind("2", 0) != 0) return;
  if (file_type != 0 && !(file_type == 1 && data_size == 8)) return;
  while (std::getline(in, line))
    if (line.rfind("$Nodes", 0) == 0) break;
  if (!std::getline(in, line)) return;
  long long count = 0;
  if (!(std::istringstream(line) >> count) || count < 0) return;  // Gmsh reports it
  std::unordered_map<long long, std::array<double, 3>> points;
  // The next record's tag and point; false at the end of the section or a broken record, which
  // Gmsh reports.
  const auto next = [&](long long& tag, std::array<double, 3>& x) {
    if (file_type == 1) {
      std::int32_t t = 0;
      if (count-- <= 0 || !in.read(reinterpret_cast<char*>(&t), sizeof t) ||
          !in.read(reinterpret_cast<char*>(x.data()), sizeof x))
        return false;
      tag = t;
      return true;
    }
    if (!std::getline(in, line) || line.rfind("$EndNodes", 0) == 0) return false;
    std::istringstream fields(line);
    return static_cast<bool>(fields >> tag >> x[0] >> x[1] >> x[2]);
  };
  long long tag = 0;
  std::array<double, 3> x{};
  while (next(tag, x)) {
    const auto [it, added] = points.emplace(tag, x);
    if (added || it->second == x) continue;
    char where[200];
    std::snprintf(where, sizeof where, " at (%.9g, %.9g, %.9g) and at (%.9g, %.9g, %.9g)",
                  it->second[0], it->second[1], it->second[2], x[0], x[1], x[2]);
    throw InputError({}, "node " + std::to_string(tag) + " is defined twice in $Nodes" + where +
                             " (Gmsh would keep the last); every node needs its own tag");
  }
}

/// In the reader process: opens `path` with Gmsh and sends the model or the error to the parent.
/// Gmsh logs its errors (GmshSession) or throws a string, std::bad_alloc (an announced count
/// beyond the memory limit) or a standard exception.
void read_in_child(const std::string& path, ReadDims what, GmshSession& session, ChildOutput& out) {
  try {
    refuse_v2_node_defined_twice(path);
    gmsh::open(path);
    session.check_input(path, "cannot read the mesh file");
    const RawGmshModel model = extract_model(what);
    session.check_input(path, "cannot read the mesh file");
    send_model(model, out);
  } catch (const InputError& e) {
    send_error(e.rule(), out);
  } catch (const std::string& message) {  // Gmsh throws strings when AbortOnError is set
    send_error("cannot read the mesh file: " + message, out);
  } catch (const std::bad_alloc&) {
    send_out_of_memory(out);
  } catch (const std::exception& e) {
    send_error(std::string("cannot read the mesh file: ") + e.what(), out);
  } catch (...) {
    send_error("cannot read the mesh file: Gmsh threw an exception of unknown type", out);
  }
}

/// The nodes of the model into `mesh.nodes`, renumbered by increasing Gmsh tag; returns the map
/// from Gmsh tag to index. Refuses a tag given to two different points.
std::unordered_map<std::size_t, int> read_nodes(const RawGmshModel& model, const std::string& path,
                                                Mesh& mesh) {
  const auto& node_tags = model.node_tags;
  const auto& coords = model.coordinates;
  if (coords.size() != 3 * node_tags.size())
    throw file_error(path, "inconsistent node data: " + std::to_string(node_tags.size()) +
                               " nodes with " + std::to_string(coords.size()) + " coordinates");
  std::vector<std::size_t> order(node_tags.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return node_tags[a] < node_tags[b]; });
  std::unordered_map<std::size_t, int> node_index;
  node_index.reserve(node_tags.size());
  mesh.nodes.reserve(node_tags.size());
  for (std::size_t i : order) {
    const Vec3d x(coords[3 * i], coords[3 * i + 1], coords[3 * i + 2]);
    const auto [it, added] = node_index.emplace(node_tags[i], static_cast<int>(mesh.nodes.size()));
    if (added) {
      mesh.nodes.push_back(x);
      continue;
    }
    // A node listed by two entities (boundary nodes) is the same node, with the same coordinates;
    // a tag given to two different points would silently move every element that uses it.
    const Vec3d& first = mesh.nodes[it->second];
    if (first != x) {
      char where[200];
      std::snprintf(where, sizeof where, " at (%.9g, %.9g, %.9g) and at (%.9g, %.9g, %.9g)",
                    first.x(), first.y(), first.z(), x.x(), x.y(), x.z());
      throw file_error(path, "node tag " + std::to_string(node_tags[i]) +
                                 " is given to two points" + where +
                                 "; every node needs its own tag");
    }
  }
  return node_index;
}

/// The Mesh from what the reader process sent (conventions: gmsh_io.hpp).
Mesh build_mesh(const RawGmshModel& model, const std::string& path, GmshReadInfo& info) {
  Mesh mesh;
  // Element types present: refuse what plisse cannot use, naming the type.
  std::vector<int> types3, types2;
  for (const auto& t : model.types) (t.dim == 3 ? types3 : types2).push_back(t.type);
  for (int type : types3)
    if (type != kTet4 && type != kTet10)
      throw file_error(
          path, "unsupported volume element type '" + type_name(model, type) + "' (Gmsh type " +
                    std::to_string(type) +
                    "): plisse reads tetrahedra only (4 or 10 nodes); re-mesh the volume with "
                    "tetrahedra");
  for (int type : types2)
    if (type != kTri3 && type != kTri6)
      throw file_error(path, "unsupported surface element type '" + type_name(model, type) +
                                 "' (Gmsh type " + std::to_string(type) +
                                 "): boundary elements must be triangles (3 or 6 nodes)");
  const bool has4 = std::count(types3.begin(), types3.end(), kTet4) > 0;
  const bool has10 = std::count(types3.begin(), types3.end(), kTet10) > 0;
  if (!has4 && !has10) throw file_error(path, "the file contains no tetrahedra");
  if (has4 && has10)
    throw file_error(path, "the file mixes 4-node and 10-node tetrahedra; use one order");
  const bool has_tri6 = std::count(types2.begin(), types2.end(), kTri6) > 0;
  const bool has_tri3 = std::count(types2.begin(), types2.end(), kTri3) > 0;
  if (has_tri6 && (has4 || has_tri3))
    throw file_error(path, "6-node triangles need 10-node tetrahedra and no 3-node triangles");

  const std::unordered_map<std::size_t, int> node_index = read_nodes(model, path, mesh);

  // Tetrahedra and triangles.
  std::unordered_map<std::size_t, int> tet_of_tag, tri_of_tag;
  if (has4) {
    auto block = read_block<4, 4>(model, kTet4, node_index, path);
    mesh.tets = std::move(block.nodes);
    tet_of_tag = std::move(block.index_of_tag);
    info.n_duplicate_elements += block.n_duplicates;
  } else {
    auto block = read_block<4, 10>(model, kTet10, node_index, path);
    for (const auto& n : block.nodes) {
      mesh.tets.push_back({n[0], n[1], n[2], n[3]});
      mesh.tet_edge_nodes.push_back({n[4], n[5], n[6], n[7], n[8], n[9]});
    }
    tet_of_tag = std::move(block.index_of_tag);
    info.n_duplicate_elements += block.n_duplicates;
  }
  if (mesh.tets.empty()) throw file_error(path, "the file contains no tetrahedra");
  if (has_tri6) {
    auto block = read_block<3, 6>(model, kTri6, node_index, path);
    for (const auto& n : block.nodes) {
      mesh.triangles.push_back({n[0], n[1], n[2]});
      mesh.triangle_edge_nodes.push_back({n[3], n[4], n[5]});
    }
    tri_of_tag = std::move(block.index_of_tag);
    info.n_duplicate_elements += block.n_duplicates;
  } else if (has_tri3) {
    auto block = read_block<3, 3>(model, kTri3, node_index, path);
    mesh.triangles = std::move(block.nodes);
    tri_of_tag = std::move(block.index_of_tag);
    info.n_duplicate_elements += block.n_duplicates;
  }
  if (has10 && has_tri3) {
    // Linear triangles on a quadratic mesh: take their edge nodes from the tetrahedra.
    std::map<std::pair<int, int>, int> mid;
    for (std::size_t t = 0; t < mesh.tets.size(); ++t)
      for (std::size_t e = 0; e < 6; ++e) {
        const int a = mesh.tets[t][static_cast<std::size_t>(kTetEdges[e][0])];
        const int b = mesh.tets[t][static_cast<std::size_t>(kTetEdges[e][1])];
        mid[{std::min(a, b), std::max(a, b)}] = mesh.tet_edge_nodes[t][e];
      }
    for (const auto& tri : mesh.triangles) {
      std::array<int, 3> edge{};
      for (int e = 0; e < 3; ++e) {
        const int a = tri[static_cast<std::size_t>(e)],
                  b = tri[static_cast<std::size_t>((e + 1) % 3)];
        const auto it = mid.find({std::min(a, b), std::max(a, b)});
        if (it == mid.end())
          throw file_error(
              path, "a 3-node triangle on a 10-node tetrahedral mesh is not on a tetrahedron edge");
        edge[static_cast<std::size_t>(e)] = it->second;
      }
      mesh.triangle_edge_nodes.push_back(edge);
    }
  }

  // Physical groups -> tags.
  const int tet_type = has4 ? kTet4 : kTet10;
  const int tri_type = has_tri6 ? kTri6 : kTri3;
  for (const auto& group : model.groups) {
    if (group.dim != 2 && group.dim != 3) continue;
    std::string name = group.name;
    if (name == kUntaggedGroupName) continue;
    if (name.empty()) name = std::to_string(group.dim) + ":" + std::to_string(group.tag);
    auto& indices = group.dim == 2 ? mesh.surface_tags[name] : mesh.volume_tags[name];
    const int type = group.dim == 3 ? tet_type : tri_type;
    const auto& index_of_tag = group.dim == 3 ? tet_of_tag : tri_of_tag;
    for (const auto& elements : group.elements) {
      if (elements.type != type) continue;
      for (std::size_t t : elements.element_tags) {
        const auto it = index_of_tag.find(t);
        if (it != index_of_tag.end()) indices.push_back(it->second);
      }
    }
    sort_unique(indices);
  }

  // Orientation (see the header: a numbering convention in a reference mesh).
  for (int t = 0; t < mesh.n_tets(); ++t)
    if (tet_signed_volume(mesh, t) < 0.0) {
      flip_tet(mesh, t);
      ++info.n_flipped_tets;
    }
  info.n_flipped_triangles = orient_triangles_outward(mesh);
  return mesh;
}

/// "Name (Gmsh type N)" of an element type, for messages.
std::string type_label(const RawGmshModel& model, int type) {
  return "'" + type_name(model, type) + "' (Gmsh type " + std::to_string(type) + ")";
}

/// Refuses the element types a shell surface cannot have (read_gmsh_surface).
void check_surface_types(const RawGmshModel& model, const std::string& path) {
  bool has_tri3 = false;
  for (const auto& t : model.types) {
    const std::string label = type_label(model, t.type);
    if (t.dim == 3) {
      if (t.type == kTet4 || t.type == kTet10) {
        const RawElementBlock* block = find_block(model, t.type);
        const std::size_t n = block ? block->element_tags.size() : 0;
        throw file_error(path, "a shell mesh is a surface: this file has " + std::to_string(n) +
                                   " tetrahedra (give the mid-surface's triangles alone)");
      }
      throw file_error(path, "a shell mesh is a surface: this file has volume elements " + label);
    }
    if (t.dim == 2) {
      if (t.type == kTri3) {
        has_tri3 = true;
        continue;
      }
      if (t.name.rfind("Triangle", 0) == 0)
        throw file_error(path, "higher-order triangles " + label +
                                   ": the shell triangle is linear; mesh with 3-node triangles "
                                   "(Gmsh: Mesh.ElementOrder = 1)");
      if (t.name.rfind("Quadrilateral", 0) == 0)
        throw file_error(path, "quadrilaterals " + label +
                                   ": a shell mesh is made of triangles; triangulate the surface "
                                   "(Gmsh: do not recombine)");
      throw file_error(path, "unsupported surface element type " + label +
                                 ": a shell mesh is made of 3-node triangles");
    }
    if (t.dim == 1 && t.type != kLine2)
      throw file_error(path,
                       "higher-order line elements " + label +
                           ": a shell's edges are 2-node lines (Gmsh: Mesh.ElementOrder = 1)");
  }
  if (!has_tri3)
    throw file_error(path,
                     "the file contains no triangles: a shell mesh is a surface of 3-node "
                     "triangles");
}

/// Makes the triangles of `mesh` (a surface) consistently oriented across every edge, piece by
/// piece (connected through shared edges), breadth first from the piece's first triangle, whose
/// orientation is kept; then turns every closed piece (each of its edges shared by two of its
/// triangles) outward, to a positive enclosed volume. `uses` counts the triangles of each
/// undirected edge, at most two. Returns the number of triangles turned; refuses a piece that no
/// orientation makes consistent (a Moebius strip).
int orient_surface(Mesh& mesh, const std::map<std::pair<int, int>, int>& uses,
                   const std::vector<std::size_t>& node_tag_of, const std::string& path) {
  const std::size_t n = mesh.triangles.size();
  auto key = [](int a, int b) { return std::make_pair(std::min(a, b), std::max(a, b)); };
  // Undirected edge -> its (at most two) triangles.
  std::map<std::pair<int, int>, std::array<int, 2>> triangles_of;
  for (std::size_t t = 0; t < n; ++t)
    for (std::size_t i = 0; i < 3; ++i) {
      auto [it, added] = triangles_of.try_emplace(
          key(mesh.triangles[t][i], mesh.triangles[t][(i + 1) % 3]), std::array<int, 2>{-1, -1});
      it->second[it->second[0] < 0 ? 0 : 1] = static_cast<int>(t);
    }
  // True when triangle t runs from a to b.
  auto runs = [&](int t, int a, int b) {
    const auto& tri = mesh.triangles[static_cast<std::size_t>(t)];
    for (std::size_t i = 0; i < 3; ++i)
      if (tri[i] == a && tri[(i + 1) % 3] == b) return true;
    return false;
  };
  std::vector<int> piece(n, -1);
  std::vector<char> turned(n, 0);
  int n_pieces = 0;
  for (std::size_t first = 0; first < n; ++first) {
    if (piece[first] >= 0) continue;
    const int id = n_pieces++;
    std::vector<int> members = {static_cast<int>(first)};
    piece[first] = id;
    for (std::size_t next = 0; next < members.size(); ++next) {
      const int t = members[next];
      const auto tri = mesh.triangles[static_cast<std::size_t>(t)];
      for (std::size_t i = 0; i < 3; ++i) {
        const int a = tri[i], b = tri[(i + 1) % 3];
        const auto& pair = triangles_of.at(key(a, b));
        const int u = pair[0] == t ? pair[1] : pair[0];
        if (u < 0) continue;
        const bool agrees = runs(u, b, a);
        if (piece[static_cast<std::size_t>(u)] >= 0) {
          if (!agrees)
            throw file_error(
                path,
                "the surface is not orientable (a Moebius strip?): no orientation of its "
                "triangles agrees across every edge, e.g. the edge between the nodes with "
                "Gmsh tags " +
                    std::to_string(node_tag_of[static_cast<std::size_t>(a)]) + " and " +
                    std::to_string(node_tag_of[static_cast<std::size_t>(b)]) +
                    "; a shell needs a surface with two sides");
          continue;
        }
        if (!agrees) {
          auto& other = mesh.triangles[static_cast<std::size_t>(u)];
          std::swap(other[1], other[2]);
          turned[static_cast<std::size_t>(u)] ^= 1;
        }
        piece[static_cast<std::size_t>(u)] = id;
        members.push_back(u);
      }
    }
    // A closed piece: outward, to a positive enclosed volume (sum of the signed volumes of the
    // cones from one of its nodes, which keeps the round-off of a piece far from the origin small).
    bool closed = true;
    for (const int t : members)
      for (std::size_t i = 0; i < 3 && closed; ++i) {
        const auto& tri = mesh.triangles[static_cast<std::size_t>(t)];
        closed = uses.at(key(tri[i], tri[(i + 1) % 3])) == 2;
      }
    if (!closed) continue;
    const Vec3d origin = mesh.nodes[static_cast<std::size_t>(mesh.triangles[first][0])];
    double six_volume = 0.0;
    for (const int t : members) {
      const auto& tri = mesh.triangles[static_cast<std::size_t>(t)];
      const Vec3d x0 = mesh.nodes[static_cast<std::size_t>(tri[0])] - origin;
      const Vec3d x1 = mesh.nodes[static_cast<std::size_t>(tri[1])] - origin;
      const Vec3d x2 = mesh.nodes[static_cast<std::size_t>(tri[2])] - origin;
      six_volume += x0.dot(x1.cross(x2));
    }
    if (six_volume < 0.0)
      for (const int t : members) {
        auto& tri = mesh.triangles[static_cast<std::size_t>(t)];
        std::swap(tri[1], tri[2]);
        turned[static_cast<std::size_t>(t)] ^= 1;
      }
  }
  return static_cast<int>(std::count(turned.begin(), turned.end(), 1));
}

/// The shell surface from what the reader process sent (conventions: gmsh_io.hpp,
/// read_gmsh_surface).
Mesh build_surface_mesh(const RawGmshModel& model, const std::string& path, GmshReadInfo& info) {
  check_surface_types(model, path);
  Mesh mesh;
  const std::unordered_map<std::size_t, int> node_index = read_nodes(model, path, mesh);
  std::vector<std::size_t> node_tag_of(mesh.nodes.size());
  for (const auto& [tag, index] : node_index) node_tag_of[static_cast<std::size_t>(index)] = tag;
  auto tags_of = [&](int a, int b) {
    return std::to_string(node_tag_of[static_cast<std::size_t>(a)]) + " and " +
           std::to_string(node_tag_of[static_cast<std::size_t>(b)]);
  };

  auto triangles = read_block<3, 3>(model, kTri3, node_index, path);
  mesh.triangles = std::move(triangles.nodes);
  info.n_duplicate_elements += triangles.n_duplicates;
  for (const auto& tri : mesh.triangles)
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[2] == tri[0])
      throw file_error(path, "a triangle repeats a node (Gmsh node tags " +
                                 std::to_string(node_tag_of[static_cast<std::size_t>(tri[0])]) +
                                 ", " + tags_of(tri[1], tri[2]) + ")");
  std::map<std::pair<int, int>, int> uses;  // undirected edge -> number of triangles
  for (const auto& tri : mesh.triangles)
    for (std::size_t i = 0; i < 3; ++i) {
      const int a = tri[i], b = tri[(i + 1) % 3];
      if (++uses[{std::min(a, b), std::max(a, b)}] == 3)
        throw file_error(path,
                         "an edge of more than two triangles, between the nodes with Gmsh "
                         "tags " +
                             tags_of(a, b) +
                             ": a shell's surface has at most two triangles on an edge");
    }

  // Line elements: a shell's edges are those of its physical curves.
  const auto lines = read_block<2, 2>(model, kLine2, node_index, path);
  info.n_duplicate_elements += lines.n_duplicates;
  std::vector<int> edge_of_line(lines.nodes.size(), -1);
  for (const auto& group : model.groups) {
    if (group.dim != 1 || group.name == kUntaggedGroupName) continue;
    for (const auto& elements : group.elements) {
      if (elements.type != kLine2) continue;
      for (std::size_t t : elements.element_tags) {
        const auto it = lines.index_of_tag.find(t);
        if (it == lines.index_of_tag.end()) continue;
        const auto& line = lines.nodes[static_cast<std::size_t>(it->second)];
        const std::string name = group.name.empty() ? "1:" + std::to_string(group.tag) : group.name;
        if (!uses.count({std::min(line[0], line[1]), std::max(line[0], line[1])}))
          throw file_error(path, "line element " + std::to_string(t) + " of the physical curve '" +
                                     name + "', between the nodes with Gmsh tags " +
                                     tags_of(line[0], line[1]) +
                                     ", is not a side of a triangle: a shell's edges lie on its "
                                     "surface");
        edge_of_line[static_cast<std::size_t>(it->second)] = 0;
      }
    }
  }
  for (std::size_t l = 0; l < lines.nodes.size(); ++l) {
    if (edge_of_line[l] < 0) continue;
    edge_of_line[l] = static_cast<int>(mesh.edges.size());
    mesh.edges.push_back(lines.nodes[l]);
  }

  // Physical groups -> tags (dimension 0 ignored; 3 cannot have elements here).
  for (const auto& group : model.groups) {
    if (group.dim != 1 && group.dim != 2) continue;
    std::string name = group.name;
    if (name == kUntaggedGroupName) continue;
    if (name.empty()) name = std::to_string(group.dim) + ":" + std::to_string(group.tag);
    auto& indices = group.dim == 2 ? mesh.surface_tags[name] : mesh.edge_tags[name];
    for (const auto& elements : group.elements) {
      if (elements.type != (group.dim == 2 ? kTri3 : kLine2)) continue;
      for (std::size_t t : elements.element_tags) {
        if (group.dim == 2) {
          const auto it = triangles.index_of_tag.find(t);
          if (it != triangles.index_of_tag.end()) indices.push_back(it->second);
        } else {
          const auto it = lines.index_of_tag.find(t);
          if (it != lines.index_of_tag.end())
            indices.push_back(edge_of_line[static_cast<std::size_t>(it->second)]);
        }
      }
    }
    sort_unique(indices);
  }

  info.n_flipped_triangles = orient_surface(mesh, uses, node_tag_of, path);
  return mesh;
}

/// Length of the well-formed UTF-8 sequence of 2 to 4 bytes at s[i], or 0 (RFC 3629, section 4;
/// overlong forms and surrogates are not excluded: the point is only a printable message).
std::size_t utf8_length(const std::string& s, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char lead = byte(i);
  std::size_t n = 0;
  if (lead >= 0xc2 && lead <= 0xdf) n = 2;
  if (lead >= 0xe0 && lead <= 0xef) n = 3;
  if (lead >= 0xf0 && lead <= 0xf4) n = 4;
  if (n == 0 || i + n > s.size()) return 0;
  for (std::size_t k = 1; k < n; ++k)
    if ((byte(i + k) & 0xc0) != 0x80) return 0;
  return n;
}

/// A Gmsh error report fit for a terminal: control characters and bytes that are not UTF-8 (Gmsh
/// quotes the offending bytes of a binary or garbage file) become '?', and of the "; "-separated
/// messages (a garbage file gives one per bad token, up to Gmsh's limit of 20) the first
/// kShownGmshErrors are kept, then a count.
std::string readable_errors(const std::string& report) {
  constexpr std::size_t kShownGmshErrors = 3;
  std::string clean;
  for (std::size_t i = 0; i < report.size();) {
    const auto ch = static_cast<unsigned char>(report[i]);
    if (ch >= 0x80) {
      if (const std::size_t n = utf8_length(report, i)) {
        clean += report.substr(i, n);
        i += n;
        continue;
      }
    }
    clean += ch < 0x20 || ch >= 0x7f ? '?' : report[i];
    ++i;
  }
  std::string out;
  std::size_t start = 0, n = 0;
  while (true) {
    const std::size_t at = clean.find("; ", start);
    if (n < kShownGmshErrors)
      out += (n ? "; " : "") + clean.substr(start, at == std::string::npos ? at : at - start);
    ++n;
    if (at == std::string::npos) break;
    start = at + 2;
  }
  if (n > kShownGmshErrors)
    out += "; and " + std::to_string(n - kShownGmshErrors) + " more Gmsh errors";
  return out;
}

/// ".msh" in any letter case: Gmsh picks its MSH reader from the extension, case-insensitively.
bool ends_with_msh(const std::string& path) {
  if (path.size() < 4) return false;
  std::string ext = path.substr(path.size() - 4);
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".msh";
}

/// True when the file begins like an MSH file by Gmsh's own test (MergeFile in Gmsh's
/// Common/OpenFile.cpp compares the first line with these prefixes and hands anything else to
/// its .geo script parser, which can run shell commands, or to its post-processing reader).
bool begins_like_msh(const std::string& path) {
  char head[16] = {};
  std::ifstream in(path, std::ios::binary);
  in.read(head, sizeof head);
  const std::string start(head, static_cast<std::size_t>(in.gcount()));
  for (const char* prefix : {"$MeshFormat", "$Comments", "$NO", "$PTS", "$PARA", "$ELM"})
    if (start.rfind(prefix, 0) == 0) return true;
  return false;
}

}  // namespace

Mesh read_gmsh(const std::string& path) {
  GmshReadInfo info;
  return read_gmsh(path, info);
}

ChildLimits gmsh_reader_limits(std::uintmax_t file_bytes) {
  // Measured on 384 000 tetrahedra (fuzz/README.md): the reader process peaks at 5-6 bytes per
  // byte of file (ASCII or binary) and reads 14 MB in 0.2 s of CPU. The factors leave a wide
  // margin over that, the floors over Gmsh's start-up and any small file.
  constexpr std::uint64_t kMemoryFloor = std::uint64_t{1} << 30;
  constexpr std::uint64_t kMemoryPerFileByte = 64;
  constexpr double kCpuFloorSeconds = 10.0;
  constexpr double kCpuSecondsPerMiB = 4.0;
  const double mib = static_cast<double>(file_bytes) / static_cast<double>(1 << 20);
  ChildLimits limits;
  // Never more than the machine has: a sparse file claiming terabytes it does not hold would
  // otherwise lift the limit altogether.
  limits.memory_bytes =
      std::min(kMemoryFloor +
                   std::min<std::uint64_t>(file_bytes, std::uint64_t{1} << 40) * kMemoryPerFileByte,
               std::max(kMemoryFloor, physical_memory_bytes()));
  limits.cpu_seconds =
      static_cast<unsigned>(std::min(kCpuFloorSeconds + kCpuSecondsPerMiB * mib, 1e6));
  limits.wall_seconds = 2.0 * limits.cpu_seconds + 10.0;  // leaves room for a loaded machine
  return limits;
}

namespace {

/// The reader process's limits for the file at `path` (gmsh_reader_limits); refuses a file too
/// large for this machine's memory before a reader starts.
ChildLimits reader_limits_for(const std::string& path) {
  std::error_code ec;
  const std::uintmax_t file_bytes = std::filesystem::file_size(path, ec);
  // The reader needs 5-6 bytes of memory per byte of file (gmsh_reader_limits): a file that
  // cannot fit is refused before a reader starts.
  if (!ec && std::filesystem::is_regular_file(path, ec) && file_bytes > physical_memory_bytes() / 6)
    throw file_error(path, "the mesh file is " + std::to_string(file_bytes) +
                               " bytes; reading it needs about 6 bytes of memory per byte, "
                               "more than this machine's " +
                               std::to_string(physical_memory_bytes() >> 20) + " MiB");
  return gmsh_reader_limits(ec ? 0 : file_bytes);
}

/// Checks the file at `path` (name, header) and reads it with Gmsh in the isolated reader process
/// (gmsh_io.hpp); returns what the reader sent, or throws InputError naming the file.
RawGmshModel read_raw_model(const std::string& path, ReadDims what, const ChildLimits& limits) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw file_error(path, "mesh file not found");
  if (!std::filesystem::is_regular_file(path, ec)) throw file_error(path, "not a regular file");
  if (!ends_with_msh(path))
    throw file_error(path,
                     "the mesh file name must end in .msh (Gmsh would read any other file as a "
                     "script and run it)");
  if (!std::ifstream(path).good()) throw file_error(path, "cannot open the mesh file for reading");
  if (!begins_like_msh(path))
    throw file_error(path,
                     "not a Gmsh mesh file: it must begin with $MeshFormat (MSH 2 and 4) or $NOD "
                     "(MSH 1); Gmsh would run any other content as a script");
  const std::uintmax_t file_bytes = std::filesystem::file_size(path, ec);
  const std::string size_note = "for a file of " + std::to_string(file_bytes) + " bytes";
  const std::string malformed = "the mesh file is malformed: ";

  ChildResult child;
  {
    // Initialised Gmsh with an empty model and its error log started, inherited by the child;
    // the session also serialises readers within this process.
    GmshSession session;
    child =
        run_isolated([&](ChildOutput& out) { read_in_child(path, what, session, out); }, limits);
  }
  if (child.end == ChildResult::End::wall_time_exceeded)
    throw file_error(path, malformed + "reading it took longer than the time limit of " +
                               std::to_string(static_cast<long>(limits.wall_seconds)) + " s " +
                               size_note + " (the Gmsh reader process was stopped)");
  if (child.cpu_limit_hit(limits))
    throw file_error(path, malformed + "reading it exceeded the CPU-time limit of " +
                               std::to_string(limits.cpu_seconds) + " s " + size_note +
                               " (the Gmsh reader process was stopped by " +
                               describe_signal(child.signal) + ")");
  if (child.end == ChildResult::End::killed_by_signal)
    throw file_error(path, malformed +
                               "Gmsh's reader failed on it: the reader process was "
                               "killed by " +
                               describe_signal(child.signal));
  if (child.exit_status != 0)
    throw file_error(path, malformed + "the Gmsh reader process stopped with exit status " +
                               std::to_string(child.exit_status) + " before sending the mesh");
  GmshReaderReply reply;
  if (!decode_reply(child.output, reply))
    throw file_error(path, malformed + "the Gmsh reader process sent an incomplete reply (" +
                               std::to_string(child.output.size()) + " bytes)");
  switch (reply.kind) {
    case GmshReaderReply::Kind::out_of_memory:
      throw file_error(path, malformed + "reading it needs more than the memory limit of " +
                                 std::to_string(limits.memory_bytes >> 20) + " MiB " + size_note +
                                 ": it announces more nodes or elements than it holds (a corrupt "
                                 "or truncated file?)");
    case GmshReaderReply::Kind::error:
      throw file_error(path, readable_errors(reply.rule));
    case GmshReaderReply::Kind::model:
      break;
  }
  return std::move(reply.model);
}

}  // namespace

Mesh read_gmsh(const std::string& path, GmshReadInfo& info) {
  return read_gmsh(path, info, reader_limits_for(path));
}

Mesh read_gmsh(const std::string& path, GmshReadInfo& info, const ChildLimits& limits) {
  info = GmshReadInfo{};
  const RawGmshModel model = read_raw_model(path, ReadDims::solid, limits);
  try {
    return build_mesh(model, path, info);
  } catch (const std::bad_alloc&) {
    throw file_error(path, "cannot read the mesh file: not enough memory for its " +
                               std::to_string(model.node_tags.size()) + " nodes");
  }
}

Mesh read_gmsh_surface(const std::string& path) {
  GmshReadInfo info;
  return read_gmsh_surface(path, info);
}

Mesh read_gmsh_surface(const std::string& path, GmshReadInfo& info) {
  return read_gmsh_surface(path, info, reader_limits_for(path));
}

Mesh read_gmsh_surface(const std::string& path, GmshReadInfo& info, const ChildLimits& limits) {
  info = GmshReadInfo{};
  const RawGmshModel model = read_raw_model(path, ReadDims::surface, limits);
  try {
    return build_surface_mesh(model, path, info);
  } catch (const std::bad_alloc&) {
    throw file_error(path, "cannot read the mesh file: not enough memory for its " +
                               std::to_string(model.node_tags.size()) + " nodes");
  }
}

}  // namespace plisse
