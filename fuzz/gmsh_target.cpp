// Fuzz target "gmsh": read_gmsh (the Gmsh SDK in an isolated reader process, then plisse's
// checks and normalisation in this one) on arbitrary file contents.
#include <gmsh.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "mesh/gmsh_io.hpp"
#include "mesh/gmsh_session.hpp"
#include "scratch_file.hpp"
#include "targets.hpp"

namespace plisse::fuzz {
namespace {

/// Inputs between two re-reads of the reference mesh (a full read costs about one input).
constexpr long kReferenceEvery = 64;

/// Limits of the reader process for inputs of at most 64 KiB (scripts/fuzz -max_len): tighter than
/// gmsh_reader_limits, so that an input on which Gmsh loops costs 2 s of CPU, well within
/// libFuzzer's -timeout, and is rejected (a malformed file) rather than reported as a timeout.
ChildLimits fuzz_limits() {
  ChildLimits limits;
  limits.memory_bytes = std::uint64_t{512} << 20;
  limits.cpu_seconds = 2;
  limits.wall_seconds = 6.0;
  return limits;
}

bool index_ok(int i, std::size_t n) { return i >= 0 && static_cast<std::size_t>(i) < n; }

/// read_gmsh's postconditions (gmsh_io.hpp, mesh.hpp) that the rest of plisse relies on.
void check_postconditions(const Mesh& m) {
  const std::size_t n_nodes = m.nodes.size();
  if (m.tets.empty()) throw Finding("accepted mesh has no tetrahedra");
  for (const auto& t : m.tets)
    for (int v : t)
      if (!index_ok(v, n_nodes)) throw Finding("tetrahedron node index out of range");
  for (const auto& t : m.triangles)
    for (int v : t)
      if (!index_ok(v, n_nodes)) throw Finding("triangle node index out of range");
  if (!m.tet_edge_nodes.empty() && m.tet_edge_nodes.size() != m.tets.size())
    throw Finding("tet_edge_nodes and tets differ in size");
  if (m.order() == 2 && m.triangle_edge_nodes.size() != m.triangles.size())
    throw Finding("triangle_edge_nodes and triangles differ in size on a second-order mesh");
  for (const auto& t : m.tet_edge_nodes)
    for (int v : t)
      if (!index_ok(v, n_nodes)) throw Finding("tetrahedron edge node index out of range");
  for (const auto& t : m.triangle_edge_nodes)
    for (int v : t)
      if (!index_ok(v, n_nodes)) throw Finding("triangle edge node index out of range");
  for (const auto& [name, indices] : m.surface_tags)
    for (int i : indices)
      if (!index_ok(i, m.triangles.size()))
        throw Finding("surface tag '" + name + "' out of range");
  for (const auto& [name, indices] : m.volume_tags)
    for (int i : indices)
      if (!index_ok(i, m.tets.size())) throw Finding("volume tag '" + name + "' out of range");
}

/// A new session must find Gmsh empty: a reader that leaves entities, views or log lines behind
/// would make the next input depend on this one.
void check_gmsh_is_clean() {
  GmshSession session;
  gmsh::vectorpair entities;
  gmsh::model::getEntities(entities, -1);
  std::vector<int> views;
  gmsh::view::getTags(views);
  std::vector<std::string> models;
  gmsh::model::list(models);
  if (!entities.empty() || !views.empty() || models.size() != 1)
    throw Finding("Gmsh state survived a read: " + std::to_string(entities.size()) + " entities, " +
                  std::to_string(views.size()) + " views, " + std::to_string(models.size()) +
                  " models");
  if (!session.take_errors().empty()) throw Finding("Gmsh errors logged by an earlier session");
}

/// One tetrahedron with a tagged face, written once by write_gmsh.
Mesh reference_mesh() {
  Mesh m;
  m.nodes = {Vec3d(0, 0, 0), Vec3d(1, 0, 0), Vec3d(0, 1, 0), Vec3d(0, 0, 1)};
  m.tets = {{0, 1, 2, 3}};
  m.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  m.surface_tags["bottom"] = {0};
  m.surface_tags["rest"] = {1, 2, 3};
  m.volume_tags["body"] = {0};
  return m;
}

bool same_mesh(const Mesh& a, const Mesh& b) {
  return a.nodes == b.nodes && a.tets == b.tets && a.triangles == b.triangles &&
         a.surface_tags == b.surface_tags && a.volume_tags == b.volume_tags;
}

/// Reads the reference file and compares it with its first reading.
void check_reference_read() {
  static const std::string path = [] {
    const std::string p = write_scratch_file("reference.msh", {}).string();
    write_gmsh(reference_mesh(), p);
    return p;
  }();
  static const Mesh first = read_gmsh(path);
  if (!same_mesh(read_gmsh(path), first))
    throw Finding("the reference mesh reads differently after earlier inputs (Gmsh state leak)");
}

}  // namespace

Outcome read_mesh(Bytes data) {
  static long n_inputs = 0;
  if (n_inputs++ % kReferenceEvery == 0) check_reference_read();
  const std::string path = write_scratch_file("input.msh", data).string();
  Outcome outcome = Outcome::rejected;
  try {
    GmshReadInfo info;
    check_postconditions(read_gmsh(path, info, fuzz_limits()));
    outcome = Outcome::accepted;
  } catch (const Error&) {  // InputError derives from Error
  }
  check_gmsh_is_clean();
  return outcome;
}

}  // namespace plisse::fuzz
