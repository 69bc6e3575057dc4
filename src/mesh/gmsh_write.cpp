// Writing a Mesh as a Gmsh MSH file (v2.2 or v4.1, ASCII or binary) through the Gmsh API: the
// tags become physical groups of discrete entities (gmsh_io.hpp); a shell's edges become line
// elements.
#include <fcntl.h>
#include <gmsh.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <map>
#include <numeric>
#include <string_view>
#include <vector>

#include "core/error.hpp"
#include "mesh/gmsh_io.hpp"
#include "mesh/gmsh_raw_model.hpp"
#include "mesh/gmsh_session.hpp"

namespace plisse {
namespace {

InputError file_error(const std::string& path, const std::string& rule) {
  return InputError(InputPlace{path, 0, 0, ""}, rule);
}

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

/// Per element: the indices (into `names`) of the tags containing it, and the tag names.
struct Signatures {
  std::vector<int> of_element;             ///< signature id per element
  std::vector<std::vector<int>> name_ids;  ///< per signature id: sorted name indices
  std::vector<std::string> names;
};

Signatures compute_signatures(const std::map<std::string, std::vector<int>>& tags,
                              std::size_t n_elements, const char* what) {
  Signatures s;
  std::vector<std::vector<int>> per_element(n_elements);
  for (const auto& [name, indices] : tags) {
    const int id = static_cast<int>(s.names.size());
    s.names.push_back(name);
    for (int i : indices) {
      PLISSE_CHECK(
          i >= 0 && static_cast<std::size_t>(i) < n_elements,
          "write_gmsh: tag '" << name << "' lists " << what << " " << i << " out of range");
      per_element[static_cast<std::size_t>(i)].push_back(id);
    }
  }
  std::map<std::vector<int>, int> id_of;
  s.of_element.resize(n_elements);
  for (std::size_t e = 0; e < n_elements; ++e) {
    auto& sig = per_element[e];
    std::sort(sig.begin(), sig.end());
    sig.erase(std::unique(sig.begin(), sig.end()), sig.end());
    const auto [it, inserted] = id_of.emplace(sig, static_cast<int>(s.name_ids.size()));
    if (inserted) s.name_ids.push_back(sig);
    s.of_element[e] = it->second;
  }
  return s;
}

/// A run of consecutive elements with the same signature, stored as one discrete Gmsh entity
/// (runs keep the element order through v2 files, whose writer renumbers elements entity by
/// entity).
struct Run {
  int entity;
  int signature;
  std::size_t begin, end;
};

std::vector<Run> make_runs(int dim, const Signatures& s) {
  std::vector<Run> runs;
  for (std::size_t e = 0; e < s.of_element.size(); ++e) {
    if (runs.empty() || s.of_element[e] != runs.back().signature)
      runs.push_back({gmsh::model::addDiscreteEntity(dim), s.of_element[e], e, e + 1});
    else
      runs.back().end = e + 1;
  }
  return runs;
}

/// Physical groups of dimension `dim` from the runs; in v2 files untagged runs join the group
/// kUntaggedGroupName so that Gmsh writes them.
void add_groups(int dim, const Signatures& s, const std::vector<Run>& runs, bool keep_untagged) {
  for (std::size_t id = 0; id < s.names.size(); ++id) {
    std::vector<int> entities;
    for (const auto& run : runs) {
      const auto& sig = s.name_ids[static_cast<std::size_t>(run.signature)];
      if (std::binary_search(sig.begin(), sig.end(), static_cast<int>(id)))
        entities.push_back(run.entity);
    }
    if (entities.empty()) continue;
    const int group = gmsh::model::addPhysicalGroup(dim, entities);
    gmsh::model::setPhysicalName(dim, group, s.names[id]);
  }
  if (!keep_untagged) return;
  std::vector<int> untagged;
  for (const auto& run : runs)
    if (s.name_ids[static_cast<std::size_t>(run.signature)].empty()) untagged.push_back(run.entity);
  if (untagged.empty()) return;
  const int group = gmsh::model::addPhysicalGroup(dim, untagged);
  gmsh::model::setPhysicalName(dim, group, kUntaggedGroupName);
}

/// Gmsh does not report a failed write (a full disk, a file size limit): its file then ends early.
/// Every MSH file it writes ends with its elements' section, so a file that does not end in
/// "$EndElements\n", or whose data the system cannot put on the disk (fsync, close), was not
/// written whole. Throws InputError naming `path`.
void check_written_whole(const std::string& path) {
  static constexpr std::string_view kEnd = "$EndElements\n";
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NOFOLLOW);
  if (fd < 0)
    throw file_error(path, std::string("cannot write the mesh file: ") + std::strerror(errno));
  struct stat info {};
  char tail[kEnd.size()] = {};
  const bool ended =
      ::fstat(fd, &info) == 0 && info.st_size >= static_cast<off_t>(kEnd.size()) &&
      ::pread(fd, tail, kEnd.size(), info.st_size - static_cast<off_t>(kEnd.size())) ==
          static_cast<ssize_t>(kEnd.size()) &&
      std::string_view(tail, kEnd.size()) == kEnd;
  const int synced = ::fsync(fd) == 0 ? 0 : errno;
  const int closed = ::close(fd) == 0 ? 0 : errno;
  if (const int error_number = synced ? synced : closed; error_number != 0)
    throw file_error(path,
                     std::string("cannot write the mesh file: ") + std::strerror(error_number));
  if (!ended)
    throw file_error(path, "cannot write the mesh file: it ends after " +
                               std::to_string(static_cast<long long>(info.st_size)) +
                               " bytes, before its $EndElements line (the disk is full, or a "
                               "file size limit was reached)");
}

}  // namespace

void write_gmsh(const Mesh& mesh, const std::string& path, double version, bool binary) {
  if (!ends_with(path, ".msh"))
    throw file_error(
        path, "the mesh file name must end in .msh (Gmsh picks the format from the extension)");
  const bool v2 = version == 2.2;
  PLISSE_CHECK(v2 || version == 4.1,
               "write_gmsh: version must be 2.2 or 4.1 (got " << version << ")");
  // A shell's mid-surface has triangles and no tetrahedra (gmsh_io.hpp).
  const bool surface = mesh.tets.empty();
  PLISSE_CHECK(!surface || !mesh.triangles.empty(),
               "write_gmsh: the mesh has neither tetrahedra nor triangles");
  const bool second = mesh.order() == 2;
  PLISSE_CHECK(!second || mesh.tet_edge_nodes.size() == mesh.tets.size(),
               "write_gmsh: tet_edge_nodes size");
  PLISSE_CHECK(!second || mesh.triangle_edge_nodes.size() == mesh.triangles.size(),
               "write_gmsh: triangle_edge_nodes size");
  const auto n_nodes = static_cast<std::size_t>(mesh.n_nodes());
  std::vector<char> used(n_nodes, 0);
  auto use = [&](int node) {
    PLISSE_CHECK(node >= 0 && static_cast<std::size_t>(node) < n_nodes,
                 "write_gmsh: node index " << node << " out of range");
    used[static_cast<std::size_t>(node)] = 1;
  };
  for (const auto& t : mesh.tets)
    for (int n : t) use(n);
  for (const auto& t : mesh.tet_edge_nodes)
    for (int n : t) use(n);
  for (const auto& t : mesh.triangles)
    for (int n : t) use(n);
  for (const auto& t : mesh.triangle_edge_nodes)
    for (int n : t) use(n);
  for (const auto& e : mesh.edges)
    for (int n : e) use(n);

  const Signatures tet_sig = compute_signatures(mesh.volume_tags, mesh.tets.size(), "tetrahedron");
  const Signatures tri_sig =
      compute_signatures(mesh.surface_tags, mesh.triangles.size(), "triangle");
  const Signatures edge_sig = compute_signatures(mesh.edge_tags, mesh.edges.size(), "edge");

  GmshSession session;
  try {
    gmsh::model::add("plisse");
    const auto tet_runs = make_runs(3, tet_sig);
    const auto tri_runs = make_runs(2, tri_sig);
    const auto edge_runs = make_runs(1, edge_sig);

    // All nodes live on the first volume entity (a surface's: the first surface entity); tags are
    // index + 1.
    std::vector<std::size_t> node_tags(n_nodes);
    std::vector<double> coords(3 * n_nodes);
    for (std::size_t i = 0; i < n_nodes; ++i) {
      node_tags[i] = i + 1;
      for (int c = 0; c < 3; ++c) coords[3 * i + static_cast<std::size_t>(c)] = mesh.nodes[i][c];
    }
    gmsh::model::mesh::addNodes(surface ? 2 : 3,
                                surface ? tri_runs.front().entity : tet_runs.front().entity,
                                node_tags, coords);

    // Element tags: tetrahedra 1..n_tets, then triangles, then edges, then (v2) points, in mesh
    // order.
    std::size_t next_tag = 1;
    for (const auto& run : tet_runs) {
      std::vector<std::size_t> tags, nodes;
      for (std::size_t e = run.begin; e < run.end; ++e) {
        tags.push_back(next_tag++);
        for (int n : mesh.tets[e]) nodes.push_back(static_cast<std::size_t>(n) + 1);
        if (second)
          for (int n : mesh.tet_edge_nodes[e]) nodes.push_back(static_cast<std::size_t>(n) + 1);
      }
      gmsh::model::mesh::addElementsByType(run.entity, second ? kTet10 : kTet4, tags, nodes);
    }
    for (const auto& run : tri_runs) {
      std::vector<std::size_t> tags, nodes;
      for (std::size_t e = run.begin; e < run.end; ++e) {
        tags.push_back(next_tag++);
        for (int n : mesh.triangles[e]) nodes.push_back(static_cast<std::size_t>(n) + 1);
        if (second)
          for (int n : mesh.triangle_edge_nodes[e])
            nodes.push_back(static_cast<std::size_t>(n) + 1);
      }
      gmsh::model::mesh::addElementsByType(run.entity, second ? kTri6 : kTri3, tags, nodes);
    }
    for (const auto& run : edge_runs) {
      std::vector<std::size_t> tags, nodes;
      for (std::size_t e = run.begin; e < run.end; ++e) {
        tags.push_back(next_tag++);
        for (int n : mesh.edges[e]) nodes.push_back(static_cast<std::size_t>(n) + 1);
      }
      gmsh::model::mesh::addElementsByType(run.entity, kLine2, tags, nodes);
    }
    add_groups(3, tet_sig, tet_runs, v2);
    add_groups(2, tri_sig, tri_runs, v2);
    add_groups(1, edge_sig, edge_runs, v2);
    if (v2) {
      // Gmsh's v2 writer only writes nodes of written elements: keep unused nodes as points.
      std::vector<std::size_t> tags, nodes;
      for (std::size_t i = 0; i < n_nodes; ++i)
        if (!used[i]) {
          tags.push_back(next_tag++);
          nodes.push_back(i + 1);
        }
      if (!tags.empty()) {
        const int entity = gmsh::model::addDiscreteEntity(0);
        gmsh::model::mesh::addElementsByType(entity, kPoint, tags, nodes);
        const int group = gmsh::model::addPhysicalGroup(0, {entity});
        gmsh::model::setPhysicalName(0, group, kUntaggedGroupName);
      }
    }
    session.check_internal("write_gmsh: building the Gmsh model");
    gmsh::option::setNumber("Mesh.MshFileVersion", version);
    gmsh::option::setNumber("Mesh.Binary", binary ? 1 : 0);
    // v4: SaveAll writes every element and keeps the physical groups in $Entities. v2: SaveAll
    // would write physical tag 0 for every element, so only grouped elements are written.
    gmsh::option::setNumber("Mesh.SaveAll", v2 ? 0 : 1);
    gmsh::option::setNumber("Mesh.SaveParametric", 0);
    gmsh::write(path);
    session.check_input(path, "cannot write the mesh file");
    check_written_whole(path);
  } catch (const Error&) {
    throw;
  } catch (const std::string& message) {
    throw file_error(path, "cannot write the mesh file: " + message);
  }
}

}  // namespace plisse
